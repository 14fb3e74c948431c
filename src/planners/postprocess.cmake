# planners/ post-processing: smoothing, refinement
list(APPEND OMPL_GLIDER_SOURCES
)
