# routes/: what is done to a route once planned, by the planners and the pipeline alike: smoothing and waypoint
# refinement of straight legs, held headings refined by shooting and tracked along a path
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/PathSmoother.cpp
  ${CMAKE_CURRENT_LIST_DIR}/WaypointRefiner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/HeadingRefiner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/HeadingTracker.cpp
  ${CMAKE_CURRENT_LIST_DIR}/CurveLegs.cpp
)
