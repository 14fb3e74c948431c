# dive profile tests (003 Table I, Sec. III.B)
glider_add_test(test_dive_profile ${CMAKE_CURRENT_LIST_DIR}/TestDiveProfile.cpp)
