# tests of reference/
