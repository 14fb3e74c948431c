# dive profiles ([EichhornOceans] Table I, Sec. III.B)
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/DiveProfile.cpp
)
