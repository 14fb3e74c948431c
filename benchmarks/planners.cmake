# benchmarks of planners
# Table 4 of [EichhornRAS]: CFC / CMC of TVE, A*TVE, ZTVE, ZA*TVE (lattice search).
glider_add_benchmark(bench_table4 ${CMAKE_CURRENT_LIST_DIR}/table4/bench_table4.cpp)
# CFC / CMC / expansions / wall time of the search configurations on the repository's problems, 100 random
# jet pairs and a 10^6-vertex gridded forecast (benchmarks/search/README.md).
glider_add_benchmark(bench_search ${CMAKE_CURRENT_LIST_DIR}/search/bench_search.cpp)
# The level-set planner's error against the shooting optimum vs wall time, beside ZA*TVE + refinement,
# and what the narrow band, the gradient heading and the threads buy.
glider_add_benchmark(bench_levelset ${CMAKE_CURRENT_LIST_DIR}/reachability/bench_levelset.cpp)
# Strong currents, per V and planner: travel time against a fine level set, wall time, random pairs solved.
glider_add_benchmark(bench_strong_currents ${CMAKE_CURRENT_LIST_DIR}/reachability/bench_strong_currents.cpp)
