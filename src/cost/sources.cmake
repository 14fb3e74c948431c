# cost/: travel time of a leg (adaptive step), dive-profile travel time.
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/TravelTimeCalculator.cpp
)
