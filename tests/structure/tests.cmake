# The structure rules of docs/ARCHITECTURE.md on the real tree (layering, file and function sizes, citations), and
# the checker's own test on small trees that break each rule.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME structure.layers_sizes_citations
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_structure.py ${PROJECT_SOURCE_DIR})
add_test(NAME structure.checker_selftest
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/check_structure_selftest.py)
# The README as a front page: its snippets are lines of a demo and of docs/PYTHON.md, its links and docs/'s resolve.
add_test(NAME structure.readme_and_docs
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/check_docs.py ${PROJECT_SOURCE_DIR})
# Every name in tests/ci_only.txt (the slow cases CI alone runs) is a test of this build: a renamed test does not
# slip back into the README's command or the sanitizer run, and a typo does not leave one out of it.
add_test(NAME structure.ci_only_list
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_ci_only_list.sh ${CMAKE_CTEST_COMMAND} ${PROJECT_SOURCE_DIR}
  WORKING_DIRECTORY ${PROJECT_BINARY_DIR})
# The C++ formatted as .clang-format says (scripts/check_format.sh; --fix formats the tree).
add_test(NAME structure.format COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/check_format.sh)
