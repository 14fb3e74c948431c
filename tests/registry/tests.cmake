# tests of registry/: a planner registered only in the tests goes through the whole pipeline
glider_add_test(test_registry_planner ${CMAKE_CURRENT_LIST_DIR}/TestRegisteredPlanner.cpp)
