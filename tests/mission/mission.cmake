# mission tests
glider_add_test(test_mission_departure ${CMAKE_CURRENT_LIST_DIR}/TestDepartureTime.cpp)
glider_add_test(test_mission_file ${CMAKE_CURRENT_LIST_DIR}/TestMissionFile.cpp)
# the declared ranges of the settings, tried bound by bound in a mission file and as overrides
glider_add_test(test_mission_setting_ranges ${CMAKE_CURRENT_LIST_DIR}/TestSettingRanges.cpp)
# an analytic flow's ensemble drawn from one set of parameters (members, spread, seed)
glider_add_test(test_mission_drawn_ensemble ${CMAKE_CURRENT_LIST_DIR}/TestDrawnEnsemble.cpp)
# an ensemble whose members disagree: the route most likely to arrive, never "no path" while members arrive
glider_add_test(test_mission_ensemble_arrival ${CMAKE_CURRENT_LIST_DIR}/TestEnsembleArrival.cpp)
target_link_libraries(test_mission_ensemble_arrival INTERFACE nlohmann_json::nlohmann_json)
target_link_libraries(test_mission_drawn_ensemble INTERFACE nlohmann_json::nlohmann_json)
glider_add_test(test_mission_run EXECUTABLE tests_mission_gis ${CMAKE_CURRENT_LIST_DIR}/TestMissionRun.cpp ${CMAKE_CURRENT_LIST_DIR}/TestForecastLand.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestForecastModelGrids.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestCoastline.cpp)
target_link_libraries(test_mission_run INTERFACE nlohmann_json::nlohmann_json netCDF::netcdf GDAL::GDAL)
# eight threads plan at once on forecasts in memory, in files, in Zarr stores and at URLs, with coastlines, writing
# their outputs: each answer the same plan's alone, to the bit (src/io/DatasetLock.h)
glider_add_test(test_mission_concurrent_sources ${CMAKE_CURRENT_LIST_DIR}/TestConcurrentSources.cpp)
target_link_libraries(test_mission_concurrent_sources INTERFACE netCDF::netcdf)
# the plan flown in another ocean through the pipeline
glider_add_test(test_mission_execution ${CMAKE_CURRENT_LIST_DIR}/TestMissionExecution.cpp)
glider_add_test(test_execution_reasons ${CMAKE_CURRENT_LIST_DIR}/TestExecutionReasons.cpp)
target_link_libraries(test_mission_execution INTERFACE nlohmann_json::nlohmann_json netCDF::netcdf)
# the execution's oracle: each pair planned and flown on the truth, the strategies' arrivals over its
glider_add_test(test_mission_execution_oracle ${CMAKE_CURRENT_LIST_DIR}/TestExecutionOracle.cpp)
target_link_libraries(test_mission_execution_oracle INTERFACE nlohmann_json::nlohmann_json)
# the many-plan modes through a TaskSpreader (TaskSpread.h) equal the threaded run bit for bit
glider_add_test(test_mission_task_spread ${CMAKE_CURRENT_LIST_DIR}/TestTaskSpread.cpp)
# a fleet: one plan per glider through the pipeline, one folder per glider, all or nothing
glider_add_test(test_mission_fleet ${CMAKE_CURRENT_LIST_DIR}/TestFleet.cpp ${CMAKE_CURRENT_LIST_DIR}/TestPlanStatus.cpp)
target_link_libraries(test_mission_fleet INTERFACE nlohmann_json::nlohmann_json)
if(TARGET glider_plan)
  add_test(NAME mission.fleet_cli
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_fleet_cli.sh $<TARGET_FILE:glider_plan> ${PROJECT_SOURCE_DIR})
endif()
# the gridded kind by its name and by its alias netcdf: one kind, the same plan to the bit
glider_add_test(test_mission_gridded_kind ${CMAKE_CURRENT_LIST_DIR}/TestGriddedKind.cpp)
# a forecast in several files (--currents LIST, current.file list or glob) planned as the combined file
glider_add_test(test_mission_forecast_files ${CMAKE_CURRENT_LIST_DIR}/TestForecastFiles.cpp)
target_link_libraries(test_mission_forecast_files INTERFACE netCDF::netcdf)
# forecast runs (current.runs): the newest run available at the departure, as that file alone
glider_add_test(test_mission_forecast_runs ${CMAKE_CURRENT_LIST_DIR}/TestForecastRuns.cpp)
target_link_libraries(test_mission_forecast_runs INTERFACE netCDF::netcdf)
# forecast runs in one file of several runs (a THREDDS FMRC: run dimension, 2-D time) as on one file a run; HYCOM's tau
glider_add_test(test_mission_forecast_runs_fmrc ${CMAKE_CURRENT_LIST_DIR}/TestForecastRunsFmrc.cpp)
target_link_libraries(test_mission_forecast_runs_fmrc INTERFACE netCDF::netcdf)
# glider_plan --mission / --currents / --speeds and its error cases
if(TARGET glider_plan)
  add_test(NAME mission.glider_plan_cli
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_glider_plan_cli.sh $<TARGET_FILE:glider_plan> ${PROJECT_SOURCE_DIR})
  set_tests_properties(mission.glider_plan_cli PROPERTIES TIMEOUT 300)
