# benchmarks of planners
