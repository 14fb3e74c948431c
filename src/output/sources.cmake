# output/: the one output layer (summary.json, route files, goto list, map; all-or-nothing writing)
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/SlocumGoto.cpp
  ${CMAKE_CURRENT_LIST_DIR}/RouteFiles.cpp
  ${CMAKE_CURRENT_LIST_DIR}/SummaryJson.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Report.cpp
  ${CMAKE_CURRENT_LIST_DIR}/OutputWriter.cpp
  ${CMAKE_CURRENT_LIST_DIR}/OutputDirectory.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ExecutionFiles.cpp
  ${CMAKE_CURRENT_LIST_DIR}/FleetFiles.cpp
)
if(OMPL_GLIDER_WITH_MAP)
  list(APPEND OMPL_GLIDER_SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/MapRenderer.cpp
    ${CMAKE_CURRENT_LIST_DIR}/MapRendererAxes.cpp
    ${CMAKE_CURRENT_LIST_DIR}/MapRendererLegend.cpp
    ${CMAKE_CURRENT_LIST_DIR}/MissionMap.cpp
    ${CMAKE_CURRENT_LIST_DIR}/ExecutionPlot.cpp
  )
endif()
