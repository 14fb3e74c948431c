# planners/
list(APPEND OMPL_GLIDER_SOURCES
)
