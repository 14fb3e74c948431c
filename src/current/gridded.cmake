# current/ gridded fields and NetCDF
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/AkimaSpline.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Interpolation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/LocalProjection.cpp
  # GriddedCurrentField: construction and evaluation, the locator, speed and velocity bounds
  ${CMAKE_CURRENT_LIST_DIR}/GriddedCurrentField.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GriddedLocator.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GriddedBounds.cpp
  ${CMAKE_CURRENT_LIST_DIR}/CoastEdges.cpp
  # the seam of gridded sources (ForecastSource.h)
  ${CMAKE_CURRENT_LIST_DIR}/ForecastSource.cpp
)
if(OMPL_GLIDER_WITH_NETCDF)
  list(APPEND OMPL_GLIDER_SOURCES
    # the NetCDF reader: loadGriddedCurrents() composing the stages in gridded/ (see gridded/GriddedInternal.h)
    ${CMAKE_CURRENT_LIST_DIR}/GriddedCurrents.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/AxisChecks.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/VariableDetection.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/GridLayout.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/TimeAxis.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/DepthAxis.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/RegionOfInterest.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/RectilinearSubset.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/CurvilinearSubset.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/Staggered.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/GridAngle.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/SigmaLevels.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/Hyperslab.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/UnitsAndPacking.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/LandMask.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/TracerLand.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/NodeCoordinates.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gridded/ForecastFiles.cpp
    # the reader as the registry's gridded source `gridded` (alias `netcdf`)
    ${CMAKE_CURRENT_LIST_DIR}/gridded/GriddedForecastSource.cpp
  )
endif()
