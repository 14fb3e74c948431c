# mission/: mission files, outputs (CSV, GeoJSON, goto list, summary), departure-time search
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/AkimaSpline.cpp
  ${CMAKE_CURRENT_LIST_DIR}/DepartureTimeSearch.cpp
  ${CMAKE_CURRENT_LIST_DIR}/SlocumGoto.cpp
  ${CMAKE_CURRENT_LIST_DIR}/IsoTime.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MissionLoader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MissionRunner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MissionOutputs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/NetCdfBathymetry.cpp
)
