// bench_search: cost-function calls (CFC), current-model calls (CMC), expanded vertices, wall time and
// travel time against TVE of the lattice search configurations, on
//   - the repository's problems: the five Table 4 starts ([EichhornRAS] Table 4, goal (7.6, 1.2)) and the four
//     campaign problems (benchmarks/campaign/CampaignProblems.h), meandering jet, grid 0.4, 3 sectors;
//   - N random start/goal pairs of the jet (default 100; lattice points, seed 1, as bench_table4 --random-pairs),
//     with the totals over all pairs and over the pairs whose goal lies upstream of the jet (west of the start:
//     the jet flows east everywhere, u > 0);
//   - a gridded forecast (synthetic meanders on a 201 x 161 node grid, 11 forecast times) searched on a lattice of
//     about 10^6 vertices, with the peak resident memory.
// Prints Markdown tables. Single thread.
//
// Usage: bench_search [--random-pairs N] [--per-pair] [--no-gridded] [--gridded-tve] [--gridded-grid G]
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "../campaign/CampaignProblems.h"
#include "ompl_glider/current/GriddedCurrentField.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "planners/TveSearch.h" // internal to the library (src/)

using namespace ompl_glider;

namespace
{
struct Config
{
    const char *name;
    TveOptions options;
};

std::vector<Config> makeConfigs()
{
    std::vector<Config> c;
    TveOptions tve;
    tve.heuristic = tve.zermelo = false;
    c.push_back({"TVE", tve});
    TveOptions astarEq1;
    astarEq1.zermelo = false;
    astarEq1.coarseFactor = 1;
    astarEq1.tightBounds = false;
    c.push_back({"A*TVE, Eq. 1", astarEq1});
    TveOptions before; // the earlier default: Eq. 1 bounds, certify_tolerance 0.1, full search
    before.coarseFactor = 1;
    before.tightBounds = false;
    before.certifyTolerance = 0.1;
    c.push_back({"ZA*TVE, before (Eq. 1, tol 0.1)", before});
    TveOptions beforeExact = before;
    beforeExact.certifyTolerance = 0.0;
    c.push_back({"ZA*TVE, Eq. 1, tol 0", beforeExact});
    TveOptions astarTight;
    astarTight.zermelo = false;
    astarTight.coarseFactor = 1;
    c.push_back({"A*TVE, tight bounds", astarTight});
    TveOptions def;
    if (const char *e = std::getenv("BENCH_ROUNDS"))
        def.windowRounds = static_cast<unsigned>(std::atoi(e));
    if (const char *e = std::getenv("BENCH_GW"))
        def.greedyWeight = std::atof(e);
    if (const char *e = std::getenv("BENCH_TWO"))
        def.greedyDeadline = std::atoi(e) != 0;
    if (const char *e = std::getenv("BENCH_CF"))
        def.coarseFactor = static_cast<unsigned>(std::atoi(e));
    if (const char *e = std::getenv("BENCH_CB"))
        def.corridorBlocks = static_cast<unsigned>(std::atoi(e));
    c.push_back({"ZA*TVE, default (tight, tol 0)", def});
    TveOptions noCoarse = def;
    noCoarse.coarseFactor = 1;
    c.push_back({"ZA*TVE, default without coarse-to-fine", noCoarse});
    if (std::getenv("BENCH_ORACLE"))
    {
        c.push_back({"oracle: ZA*TVE, deadline = TVE arrival", TveOptions{}});
        TveOptions a;
        a.zermelo = false;
        c.push_back({"oracle: A*TVE, deadline = TVE arrival", a});
    }
    return c;
}

struct Run
{
    TveOutcome outcome{TveOutcome::Exhausted};
    double time{0.0};
    std::uint64_t cfc{0}, cmc{0}, expanded{0};
    double wall{0.0};              // seconds
    unsigned rounds{0}, blocks{0}; // coarse-to-fine: fine searches and the final corridor (0: full search)
};

Run runOnce(TveSearch &search, double sx, double sy, double t0, double gx, double gy, const TveOptions &o)
{
    const auto a = std::chrono::steady_clock::now();
    const TveResult r = search.run(sx, sy, t0, gx, gy, o);
    const auto b = std::chrono::steady_clock::now();
    Run out;
    out.outcome = r.outcome;
    out.time = r.travelTime;
    out.cfc = r.costFunctionCalls;
    out.cmc = r.currentModelCalls;
    out.expanded = r.expansions;
    out.wall = std::chrono::duration<double>(b - a).count();
    out.rounds = r.corridorRounds;
    out.blocks = r.corridorBlocks;
    return out;
}

double relDev(const Run &r, const Run &tve)
{
    if (r.outcome != TveOutcome::Exact || tve.outcome != TveOutcome::Exact)
        return r.outcome == tve.outcome ? 0.0 : INFINITY;
    return std::abs(r.time / tve.time - 1.0);
}

void printRow(const char *problem, const char *config, const Run &r, const Run &tve)
{
    std::printf("| %s | %s | %llu | %llu | %llu | %.1f | ", problem, config, static_cast<unsigned long long>(r.cfc),
                static_cast<unsigned long long>(r.cmc), static_cast<unsigned long long>(r.expanded), 1e3 * r.wall);
    if (r.outcome == TveOutcome::Exact && tve.outcome == TveOutcome::Terminated)
        std::printf("%.9f | TVE not run (--gridded-tve) |\n", r.time);
    else if (r.outcome == TveOutcome::Exact)
        std::printf("%.9f | %.1e |\n", r.time, relDev(r, tve));
    else
        std::printf("no path | %s |\n", r.outcome == tve.outcome ? "same" : "DIFFERENT");
}

struct Total
{
    double cfc{0}, cmc{0}, expanded{0}, wall{0}, maxDev{0};
    int pairs{0}, equal{0};
    void add(const Run &r, const Run &tve)
    {
        cfc += double(r.cfc);
        cmc += double(r.cmc);
        expanded += double(r.expanded);
        wall += r.wall;
        const double d = relDev(r, tve);
        maxDev = std::max(maxDev, d);
        ++pairs;
        if (d <= 1e-9)
            ++equal;
    }
};

void printTotals(const char *title, const std::vector<Config> &configs, const std::vector<Total> &tot)
{
    std::printf("\n%s\n\n| configuration | CFC | CMC | expanded | wall [ms] | TVE / config CFC | TVE / config CMC | "
                "travel time = TVE (1e-9 rel.) | max rel. deviation |\n|---|---|---|---|---|---|---|---|---|\n",
                title);
    for (std::size_t c = 0; c < configs.size(); ++c)
        std::printf("| %s | %.0f | %.0f | %.0f | %.0f | %.2fx | %.2fx | %d / %d | %.1e |\n", configs[c].name,
                    tot[c].cfc, tot[c].cmc, tot[c].expanded, 1e3 * tot[c].wall, tot[0].cfc / tot[c].cfc,
                    tot[0].cmc / tot[c].cmc, tot[c].equal, tot[c].pairs, tot[c].maxDev);
}

long peakRssKb()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;
}

