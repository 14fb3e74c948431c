# dive profile tests ([EichhornOceans] Table I, Sec. III.B)
glider_add_test(test_dive_profile ${CMAKE_CURRENT_LIST_DIR}/TestDiveProfile.cpp)
