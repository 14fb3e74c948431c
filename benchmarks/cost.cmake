glider_add_benchmark(bench_travel_time ${CMAKE_CURRENT_LIST_DIR}/bench_travel_time.cpp)
