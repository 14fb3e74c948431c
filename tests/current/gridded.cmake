# gridded / NetCDF tests
