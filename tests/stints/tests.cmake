# stints tests: constant-bearing stints, CTS-A*, bearing optimisation, stint planners, paths to stints
glider_add_test(test_stints ${CMAKE_CURRENT_LIST_DIR}/TestStints.cpp)
if(OMPL_GLIDER_WITH_MISSION)
  glider_add_test(test_stints_mission ${CMAKE_CURRENT_LIST_DIR}/TestStintMissions.cpp)
endif()
