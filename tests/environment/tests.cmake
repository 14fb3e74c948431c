# tests of environment/
glider_add_test(test_environment ${CMAKE_CURRENT_LIST_DIR}/TestEnvironment.cpp)
glider_add_test(test_environment_planning ${CMAKE_CURRENT_LIST_DIR}/TestEnvironmentPlanning.cpp)
glider_add_test(test_environment_keep_off ${CMAKE_CURRENT_LIST_DIR}/TestKeepOff.cpp)
