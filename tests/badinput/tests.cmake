# Bad and edge inputs of glider_plan, one table row each (bad_inputs.py): exit status, message, no signal, no NaN,
# the output directory unchanged.
if(TARGET glider_plan)
  find_program(OMPL_GLIDER_PYTHON3 python3 REQUIRED)
  add_test(NAME badinput.table
    COMMAND ${OMPL_GLIDER_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/bad_inputs.py $<TARGET_FILE:glider_plan>)
  set_tests_properties(badinput.table PROPERTIES TIMEOUT 900)
endif()
