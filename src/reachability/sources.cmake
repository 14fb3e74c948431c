# reachability/: the level-set solver (reachable sets, first-arrival times, optimal paths, isochrones)
# LevelSetInternal.h (internal, not installed) describes how the solver is split over the LevelSet*.cpp files.
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/LevelSetGrid.cpp
  ${CMAKE_CURRENT_LIST_DIR}/LevelSet.cpp
  ${CMAKE_CURRENT_LIST_DIR}/LevelSetStep.cpp
  ${CMAKE_CURRENT_LIST_DIR}/LevelSetDistance.cpp
  ${CMAKE_CURRENT_LIST_DIR}/LevelSetBacktrack.cpp
)
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/LevelSetPlanner.cpp
)
