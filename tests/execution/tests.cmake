# execution tests: flying plans in another ocean
glider_add_test(test_execution ${CMAKE_CURRENT_LIST_DIR}/TestExecution.cpp)
# the accurate re-flight of a route ("honest times")
glider_add_test(test_reflight ${CMAKE_CURRENT_LIST_DIR}/TestReflight.cpp)
# every flight ends (its end time, a station not reached, a stay) and its memory stays bounded
glider_add_test(test_execution_bounds ${CMAKE_CURRENT_LIST_DIR}/TestExecutionBounds.cpp)
# the robust plan's work over an ensemble's members: bounded candidates, few flown in every member, the time limit
glider_add_test(test_ensemble_work ${CMAKE_CURRENT_LIST_DIR}/TestEnsembleWork.cpp)
