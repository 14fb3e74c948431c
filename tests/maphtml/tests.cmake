# map.html in a real browser: glider_plan's page opened offline in Debian's headless Chromium over the DevTools
# protocol (check_map_html.py): no console error, the route's vertices, the waypoints' dates in the popups,
# isochrones, land, flown tracks, the time slider, a screenshot that is not blank
if(TARGET glider_plan)
  add_test(NAME maphtml.chromium
    COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/check_glider_plan_map.py $<TARGET_FILE:glider_plan> ${PROJECT_SOURCE_DIR})
  set_tests_properties(maphtml.chromium PROPERTIES TIMEOUT 900)
endif()
