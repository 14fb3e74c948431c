# reference/: optimal-control (Zermelo shooting) reference solutions
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/ZermeloReference.cpp
)
