# dive profiles ([EichhornOceans] Table I, Sec. III.B) and the worker pool that evaluates them in parallel
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/DiveProfilePool.cpp
  ${CMAKE_CURRENT_LIST_DIR}/DiveProfile.cpp
)
