# gridded / NetCDF tests (current model from forecasts)
glider_add_test(test_current_interpolation ${CMAKE_CURRENT_LIST_DIR}/TestInterpolation.cpp)
glider_add_test(test_current_gridded ${CMAKE_CURRENT_LIST_DIR}/TestGriddedField.cpp)
glider_add_test(test_current_projection ${CMAKE_CURRENT_LIST_DIR}/TestProjection.cpp)
glider_add_test(test_current_netcdf
  ${CMAKE_CURRENT_LIST_DIR}/TestNetCdfTime.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestNetCdfLayouts.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestNetCdfLand.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestNetCdfTracerLand.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestNetCdfUnitsAndNames.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestNetCdfMultiFile.cpp

  ${CMAKE_CURRENT_LIST_DIR}/TestNetCdfGlobal.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestNetCdfModelGrids.cpp)
target_link_libraries(test_current_netcdf INTERFACE netCDF::netcdf)
glider_add_test(test_current_gridded_agreement ${CMAKE_CURRENT_LIST_DIR}/TestGriddedAgreement.cpp)
target_link_libraries(test_current_gridded_agreement INTERFACE netCDF::netcdf)
# bad forecast files refused with a clear Error; the classic-format size check and the derived grid angle (internals
# of the reader)
glider_add_test(test_current_netcdf_checks
  ${CMAKE_CURRENT_LIST_DIR}/TestNetCdfBadFiles.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestNetCdfClassicSize.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestNetCdfGridAngle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TestFastNodes.cpp)
target_link_libraries(test_current_netcdf_checks INTERFACE netCDF::netcdf)
target_include_directories(test_current_netcdf_checks INTERFACE ${PROJECT_SOURCE_DIR}/src/current)
# glider_plan on steady files, undated time axes and mislabelled velocity units
if(TARGET glider_plan)
  add_test(NAME current.glider_plan_forecast_files
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_glider_plan_forecast_files.sh $<TARGET_FILE:glider_plan>)
  set_tests_properties(current.glider_plan_forecast_files PROPERTIES TIMEOUT 600)
  # glider_plan --currents with a glob and a list of daily files: the combined file's travel time
  add_test(NAME current.glider_plan_forecast_glob
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_glider_plan_forecast_glob.sh $<TARGET_FILE:glider_plan>)
  set_tests_properties(current.glider_plan_forecast_glob PROPERTIES TIMEOUT 600)
  # glider_plan on NCL's POP sample (libncarg-data): coastal routes checked against the model's own tracer mask
  add_test(NAME current.glider_plan_pop_land
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_glider_plan_pop_land.sh $<TARGET_FILE:glider_plan>)
  set_tests_properties(current.glider_plan_pop_land PROPERTIES TIMEOUT 600)
endif()
