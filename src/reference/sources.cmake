# reference/: optimal-control (Zermelo shooting) reference solutions
list(APPEND OMPL_GLIDER_SOURCES
)
