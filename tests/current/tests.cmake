glider_add_test(test_current ${CMAKE_CURRENT_LIST_DIR}/TestCurrentConformance.cpp)
include(${CMAKE_CURRENT_LIST_DIR}/gridded.cmake)
