# benchmarks of the stint planners: [IsernObstacles] Tables I-III in shape, lattice paths as stints
if(OMPL_GLIDER_WITH_MISSION AND OMPL_GLIDER_WITH_NETCDF AND OMPL_GLIDER_WITH_MAP)
  glider_add_benchmark(bench_stints ${CMAKE_CURRENT_LIST_DIR}/stints/bench_stints.cpp)
  target_link_libraries(bench_stints PRIVATE netCDF::netcdf)
endif()
