# the one planning pipeline and the one output layer
glider_add_test(test_pipeline ${CMAKE_CURRENT_LIST_DIR}/TestPipeline.cpp)
target_link_libraries(test_pipeline PRIVATE nlohmann_json::nlohmann_json)
