# current/: analytic flows
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/MeanderingJet.cpp
  ${CMAKE_CURRENT_LIST_DIR}/UniformCurrent.cpp
  ${CMAKE_CURRENT_LIST_DIR}/LinearShear.cpp
  ${CMAKE_CURRENT_LIST_DIR}/DoubleGyre.cpp
  ${CMAKE_CURRENT_LIST_DIR}/RankineVortex.cpp
  ${CMAKE_CURRENT_LIST_DIR}/CurrentFieldRegistry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ShiftedTimeField.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ForecastRuns.cpp
  ${CMAKE_CURRENT_LIST_DIR}/EnsembleField.cpp
  ${CMAKE_CURRENT_LIST_DIR}/CorrectedField.cpp
  ${CMAKE_CURRENT_LIST_DIR}/CorrectionFit.cpp
  ${CMAKE_CURRENT_LIST_DIR}/EnsembleLearning.cpp
)
include(${CMAKE_CURRENT_LIST_DIR}/gridded.cmake)
