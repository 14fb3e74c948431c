glider_add_test(test_current ${CMAKE_CURRENT_LIST_DIR}/TestCurrentConformance.cpp)
include(${CMAKE_CURRENT_LIST_DIR}/gridded.cmake)
glider_add_test(test_current_analytic ${CMAKE_CURRENT_LIST_DIR}/TestAnalyticVortexGyre.cpp)
# a forecast corrected by a glider's depth-averaged currents (optimal interpolation)
glider_add_test(test_corrected_field ${CMAKE_CURRENT_LIST_DIR}/TestCorrectedField.cpp
                ${CMAKE_CURRENT_LIST_DIR}/TestCorrectionLearning.cpp
                ${CMAKE_CURRENT_LIST_DIR}/TestEnsembleLearning.cpp)
