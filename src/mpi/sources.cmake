# mpi: the TaskSpreader of an MPI job (OMPL_GLIDER_WITH_MPI), its own library ompl_glider_mpi so that the main
# library does not depend on MPI; only the executables (apps/, benchmarks/) link it.
set(OMPL_GLIDER_MPI_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/MpiTaskSpreader.cpp
)
