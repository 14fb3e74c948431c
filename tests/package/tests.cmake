# find_package(ompl_glider) from an install prefix works for a downstream project.
add_test(NAME package.find_package_consumer
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run_consumer.sh ${PROJECT_BINARY_DIR} ${CMAKE_CURRENT_LIST_DIR}/consumer
          ${CMAKE_CURRENT_BINARY_DIR}/package_consumer)
set_tests_properties(package.find_package_consumer PROPERTIES TIMEOUT 300)
