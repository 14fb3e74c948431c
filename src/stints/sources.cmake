# stints/: the stint planners ([IsernObstacles]): CTS-A* and StintPlanner (its methods), on the stint simulator and
# the bearing optimisation of routes/
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/CtsAStar.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StintPlanner.cpp
)
