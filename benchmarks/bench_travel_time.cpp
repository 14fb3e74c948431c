// Micro-benchmark of the travel-time cost function (CALC-TRAVELTIME) on legs of length 0.4 - 1.2 in the
// meandering jet: evaluations per second and current-model calls per evaluation.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/current/MeanderingJet.h"

using namespace ompl_glider;

namespace
{
struct Leg
{
    double x1, y1, x2, y2, t;
};

// Legs of the given length in 16 headings from a 5 x 5 set of start points in [0, 10] x [-4, 4].
std::vector<Leg> legs(double length)
{
    std::vector<Leg> out;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            for (int k = 0; k < 16; ++k)
            {
                const double x = 1.0 + 2.0 * i, y = -3.0 + 1.5 * j, a = 2 * M_PI * k / 16;
                out.push_back({x, y, x + length * std::cos(a), y + length * std::sin(a), 0.7 * (i + j + k)});
            }
    return out;
}

void BM_TravelTimeJet(benchmark::State &state)
{
    const double length = state.range(0) / 10.0;
    auto jet = std::make_shared<MeanderingJet>();
    TravelTimeCalculator calc(jet);
    const std::vector<Leg> ls = legs(length);
    jet->resetCallCount();
    std::size_t i = 0, feasible = 0;
    for (auto _ : state)
    {
        const Leg &l = ls[i++ % ls.size()];
        const double t = calc.travelTime(l.x1, l.y1, l.x2, l.y2, l.t);
        feasible += std::isfinite(t);
        benchmark::DoNotOptimize(t);
    }
    state.counters["evals_per_s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["CMC_per_eval"] = double(jet->callCount()) / double(state.iterations());
    state.counters["feasible_frac"] = double(feasible) / double(state.iterations());
}
BENCHMARK(BM_TravelTimeJet)->Arg(4)->Arg(8)->Arg(12);

void BM_CurrentModelJet(benchmark::State &state)
{
    MeanderingJet jet;
    double x = 0.0;
    for (auto _ : state)
    {
        x += 1e-3;
        benchmark::DoNotOptimize(jet.velocity(x, 0.3, 0.0, 1.0));
    }
    state.counters["calls_per_s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CurrentModelJet);
} // namespace

BENCHMARK_MAIN();
