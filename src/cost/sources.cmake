# cost/
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/TravelTimeCalculator.cpp
)
include(${CMAKE_CURRENT_LIST_DIR}/dive.cmake)
