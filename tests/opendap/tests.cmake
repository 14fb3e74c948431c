# OPeNDAP forecasts: glider_plan --currents URL through NetCDF-C's DAP client against a DAP2 server of the tests on
# 127.0.0.1 (dap2_server.py): the file's travel time, a subset fetched, the cache, a stopped, slow and failing server
if(TARGET glider_plan)
  add_test(NAME opendap.glider_plan_url
    COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/check_opendap.py $<TARGET_FILE:glider_plan>)
  set_tests_properties(opendap.glider_plan_url PROPERTIES TIMEOUT 600)
endif()
