# planners/ search: lattice, ZAStarTVE, Wavefront
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/Lattice.cpp
  ${CMAKE_CURRENT_LIST_DIR}/LatticePlanner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/VelocityBounds.cpp
  ${CMAKE_CURRENT_LIST_DIR}/SearchHeuristic.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TveSearch.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TveSearchCore.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TveSearchExpansion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ZAStarTVE.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Wavefront.cpp
  ${CMAKE_CURRENT_LIST_DIR}/WavefrontSearch.cpp
)
