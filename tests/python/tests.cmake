# The Python module's tests (pytest, Debian's python3-pytest), one ctest per file; examples/python run headless.
if(TARGET ompl_glider_python)
  set(OMPL_GLIDER_PY_ENV "PYTHONPATH=${PROJECT_BINARY_DIR}/python" "MPLBACKEND=Agg"
      "OMPL_GLIDER_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
  if(TARGET glider_plan)
    list(APPEND OMPL_GLIDER_PY_ENV "GLIDER_PLAN=$<TARGET_FILE:glider_plan>")
  endif()
  foreach(file api cli_equivalence opendap legs observations settings resume correction threads gridded_kind
               reachability read_observations runs)
    add_test(NAME python.${file}
      COMMAND ${Python3_EXECUTABLE} -m pytest -q -p no:cacheprovider ${CMAKE_CURRENT_LIST_DIR}/test_${file}.py)
    set_tests_properties(python.${file} PROPERTIES ENVIRONMENT "${OMPL_GLIDER_PY_ENV}" TIMEOUT 300 LABELS python)
  endforeach()
  # the forecast-run test bed (scripts/make_forecast_runs.py): pure Python with netCDF-C's ncgen and ncdump, run by
  # the Python that runs the module's tests (one with pytest: a sanitized build has no module and runs none of them)
  find_program(OMPL_GLIDER_NCGEN ncgen)
  find_program(OMPL_GLIDER_NCDUMP ncdump)
  if(OMPL_GLIDER_NCGEN AND OMPL_GLIDER_NCDUMP)
    add_test(NAME python.forecast_runs
      COMMAND ${Python3_EXECUTABLE} -m pytest -q -p no:cacheprovider ${CMAKE_CURRENT_LIST_DIR}/test_forecast_runs.py)
    set_tests_properties(python.forecast_runs PROPERTIES
      ENVIRONMENT "OMPL_GLIDER_SOURCE_DIR=${PROJECT_SOURCE_DIR}" TIMEOUT 120 LABELS python)
  endif()
  add_test(NAME python.example_forecast_map
    COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/examples/python/plan_forecast.py
            ${CMAKE_CURRENT_BINARY_DIR}/example_forecast_map)
  set_tests_properties(python.example_forecast_map PROPERTIES ENVIRONMENT "${OMPL_GLIDER_PY_ENV}" TIMEOUT 300
    LABELS python)
endif()
