# map rendering (cairo: SVG + PNG)
list(APPEND OMPL_GLIDER_SOURCES
)
