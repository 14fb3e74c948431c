// Missions of several legs on the meandering jet ([EichhornRAS] Sec. 6.1).
//
// 1. Legs planned in sequence on one clock (planMission(): each leg departs at the previous one's arrival) against
//    legs each planned from a departure guessed in advance (the straight-line time at the glider's speed, as a pilot
//    planning legs by hand would), those guessed plans then flown in turn from the real arrivals (the accurate
//    re-flight, reflyPath()). Prints both travel times and what the guess costs.
// 2. The free-order search (branch and bound over orders) against n!: orders planned to the goal and legs planned.
//
// Usage: bench_legs [--cases 8] [--seed 1] [--grid 0.4] [--max-free 6]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ompl_glider/execution/Reflight.h"
#include "ompl_glider/mission/MissionLegs.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"

using namespace ompl_glider;

namespace
{
MissionSpec jetMission(std::mt19937 &rng, std::size_t via, double grid)
{
    std::uniform_real_distribution<double> ux(0.5, 9.5), uy(-3.5, 3.5);
    std::string y = "current: {type: meandering_jet}\nregion: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
                    "vehicle: {speed: 0.5}\nplanner: {grid_size: " +
                    std::to_string(grid) + "}\n";
    y += "start: {x: " + std::to_string(ux(rng)) + ", y: " + std::to_string(uy(rng)) + "}\n";
    y += "goal: {x: " + std::to_string(ux(rng)) + ", y: " + std::to_string(uy(rng)) + "}\nwaypoints:\n";
    for (std::size_t i = 0; i < via; ++i)
        y += "  - {x: " + std::to_string(ux(rng)) + ", y: " + std::to_string(uy(rng)) + "}\n";
    return parseMission(y);
}

/// Each leg planned from the straight-line guess of its departure, then flown in turn: the arrival (+inf: a leg's
/// guessed route cannot be flown from the real departure, or has no route).
double guessedLegsFlown(const MissionProblem &problem)
{
    std::vector<Point2> stops{problem.getStart()};
    for (const Point2 &p : problem.getViaPoints())
        stops.push_back(p);
    stops.push_back(problem.getGoal());
    const double V = problem.getSpec().vehicle.speed;
    double guess = 0.0, actual = 0.0;
    ReflightSettings s;
    s.speed = V;
    for (std::size_t k = 0; k + 1 < stops.size(); ++k)
    {
        const MissionProblem leg = problem.withLeg(stops[k], stops[k + 1], {});
        const PlannedPath p = planRoute(leg, guess, {});
        guess += std::hypot(stops[k + 1].x - stops[k].x, stops[k + 1].y - stops[k].y) / V;
        if (!p.solved)
            return std::numeric_limits<double>::infinity();
        // the waypoints a pilot uploads (a heading route's segment ends) flown as straight legs
        std::vector<TimedPoint> path = p.path;
        const double t0 = path.front().t;
        for (TimedPoint &q : path)
            q.t = q.t - t0 + actual;
        const PathReflight f = reflyPath(path, *problem.getField(), problem.getEnvironment().get(), s);
        if (!f.feasible)
            return std::numeric_limits<double>::infinity();
        actual = f.arrivalTime;
    }
    return actual;
}
} // namespace

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    unsigned cases = 8, seed = 1;
    double grid = 0.4;
    std::size_t maxFree = 6;
    for (int i = 1; i + 1 < argc; i += 2)
    {
        const std::string k = argv[i];
        if (k == "--cases")
            cases = static_cast<unsigned>(std::atoi(argv[i + 1]));
        else if (k == "--seed")
            seed = static_cast<unsigned>(std::atoi(argv[i + 1]));
        else if (k == "--grid")
            grid = std::atof(argv[i + 1]);
        else if (k == "--max-free")
            maxFree = static_cast<std::size_t>(std::atoi(argv[i + 1]));
    }
    std::mt19937 rng(seed);
    std::printf("1. three via points on the jet: legs on one clock against legs planned from guessed departures\n");
    std::printf("%5s %14s %22s %10s\n", "case", "one clock", "guessed, flown in turn", "cost");
    double sumChain = 0.0, sumGuess = 0.0;
    unsigned both = 0, guessFails = 0;
    for (unsigned c = 0; c < cases; ++c)
    {
        const MissionProblem problem(jetMission(rng, 3, grid));
        const MissionPlan chain = planMission(problem, 0.0);
        if (!chain.plan.solved)
        {
            std::printf("%5u %14s\n", c + 1, "no path");
            continue;
        }
        const double guessed = guessedLegsFlown(problem);
        const double t = chain.plan.travelTime;
        if (std::isfinite(guessed))
        {
            std::printf("%5u %14.4f %22.4f %+9.2f%%\n", c + 1, t, guessed, 100.0 * (guessed / t - 1.0));
            sumChain += t;
            sumGuess += guessed;
            ++both;
        }
        else
        {
            std::printf("%5u %14.4f %22s\n", c + 1, t, "cannot be flown");
            ++guessFails;
        }
    }
    if (both > 0)
        std::printf("total over %u cases: one clock %.4f, guessed %.4f (%+.2f%%); %u guessed plans cannot be flown\n",
                    both, sumChain, sumGuess, 100.0 * (sumGuess / sumChain - 1.0), guessFails);

    std::printf("\n2. free order: branch and bound against all n! orders (grid %.2f)\n", 2.0 * grid);
    std::printf("%3s %8s %16s %13s %14s %10s %9s\n", "n", "n!", "orders planned", "legs planned", "legs of all n!",
                "gain", "seconds");
    for (std::size_t n = 3; n <= maxFree; ++n)
    {
        MissionSpec m = jetMission(rng, n, 2.0 * grid);
        m.order = VisitOrder::Free;
        const MissionProblem problem(m);
        const auto t0 = std::chrono::steady_clock::now();
        const MissionPlan plan = planMission(problem, 0.0);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        // planning every order on its own: n + 1 legs each, prefixes shared: sum_k n!/(n-k)! legs and n! last legs
        std::size_t all = 0, perm = 1;
        for (std::size_t k = 1; k <= n; ++k)
        {
            perm *= n - k + 1;
            all += perm;
        }
        all += perm;
        const OrderSearch &s = *plan.orderSearch;
        std::printf("%3zu %8zu %16zu %13zu %14zu %9.2f%% %9.2f\n", n, s.ordersTotal, s.ordersEvaluated, s.legsPlanned,
                    all, 100.0 * s.gain, seconds);
    }
    return 0;
}
