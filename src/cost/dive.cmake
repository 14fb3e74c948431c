# dive profiles
list(APPEND OMPL_GLIDER_SOURCES
)
