# mission tests
glider_add_test(test_mission_goto ${CMAKE_CURRENT_LIST_DIR}/TestSlocumGoto.cpp)
glider_add_test(test_mission_departure ${CMAKE_CURRENT_LIST_DIR}/TestDepartureTime.cpp)
glider_add_test(test_mission_file ${CMAKE_CURRENT_LIST_DIR}/TestMissionFile.cpp)
glider_add_test(test_mission_run ${CMAKE_CURRENT_LIST_DIR}/TestMissionRun.cpp ${CMAKE_CURRENT_LIST_DIR}/TestForecastLand.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestCoastline.cpp)
target_link_libraries(test_mission_run PRIVATE nlohmann_json::nlohmann_json netCDF::netcdf GDAL::GDAL)
glider_add_test(test_mission_bathymetry ${CMAKE_CURRENT_LIST_DIR}/TestBathymetry.cpp)
# glider_plan --mission / --currents / --speeds and its error cases (issues 5, 6)
if(TARGET glider_plan)
  add_test(NAME mission.glider_plan_cli
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_glider_plan_cli.sh $<TARGET_FILE:glider_plan> ${PROJECT_SOURCE_DIR})
  set_tests_properties(mission.glider_plan_cli PROPERTIES TIMEOUT 300)
endif()
