# mission tests
glider_add_test(test_mission_goto ${CMAKE_CURRENT_LIST_DIR}/TestSlocumGoto.cpp)
glider_add_test(test_mission_departure ${CMAKE_CURRENT_LIST_DIR}/TestDepartureTime.cpp)
glider_add_test(test_mission_file ${CMAKE_CURRENT_LIST_DIR}/TestMissionFile.cpp)
glider_add_test(test_mission_run ${CMAKE_CURRENT_LIST_DIR}/TestMissionRun.cpp)
target_link_libraries(test_mission_run PRIVATE yaml-cpp)
glider_add_test(test_mission_bathymetry ${CMAKE_CURRENT_LIST_DIR}/TestBathymetry.cpp)
