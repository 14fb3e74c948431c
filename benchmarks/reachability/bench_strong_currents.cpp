// Strong currents: per vehicle speed V and per planner, the travel time against a fine level set, the wall
// time, and the share of random start/goal pairs each planner solves, on the meandering jet (peak speed about 1;
// region x in [0, 10], y in [-4, 4]) and on a time-dependent double gyre whose flow is about six times V.
// "default" is the pipeline as glider_plan runs it (ZA*TVE, switching to Isochrone, then LevelSet, when the lattice
// finds no path); the others are the named planner alone (no switch).
//   bench_strong_currents [--quick] [--pairs N] [--only-pairs]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <array>
#include <random>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;

namespace
{
double seconds(std::chrono::steady_clock::time_point a)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

std::string jetMission(double V, double sx, double sy, double gx, double gy, const std::string &planner)
{
    char text[1024];
    std::snprintf(text, sizeof text,
                  "name: jet\ncurrent: {type: meandering_jet}\nregion: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
                  "start: {x: %.17g, y: %.17g}\ngoal: {x: %.17g, y: %.17g}\ndeparture: {time: 0}\n"
                  "vehicle: {speed: %.17g}\nplanner: %s\n",
                  sx, sy, gx, gy, V, planner.c_str());
    return text;
}

std::string gyreMission(double V, const std::string &planner)
{
    char text[1024];
    std::snprintf(text, sizeof text,
                  "name: gyre\ncurrent: {type: double_gyre, parameters: {amplitude: 0.3, length: 1, epsilon: 0.25, "
                  "omega: 0.6283185307179586}}\nregion: {x_min: 0, x_max: 2, y_min: 0, y_max: 1}\n"
                  "start: {x: 0.3, y: 0.3}\ngoal: {x: 1.6, y: 0.7}\ndeparture: {time: 0}\nvehicle: {speed: %.17g}\n"
                  "planner: %s\n",
                  V, planner.c_str());
    return text;
}

struct Outcome
{
    bool solved{false};
    double travelTime{NAN};
    double seconds{0.0};
    std::string planner;
    std::string reason;
};

/// One plan; @p alone: the named planner only (no switch).
Outcome plan(const std::string &yaml, bool alone, const std::string &name)
{
    MissionProblem problem(parseMission(yaml, "<bench>"));
    PlanOptions o;
    if (alone)
        o.planner = name;
    const auto t = std::chrono::steady_clock::now();
    const PlannedPath p = planRoute(problem, problem.getSpec().departure.time, o);
    Outcome r;
    r.reason = p.reason;
    r.seconds = seconds(t);
    r.solved = p.solved;
    r.travelTime = p.solved ? p.travelTime : NAN;
    r.planner = p.planner;
    return r;
}

const char *planners[][2] = {{"default", "{name: ZA*TVE}"},
                             {"ZA*TVE", "{name: ZA*TVE}"},
                             {"Isochrone", "{name: Isochrone}"},
                             {"LevelSet", "{name: LevelSet}"}};
} // namespace

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    bool quick = false, onlyPairs = false;
    int pairs = 10;
    for (int i = 1; i < argc; ++i)
    {
        if (!std::strcmp(argv[i], "--quick"))
            quick = true;
        else if (!std::strcmp(argv[i], "--only-pairs"))
            onlyPairs = true;
        else if (!std::strcmp(argv[i], "--pairs") && i + 1 < argc)
            pairs = std::atoi(argv[++i]);
    }
    if (quick)
        pairs = std::min(pairs, 4);
    const double fine = quick ? 0.05 : 0.025;
    char ref[96];
    std::snprintf(ref, sizeof ref, "{name: LevelSet, parameters: {resolution: %g}}", fine);

    if (onlyPairs)
        goto randomPairs;
    std::printf("Jet crossing (1,-3) -> (8,3); reference: LevelSet at cell %g\n\n", fine);
    std::printf(
        "| V | reference | planner | used | travel time | vs reference | wall s |\n|---|---|---|---|---|---|---|\n");
    for (double V : {0.3, 0.2, 0.15, 0.1})
    {
        const Outcome r = plan(jetMission(V, 1, -3, 8, 3, ref), true, "LevelSet");
        for (const auto &p : planners)
        {
            const bool alone = std::strcmp(p[0], "default") != 0;
            const Outcome o = plan(jetMission(V, 1, -3, 8, 3, p[1]), alone, alone ? p[0] : "");
            std::printf("| %.2f | %.4f | %s | %s | %s | %s | %.2f |\n", V, r.travelTime, p[0],
                        o.solved ? o.planner.c_str() : "-", o.solved ? std::to_string(o.travelTime).c_str() : "no path",
                        o.solved && r.solved
                            ? (std::to_string(100.0 * (o.travelTime / r.travelTime - 1.0)) + " %").c_str()
                            : "-",
                        o.seconds);
        }
    }

    std::printf("\nTime-dependent double gyre (A 0.3, eps 0.25, omega 2 pi / 10; flow up to about 0.94), (0.3,0.3) -> "
                "(1.6,0.7); reference: LevelSet at cell 0.005\n\n");
    std::printf(
        "| V | reference | planner | used | travel time | vs reference | wall s |\n|---|---|---|---|---|---|---|\n");
    for (double V : {0.15})
    {
        const Outcome r = plan(gyreMission(V, "{name: LevelSet, parameters: {resolution: 0.005}}"), true, "LevelSet");
        for (const auto &p : planners)
        {
            const bool alone = std::strcmp(p[0], "default") != 0;
            const Outcome o = plan(gyreMission(V, p[1]), alone, alone ? p[0] : "");
            std::printf("| %.2f | %.4f | %s | %s | %s | %s | %.2f |\n", V, r.travelTime, p[0],
                        o.solved ? o.planner.c_str() : "-", o.solved ? std::to_string(o.travelTime).c_str() : "no path",
                        o.solved && r.solved
                            ? (std::to_string(100.0 * (o.travelTime / r.travelTime - 1.0)) + " %").c_str()
                            : "-",
                        o.seconds);
        }
    }

