// Reproduces the shape of [EichhornRAS] Table 4: cost-function calls (CFC) and current-model calls (CMC) of TVE, A*TVE,
// ZTVE and ZA*TVE on the meandering jet ([EichhornRAS] Sec. 6.1; V = 0.5, 3-sector lattice, grid 0.4, x in [0, 10],
// y in [-4, 4], t0 = 0) from five start positions at decreasing distance from one goal, with the travel times and
// the ZA*TVE-vs-TVE reduction factors. Prints a Markdown table. Runs in about a second.
//
// Usage: bench_table4 [--delta-phi-max DEG] [--course-extrapolation K] [--turn-widening W] [--reliable-turn DEG]
//                     [--goal-radius R] [--goal X,Y] [--random-pairs N]
// Also prints TVE / ZTVE / ZA*TVE on the benchmark campaign's four problems.
// --random-pairs N adds a robustness check: N random lattice start/goal pairs (fixed seed) over the region,
// ZA*TVE against TVE (share within 0.5 %, median and worst deviation, total CFC / CMC reduction).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include "../campaign/CampaignProblems.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "planners/TveSearch.h" // internal to the library (src/)
#include "ompl_glider/planners/ZAStarTVE.h"

using namespace ompl_glider;

namespace
{
struct Cell
{
    bool ok{false};
    double time{0.0};
    std::uint64_t cfc{0}, cmc{0}, expanded{0};
    bool valid{false};
};
} // namespace

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    double dphi = -1.0, k = -1.0;
    double gx = 7.6, gy = 1.2;
    int randomPairs = 0;
    double tw = -1.0;
    double reliableTurnDeg = -1.0, goalRadius = -1.0, certify = -2.0;
    bool looseBounds = false; // [EichhornRAS] Eq. 1 with the region's maximum current (tight_bounds 0)
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        if (a == "--delta-phi-max" && i + 1 < argc)
            dphi = std::atof(argv[++i]);
        else if (a == "--course-extrapolation" && i + 1 < argc)
            k = std::atof(argv[++i]);
        else if (a == "--goal" && i + 1 < argc && std::sscanf(argv[++i], "%lf,%lf", &gx, &gy) == 2)
            ;
        else if (a == "--turn-widening" && i + 1 < argc)
            tw = std::atof(argv[++i]);
        else if (a == "--reliable-turn" && i + 1 < argc)
            reliableTurnDeg = std::atof(argv[++i]);
        else if (a == "--certify" && i + 1 < argc)
            certify = std::atof(argv[++i]);
        else if (a == "--loose-bounds")
            looseBounds = true;
        else if (a == "--goal-radius" && i + 1 < argc)
            goalRadius = std::atof(argv[++i]);
        else if (a == "--random-pairs" && i + 1 < argc)
            randomPairs = std::atoi(argv[++i]);
        else
        {
            std::fprintf(stderr,
                         "usage: %s [--delta-phi-max DEG] [--course-extrapolation K] [--goal X,Y] [--random-pairs N] "
                         "[--certify TOL] [--loose-bounds]\n",
                         argv[0]);
            return 2;
        }
    }
    // Starts on the line from the far corner (0.4, -3.2) to the goal at 100, 80, 60, 40, 20 % of the distance,
    // snapped to the lattice (as the paper's Fig. 10: spread over the area, at decreasing distance).
    const double starts[5][2] = {{0.4, -3.2}, {2.0, -2.4}, {3.2, -1.6}, {4.8, -0.4}, {6.0, 0.4}};
    const char *configs[4] = {"TVE", "A*TVE", "ZTVE", "ZA*TVE"};
    Cell cells[4][5];

    auto jet = std::make_shared<MeanderingJet>();
    for (int s = 0; s < 5; ++s)
    {
        GliderProblem p;
        p.field = jet;
        p.start.x = starts[s][0];
        p.start.y = starts[s][1];
        p.goal.x = gx;
        p.goal.y = gy;
        std::shared_ptr<GliderContext> ctx;
        auto ss = makeSimpleSetup(p, &ctx);
        for (int c = 0; c < 4; ++c)
        {
            auto planner = std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, configs[c]);
            // Table 4 measures the search: the lattice path as found, without smoothing and refinement (params
            // "smooth" and "refine", on by default), so that CFC / CMC, the travel time and the path checked are
            // the search's.
            planner->setSmooth(false);
            planner->setRefine(false);
            if (dphi > 0)
                planner->setDeltaPhiMax(dphi);
            if (k >= 0)
                planner->setCourseExtrapolation(k);
            if (tw >= 0)
                planner->options().turnWidening = tw;
            if (reliableTurnDeg >= 0)
                planner->options().reliableTurn = reliableTurnDeg * 3.14159265358979323846 / 180.0;
            if (goalRadius >= 0)
                planner->options().goalRadius = goalRadius;
            if (certify > -2.0)
                planner->options().certifyTolerance = certify;
            if (looseBounds)
                planner->options().tightBounds = false;
            ss->clear();
            ss->setPlanner(planner);
            ss->setup();
            const auto status = ss->solve(ompl::base::timedPlannerTerminationCondition(30.0));
            Cell &cell = cells[c][s];
            cell.ok = status == ompl::base::PlannerStatus::EXACT_SOLUTION;
            cell.time = planner->getTravelTime();
            cell.cfc = planner->getCostFunctionCalls();
            cell.cmc = planner->getCurrentModelCalls();
            cell.expanded = planner->getExpandedVertices();
            cell.valid = cell.ok && ss->getSolutionPath().check();
        }
    }

    std::printf(
        "Meandering jet, V = 0.5, 3-sector lattice, grid 0.4, x in [0, 10], y in [-4, 4], t0 = 0; goal (%g, %g)\n\n",
        gx, gy);
    std::printf("| Method |");
    for (int s = 0; s < 5; ++s)
        std::printf(" SP%d (%g, %g) CFC / CMC |", s + 1, starts[s][0], starts[s][1]);
    std::printf(" total CFC / CMC |\n|---|");
    for (int s = 0; s < 6; ++s)
        std::printf("---|");
    std::printf("\n");
    std::uint64_t tot[4][2] = {};
    for (int c = 0; c < 4; ++c)
    {
        std::printf("| %s |", configs[c]);
        for (int s = 0; s < 5; ++s)
        {
            std::printf(" %llu / %llu |", static_cast<unsigned long long>(cells[c][s].cfc),
                        static_cast<unsigned long long>(cells[c][s].cmc));
            tot[c][0] += cells[c][s].cfc;
            tot[c][1] += cells[c][s].cmc;
        }
        std::printf(" %llu / %llu |\n", static_cast<unsigned long long>(tot[c][0]),
                    static_cast<unsigned long long>(tot[c][1]));
    }
    std::printf("| reduction TVE / ZA*TVE |");
    for (int s = 0; s < 5; ++s)
        std::printf(" %.1fx / %.1fx |", double(cells[0][s].cfc) / double(cells[3][s].cfc),
                    double(cells[0][s].cmc) / double(cells[3][s].cmc));
    std::printf(" **%.1fx / %.1fx** |\n\n", double(tot[0][0]) / double(tot[3][0]),
                double(tot[0][1]) / double(tot[3][1]));

    std::printf("| Method | travel time SP1 | SP2 | SP3 | SP4 | SP5 | max deviation from TVE "
                "|\n|---|---|---|---|---|---|---|\n");
    bool allOk = true;
    for (int c = 0; c < 4; ++c)
    {
        std::printf("| %s |", configs[c]);
        double worst = 0.0;
        for (int s = 0; s < 5; ++s)
        {
            const Cell &cell = cells[c][s];
            allOk = allOk && cell.ok && cell.valid;
            if (cell.ok)
                std::printf(" %.6f%s |", cell.time, cell.valid ? "" : " (check failed)");
            else
                std::printf(" no solution |");
            if (cell.ok && cells[0][s].ok)
                worst = std::max(worst, cell.time / cells[0][s].time - 1.0);
        }
        std::printf(" %.3f %% |\n", 100.0 * worst);
    }
    std::printf("\nAll paths exact and passing PathGeometric::check(): %s\n", allOk ? "yes" : "NO");

    {
        // The benchmark campaign's problems (benchmarks/campaign/CampaignProblems.h: start (0.6, -2.6), goal
        // (9.4, 2.6), horizon 40, grid 0.4, 3 sectors): ZTVE / ZA*TVE against TVE with the same options.
        std::printf("\nCampaign problems (grid 0.4, 3 sectors): travel time TVE / ZTVE / ZA*TVE, deviation, CFC\n");
        for (const CampaignProblem &cp : makeCampaignProblems(jet))
        {
            auto ctx = makeGliderContext(cp.problem);
            TveSearch search(ctx, 0.4, 3);
            TveOptions opts[3];
            opts[0].heuristic = opts[0].zermelo = false;
            opts[1].heuristic = false;
            for (int c = 1; c < 3; ++c)
            {
                if (dphi > 0)
                    opts[c].deltaPhiMax = dphi * 3.14159265358979323846 / 180.0;
                if (k >= 0)
                    opts[c].courseExtrapolation = k;
                if (tw >= 0)
                    opts[c].turnWidening = tw;
                if (reliableTurnDeg >= 0)
                    opts[c].reliableTurn = reliableTurnDeg * 3.14159265358979323846 / 180.0;
                if (goalRadius >= 0)
                    opts[c].goalRadius = goalRadius;
                if (certify > -2.0)
                    opts[c].certifyTolerance = certify;
            }
            TveResult r[3];
            for (int c = 0; c < 3; ++c)
                r[c] = search.run(cp.problem.start.x, cp.problem.start.y, cp.problem.t0, cp.problem.goal.x,
                                  cp.problem.goal.y, opts[c]);
            std::printf("  %-10s %.6f / %.6f / %.6f  (%+.2f %% / %+.2f %%)  CFC %llu / %llu / %llu\n", cp.name.c_str(),
                        r[0].travelTime, r[1].travelTime, r[2].travelTime,
                        100 * (r[1].travelTime / r[0].travelTime - 1), 100 * (r[2].travelTime / r[0].travelTime - 1),
                        static_cast<unsigned long long>(r[0].costFunctionCalls),
                        static_cast<unsigned long long>(r[1].costFunctionCalls),
                        static_cast<unsigned long long>(r[2].costFunctionCalls));
        }
    }

    if (randomPairs > 0)
    {
        // Robustness: random lattice-aligned pairs, ZA*TVE (same options) against TVE on the same lattice.
        GliderProblem p;
        p.field = jet;
        p.start.x = p.start.y = p.goal.x = p.goal.y = 0.0;
        auto ctx = makeGliderContext(p);
        TveSearch search(ctx, 0.4, 3);
        TveOptions tve;
        tve.heuristic = tve.zermelo = false;
        TveOptions za;
        if (dphi > 0)
            za.deltaPhiMax = dphi * 3.14159265358979323846 / 180.0;
        if (k >= 0)
            za.courseExtrapolation = k;
        if (tw >= 0)
            za.turnWidening = tw;
        if (reliableTurnDeg >= 0)
            za.reliableTurn = reliableTurnDeg * 3.14159265358979323846 / 180.0;
        if (goalRadius >= 0)
            za.goalRadius = goalRadius;
        if (certify > -2.0)
            za.certifyTolerance = certify;
        std::mt19937 rng(1);
        std::uniform_int_distribution<int> ix(1, 24), iy(1, 19);
        std::vector<double> dev;
        double cfc[2] = {0, 0}, cmc[2] = {0, 0};
        int unreachable = 0;
        for (int i = 0; i < randomPairs; ++i)
        {
            const double sx = 0.4 * ix(rng), sy = -4.0 + 0.4 * iy(rng), ex = 0.4 * ix(rng), ey = -4.0 + 0.4 * iy(rng);
            const TveResult a = search.run(sx, sy, p.t0, ex, ey, tve);
            const TveResult b = search.run(sx, sy, p.t0, ex, ey, za);
            if (a.outcome != TveOutcome::Exact || b.outcome != TveOutcome::Exact)
            {
                ++unreachable;
                continue;
            }
            dev.push_back(b.travelTime / a.travelTime - 1.0);
            cfc[0] += double(a.costFunctionCalls);
            cfc[1] += double(b.costFunctionCalls);
            cmc[0] += double(a.currentModelCalls);
            cmc[1] += double(b.currentModelCalls);
        }
        std::sort(dev.begin(), dev.end());
        const auto within = std::count_if(dev.begin(), dev.end(), [](double d) { return d <= 0.005; });
        std::printf("\nRobustness, %d random lattice pairs (seed 1): ZA*TVE within 0.5 %% of TVE in %ld of %zu; "
                    "median deviation %.3f %%, 90th percentile %.2f %%, worst %.1f %%; total reduction %.1fx CFC / "
                    "%.1fx CMC; %d pairs without a solution\n",
                    randomPairs, static_cast<long>(within), dev.size(), dev.empty() ? 0.0 : 100 * dev[dev.size() / 2],
                    dev.empty() ? 0.0 : 100 * dev[dev.size() * 9 / 10], dev.empty() ? 0.0 : 100 * dev.back(),
                    cfc[0] / cfc[1], cmc[0] / cmc[1], unreachable);
    }
    return allOk ? 0 : 1;
}
