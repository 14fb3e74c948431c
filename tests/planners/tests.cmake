# tests of planners/
include(${CMAKE_CURRENT_LIST_DIR}/search.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/postprocess.cmake)
