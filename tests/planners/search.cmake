# tests of the lattice search
