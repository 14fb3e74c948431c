# execution/: flying a plan in another ocean (surfacings, control strategies), OMPL control planning
# with the dive integrator (GliderControl)
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/Dive.cpp
  ${CMAKE_CURRENT_LIST_DIR}/HeadingRoute.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Stints.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Reflight.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Execution.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GliderControl.cpp
)
