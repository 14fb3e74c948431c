# benchmarks of current
