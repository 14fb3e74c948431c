# environment/
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/Polygon.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StaticRegion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TimeWindowedZone.cpp
  ${CMAKE_CURRENT_LIST_DIR}/IceZone.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ForbiddenRegions.cpp
  ${CMAKE_CURRENT_LIST_DIR}/SegmentIndex.cpp
  ${CMAKE_CURRENT_LIST_DIR}/KeepOffZone.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ForbiddenCells.cpp
)
