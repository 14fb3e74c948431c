# stints/: constant-bearing stints between surfacings ([IsernObstacles]): the stint simulator, CTS-A*, the bearing
# optimisation (NLopt), the stint planners and the conversion of any timed path to stints
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/StintSimulator.cpp
  ${CMAKE_CURRENT_LIST_DIR}/CtsAStar.cpp
  ${CMAKE_CURRENT_LIST_DIR}/BearingOptimizer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PathToStints.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StintPlanner.cpp
)
