# Findudunits2: the UDUNITS-2 unit library (unit strings of NetCDF forecasts), which installs no CMake package
# configuration. Debian's libudunits2-dev puts udunits2.h in /usr/include; other distributions use
# /usr/include/udunits2.
#
# Defines the imported target udunits2::udunits2 and udunits2_FOUND, udunits2_INCLUDE_DIR, udunits2_LIBRARY.
# Installed beside ompl_gliderConfig.cmake, which uses it to find UDUNITS-2 again for a static ompl_glider.
find_path(udunits2_INCLUDE_DIR udunits2.h PATH_SUFFIXES udunits2)
find_library(udunits2_LIBRARY NAMES udunits2)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(udunits2 REQUIRED_VARS udunits2_LIBRARY udunits2_INCLUDE_DIR)
mark_as_advanced(udunits2_INCLUDE_DIR udunits2_LIBRARY)
if(udunits2_FOUND AND NOT TARGET udunits2::udunits2)
  add_library(udunits2::udunits2 UNKNOWN IMPORTED)
  set_target_properties(udunits2::udunits2 PROPERTIES
    IMPORTED_LOCATION "${udunits2_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${udunits2_INCLUDE_DIR}")
  if(udunits2_LIBRARY MATCHES "\\.a$")
    # the static archive reads its XML database with expat
    find_library(udunits2_EXPAT_LIBRARY NAMES expat)
    mark_as_advanced(udunits2_EXPAT_LIBRARY)
    if(udunits2_EXPAT_LIBRARY)
      set_property(TARGET udunits2::udunits2 APPEND PROPERTY INTERFACE_LINK_LIBRARIES "${udunits2_EXPAT_LIBRARY}")
    endif()
  endif()
endif()
