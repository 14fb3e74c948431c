# benchmarks of planners
# Table 4 of [EichhornRAS]: CFC / CMC of TVE, A*TVE, ZTVE, ZA*TVE (lattice search).
glider_add_benchmark(bench_table4 ${CMAKE_CURRENT_LIST_DIR}/table4/bench_table4.cpp)
