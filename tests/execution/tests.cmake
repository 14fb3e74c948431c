# execution tests: flying plans in another ocean (issue 13)
glider_add_test(test_execution ${CMAKE_CURRENT_LIST_DIR}/TestExecution.cpp)
