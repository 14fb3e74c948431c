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
    # the NetCDF reader: loadNetCdfCurrents() composing the stages in netcdf/ (see netcdf/NetCdfInternal.h)
    ${CMAKE_CURRENT_LIST_DIR}/NetCdfCurrents.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/AxisChecks.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/VariableDetection.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/GridLayout.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/TimeAxis.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/DepthAxis.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/RegionOfInterest.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/RectilinearSubset.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/CurvilinearSubset.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/Staggered.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/GridAngle.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/SigmaLevels.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/Hyperslab.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/UnitsAndPacking.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/LandMask.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/TracerLand.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/NodeCoordinates.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/ForecastFiles.cpp
    # the reader as the registry's gridded source `netcdf`
    ${CMAKE_CURRENT_LIST_DIR}/netcdf/NetCdfSource.cpp
  )
endif()
