# the one planning pipeline and the one output layer
glider_add_test(test_pipeline ${CMAKE_CURRENT_LIST_DIR}/TestPipeline.cpp)
target_link_libraries(test_pipeline INTERFACE nlohmann_json::nlohmann_json)

if(TARGET glider_plan)
  add_test(NAME mission.three_modes
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_three_modes.sh $<TARGET_FILE:glider_plan> ${PROJECT_SOURCE_DIR})
  set_tests_properties(mission.three_modes PROPERTIES TIMEOUT 300)
  # every example mission exits 0 with a solved plan, as a user runs it (minutes: CI only)
  add_test(NAME mission.examples_exit_zero
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_examples.sh $<TARGET_FILE:glider_plan> ${PROJECT_SOURCE_DIR})
  set_tests_properties(mission.examples_exit_zero PROPERTIES TIMEOUT 3600)
endif()
# strong currents: the heading planners against closed forms, a brute-force bound and the level set
glider_add_test(test_strong_currents ${CMAKE_CURRENT_LIST_DIR}/TestStrongCurrents.cpp)
# the same against the level set at a fine resolution: slow
add_executable(test_strong_currents_fine ${CMAKE_CURRENT_LIST_DIR}/TestStrongCurrentsFine.cpp)
target_link_libraries(test_strong_currents_fine PRIVATE ompl_glider::ompl_glider GTest::gtest GTest::gtest_main)
target_compile_options(test_strong_currents_fine PRIVATE -Wall -Wextra)
gtest_discover_tests(test_strong_currents_fine DISCOVERY_TIMEOUT 60 NO_PRETTY_VALUES
                     PROPERTIES TIMEOUT 1800 LABELS ci)
if(TARGET glider_plan)
  # flags override a mission file's fields: --mission m.yaml --speed 0.6 plans the mission edited to 0.6
  add_test(NAME mission.flags_override_mission_file
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_mission_overrides.sh $<TARGET_FILE:glider_plan>)
  set_tests_properties(mission.flags_override_mission_file PROPERTIES TIMEOUT 300)
endif()
if(TARGET glider_plan)
  # a real-data coastal trial: GSHHG coastlines (GMT), ETOPO5 depths, six routes checked independently (~10 s)
  add_test(NAME mission.real_coast_trial
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_real_coast_trial.sh $<TARGET_FILE:glider_plan> ${PROJECT_SOURCE_DIR})
  set_tests_properties(mission.real_coast_trial PROPERTIES TIMEOUT 300 SKIP_RETURN_CODE 77)
endif()
# the trust property: the default against an independent extremal sweep on random pairs (TrustFast: a dozen pairs;
# TrustProperty: more than a hundred, CI only). Not glider_add_test: its independent extremal sweep, in this file, is
# most of its work and keeps the build type's optimisation (no OMPL_GLIDER_TEST_CXX_FLAGS)
add_executable(test_trust ${CMAKE_CURRENT_LIST_DIR}/TestTrust.cpp)
target_link_libraries(test_trust PRIVATE ompl_glider::ompl_glider GTest::gtest GTest::gtest_main)
target_compile_options(test_trust PRIVATE -Wall -Wextra)
gtest_discover_tests(test_trust TEST_FILTER "TrustFast.*" DISCOVERY_TIMEOUT 60 NO_PRETTY_VALUES
                     PROPERTIES TIMEOUT 600)
gtest_discover_tests(test_trust TEST_FILTER "TrustProperty.*" DISCOVERY_TIMEOUT 60 NO_PRETTY_VALUES
                     PROPERTIES TIMEOUT 1800 LABELS ci)
# the global check of the route class: the upstream crossing of the jet, V = 0.1, --optimum inside the region
glider_add_test(test_global_check ${CMAKE_CURRENT_LIST_DIR}/TestGlobalCheck.cpp)
target_link_libraries(test_global_check INTERFACE nlohmann_json::nlohmann_json)
if(TARGET glider_plan)
  # every real forecast file bundled (examples/*.nc) or installed (NCL's pop.nc): coastal trips, each route sample
  # checked against the file's own land read with ncdump (fill values, masks, POP's tracer); fails if a file is missing
  add_test(NAME mission.bundled_files_land
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_bundled_files_land.sh $<TARGET_FILE:glider_plan> ${PROJECT_SOURCE_DIR})
  set_tests_properties(mission.bundled_files_land PROPERTIES TIMEOUT 300)
endif()
