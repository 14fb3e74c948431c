# tests of output/: the map, the Slocum goto list, the output directory under faults
include(${CMAKE_CURRENT_LIST_DIR}/map.cmake)
glider_add_test(test_mission_goto ${CMAKE_CURRENT_LIST_DIR}/TestSlocumGoto.cpp)
# map.html's page: Leaflet and the data in the template, escaping, the data read back, a fleet's page
glider_add_test(test_map_html ${CMAKE_CURRENT_LIST_DIR}/TestMapHtml.cpp)
target_link_libraries(test_map_html INTERFACE nlohmann_json::nlohmann_json)
# the output directory under faults: SIGKILL at every step, a signal while staging, a failing write, a lock
glider_add_test(test_output_faults ${CMAKE_CURRENT_LIST_DIR}/TestOutputFaults.cpp)
target_include_directories(test_output_faults INTERFACE ${PROJECT_SOURCE_DIR}/src/output)
if(TARGET glider_plan)
  # glider_plan under SIGINT/SIGTERM, a second run, a dangling link, a full and a read-only tmpfs
  add_test(NAME mission.output_faults
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_output_faults.sh $<TARGET_FILE:glider_plan>)
  set_tests_properties(mission.output_faults PROPERTIES TIMEOUT 300)
endif()
# the output formats' writers: one per format of outputFormats(), each making the files its format declares
glider_add_test(test_output_formats ${CMAKE_CURRENT_LIST_DIR}/TestOutputFormats.cpp)
