// Level-set planner: error against the shooting optimum versus wall time, beside ZA*TVE + refinement, on
// the eight meandering-jet crossings of test_planner_vs_optimum (region x in [0, 10], y in [-4, 4], V = 0.5,
// t0 = 0), with the node updates per second; then what the coarse corridor, the narrow band, the step, the gradient
// heading and the threads each buy at cell 0.05. --only-levelset leaves ZA*TVE out.
//   bench_levelset [--quick] [--cells 0.05,0.035] [--cfl C] [--reinit K] [--threads N] [--only-levelset]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <memory>
#include <vector>

#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/planners/ZAStarTVE.h"
#include "ompl_glider/reachability/LevelSet.h"
#include "ompl_glider/reference/ZermeloReference.h"

using namespace ompl_glider;

namespace
{
struct Pair
{
    double sx, sy, gx, gy, optimum;
};

double seconds(std::chrono::steady_clock::time_point a)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

GliderProblem problem(const std::shared_ptr<const CurrentField> &jet, const Pair &p)
{
    GliderProblem g;
    g.field = jet;
    g.start.x = p.sx;
    g.start.y = p.sy;
    g.goal.x = p.gx;
    g.goal.y = p.gy;
    return g;
}

struct Row
{
    double meanErr{0}, maxErr{0}, meanSeconds{0};
};

template <class F> Row measure(const std::vector<Pair> &pairs, F &&solve)
{
    Row r;
    for (const Pair &p : pairs)
    {
        const auto t = std::chrono::steady_clock::now();
        const double T = solve(p);
        r.meanSeconds += seconds(t) / pairs.size();
        const double e = std::abs(T - p.optimum) / p.optimum;
        r.meanErr += e / pairs.size();
        r.maxErr = std::max(r.maxErr, e);
    }
    return r;
}
} // namespace