endif()
# glider_plan on real-sized global forecasts in both longitude conventions: the forecasts are written
# once by make_global_forecast (NetCDF-C) as a fixture, then one test per scenario (check_geography.sh)
if(TARGET glider_plan)
  add_executable(make_global_forecast ${CMAKE_CURRENT_LIST_DIR}/MakeGlobalForecast.cpp)
  target_link_libraries(make_global_forecast PRIVATE netCDF::netcdf)
  set(_geo_data ${CMAKE_CURRENT_BINARY_DIR}/geography_data)
  add_test(NAME mission.geography.files
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_geography.sh files $<TARGET_FILE:glider_plan>
            $<TARGET_FILE:make_global_forecast> ${_geo_data})
  set_tests_properties(mission.geography.files PROPERTIES FIXTURES_SETUP geography_files TIMEOUT 120)
  foreach(scenario dateline greenwich seam duplicate wide polar region)
    add_test(NAME mission.geography.${scenario}
      COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_geography.sh ${scenario} $<TARGET_FILE:glider_plan>
              $<TARGET_FILE:make_global_forecast> ${_geo_data})
    set_tests_properties(mission.geography.${scenario} PROPERTIES FIXTURES_REQUIRED geography_files TIMEOUT 300)
  endforeach()
endif()
# goals in time: a goal window met by holding at the goal or by timing the arrival, or not at all
glider_add_test(test_mission_goal_window ${CMAKE_CURRENT_LIST_DIR}/TestGoalWindow.cpp)
target_link_libraries(test_mission_goal_window INTERFACE nlohmann_json::nlohmann_json)
# missions of several legs: the chain of legs, the free order against all orders, stays, bad via points, targets
glider_add_test(test_mission_legs ${CMAKE_CURRENT_LIST_DIR}/TestMissionLegs.cpp
                ${CMAKE_CURRENT_LIST_DIR}/TestSeagliderTargets.cpp ${CMAKE_CURRENT_LIST_DIR}/TestPilotFilesFly.cpp
                ${CMAKE_CURRENT_LIST_DIR}/TestResume.cpp ${CMAKE_CURRENT_LIST_DIR}/TestTrueBearings.cpp)
target_link_libraries(test_mission_legs INTERFACE nlohmann_json::nlohmann_json)
# the glider's measurements: the forecast corrected by its DAC, the plan from the last fix
glider_add_test(test_mission_observations ${CMAKE_CURRENT_LIST_DIR}/TestObservations.cpp
                ${CMAKE_CURRENT_LIST_DIR}/TestExecutionObserved.cpp)
target_link_libraries(test_mission_observations INTERFACE netCDF::netcdf)
# safety margins (keep-off distance, depth limit) through the pipeline
glider_add_test(test_mission_safety ${CMAKE_CURRENT_LIST_DIR}/TestSafety.cpp)
target_link_libraries(test_mission_safety INTERFACE netCDF::netcdf)
# shorelines cut by the box closed along its edges (scripts/close_shorelines.py, used by make_coastline.sh)
add_test(NAME mission.close_shorelines
  COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/check_close_shorelines.py ${PROJECT_SOURCE_DIR}/scripts/close_shorelines.py)
# what a pilot reads and loads: calendars of climatologies, route.kml, the thinned goto list, no-path reasons,
# units for people, zero velocity as land
glider_add_test(test_mission_pilot EXECUTABLE tests_mission_gis ${CMAKE_CURRENT_LIST_DIR}/TestPilotOutputs.cpp)
target_link_libraries(test_mission_pilot INTERFACE nlohmann_json::nlohmann_json netCDF::netcdf GDAL::GDAL)
# the probability of reach over an ensemble's members: one level-set front per member, against each member's own
# solve, and its files (reachability.nc read back with NetCDF-C, the GeoJSON, summary.json)
glider_add_test(test_mission_reach_probability EXECUTABLE tests_mission_reach
  ${CMAKE_CURRENT_LIST_DIR}/TestReachProbability.cpp)
target_link_libraries(test_mission_reach_probability INTERFACE nlohmann_json::nlohmann_json netCDF::netcdf)
