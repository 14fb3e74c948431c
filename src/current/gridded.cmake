# current/ gridded fields and NetCDF
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/Interpolation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/CfTime.cpp
  ${CMAKE_CURRENT_LIST_DIR}/LocalProjection.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GriddedCurrentField.cpp
  ${CMAKE_CURRENT_LIST_DIR}/NetCdfCurrents.cpp
)
