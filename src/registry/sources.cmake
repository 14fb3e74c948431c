# registry/: every planner by name (lattice, sampling, level set, stints), above the layers that define them
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/PlannerRegistry.cpp
)
