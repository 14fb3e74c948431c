# execution tests: flying plans in another ocean
glider_add_test(test_execution ${CMAKE_CURRENT_LIST_DIR}/TestExecution.cpp)
# the accurate re-flight of a route ("honest times")
glider_add_test(test_reflight ${CMAKE_CURRENT_LIST_DIR}/TestReflight.cpp)
