# io/: outside formats several layers share: dates and times (CF calendars, ISO 8601), the NetCDF file, bathymetry
# grids and coastlines (GIS files)
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/Time.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Length.cpp
  ${CMAKE_CURRENT_LIST_DIR}/RemoteSource.cpp  # remote sources: settings, the record of what came from where
  ${CMAKE_CURRENT_LIST_DIR}/GeoBox.cpp  # lon/lat boxes: regions, the trip's box, great circles
  ${CMAKE_CURRENT_LIST_DIR}/TempFolder.cpp  # the folder for temporary files (TMPDIR), checked
  ${CMAKE_CURRENT_LIST_DIR}/FileList.cpp  # a forecast's files: paths, glob patterns, URLs
  ${CMAKE_CURRENT_LIST_DIR}/DegMin.cpp  # the Slocum's [-]DDDMM.MMMM coordinates (goto lists, dba files)
  ${CMAKE_CURRENT_LIST_DIR}/DatasetLock.cpp  # the one lock of NetCDF-C and GDAL's datasets (DatasetLock.h)
)
if(OMPL_GLIDER_WITH_NETCDF)
  list(APPEND OMPL_GLIDER_SOURCES
    # the open gridded dataset (GriddedDataset.h, internal) of the forecast reader (current/gridded/), the bathymetry
    # and the observations; NetCDF-C's reader of files, in-memory datasets and OPeNDAP URLs
    ${CMAKE_CURRENT_LIST_DIR}/GriddedDataset.cpp
    ${CMAKE_CURRENT_LIST_DIR}/RemoteDataset.cpp  # OPeNDAP: time limits, retries, the values fetched
    ${CMAKE_CURRENT_LIST_DIR}/RemoteCache.cpp  # OPeNDAP: the cache file, checked and written (RemoteDataset.h)
    ${CMAKE_CURRENT_LIST_DIR}/FetchStop.cpp  # a stop request cuts a blocking HTTP request (FetchStop.h)
    ${CMAKE_CURRENT_LIST_DIR}/ClassicSize.cpp
    ${CMAKE_CURRENT_LIST_DIR}/GriddedBathymetry.cpp
    ${CMAKE_CURRENT_LIST_DIR}/DepthGrid.cpp
    ${CMAKE_CURRENT_LIST_DIR}/GliderObservations.cpp  # a glider's DAC: IOOS profile files, CSV
    ${CMAKE_CURRENT_LIST_DIR}/SlocumBinary.cpp  # a Slocum's binary files (dinkum binary data, LZ4: liblz4)
    ${CMAKE_CURRENT_LIST_DIR}/UnitConversion.cpp  # unit strings (UDUNITS-2): forecasts, depths, DAC
  )
endif()
if(OMPL_GLIDER_WITH_MISSION)
  # the library's GDAL part, loaded when first needed (GdalModule.h): the module libompl_glider_gdal.so beside a
  # shared library (CMakeLists.txt), inside a static one
  list(APPEND OMPL_GLIDER_SOURCES ${CMAKE_CURRENT_LIST_DIR}/GdalModule.cpp)
  set(OMPL_GLIDER_GDAL_SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/GdalEntryPoints.cpp  # the module's table of functions
    ${CMAKE_CURRENT_LIST_DIR}/Coastline.cpp  # GDAL/OGR
  )
  if(OMPL_GLIDER_WITH_NETCDF)
    # Zarr stores and GRIB files through GDAL's multidimensional API, read as NetCDF-C's are (GdalGrid.h, Dataset.h)
    list(APPEND OMPL_GLIDER_GDAL_SOURCES ${CMAKE_CURRENT_LIST_DIR}/GdalGrid.cpp
      ${CMAKE_CURRENT_LIST_DIR}/GribTimes.cpp  # a GRIB file's time dimension from GDAL's arrays (GdalGridImpl.h)
      ${CMAKE_CURRENT_LIST_DIR}/GdalFaults.cpp  # what is wrong with such a source, in its own words
      ${CMAKE_CURRENT_LIST_DIR}/HttpMirror.cpp  # a store or a GRIB file over HTTP: its mirror, the cache
      ${CMAKE_CURRENT_LIST_DIR}/HttpRequests.cpp  # GET and HEAD with the time limit and retries (HttpMirror.h)
    )
    list(APPEND OMPL_GLIDER_SOURCES
      # a glider's real-time data: an ERDDAP answer over HTTP, Slocum dba files
      ${CMAKE_CURRENT_LIST_DIR}/ErddapObservations.cpp
      ${CMAKE_CURRENT_LIST_DIR}/SlocumDba.cpp  # a Slocum's dba files and binary files as one table (SlocumTable.h)
      ${CMAKE_CURRENT_LIST_DIR}/SlocumDive.cpp)  # its fixes and DAC over the dives
  endif()
endif()