/// Scale of the synthetic forecast's currents: peak about 0.4 against V = 0.5 (an ocean forecast against a glider's
/// 0.3-0.5 m/s).
constexpr double kForecastScale = 0.4;

/// Synthetic forecast: two meandering jets (the jet's closed form, one reversed) across the box, drifting east, on a
/// 201 x 161 node grid (x in [0, 50], y in [-20, 20]), 11 forecast times 0, 10, ..., 100; calm water between them.
bool onIsland(double x, double y)
{
    return std::hypot(x - 20.0, y) < 3.0 || std::hypot(x - 31.0, y - 6.0) < 2.0 || std::hypot(x - 12.0, y + 8.0) < 2.5;
}

std::shared_ptr<GriddedCurrentField> makeForecast()
{
    GriddedData d;
    d.nx = 201;
    d.ny = 161;
    for (std::size_t i = 0; i < d.nx; ++i)
        d.x.push_back(0.25 * double(i));
    for (std::size_t j = 0; j < d.ny; ++j)
        d.y.push_back(-20.0 + 0.25 * double(j));
    d.time.clear();
    for (int t = 0; t <= 10; ++t)
        d.time.push_back(10.0 * t);
    const MeanderingJet jet; // two jets: the jet's closed form at y - 8 and (reversed) at y + 8
    for (double t : d.time)
        for (std::size_t j = 0; j < d.ny; ++j)
            for (std::size_t i = 0; i < d.nx; ++i)
            {
                const double x = d.x[i], y = d.y[j];
                const Velocity a = jet.velocity(x, y - 8.0, 0.0, t);
                const Velocity b = jet.velocity(x + 3.0, y + 8.0, 0.0, t);
                d.u.push_back(static_cast<float>(kForecastScale * (a.u - b.u)));
                d.v.push_back(static_cast<float>(kForecastScale * (a.v - b.v)));
            }
    // three islands (land nodes, as a model's mask writes them): corridors must go around them
    for (std::size_t j = 0; j < d.ny; ++j)
        for (std::size_t i = 0; i < d.nx; ++i)
            d.water.push_back(onIsland(d.x[i], d.y[j]) ? 0 : 1);
    GriddedFieldOptions o;
    o.name = "synthetic forecast";
    o.beyond = BeyondForecast::HoldLast;
    return std::make_shared<GriddedCurrentField>(std::move(d), o);
}
} // namespace

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    int randomPairs = 100;
    bool perPair = false, gridded = true, griddedTve = false, jetProblems = true;
    std::string griddedOnly; // --gridded-config NAME: only that configuration on the gridded problem
    double griddedGrid = 0.045;
    int griddedPairs = 0; // --gridded-pairs N: coarse-to-fine against the full search on N random water pairs
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        if (a == "--random-pairs" && i + 1 < argc)
            randomPairs = std::atoi(argv[++i]);
        else if (a == "--per-pair")
            perPair = true;
        else if (a == "--no-gridded")
            gridded = false;
        else if (a == "--only-gridded")
            jetProblems = false;
        else if (a == "--gridded-config" && i + 1 < argc)
            griddedOnly = argv[++i];
        else if (a == "--gridded-tve")
            griddedTve = true;
        else if (a == "--gridded-grid" && i + 1 < argc)
            griddedGrid = std::atof(argv[++i]);
        else if (a == "--gridded-pairs" && i + 1 < argc)
            griddedPairs = std::atoi(argv[++i]);
        else
        {
            std::fprintf(stderr,
                         "usage: %s [--random-pairs N] [--per-pair] [--no-gridded] [--only-gridded] [--gridded-tve] "
                         "[--gridded-grid G] [--gridded-config NAME] [--gridded-pairs N]\n",
                         argv[0]);
            return 2;
        }
    }
    const std::vector<Config> configs = makeConfigs();
    auto jet = std::make_shared<MeanderingJet>();
    bool allEqual = true;

    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    if (!jetProblems)
        randomPairs = 0;
    if (jetProblems)
    {
        std::printf(
            "Meandering jet ([EichhornRAS] Sec. 6.1), V = 0.5, grid 0.4, 3 sectors, horizon 60.\n"
            "CFC = travel-time calls, CMC = current-model calls (velocity + Jacobian), expanded = vertices taken "
            "from the queue.\n\n");
        std::printf(
            "| problem | configuration | CFC | CMC | expanded | wall [ms] | travel time | rel. deviation from TVE "
            "|\n|---|---|---|---|---|---|---|---|\n");
        {
            GliderProblem p;
            p.field = jet;
            p.start.x = p.start.y = p.goal.x = p.goal.y = 0.0;
            auto ctx = makeGliderContext(p);
            TveSearch search(ctx, 0.4, 3);
            const double starts[5][2] = {{0.4, -3.2}, {2.0, -2.4}, {3.2, -1.6}, {4.8, -0.4}, {6.0, 0.4}};
            for (int s = 0; s < 5; ++s)
            {
                char name[64];
                std::snprintf(name, sizeof name, "Table 4 SP%d", s + 1);
                Run tve;
                for (std::size_t c = 0; c < configs.size(); ++c)
                {
                    const Run r = runOnce(search, starts[s][0], starts[s][1], 0.0, 7.6, 1.2, configs[c].options);
                    if (c == 0)
                        tve = r;
                    printRow(name, configs[c].name, r, tve);
                }
            }
        }
        for (const CampaignProblem &cp : makeCampaignProblems(jet))
        {
            auto ctx = makeGliderContext(cp.problem);
            TveSearch search(ctx, 0.4, 3);
            Run tve;
            for (std::size_t c = 0; c < configs.size(); ++c)
            {
                const Run r = runOnce(search, cp.problem.start.x, cp.problem.start.y, cp.problem.t0, cp.problem.goal.x,
                                      cp.problem.goal.y, configs[c].options);
                if (c == 0)
                    tve = r;
                const std::string name = "campaign " + cp.name;
                printRow(name.c_str(), configs[c].name, r, tve);
            }
        }
    }
    if (randomPairs > 0)
    {
        GliderProblem p;
        p.field = jet;
        p.start.x = p.start.y = p.goal.x = p.goal.y = 0.0;
        auto ctx = makeGliderContext(p);
        TveSearch search(ctx, 0.4, 3);
        std::mt19937 rng(1);
        std::uniform_int_distribution<int> ix(1, 24), iy(1, 19);
        std::vector<Total> all(configs.size()), up(configs.size());
        if (perPair)
            std::printf("\n| pair | start | goal | configuration | CFC | CMC | expanded | wall [ms] | travel time | "
                        "rel. deviation from TVE |\n|---|---|---|---|---|---|---|---|---|---|\n");
        int n = 0;
        while (n < randomPairs)
        {
            const double sx = 0.4 * ix(rng), sy = -4.0 + 0.4 * iy(rng), gx = 0.4 * ix(rng), gy = -4.0 + 0.4 * iy(rng);
            if (sx == gx && sy == gy)
                continue;
            ++n;
            const bool upstream = gx < sx;
            Run tve;
            for (std::size_t c = 0; c < configs.size(); ++c)
            {
                TveOptions o = configs[c].options;
                if (std::strncmp(configs[c].name, "oracle", 6) == 0)
                    o.deadline = tve.time * (1 + 1e-9);
                const Run r = runOnce(search, sx, sy, 0.0, gx, gy, o);
                if (c == 0)
                    tve = r;
                all[c].add(r, tve);
                if (upstream)
                    up[c].add(r, tve);
                if (std::strcmp(configs[c].name, "ZA*TVE, default (tight, tol 0)") == 0 && relDev(r, tve) > 1e-9)
                    allEqual = false;
                if (perPair)
                {
                    std::printf(
                        "| %d%s | (%.1f, %.1f) | (%.1f, %.1f) | %s | %llu | %llu | %llu | %.1f | %.9f | %.1e |\n", n,
                        upstream ? " up" : "", sx, sy, gx, gy, configs[c].name, static_cast<unsigned long long>(r.cfc),
                        static_cast<unsigned long long>(r.cmc), static_cast<unsigned long long>(r.expanded),
                        1e3 * r.wall, r.time, relDev(r, tve));
                }
            }
        }
        char title[160];
        std::snprintf(title, sizeof title, "Totals over %d random jet pairs (lattice points, seed 1):", randomPairs);
        printTotals(title, configs, all);
        std::snprintf(title, sizeof title,
                      "Totals over the %d of them whose goal lies upstream (west) of the start:", up[0].pairs);
        printTotals(title, configs, up);
    }

    if (gridded)
    {
        auto field = makeForecast();
        GliderProblem p;
        p.field = field;
        p.xMin = 0.0;
        p.xMax = 50.0;
        p.yMin = -20.0;
        p.yMax = 20.0;
        p.horizon = 100.0;
        p.start.x = 2.0;
        p.start.y = -15.0;
        p.goal.x = 40.0;
        p.goal.y = 12.0;
        auto ctx = makeGliderContext(p);
        const long rss0 = peakRssKb();
        TveSearch search(ctx, griddedGrid, 3);
        std::printf("\nGridded forecast (synthetic, %zu x %zu nodes, %zu times), lattice %ld x %ld = %.2f million "
                    "vertices (grid %g, 3 sectors), (%g, %g) -> (%g, %g); peak RSS before the searches %.0f MB\n\n",
                    field->nx(), field->ny(), field->nt(), search.lattice().nx(), search.lattice().ny(),
                    1e-6 * double(search.lattice().numGridVertices()), griddedGrid, p.start.x, p.start.y, p.goal.x,
                    p.goal.y, rss0 / 1024.0);
        std::printf("| problem | configuration | CFC | CMC | expanded | wall [ms] | travel time | rel. deviation from "
                    "TVE |\n|---|---|---|---|---|---|---|---|\n");
        Run tve;
        tve.outcome = TveOutcome::Terminated; // not run
        for (std::size_t c = griddedTve ? 0 : 1; c < configs.size(); ++c)
        {
            if (!griddedOnly.empty() && griddedOnly != configs[c].name)
                continue;
            const Run r = runOnce(search, p.start.x, p.start.y, 0.0, p.goal.x, p.goal.y, configs[c].options);
            if (c == 0)
                tve = r;
            char label[64];
            std::snprintf(label, sizeof label, "gridded %.2fe6", 1e-6 * double(search.lattice().numGridVertices()));
            printRow(label, configs[c].name, r, tve);
            if (r.rounds > 0)
                std::printf("|   | coarse-to-fine: %u fine search(es), corridor %u blocks | | | | | | |\n", r.rounds,
                            r.blocks);
            std::printf("|   | peak RSS so far %.0f MB | | | | | | |\n", peakRssKb() / 1024.0);
        }
    }
    if (gridded && griddedPairs > 0)
    {
        // coarse-to-fine (the default above 2^19 vertices) against the same search without it, on random pairs
        auto field = makeForecast();
        GliderProblem p;
        p.field = field;
        p.xMin = 0.0;
        p.xMax = 50.0;
        p.yMin = -20.0;
        p.yMax = 20.0;
        p.horizon = 200.0;
        p.start.x = p.start.y = p.goal.x = p.goal.y = 1.0;
        auto ctx = makeGliderContext(p);
        TveSearch search(ctx, griddedGrid, 3);
        TveOptions c2f, full;
        full.coarseFactor = 1;
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> ux(0.5, 49.5), uy(-19.5, 19.5);
        auto water = [&](double &x, double &y) {
            do
            {
                x = ux(rng);
                y = uy(rng);
            } while (!field->inWater(x, y, 0.0));
        };
        int equal = 0, compared = 0, widened = 0, noPath = 0;
        double worst = 0.0, wallC = 0.0, wallF = 0.0;
        std::uint64_t cfcC = 0, cfcF = 0, cmcC = 0, cmcF = 0;
        std::printf("\nCoarse-to-fine against the full search, %d random water pairs of the gridded forecast "
                    "(%.2f million vertices):\n\n| pair | start | goal | full: CFC | wall [ms] | coarse-to-fine: CFC | "
                    "wall [ms] | fine searches | corridor [blocks] | travel time | rel. deviation |\n"
                    "|---|---|---|---|---|---|---|---|---|---|---|\n",
                    griddedPairs, 1e-6 * double(search.lattice().numGridVertices()));
        for (int k = 0; k < griddedPairs; ++k)
        {
            double sx, sy, gx, gy;
            water(sx, sy);
            water(gx, gy);
            if (const char *only = std::getenv("BENCH_ONLY_PAIR"); only && std::atoi(only) != k + 1)
                continue;
            const Run a = runOnce(search, sx, sy, 0.0, gx, gy, full);
            const Run b = runOnce(search, sx, sy, 0.0, gx, gy, c2f);
            wallF += a.wall;
            wallC += b.wall;
            cfcF += a.cfc;
            cfcC += b.cfc;
            cmcF += a.cmc;
            cmcC += b.cmc;
            if (b.rounds > 1)
                ++widened;
            const double dev = relDev(b, a);
            if (a.outcome != TveOutcome::Exact)
                ++noPath;
            else
            {
                ++compared;
                worst = std::max(worst, dev);
                if (dev <= 1e-9)
                    ++equal;
            }
            std::printf("| %d | (%.2f, %.2f) | (%.2f, %.2f) | %llu | %.0f | %llu | %.0f | %u | %u | %.6f | %.1e |\n",
                        k + 1, sx, sy, gx, gy, static_cast<unsigned long long>(a.cfc), 1e3 * a.wall,
                        static_cast<unsigned long long>(b.cfc), 1e3 * b.wall, b.rounds, b.blocks, a.time, dev);
        }
        std::printf("\nTotals: full search %llu CFC / %llu CMC / %.1f s; coarse-to-fine %llu CFC / %llu CMC / %.1f s "
                    "(%.1fx / %.1fx / %.1fx fewer); equal travel time (1e-9 relative) on %d of %d pairs with a path "
                    "(worst deviation %.1e); %d needed a wider corridor; %d without a path\n",
                    static_cast<unsigned long long>(cfcF), static_cast<unsigned long long>(cmcF), wallF,
                    static_cast<unsigned long long>(cfcC), static_cast<unsigned long long>(cmcC), wallC,
                    double(cfcF) / double(std::max<std::uint64_t>(1, cfcC)),
                    double(cmcF) / double(std::max<std::uint64_t>(1, cmcC)), wallF / std::max(1e-9, wallC), equal,
                    compared, worst, widened, noPath);
    }
    std::printf("\nDefault configuration equal to TVE (1e-9 relative) on every random pair: %s\n",
                allEqual ? "yes" : "NO");
    return allEqual ? 0 : 1;
}
