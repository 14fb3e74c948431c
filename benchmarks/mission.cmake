# benchmarks of mission: optimal departure time vs brute force; dive-profile parallel speedup
glider_add_benchmark(bench_departure ${CMAKE_CURRENT_LIST_DIR}/mission/bench_departure.cpp)
glider_add_benchmark(bench_dive_profiles ${CMAKE_CURRENT_LIST_DIR}/mission/bench_dive_profiles.cpp)
