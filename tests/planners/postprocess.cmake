# tests of smoothing / refinement / comparison with the optimum
glider_add_test(test_smoothing ${CMAKE_CURRENT_LIST_DIR}/TestSmoothing.cpp)
glider_add_test(test_refine ${CMAKE_CURRENT_LIST_DIR}/TestRefine.cpp)
glider_add_test(test_isochrone_search ${CMAKE_CURRENT_LIST_DIR}/TestIsochroneSearch.cpp)
glider_add_test(test_planner_vs_optimum ${CMAKE_CURRENT_LIST_DIR}/TestPlannerVsOptimum.cpp)
# The main job: glider_plan with --out writes summary.json, path.csv, map.svg and map.png.
if(TARGET glider_plan)
  add_test(NAME planners.glider_plan_outputs
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_glider_plan.sh $<TARGET_FILE:glider_plan>)
  set_tests_properties(planners.glider_plan_outputs PROPERTIES TIMEOUT 300)
endif()
