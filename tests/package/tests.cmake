# find_package(ompl_glider) from an install prefix works for a downstream project: the shared library with every
# component, and a static library without NetCDF and maps (built here, from the same sources).
add_test(NAME package.find_package_consumer
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run_consumer.sh ${PROJECT_BINARY_DIR} ${CMAKE_CURRENT_LIST_DIR}/consumer
          ${CMAKE_CURRENT_BINARY_DIR}/package_consumer)
set_tests_properties(package.find_package_consumer PROPERTIES TIMEOUT 300)
add_test(NAME package.static_without_netcdf_and_map
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run_consumer.sh ${CMAKE_CURRENT_BINARY_DIR}/static_build
          ${CMAKE_CURRENT_LIST_DIR}/consumer ${CMAKE_CURRENT_BINARY_DIR}/package_static ${PROJECT_SOURCE_DIR})
# rebuilds the whole library (minutes on two cores): CI only (label "ci"; scripts/run_tests.sh leaves it out)
set_tests_properties(package.static_without_netcdf_and_map PROPERTIES TIMEOUT 1200 LABELS ci)
# the Debian package (cpack -G DEB): its contents and Depends, the unpacked glider_plan and module run; installed
# with apt only as root with CI=true (a throwaway environment). cpack reinstalls the whole build: CI only.
add_test(NAME package.deb COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_deb.sh ${PROJECT_BINARY_DIR} "${Python3_EXECUTABLE}")
set_tests_properties(package.deb PROPERTIES TIMEOUT 900 LABELS ci RUN_SERIAL TRUE)
# the GDAL part loaded only when needed (src/io/GdalModule.h); a missing module named
if(TARGET glider_plan AND TARGET ompl_glider_gdal)
  add_test(NAME package.gdal_module_on_demand
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_gdal_module.sh $<TARGET_FILE:glider_plan> $<TARGET_FILE_DIR:ompl_glider>)
endif()
