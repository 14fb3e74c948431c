# core: the sources of the top-level headers every layer may use (ThreadPool.h, ResourceLimits.h, TaskSpread.h,
# StopRequest.h)
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/ThreadPool.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ResourceLimits.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TaskSpread.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StopRequest.cpp
)
