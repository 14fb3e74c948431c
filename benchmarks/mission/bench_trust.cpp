// bench_trust: how far the default answer is from the best route, over random start/goal pairs.
// Per flow and speed: the distribution of default / reference (median, 95th percentile, worst, share within 0.5 %),
// the share of reachable goals given a route, and the wall time of the default; the reference is the independent
// extremal sweep of the property test (tests/mission/ExtremalSweep.h: its own RK4, no code of the planners).
//
//   build/benchmarks/bench_trust [--pairs N] [--seed S] [--no-global-check]
//
// --no-global-check plans without the global check of the route class, to show what it changes.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "TrustCases.h"

int main(int argc, char **argv)
{
    int pairs = 16;
    unsigned seed = 20261127;
    bool check = true;
    for (int i = 1; i < argc; ++i)
    {
        if (!std::strcmp(argv[i], "--pairs") && i + 1 < argc)
            pairs = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc)
            seed = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
        else if (!std::strcmp(argv[i], "--no-global-check"))
            check = false;
        else
        {
            std::fprintf(stderr, "usage: bench_trust [--pairs N] [--seed S] [--no-global-check]\n");
            return 2;
        }
    }
    if (pairs < 1)
    {
        std::fprintf(stderr, "bench_trust: --pairs must be >= 1\n");
        return 2;
    }
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    std::mt19937 rng(seed);
    std::printf("bench_trust: %d random pairs per flow and speed, seed %u, global check %s\n\n", pairs, seed,
                check ? "on" : "off");
    std::printf("| flow | V | pairs | reachable | given a route | median | p95 | worst | within 0.5 %% | "
                "default wall time (median, max s) |\n|---|---|---|---|---|---|---|---|---|---|\n");
    const std::vector<std::pair<std::string, std::vector<double>>> speeds = {{"jet", {0.5, 0.3, 0.2, 0.15, 0.1}},
                                                                             {"double gyre", {0.5, 0.3}},
                                                                             {"Rankine vortex", {0.5, 0.3}},
                                                                             {"shear", {0.5, 0.3}}};
    for (trust::Flow flow : trust::flows())
    {
        flow.mission.planner.globalCheck = check;
        for (const auto &[name, vs] : speeds)
        {
            if (name != flow.name)
                continue;
            for (const double v : vs)
            {
                std::vector<double> ratios, secs;
                int reachable = 0, routed = 0;
                for (trust::Trial t : trust::draw(flow, v, pairs, rng))
                {
                    trust::run(flow, t);
                    secs.push_back(t.seconds);
                    if (!t.referenceFound)
                        continue;
                    ++reachable;
                    routed += t.defaultSolved;
                    ratios.push_back(t.defaultSolved ? t.ratio() : INFINITY);
                }
                std::sort(ratios.begin(), ratios.end());
                std::sort(secs.begin(), secs.end());
                const auto at = [&](double q) {
                    return ratios.empty() ? NAN : ratios[std::min(ratios.size() - 1, std::size_t(q * ratios.size()))];
                };
                const long within = std::count_if(ratios.begin(), ratios.end(), [](double r) { return r <= 1.005; });
                std::printf("| %s | %.2f | %d | %d | %d | %.4f | %.4f | %.4f | %.0f %% | %.2f, %.2f |\n",
                            flow.name.c_str(), v, pairs, reachable, routed, at(0.5), at(0.95),
                            ratios.empty() ? NAN : ratios.back(),
                            ratios.empty() ? NAN : 100.0 * double(within) / double(ratios.size()),
                            secs[secs.size() / 2], secs.back());
                std::fflush(stdout);
            }
        }
    }
    return 0;
}
