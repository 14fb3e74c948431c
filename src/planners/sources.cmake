# planners/: lattice search (ZAStarTVE) and path post-processing (smoothing, refinement)
include(${CMAKE_CURRENT_LIST_DIR}/search.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/postprocess.cmake)
