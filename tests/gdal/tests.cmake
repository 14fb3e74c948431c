# Forecasts GDAL reads (io/GdalGrid.h): Copernicus-like Zarr stores written by xarray, from disk and over a loopback
# HTTP server, and a GRIB2 file written by GDAL's GRIB driver, each planned as the same data in NetCDF
if(TARGET glider_plan)
  add_test(NAME gdal.zarr_and_grib
    COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/check_gdal_sources.py $<TARGET_FILE:glider_plan>)
  set_tests_properties(gdal.zarr_and_grib PROPERTIES TIMEOUT 600)
endif()
