# benchmarks of campaign
