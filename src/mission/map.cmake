# map rendering (cairo: SVG + PNG) and the plan runner behind glider_plan
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/MapRenderer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PlanRun.cpp
)
