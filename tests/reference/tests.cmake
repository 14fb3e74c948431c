# tests of reference/
glider_add_test(test_reference ${CMAKE_CURRENT_LIST_DIR}/TestZermeloReference.cpp)
