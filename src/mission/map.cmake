# map rendering (cairo: SVG + PNG)
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/MapRenderer.cpp
)
