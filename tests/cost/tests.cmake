glider_add_test(test_cost ${CMAKE_CURRENT_LIST_DIR}/TestTravelTime.cpp)
include(${CMAKE_CURRENT_LIST_DIR}/dive.cmake)
