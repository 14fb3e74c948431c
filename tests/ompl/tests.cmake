# tests of ompl/
glider_add_test(test_ompl_space ${CMAKE_CURRENT_LIST_DIR}/TestTimeSE2StateSpace.cpp)
glider_add_test(test_ompl_validator ${CMAKE_CURRENT_LIST_DIR}/TestMotionValidator.cpp)
glider_add_test(test_ompl_setup ${CMAKE_CURRENT_LIST_DIR}/TestGliderSetup.cpp)
glider_add_test(test_ompl_rrtstar ${CMAKE_CURRENT_LIST_DIR}/TestRRTstarOnJet.cpp)
glider_add_test(test_ompl_control ${CMAKE_CURRENT_LIST_DIR}/TestGliderControl.cpp)
