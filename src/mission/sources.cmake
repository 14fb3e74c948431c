# mission/: mission files, outputs, departure-time search, map rendering
include(${CMAKE_CURRENT_LIST_DIR}/mission.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/map.cmake)
