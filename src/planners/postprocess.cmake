# planners/ heading routes: the isochrone planner
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/IsochronePlanner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/IsochroneSearch.cpp
)
