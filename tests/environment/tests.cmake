# tests of environment/
