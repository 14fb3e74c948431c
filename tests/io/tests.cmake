# tests of io/: lon/lat boxes, bathymetry files
glider_add_test(test_io_geobox ${CMAKE_CURRENT_LIST_DIR}/TestGeoBox.cpp)
glider_add_test(test_mission_bathymetry ${CMAKE_CURRENT_LIST_DIR}/TestBathymetry.cpp)
