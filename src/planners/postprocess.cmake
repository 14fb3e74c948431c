# planners/ post-processing: smoothing, refinement
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/PathSmoother.cpp
  ${CMAKE_CURRENT_LIST_DIR}/WaypointRefiner.cpp
)
# planners/ heading routes: the isochrone planner and the refinement of headings
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/HeadingRefiner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/HeadingTracker.cpp
  ${CMAKE_CURRENT_LIST_DIR}/IsochronePlanner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/IsochroneSearch.cpp
)
