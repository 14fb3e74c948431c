# tests of reachability/
glider_add_test(test_reachability ${CMAKE_CURRENT_LIST_DIR}/TestLevelSet.cpp
                ${CMAKE_CURRENT_LIST_DIR}/TestLevelSetPlanner.cpp ${CMAKE_CURRENT_LIST_DIR}/TestIsochrones.cpp
                ${CMAKE_CURRENT_LIST_DIR}/TestLevelSetIslands.cpp)
target_link_libraries(test_reachability INTERFACE nlohmann_json::nlohmann_json)
# the level set's first arrival through the pipeline interface (the global check's question), as the solver gives it
glider_add_test(test_reachability_first_arrival ${CMAKE_CURRENT_LIST_DIR}/TestFirstArrival.cpp)
