# map tests (the test reads the PNG back with cairo)
glider_add_test(test_map ${CMAKE_CURRENT_LIST_DIR}/TestMapRenderer.cpp)
target_link_libraries(test_map INTERFACE PkgConfig::CAIRO)
