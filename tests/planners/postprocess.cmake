# tests of smoothing / refinement / comparison with the optimum
glider_add_test(test_smoothing ${CMAKE_CURRENT_LIST_DIR}/TestSmoothing.cpp)
glider_add_test(test_refine ${CMAKE_CURRENT_LIST_DIR}/TestRefine.cpp)
glider_add_test(test_planner_vs_optimum ${CMAKE_CURRENT_LIST_DIR}/TestPlannerVsOptimum.cpp)
