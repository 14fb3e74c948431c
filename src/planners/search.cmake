# planners/ search: lattice, ZAStarTVE
list(APPEND OMPL_GLIDER_SOURCES
)
