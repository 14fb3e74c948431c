# tests of mission/
include(${CMAKE_CURRENT_LIST_DIR}/mission.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/pipeline.cmake)
