glider_add_test(test_cost ${CMAKE_CURRENT_LIST_DIR}/TestTravelTime.cpp)
