# ompl/
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/TimeSE2StateSpace.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GliderStateValidityChecker.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TravelTimeMotionValidator.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TravelTimeObjective.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PositionGoal.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GliderSetup.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PathResimulation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GliderStateSampler.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PipelinePlanner.cpp
)
