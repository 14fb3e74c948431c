# planners/ post-processing: smoothing, refinement
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/PathSmoother.cpp
  ${CMAKE_CURRENT_LIST_DIR}/WaypointRefiner.cpp
)
