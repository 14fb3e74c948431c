# tests of io/: lon/lat boxes, bathymetry files
glider_add_test(test_io_geobox ${CMAKE_CURRENT_LIST_DIR}/TestGeoBox.cpp)
glider_add_test(test_mission_bathymetry ${CMAKE_CURRENT_LIST_DIR}/TestBathymetry.cpp)
# a glider deployment's depth-averaged currents: IOOS profile files written in the template's layout, CSV
glider_add_test(test_io_glider_observations ${CMAKE_CURRENT_LIST_DIR}/TestGliderObservations.cpp)
target_link_libraries(test_io_glider_observations INTERFACE netCDF::netcdf)
# a glider's real-time sources: an ERDDAP answer (.csvp, .csv, .ncCF) from a loopback server of the test
# (LoopbackHttp.h), Slocum dba files; each the same DAC and fixes as the deployment's IOOS files (RealtimeDeployment.h)
glider_add_test(test_io_glider_realtime ${CMAKE_CURRENT_LIST_DIR}/TestGliderRealtime.cpp)
target_link_libraries(test_io_glider_realtime INTERFACE netCDF::netcdf)
if(TARGET glider_plan)
  # glider_plan --observations with a dba folder and an ERDDAP URL
  glider_add_test(test_io_glider_realtime_cli ${CMAKE_CURRENT_LIST_DIR}/TestGliderRealtimeCli.cpp)
  target_link_libraries(test_io_glider_realtime_cli INTERFACE netCDF::netcdf)
  target_compile_definitions(test_io_glider_realtime_cli INTERFACE GLIDER_PLAN_EXE="$<TARGET_FILE:glider_plan>")
  add_dependencies(test_io_glider_realtime_cli glider_plan)
endif()
# a Slocum glider's binary files written from the format's description (SlocumBinaryWriter.h): the decoder's round
# trip, byte orders, LZ4, cache files, bad files; as observations the same as their dba twins, planned alike
glider_add_test(test_io_slocum_binary ${CMAKE_CURRENT_LIST_DIR}/TestSlocumBinary.cpp)
target_link_libraries(test_io_slocum_binary INTERFACE netCDF::netcdf PkgConfig::LZ4)
