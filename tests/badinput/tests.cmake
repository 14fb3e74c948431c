# Bad and edge inputs of glider_plan, one table row each (bad_inputs.py): exit status, message, no signal, no NaN,
# the output directory unchanged.
if(TARGET glider_plan)
  find_program(OMPL_GLIDER_PYTHON3 python3 REQUIRED)
  add_test(NAME badinput.table
    COMMAND ${OMPL_GLIDER_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/bad_inputs.py $<TARGET_FILE:glider_plan>)
  set_tests_properties(badinput.table PROPERTIES TIMEOUT 900)
endif()
# glider_plan under ulimit -t, -v and -u: a clear message, never a crash (resource_limits.sh)
if(TARGET glider_plan)
  add_test(NAME badinput.resource_limits
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/resource_limits.sh $<TARGET_FILE:glider_plan>)
  set_tests_properties(badinput.resource_limits PROPERTIES TIMEOUT 120)
endif()