int main(int argc, char **argv)
{
    bool quick = false, onlyLevelSet = false;
    double cfl = LevelSetParams{}.cfl;
    unsigned threads = 0;
    int reinit = LevelSetParams{}.reinitEvery;
    std::vector<double> givenCells;
    for (int i = 1; i < argc; ++i)
    {
        if (!std::strcmp(argv[i], "--quick"))
            quick = true;
        else if (!std::strcmp(argv[i], "--only-levelset"))
            onlyLevelSet = true;
        else if (!std::strcmp(argv[i], "--cfl") && i + 1 < argc)
            cfl = std::atof(argv[++i]);
        else if (!std::strcmp(argv[i], "--reinit") && i + 1 < argc)
            reinit = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc)
            threads = static_cast<unsigned>(std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--cells") && i + 1 < argc)
        {
            const std::string list = argv[++i];
            for (std::size_t a = 0; a < list.size();)
            {
                const std::size_t b = std::min(list.find(',', a), list.size());
                givenCells.push_back(std::atof(list.substr(a, b - a).c_str()));
                a = b + 1;
            }
        }
        else
        {
            std::fprintf(stderr, "usage: bench_levelset [--quick] [--cells H,H,...] [--cfl C] [--threads N] "
                                 "[--reinit K] [--only-levelset]\n");
            return 2;
        }
    }
    auto jet = std::make_shared<MeanderingJet>();
    std::vector<Pair> pairs = {{1.0, -3.0, 8.0, 3.0, 0}, {1.0, 3.0, 9.0, -2.5, 0}, {2.0, -3.5, 7.0, 3.5, 0},
                               {0.5, -2.0, 9.5, 2.0, 0}, {2.0, 3.5, 8.0, -3.5, 0}, {0.5, 3.0, 5.0, -3.0, 0},
                               {8.0, 3.0, 2.0, -3.0, 0}, {5.0, -3.5, 4.0, 3.5, 0}};
    if (quick)
        pairs.resize(3);
    ZermeloParams zp;
    zp.speed = 0.5;
    zp.maxTime = 40.0;
    const ZermeloReference ref(jet, zp);
    for (Pair &p : pairs)
        p.optimum = ref.solve(p.sx, p.sy, p.gx, p.gy, 0.0).travelTime;
    const auto ctx = makeGliderContext(problem(jet, pairs.front()));

    std::printf("Error against the shooting optimum vs wall time, %zu jet crossings (mean over pairs)\n\n",
                pairs.size());
    std::printf("| method | resolution | mean error | max error | mean time (s) | node updates/s |\n"
                "|---|---|---|---|---|---|\n");
    const std::vector<double> cells = !givenCells.empty() ? givenCells
                                      : quick             ? std::vector<double>{0.1, 0.05}
                                                          : std::vector<double>{0.1, 0.07, 0.05, 0.035, 0.025};
    for (double h : cells)
    {
        LevelSetParams lp;
        lp.cellSize = h;
        lp.cfl = cfl;
        lp.threads = threads;
        lp.reinitEvery = reinit;
        const LevelSetSolver solver(ctx, lp);
        double updates = 0.0, busy = 0.0;
        const Row r = measure(pairs, [&](const Pair &p) {
            const Reachability s = solver.solve(p.sx, p.sy, 0.0, 60.0, Point2{p.gx, p.gy});
            updates += static_cast<double>(s.stats.nodeUpdates);
            busy += s.stats.seconds;
            return s.goalTime;
        });
        std::printf("| LevelSet | cell %.3f | %.3f %% | %.3f %% | %.3f | %.3g |\n", h, 100 * r.meanErr, 100 * r.maxErr,
                    r.meanSeconds, updates / busy);
    }
    for (double grid : onlyLevelSet ? std::vector<double>{}
                       : quick      ? std::vector<double>{0.4}
                                    : std::vector<double>{0.8, 0.4, 0.2})
    {
        const Row r = measure(pairs, [&](const Pair &p) {
            std::shared_ptr<GliderContext> c;
            auto ss = makeSimpleSetup(problem(jet, p), &c);
            auto z = std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), c, "ZA*TVE");
            z->setGridSize(grid);
            ss->setPlanner(z);
            if (ss->solve(600.0) != ompl::base::PlannerStatus::EXACT_SOLUTION)
                return static_cast<double>(INFINITY);
            // ZA*TVE smooths and refines its path by default: the arrival of the returned path
            const auto *last = ss->getSolutionPath().getStates().back()->as<TimeSE2StateSpace::StateType>();
            return last->getTime();
        });
        std::printf("| ZA*TVE + smoothing + refinement | grid %.1f, 3 sectors | %.3f %% | %.3f %% | %.3f | - |\n", grid,
                    100 * r.meanErr, 100 * r.maxErr, r.meanSeconds);
    }

    std::printf("\nWhat each part buys, cell 0.05, pair (%.1f, %.1f) -> (%.1f, %.1f), optimum %.4f\n\n",
                pairs.front().sx, pairs.front().sy, pairs.front().gx, pairs.front().gy, pairs.front().optimum);
    std::printf("| configuration | travel time | error | time (s) | node updates | node updates/s |\n"
                "|---|---|---|---|---|---|\n");
    struct Config
    {
        const char *name;
        bool band;
        int scan;
        unsigned threads;
        double cfl;
        bool corridor;
    };
    const Config configs[] = {
        {"default: corridor, narrow band, automatic step (cfl 4 here), gradient heading, 2 threads", true, 0, 2, 0.0,
         true},
        {"1 thread", true, 0, 1, 0.0, true},
        {"no corridor (the whole front to the goal)", true, 0, 2, 0.0, false},
        {"no corridor, 1 thread", true, 0, 1, 0.0, false},
        {"no corridor, cfl 1.5 (the step near a forbidden set; the default before)", true, 0, 2, 1.5, false},
        {"no corridor, every node every step (no narrow band)", false, 0, 2, 0.0, false},
        {"16 headings instead of the gradient", true, 16, 2, 0.0, true},
        {"64 headings instead of the gradient", true, 64, 2, 0.0, true}};
    for (const Config &c : configs)
    {
        LevelSetParams lp;
        lp.cellSize = 0.05;
        lp.narrowBand = c.band;
        lp.headingScan = c.scan;
        lp.threads = c.threads;
        lp.cfl = c.cfl;
        lp.corridor = c.corridor;
        const Pair &p = pairs.front();
        const Reachability r = LevelSetSolver(ctx, lp).solve(p.sx, p.sy, 0.0, 60.0, Point2{p.gx, p.gy});
        std::printf("| %s | %.4f | %+.3f %% | %.3f | %.3g | %.3g |\n", c.name, r.goalTime,
                    100 * (r.goalTime / p.optimum - 1), r.stats.seconds, static_cast<double>(r.stats.nodeUpdates),
                    static_cast<double>(r.stats.nodeUpdates) / r.stats.seconds);
    }
    return 0;
}
