# routes/: what is done to a route once planned, by the planners and the pipeline alike: smoothing and waypoint
# refinement of straight legs, held headings refined by shooting and tracked along a path, a curve flown as legs;
# constant-bearing stints ([IsernObstacles]): the stint simulator, the bearing optimisation (NLopt) and the conversion
# of any timed path to stints
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/PathSmoother.cpp
  ${CMAKE_CURRENT_LIST_DIR}/WaypointRefiner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/HeadingRefiner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/HeadingTracker.cpp
  ${CMAKE_CURRENT_LIST_DIR}/CurveLegs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StintSimulator.cpp
  ${CMAKE_CURRENT_LIST_DIR}/BearingOptimizer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PathToStints.cpp
)
