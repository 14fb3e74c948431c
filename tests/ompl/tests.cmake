# tests of ompl/
