# tests of planners/
