# the one planning pipeline and the one output layer
glider_add_test(test_pipeline ${CMAKE_CURRENT_LIST_DIR}/TestPipeline.cpp)
target_link_libraries(test_pipeline PRIVATE nlohmann_json::nlohmann_json)

if(TARGET glider_plan)
  add_test(NAME mission.three_modes
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_three_modes.sh $<TARGET_FILE:glider_plan> ${PROJECT_SOURCE_DIR})
  set_tests_properties(mission.three_modes PROPERTIES TIMEOUT 300)
endif()
