# tests of the lattice search
glider_add_test(test_lattice ${CMAKE_CURRENT_LIST_DIR}/TestLattice.cpp)
glider_add_test(test_zastartve ${CMAKE_CURRENT_LIST_DIR}/TestZAStarTVE.cpp)
glider_add_test(test_search_heuristic ${CMAKE_CURRENT_LIST_DIR}/TestSearchHeuristic.cpp)
glider_add_test(test_wavefront ${CMAKE_CURRENT_LIST_DIR}/TestWavefront.cpp)
# holding in the lattice search: waiting edges at time-windowed zones, goal windows
glider_add_test(test_lattice_waiting ${CMAKE_CURRENT_LIST_DIR}/TestWaiting.cpp)
glider_add_test(test_coarse_to_fine ${CMAKE_CURRENT_LIST_DIR}/TestCoarseToFine.cpp)
