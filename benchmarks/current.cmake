# benchmarks of current: gridded current-model calls per second for each (x/y, time) scheme pair
glider_add_benchmark(bench_current_model ${CMAKE_CURRENT_LIST_DIR}/current/bench_current_model.cpp)
