# benchmarks of mission: optimal departure time vs brute force; dive-profile parallel speedup
glider_add_benchmark(bench_departure ${CMAKE_CURRENT_LIST_DIR}/mission/bench_departure.cpp)
glider_add_benchmark(bench_dive_profiles ${CMAKE_CURRENT_LIST_DIR}/mission/bench_dive_profiles.cpp)
# the trust benchmark: the default against an independent extremal sweep over random pairs (docs/TRUST.md)
glider_add_benchmark(bench_trust ${CMAKE_CURRENT_LIST_DIR}/mission/bench_trust.cpp)
target_include_directories(bench_trust PRIVATE ${PROJECT_SOURCE_DIR}/tests/mission)
# missions of several legs: legs on one clock against guessed departures; the free order against n!
glider_add_benchmark(bench_legs ${CMAKE_CURRENT_LIST_DIR}/mission/bench_legs.cpp)
# many DAC correcting the forecast: the correction's and the plan's time against the uncorrected plan's
glider_add_benchmark(bench_many_dac ${CMAKE_CURRENT_LIST_DIR}/mission/bench_many_dac.cpp)