randomPairs:
    std::printf(
        "\nRandom jet pairs (start in y < -1, goal in y > 1, across the jet; seed 7): share solved, mean wall s\n\n");
    std::printf("| V | planner | solved | mean wall s |\n|---|---|---|---|\n");
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ux(0.5, 9.5), uys(-3.5, -1.0), uyg(1.0, 3.5);
    std::vector<std::array<double, 4>> list;
    for (int i = 0; i < pairs; ++i)
        list.push_back({ux(rng), uys(rng), ux(rng), uyg(rng)});
    std::vector<std::string> failures;
    for (double V : {0.2, 0.1})
        for (const auto &p : planners)
        {
            if (!std::strcmp(p[0], "LevelSet") && quick)
                continue;
            const bool alone = std::strcmp(p[0], "default") != 0;
            int solved = 0;
            double wall = 0.0;
            for (const auto &q : list)
            {
                const Outcome o = plan(jetMission(V, q[0], q[1], q[2], q[3], p[1]), alone, alone ? p[0] : "");
                solved += o.solved;
                wall += o.seconds;
                if (!o.solved)
                    failures.push_back(std::string(p[0]) + " at V " + std::to_string(V) + ", (" + std::to_string(q[0]) +
                                       ", " + std::to_string(q[1]) + ") -> (" + std::to_string(q[2]) + ", " +
                                       std::to_string(q[3]) + "): " + o.reason);
            }
            std::printf("| %.2f | %s | %d / %d | %.2f |\n", V, p[0], solved, pairs, wall / pairs);
        }
    std::printf("\nWithout a route (the named planner alone, or the default):\n");
    for (const std::string &f : failures)
        if (f.rfind("ZA*TVE", 0) != 0)
            std::printf("- %s\n", f.c_str());
    return 0;
}
