# mission tests
