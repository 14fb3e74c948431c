#pragma once
/// @file CampaignSpread.h
/// @brief The campaign's benchmarks spread over the processes of a job (TaskSpread.h; under mpirun, MPI ranks): every
/// rank builds the same benchmarks (CampaignBenchmark.h); a task is one run of one planner of one benchmark, made on
/// a fresh copy of that benchmark with the planner alone and one run; rank 0 hands the tasks out as ranks ask (runs
/// differ a lot in length), puts every run back in its place (planner, run index) of the benchmark's recorded
/// experiment and writes the same OMPL logs as one process: the same experiments, planners, runs and properties;
/// the timing columns (time, memory, the seconds of the experiment) are those measured on the ranks. The logs are
/// written only when every run succeeded, each to a temporary name first, then all renamed.

#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <ompl/tools/benchmark/MachineSpecs.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Time.h>

#include "CampaignBenchmark.h"
#include "ompl_glider/TaskSpread.h"

namespace ompl_glider
{
namespace campaign_spread
{
/// The recorded experiment and the planners of a Benchmark (protected members, reached through a derived class).
struct Access : ompl::tools::Benchmark
{
    static CompleteExperiment &experiment(ompl::tools::Benchmark &b) { return b.*(&Access::exp_); }
    static std::vector<ompl::base::PlannerPtr> &planners(ompl::tools::Benchmark &b) { return b.*(&Access::planners_); }
};

inline void putMap(ByteWriter &w, const std::map<std::string, std::string> &m)
{
    w.put(static_cast<std::uint64_t>(m.size()));
    for (const auto &kv : m)
    {
        w.put(kv.first);
        w.put(kv.second);
    }
}

inline void getMap(ByteReader &r, std::map<std::string, std::string> &m)
{
    const auto n = r.value<std::uint64_t>();
    for (std::uint64_t i = 0; i < n; ++i)
    {
        std::string k, v;
        r.get(k);
        r.get(v);
        m[k] = v;
    }
}

/// One run of one planner of a benchmark, on a fresh copy of it: the planner's name, its common properties, the
/// run's properties and progress, the setup's description.
inline std::string runOne(BuiltBenchmark &b, std::size_t planner)
{
    auto &planners = Access::planners(*b.benchmark);
    planners = {planners.at(planner)};
    ompl::tools::Benchmark::Request request = b.request;
    request.runCount = 1;
    b.benchmark->benchmark(request);
    const auto &exp = b.benchmark->getRecordedExperimentData();
    if (exp.planners.size() != 1 || exp.planners[0].runs.size() != 1)
        throw std::runtime_error("the benchmark recorded no run");
    const auto &pe = exp.planners[0];
    ByteWriter w;
    w.put(pe.name);
    putMap(w, pe.common);
    putMap(w, pe.runs[0]);
    w.put(pe.progressPropertyNames);
    w.put(!pe.runsProgressData.empty());
    if (!pe.runsProgressData.empty())
        w.putEach(pe.runsProgressData[0], putMap);
    w.put(exp.setupInfo);
    return w.take();
}

using Maker = std::function<std::unique_ptr<BuiltBenchmark>()>;

/// Runs every benchmark @p makers build, spread over the job; rank 0 prints the progress and writes the logs.
inline void spreadBenchmarks(TaskSpreader &spread, const std::vector<Maker> &makers)
{
    struct Task
    {
        std::size_t benchmark, planner;
        unsigned run;
    };
    std::vector<Task> tasks;
    std::vector<std::unique_ptr<BuiltBenchmark>> built;
    for (std::size_t i = 0; i < makers.size(); ++i)
    {
        built.push_back(makers[i]());
        if (!built.back())
            continue;
        const std::size_t planners = Access::planners(*built.back()->benchmark).size();
        for (std::size_t k = 0; k < planners; ++k)
            for (unsigned r = 0; r < built.back()->request.runCount; ++r)
                tasks.push_back({i, k, r});
        if (spread.rank() == 0)
            std::cout << built.back()->banner << std::endl;
    }
    if (spread.rank() == 0)
        std::cout << tasks.size() << " runs spread over " << spread.size() << " processes" << std::endl;
    const ompl::time::point start = ompl::time::now();
    const std::vector<std::string> out = spread.run(
        "benchmark run", tasks.size(),
        [&](std::size_t t) {
            const std::unique_ptr<BuiltBenchmark> b = makers[tasks[t].benchmark]();
            return runOne(*b, tasks[t].planner);
        },
        [](std::size_t done, std::size_t n) {
            std::fprintf(stderr, "\rcampaign: %zu/%zu runs%s", done, n, done == n ? "\n" : "   ");
            std::fflush(stderr);
        });
    if (spread.rank() != 0)
        return;
    const double seconds = ompl::time::seconds(ompl::time::now() - start);
    for (std::size_t t = 0; t < tasks.size(); ++t)
    {
        auto &exp = Access::experiment(*built[tasks[t].benchmark]->benchmark);
        const BuiltBenchmark &b = *built[tasks[t].benchmark];
        exp.planners.resize(Access::planners(*b.benchmark).size());
        auto &pe = exp.planners[tasks[t].planner];
        pe.runs.resize(b.request.runCount);
        ByteReader in(out[t]);
        in.get(pe.name);
        pe.common.clear();
        getMap(in, pe.common);
        getMap(in, pe.runs[tasks[t].run]);
        in.get(pe.progressPropertyNames);
        if (in.value<bool>())
        {
            pe.runsProgressData.resize(b.request.runCount);
            in.getEach(pe.runsProgressData[tasks[t].run], getMap);
        }
        in.get(exp.setupInfo);
    }
    std::vector<std::string> written;
    for (const auto &b : built)
    {
        if (!b)
            continue;
        auto &exp = Access::experiment(*b->benchmark);
        exp.maxTime = b->request.maxTime;
        exp.maxMem = b->request.maxMem;
        exp.runCount = b->request.runCount;
        exp.startTime = start;
        exp.totalDuration = seconds;
        exp.seed = ompl::RNG::getSeed();
        exp.host = ompl::machine::getHostname();
        exp.cpuInfo = ompl::machine::getCPUInfo();
        const std::string part = b->log + ".part";
        if (!b->benchmark->saveResultsToFile(part.c_str()))
            throw std::runtime_error("cannot write " + part);
        written.push_back(b->log);
    }
    for (const std::string &log : written)
    {
        if (std::rename((log + ".part").c_str(), log.c_str()) != 0)
            throw std::runtime_error("cannot rename " + log + ".part");
        std::cout << "  -> " << log << std::endl;
    }
}
} // namespace campaign_spread
} // namespace ompl_glider
