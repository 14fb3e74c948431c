# tests of mission/
