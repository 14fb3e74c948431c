# benchmarks of mission
