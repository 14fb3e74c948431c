# tests of registry/: a planner registered only in the tests goes through the whole pipeline
glider_add_test(test_registry_planner ${CMAKE_CURRENT_LIST_DIR}/TestRegisteredPlanner.cpp)
# a gridded current source registered only in the tests (the recipe of docs/ARCHITECTURE.md) plans like NetCDF's
glider_add_test(test_registry_source ${CMAKE_CURRENT_LIST_DIR}/TestRegisteredSource.cpp)
# the planner the pipeline asks for by family: the family's first entry, a registered stranger found by name only
glider_add_test(test_registry_family ${CMAKE_CURRENT_LIST_DIR}/TestPlannerFamily.cpp)
