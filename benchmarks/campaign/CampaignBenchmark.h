#pragma once
/// @file CampaignBenchmark.h
/// @brief One benchmark of the campaign (a problem's registry planners, or its control planners) as built, before it
/// runs: the setup it refers to, the ompl::tools::Benchmark with its planners and events, its request and log. The
/// one-process campaign runs it whole (runBenchmark()); an MPI job builds it on every rank and spreads its
/// (planner, run) pairs over the ranks (CampaignSpread.h).

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include <ompl/tools/benchmark/Benchmark.h>

namespace ompl_glider
{
struct BuiltBenchmark
{
    std::shared_ptr<void> setup; ///< the SimpleSetup the benchmark refers to (kept alive)
    std::unique_ptr<ompl::tools::Benchmark> benchmark;
    ompl::tools::Benchmark::Request request;
    std::string banner; ///< printed before it runs ("problem islands: 5 runs x 12 planners, ...")
    std::string log;    ///< OUTDIR/<problem>.log
};

/// Runs a benchmark in this process, as the campaign always has, and writes its log.
inline void runBenchmark(BuiltBenchmark &b)
{
    std::cout << b.banner << std::endl;
    b.benchmark->benchmark(b.request);
    if (!b.benchmark->saveResultsToFile(b.log.c_str()))
        throw std::runtime_error("cannot write " + b.log);
    std::cout << "  -> " << b.log << std::endl;
}
} // namespace ompl_glider
