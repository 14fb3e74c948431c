# tests of io/: lon/lat boxes, bathymetry files
glider_add_test(test_io_geobox ${CMAKE_CURRENT_LIST_DIR}/TestGeoBox.cpp)
glider_add_test(test_mission_bathymetry ${CMAKE_CURRENT_LIST_DIR}/TestBathymetry.cpp)
# a glider deployment's depth-averaged currents: IOOS profile files written in the template's layout, CSV
glider_add_test(test_io_glider_observations ${CMAKE_CURRENT_LIST_DIR}/TestGliderObservations.cpp)
target_link_libraries(test_io_glider_observations PRIVATE netCDF::netcdf)
