# reachability/: the level-set solver (reachable sets, first-arrival times, optimal paths, isochrones; issue 12)
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/LevelSet.cpp
)
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/LevelSetPlanner.cpp
)
