# A Debian package of what `cmake --install` installs: the library, its headers and CMake package files,
# glider_plan and the Python module (when built). From the build directory:
#   cpack -G DEB            -> ompl-glider_<version>_<arch>.deb
#   apt install ./ompl-glider_*.deb
# The shared libraries it needs become Depends through dpkg-shlibdeps; the Python module adds the interpreter
# it was built for and numpy. Tested by ctest's package.deb (label ci).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME ompl-glider)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "time-optimal glider routes through time-varying ocean currents, on OMPL")
set(CPACK_PACKAGE_CONTACT "ompl_glider maintainers <maintainers@users.noreply.github.com>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(OMPL_GLIDER_BUILD_PYTHON AND Python3_VERSION_MINOR)
  math(EXPR _py_next "${Python3_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "python3 (>= 3.${Python3_VERSION_MINOR}~), python3 (<< 3.${_py_next}), python3-numpy")
endif()
# for find_package(ompl_glider) in a project of one's own: the headers include OMPL's, Eigen's and Boost's
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libompl-dev, libeigen3-dev, libboost-dev")
include(CPack)
