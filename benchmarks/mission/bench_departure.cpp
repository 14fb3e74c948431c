// Optimal departure time ([EichhornRAS] Sec. 5) against a brute-force sweep on the meandering jet.
//
// Every evaluation is a full ZA*TVE lattice search (departureFunction() of mission/Planning.h: the lattice path,
// without smoothing or refinement). The brute force searches
// at every departure of a fine grid over the window; the optimal-departure scheme uses supporting points every
// `spacing`, Akima interpolation and Brent's method. Prints both counts and wall times and checks the claim of
// The departure found is within 1 % (travel time) of the brute-force best with at most a fifth of its
// searches.
//
// Usage: bench_departure [--begin 5] [--end 21] [--fine 0.02] [--spacing 1] [--tol 0.001] [--threads 0]
//                        [--coarse-grid 0] [--start 0.5,-3] [--goal 9.5,3] [--grid 0.4] [--curve FILE.csv]
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include <ompl/util/Console.h>

#include "ompl_glider/mission/DepartureTimeSearch.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN); // one "Solution found" line per search would bury the table
    double begin = 5.0, end = 21.0, fine = 0.02, spacing = 1.0, tol = 1e-3, coarseGrid = 0.0, grid = 0.4;
    double sx = 0.5, sy = -3.0, gx = 9.5, gy = 3.0;
    unsigned threads = 0;
    std::string curve;
    for (int i = 1; i + 1 < argc; i += 2)
    {
        const std::string k = argv[i];
        const char *v = argv[i + 1];
        if (k == "--begin")
            begin = std::atof(v);
        else if (k == "--end")
            end = std::atof(v);
        else if (k == "--fine")
            fine = std::atof(v);
        else if (k == "--spacing")
            spacing = std::atof(v);
        else if (k == "--tol")
            tol = std::atof(v);
        else if (k == "--threads")
            threads = static_cast<unsigned>(std::atoi(v));
        else if (k == "--coarse-grid")
            coarseGrid = std::atof(v);
        else if (k == "--grid")
            grid = std::atof(v);
        else if (k == "--start")
            std::sscanf(v, "%lf,%lf", &sx, &sy);
        else if (k == "--goal")
            std::sscanf(v, "%lf,%lf", &gx, &gy);
        else if (k == "--curve")
            curve = v;
        else
        {
            std::fprintf(stderr, "unknown option %s\n", k.c_str());
            return 2;
        }
    }
    MissionSpec spec = defaultGulfStreamMission();
    spec.start.xy = {sx, sy};
    spec.goal.xy = {gx, gy};
    spec.planner.gridSize = grid;
    const MissionProblem problem(spec);

    std::atomic<std::size_t> fineCalls{0}, coarseCalls{0};
    const TravelTimeOfDeparture search = departureFunction(problem);
    const TravelTimeOfDeparture f = [&](double t) {
        ++fineCalls;
        return search(t);
    };
    const TravelTimeOfDeparture coarseSearch = departureFunction(problem, coarseGrid);
    const TravelTimeOfDeparture c = [&](double t) {
        ++coarseCalls;
        return coarseSearch(t);
    };

    DepartureSearchParams p;
    p.windowBegin = begin;
    p.windowEnd = end;
    p.threads = threads;
    p.progress = [](const std::string &line, bool done) { // progress lines on stderr, as glider_plan prints them
        std::fprintf(stderr, "\r%s%s", line.c_str(), done ? "\n" : "   ");
        std::fflush(stderr);
    };

    p.spacing = fine;
    const DepartureSearchResult brute = bruteForceDepartureTime(f, p);
    const std::size_t bruteCalls = fineCalls.exchange(0);

    p.spacing = spacing;
    p.tolerance = tol;
    const DepartureSearchResult opt = coarseGrid > 0 ? optimalDepartureTime(f, p, c) : optimalDepartureTime(f, p);
    const std::size_t optCalls = fineCalls.load() + coarseCalls.load();

    if (!curve.empty())
    {
        std::ofstream out(curve);
        out << "departure,travel_time\n";
        for (const auto &s : brute.supportingPoints)
            out << s.tDep << "," << s.travelTime << "\n";
    }
    const double rel = (opt.travelTime - brute.travelTime) / brute.travelTime;
    std::printf("meandering jet, start (%g, %g) -> goal (%g, %g), ZA*TVE grid %g, 3 sectors, V = 0.5\n", sx, sy, gx, gy,
                grid);
    std::printf("departure window [%g, %g] (flow period 2 pi / 0.4 = %.3f)\n", begin, end, 2 * M_PI / 0.4);
    std::printf("brute force : %zu searches (spacing %g), %.3f s wall: best departure %.4f, travel time %.6f\n",
                bruteCalls, fine, brute.wallSeconds, brute.departure, brute.travelTime);
    std::printf("optimal dep.: %zu searches (%zu supporting%s + %zu Brent), %.3f s wall: departure %.4f, "
                "travel time %.6f\n",
                optCalls, opt.supportingPoints.size(), coarseGrid > 0 ? " coarse" : "", opt.refinements.size(),
                opt.wallSeconds, opt.departure, opt.travelTime);
    std::printf("Akima minimum at %.4f, Brent bracket [%.4f, %.4f]\n", opt.interpolatedMinimum, opt.bracketLo,
                opt.bracketHi);
    std::printf("travel time difference %+.4f %% of the brute-force best; searches %.1f %% of brute force\n",
                100.0 * rel, 100.0 * optCalls / bruteCalls);
    const bool ok = opt.found && rel <= 0.01 && optCalls * 5 <= bruteCalls && end - begin >= 2 * M_PI / 0.4;
    std::printf("%s: within 1 %% using at most a fifth of the searches over at least one flow period\n",
                ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
}
