# current/ gridded fields and NetCDF
list(APPEND OMPL_GLIDER_SOURCES
)
