// The OMPL Benchmark campaign: ZA*TVE and its relatives against OMPL's sampling planners on four
// meandering-jet problems (open water, islands, drifting ice, a time-windowed closure), every planner on the
// identical SpaceInformation of one SimpleSetup per problem; and the strong-current set (the jet at
// V = 0.2 and 0.15, a double gyre six times the speed), where ZA*TVE, LevelSet and the heading planner Isochrone (when
// the registry has it) run beside OMPL's control planners oc::SST, oc::RRT and oc::KPIECE1 on the heading-control
// setup of the same problem (CampaignControl.h: one more experiment per problem, its own log).
//
// Per run a post-run event re-flies the returned path's x, y from t0 with the travel-time code (resimulatePath,
// not the planner's bookkeeping) and records "travel time REAL" and "plan valid BOOLEAN" (every waypoint and leg
// re-checked against the region, the time window and the forbidden regions), plus "path motions valid BOOLEAN"
// (every motion of the path as returned, with its own time stamps, accepted by the motion validator: OMPL's PRM
// keeps undirected edges and may return motions that run backwards in time), the planner's own travel time, and
// CFC / CMC counted on the shared travel-time calculator and current field during solve(). "best cost REAL" is the
// travel time of a run that reached the goal with a valid path (for the control planners: the sum of the control
// durations, confirmed by re-flying the controls), the one figure to compare across planners in Planner Arena.
//
// The planners come from the planner registry (registry/PlannerRegistry.h), the one list the command line and the
// mission files use, by their canonical names; the lattice planners get the campaign's grid size and sectors
// through OMPL's ParamSet ("grid_size", "sectors") and keep "smooth" and "refine" at their defaults (on), so the
// campaign records the smoothed and refined ZA*TVE path (its CFC includes that post-processing; the search's own
// CFC is recorded as "search CFC").
//
// Usage: glider_campaign [--quick] [--no-reference] [--runs N] [--time SECONDS] [--grid G] [--seed S] [--problems a,b]
//                        [--planners NAME,...] [--control SST,RRT,KPIECE1|none] [--own-end-time S] OUTDIR
// --problems takes problem names and the set names classic (the default: open_water, islands, ice, closure), strong
// (jet_v020, jet_v015, gyre) and all; --planners restricts the registry planners (names and aliases of the
// registry), --control the control planners of the strong set (default: all three). --time is the budget of every
// planner, except on the strong set, whose registry planners all run to their own end (ZA*TVE, LevelSet, Isochrone):
// they get at most max(--time, --own-end-time) (default 60 s), and their solve time is what they used.
// Under mpirun -np N (a build with OMPL_GLIDER_WITH_MPI) the (problem, planner, run) runs are spread over the ranks
// (CampaignSpread.h) and rank 0 writes the same files; -np 1 and a build without MPI run as one process.
// Writes OUTDIR/<problem>.log and OUTDIR/<problem>_control.log (OMPL benchmark logs) and OUTDIR/reference.csv (the
// optimum of every problem: the level-set front at three cells and its extrapolation, Zermelo shooting in open
// water, and the level-set first entry into the control planners' goal disc).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "ompl_glider/ompl/PipelinePlanner.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/IceZone.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/TimeWindowedZone.h"
#include "ompl_glider/execution/GliderControl.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/ompl/PathResimulation.h"
#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/execution/Reflight.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#include "ompl_glider/planners/ZAStarTVE.h"
#include "ompl_glider/reachability/LevelSet.h"
#include "ompl_glider/reference/ZermeloReference.h"

#include "CampaignBenchmark.h"
#include "CampaignControl.h"
#include "CampaignProblems.h"
#include "CampaignSpread.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/TaskSpread.h"
#if OMPL_GLIDER_WITH_MPI
#include "ompl_glider/mpi/MpiTaskSpreader.h"
#endif

namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace ot = ompl::tools;
using namespace ompl_glider;

namespace
{
const char *const kReferenceHeader =
    "problem,reference_travel_time,found,method,cells,level_set_coarse,level_set_medium,level_set_fine,"
    "level_set_extrapolated,level_set_seconds_fine,shooting,ice_passable_fine,control_goal_tolerance,"
    "reference_disc\n";

/// The planners of the campaign, by their registry names (PlannerRegistry.h).
const std::vector<std::string> kCampaignPlanners = {"TVE",      "A*TVE",   "ZTVE",    "ZA*TVE",  "Wavefront",
                                                    "LevelSet", "RRTstar", "PRM",     "PRMstar", "RRTConnect",
                                                    "RRT#",     "LBTRRT",  "BITstar", "SST"};

struct Options
{
    bool quick{false};
    bool reference{true}; ///< --no-reference: no reference.csv (its level sets take tens of seconds)
    unsigned runs{0};
    double time{0.0};
    double grid{0.4};
    double ownEnd{60.0}; ///< time limit of a benchmark whose planners all run to their own end
    std::uint32_t seed{20240601};
    std::set<std::string> problems; ///< names and set names; empty: the classic set
    std::set<std::string> planners;
    std::set<std::string> control{campaignControlPlanners()};
    std::string outdir;
};

[[noreturn]] void usage(const std::string &why)
{
    std::cerr << "glider_campaign: " << why << "\n"
              << "usage: glider_campaign [--quick] [--no-reference] [--runs N] [--time SECONDS] [--grid G] "
                 "[--own-end-time S] [--seed S] "
                 "[--problems classic|strong|all|open_water,islands,ice,closure,jet_v020,jet_v015,gyre] "
                 "[--planners TVE,RRTstar,...] [--control SST,RRT,KPIECE1|none] OUTDIR\n";
    std::exit(2);
}

/// Adds the comma-separated items of @p list to the option @p a.
void addList(Options &o, const std::string &a, const std::string &list)
{
    if (a == "--control")
        o.control.clear();
    std::stringstream ss(list);
    std::string p;
    while (std::getline(ss, p, ','))
    {
        if (a == "--problems")
            o.problems.insert(p);
        else if (a == "--control")
        {
            if (p == "none")
                continue;
            if (!campaignControlPlanners().count(p))
                usage("unknown control planner '" + p + "' (SST, RRT, KPIECE1 or none)");
            o.control.insert(p);
        }
        else if (const PlannerEntry *e = findPlanner(p)) // any accepted spelling: "BIT*", "zastartve"
            o.planners.insert(e->name);
        else
            usage("unknown planner '" + p + "' (" + plannerNameList() + ")");
    }
}

Options parse(int argc, char **argv)
{
    Options o;
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc)
                usage("missing value after " + a);
            return argv[++i];
        };
        try
        {
            if (a == "--quick")
                o.quick = true;
            else if (a == "--no-reference")
                o.reference = false;
            else if (a == "--runs")
                o.runs = static_cast<unsigned>(std::stoul(next()));
            else if (a == "--time")
                o.time = std::stod(next());
            else if (a == "--grid")
                o.grid = std::stod(next());
            else if (a == "--own-end-time")
                o.ownEnd = std::stod(next());
            else if (a == "--seed")
                o.seed = static_cast<std::uint32_t>(std::stoul(next()));
            else if (a == "--problems" || a == "--planners" || a == "--control")
                addList(o, a, next());
            else if (!a.empty() && a[0] == '-')
                usage("unknown option " + a);
            else if (o.outdir.empty())
                o.outdir = a;
            else
                usage("more than one OUTDIR");
        }
        catch (const std::logic_error &)
        {
            usage("bad value for " + a);
        }
    }
    if (o.outdir.empty())
        usage("OUTDIR missing");
    if (o.runs == 0)
        o.runs = o.quick ? 5 : 20;
    if (!(o.time > 0))
        o.time = o.quick ? 2.0 : 10.0;
    return o;
}

/// True when the options select the problem (by name, by its set, or "all"; the classic set by default).
bool selected(const Options &o, const CampaignProblem &p)
{
    if (o.problems.empty())
        return p.set == "classic";
    return o.problems.count("all") || o.problems.count(p.name) || o.problems.count(p.set);
}

std::string str(double v)
{
    std::ostringstream os;
    os << std::setprecision(10) << v;
    return os.str();
}

/// Sets a declared parameter of a planner (OMPL's ParamSet); a refused value ends the campaign.
void setParameter(ob::Planner &planner, const std::string &name, const std::string &value)
{
    if (!planner.params().setParam(name, value))
    {
        std::cerr << "glider_campaign: planner " << planner.getName() << " refuses " << name << " = " << value << "\n";
        std::exit(2);
    }
}

/// First arrival of the level-set front in the disc of radius @p r around the goal: the smallest arrival on its
/// boundary (720 points; the front enters a disc that does not hold the start through its boundary).
double discArrival(const Reachability &r, Point2 goal, double radius)
{
    double best = r.arrivalAt(goal.x, goal.y);
    for (int k = 0; k < 720; ++k)
    {
        const double a = 2.0 * M_PI * k / 720.0;
        best = std::min(best, r.arrivalAt(goal.x + radius * std::cos(a), goal.y + radius * std::sin(a)));
    }
    return best;
}

/// The optimum of one problem as a line of reference.csv (and the line printed): the level-set front (LevelSetSolver,
/// [LollaLevelSet]) at cells 4h, 2h, h (the convergence study; h = referenceCell), in open water also Zermelo
/// shooting. The reference is shooting where it exists, else the level set extrapolated to cell 0. Ice zones are
/// kept out of the front (the glider cannot surface there), an upper bound of the optimum; the same front with the
/// ice ignored is a lower bound (ice_passable). The control planners' goal is a disc (ControlSettings::goalTolerance):
/// their reference is the front's first entry into that disc, extrapolated the same way (reference_disc).
std::pair<std::string, std::string> referenceLines(const CampaignProblem &p)
{
    std::ostringstream ref, console;
    const auto ctx = makeGliderContext(p.problem);
    const Point2 goal{p.problem.goal.x, p.problem.goal.y};
    const double tolerance = resolveControlSettings(p.problem, *ctx, ControlSettings()).goalTolerance;
    const double inf = std::numeric_limits<double>::infinity();
    double ls[3] = {0, 0, 0}, disc[3] = {0, 0, 0}, lsSeconds = 0.0, passable = std::numeric_limits<double>::quiet_NaN();
    const double hs[3] = {4.0 * p.referenceCell, 2.0 * p.referenceCell, p.referenceCell};
    for (int k = 0; k < 3; ++k)
    {
        LevelSetParams lp;
        lp.cellSize = hs[k];
        const Reachability r = LevelSetSolver(ctx, lp).solve(p.problem.start.x, p.problem.start.y, p.problem.t0,
                                                             p.problem.t0 + p.problem.horizon, goal);
        ls[k] = r.goalReached ? r.goalTime - p.problem.t0 : inf;
        disc[k] = discArrival(r, goal, tolerance) - p.problem.t0;
        lsSeconds = r.stats.seconds;
        if (k == 2 && p.name == "ice")
        {
            lp.iceForbidden = false;
            const Reachability q = LevelSetSolver(ctx, lp).solve(p.problem.start.x, p.problem.start.y, p.problem.t0,
                                                                 p.problem.t0 + p.problem.horizon, goal);
            passable = q.goalReached ? q.goalTime - p.problem.t0 : inf;
        }
    }
    double shooting = std::numeric_limits<double>::quiet_NaN();
    if (p.shooting && !p.environment)
    {
        ZermeloParams zp;
        zp.speed = p.problem.travel.speed;
        zp.maxTime = p.problem.horizon;
        const ZermeloSolution s =
            ZermeloReference(p.problem.field, zp)
                .solve(p.problem.start.x, p.problem.start.y, p.problem.goal.x, p.problem.goal.y, p.problem.t0);
        if (s.found)
            shooting = s.travelTime;
    }
    // The front converges to first order in the cell size (halving the cell halves the gap to the shooting
    // optimum in open water), so the reference is the Richardson extrapolation 2 T(h) - T(2h).
    const double extrapolated = 2.0 * ls[2] - ls[1], discExtrapolated = 2.0 * disc[2] - disc[1];
    const bool shot = std::isfinite(shooting);
    const double best = shot ? shooting : extrapolated;
    ref << p.name << "," << std::setprecision(10) << best << "," << (std::isfinite(best) ? 1 : 0) << ","
        << (shot ? "shooting" : "level set extrapolated") << "," << hs[0] << "/" << hs[1] << "/" << hs[2] << ","
        << ls[0] << "," << ls[1] << "," << ls[2] << "," << extrapolated << "," << lsSeconds << "," << shooting << ","
        << passable << "," << tolerance << "," << discExtrapolated << "\n";
    console << "optimum " << p.name << ": " << std::setprecision(6) << best
            << (shot ? " (shooting)" : " (level set extrapolated)") << "; level set cells " << hs[0] << " / " << hs[1]
            << " / " << hs[2] << ": " << ls[0] << " / " << ls[1] << " / " << ls[2] << ", extrapolated " << extrapolated
            << " (" << lsSeconds << " s at " << hs[2] << "); first entry into the goal disc of " << tolerance << ": "
            << discExtrapolated
            << (std::isfinite(passable) ? "; with the ice passable " + std::to_string(passable) : "");
    return {ref.str(), console.str()};
}

/// Records a finished run of a registry planner (see the file's documentation).
void recordGeometricRun(const ob::PlannerPtr &planner, ot::Benchmark::RunProperties &run, const GliderContext &ctx,
                        const ob::SpaceInformationPtr &si, const GliderProblem &pr)
{
    // counters first: the re-simulation below calls the travel-time code too
    run["CFC INTEGER"] = std::to_string(ctx.travel->costFunctionCalls());
    run["CMC INTEGER"] = std::to_string(ctx.field->callCount());
    if (const auto *z = dynamic_cast<const ZAStarTVE *>(planner.get()))
    {
        // the lattice search alone ([EichhornRAS] Table 4) and the smoothing + refinement after it
        run["search CFC INTEGER"] = std::to_string(z->getCostFunctionCalls());
        run["postprocess CFC INTEGER"] = std::to_string(z->getPostprocessCostFunctionCalls());
        if (std::isfinite(z->getTravelTime()))
            run["lattice travel time REAL"] = str(z->getTravelTime());
    }
    const ob::ProblemDefinitionPtr pdef = planner->getProblemDefinition();
    if (!pdef || !pdef->hasSolution())
        return;
    const bool exact = !pdef->hasApproximateSolution();
    auto path = std::dynamic_pointer_cast<og::PathGeometric>(pdef->getSolutionPath());
    if (!path || path->getStateCount() == 0)
        return;
    const auto *last = path->getStates().back()->as<TimeSE2StateSpace::StateType>();
    const bool atGoal = std::hypot(last->getX() - pr.goal.x, last->getY() - pr.goal.y) <= pr.goalTolerance;
    PathResimulation r = resimulatePath(ctx, *path, pr.t0);
    if (const HeadingRoute *route = pipelineView(*planner).lastHeadingRoute())
    {
        // a route of held headings (Isochrone, LevelSet in strong currents): re-flown as headings, accurately
        ReflightSettings rs;
        rs.speed = ctx.speed();
        rs.depth = ctx.travel->params().depth;
        const HeadingReflight f = reflyHeadingRoute(*route, *ctx.field, ctx.environment.get(), rs);
        r.finite = f.ok && !f.grounded;
        r.valid = r.finite && std::hypot(f.end.x - pr.goal.x, f.end.y - pr.goal.y) <= pr.goalTolerance;
        r.travelTime = f.end.t - pr.t0;
        run["heading route BOOLEAN"] = "1";
    }
    const bool reached = exact && atGoal;
    run["reached goal BOOLEAN"] = reached ? "1" : "0";
    run["plan valid BOOLEAN"] = (reached && r.valid) ? "1" : "0";
    if (reached && r.finite)
        run["travel time REAL"] = str(r.travelTime);
    if (reached && r.valid)
        run["best cost REAL"] = str(r.travelTime);
    run["planner travel time REAL"] = str(last->getTime() - pr.t0);
    run["waypoints INTEGER"] = std::to_string(path->getStateCount());
    bool motions = true;
    for (std::size_t i = 0; i + 1 < path->getStateCount() && motions; ++i)
        motions = si->checkMotion(path->getState(i), path->getState(i + 1));
    run["path motions valid BOOLEAN"] = motions ? "1" : "0";
    if (!r.valid && reached)
        OMPL_WARN("%s: re-simulated path invalid at leg %d: %s", planner->getName().c_str(), r.firstBadLeg,
                  r.reason.c_str());
}

/// The benchmark of the registry planners of one problem (its own list, else the campaign's) into
/// OUTDIR/<problem>.log; null when no planner is selected.
std::unique_ptr<BuiltBenchmark> buildRegistryBenchmark(const Options &opt, const CampaignProblem &p)
{
    std::shared_ptr<GliderContext> ctx;
    og::SimpleSetupPtr ss = makeSimpleSetup(p.problem, &ctx);
    ss->setup();
    const ob::SpaceInformationPtr si = ss->getSpaceInformation();

    auto built = std::make_unique<BuiltBenchmark>();
    built->setup = ss;
    built->benchmark = std::make_unique<ot::Benchmark>(*ss, "glider " + p.name);
    ot::Benchmark &b = *built->benchmark;
    b.addExperimentParameter("problem", "VARCHAR(64)", p.name);
    b.addExperimentParameter("description", "VARCHAR(256)", p.description);
    b.addExperimentParameter("field", "VARCHAR(64)", p.problem.field->name());
    b.addExperimentParameter("speed", "REAL", str(p.problem.travel.speed));
    b.addExperimentParameter("grid_size", "REAL", str(opt.grid));
    b.addExperimentParameter("sectors", "INTEGER", "3");
    b.addExperimentParameter("t0", "REAL", str(p.problem.t0));
    b.addExperimentParameter("horizon", "REAL", str(p.problem.horizon));
    b.addExperimentParameter("start_x", "REAL", str(p.problem.start.x));
    b.addExperimentParameter("start_y", "REAL", str(p.problem.start.y));
    b.addExperimentParameter("goal_x", "REAL", str(p.problem.goal.x));
    b.addExperimentParameter("goal_y", "REAL", str(p.problem.goal.y));
    b.addExperimentParameter("regions", "INTEGER", std::to_string(p.environment ? p.environment->size() : 0));
    b.addExperimentParameter("campaign_seed", "INTEGER", std::to_string(opt.seed));

    std::size_t nPlanners = 0;
    bool allOwnEnd = true; // every planner runs to its own end (lattice, level set, heading planners)
    // BIT* (OMPL names it kBITstar) draws goal states up to PositionGoal::maxSampleCount() in its setup: finite
    // (the valid goal times).
    for (const std::string &name : p.planners.empty() ? kCampaignPlanners : p.planners)
    {
        const PlannerEntry *entry = findPlanner(name);
        if (!entry)
        {
            std::cout << "note: planner '" << name << "' is not in the registry; skipped on " << p.name << std::endl;
            continue;
        }
        if (!opt.planners.empty() && !opt.planners.count(entry->name))
            continue;
        const ob::PlannerPtr planner = entry->make(si, ctx);
        if (entry->lattice())
        {
            setParameter(*planner, "grid_size", str(opt.grid));
            setParameter(*planner, "sectors", "3");
        }
        b.addPlanner(planner);
        ++nPlanners;
        allOwnEnd = allOwnEnd && entry->runsToItsEnd();
    }
    if (nPlanners == 0)
        return nullptr;
    // A problem with its own list of planners that all run to their own end (the strong set) gets --own-end-time:
    // --time is the budget of the sampling and control planners, and would cut LevelSet short. The classic set's
    // mixed list keeps --time for everyone, as before.
    const double limit = (!p.planners.empty() && allOwnEnd) ? std::max(opt.time, opt.ownEnd) : opt.time;

    b.setPreRunEvent([ctx](const ob::PlannerPtr &) {
        ctx->field->resetCallCount();
        ctx->travel->resetCostFunctionCalls();
    });
    b.setPostRunEvent([ctx, si, pr = p.problem](const ob::PlannerPtr &planner, ot::Benchmark::RunProperties &run) {
        recordGeometricRun(planner, run, *ctx, si, pr);
    });

    built->request = ot::Benchmark::Request(limit, 4096.0, opt.runs, 0.1, false, false, false);
    built->banner = "problem " + p.name + ": " + std::to_string(opt.runs) + " runs x " + std::to_string(nPlanners) +
                    " planners, at most " + str(limit) + " s each";
    built->log = opt.outdir + "/" + p.name + ".log";
    return built;
}

/// The campaign in one process, as it has always run: the references, then each benchmark in turn.
void runHere(const Options &opt, const std::vector<CampaignProblem> &problems)
{
    if (opt.reference)
    {
        std::ofstream ref(opt.outdir + "/reference.csv");
        ref << kReferenceHeader;
        for (const CampaignProblem &p : problems)
        {
            const auto lines = referenceLines(p);
            ref << lines.first;
            std::cout << lines.second << std::endl;
        }
    }
    for (const CampaignProblem &p : problems)
    {
        if (auto b = buildRegistryBenchmark(opt, p))
            runBenchmark(*b);
        if (p.control && !opt.control.empty())
            if (auto b = buildControlBenchmark(p, opt.control, opt.runs, opt.time, opt.seed, opt.outdir))
                runBenchmark(*b);
    }
}

/// The campaign spread over the processes of a job (CampaignSpread.h): the references (one task per problem),
/// then every (benchmark, planner, run); rank 0 writes reference.csv and the logs once everything succeeded.
void runSpread(TaskSpreader &spread, const Options &opt, const std::vector<CampaignProblem> &problems)
{
    const std::vector<std::string> refs =
        spread.run("reference problem", opt.reference ? problems.size() : 0, [&](std::size_t i) {
            const auto lines = referenceLines(problems[i]);
            ByteWriter w;
            w.put(lines.first);
            w.put(lines.second);
            return w.take();
        });
    std::vector<campaign_spread::Maker> makers;
    for (const CampaignProblem &p : problems)
    {
        makers.push_back([&opt, &p] { return buildRegistryBenchmark(opt, p); });
        if (p.control && !opt.control.empty())
            makers.push_back(
                [&opt, &p] { return buildControlBenchmark(p, opt.control, opt.runs, opt.time, opt.seed, opt.outdir); });
    }
    std::string csv = kReferenceHeader;
    for (const std::string &r : refs)
    {
        ByteReader in(r);
        const std::string line = in.value<std::string>(), console = in.value<std::string>();
        csv += line;
        if (spread.rank() == 0)
            std::cout << console << std::endl;
    }
    campaign_spread::spreadBenchmarks(spread, makers);
    if (spread.rank() == 0 && opt.reference)
    {
        const std::string part = opt.outdir + "/reference.csv.part";
        std::ofstream(part) << csv;
        std::rename(part.c_str(), (opt.outdir + "/reference.csv").c_str());
    }
}
} // namespace

int main(int argc, char **argv)
{
#if OMPL_GLIDER_WITH_MPI
    // started by mpirun or srun: the runs are spread over the ranks (finalised when main returns)
    const MpiLaunchScope mpi(argc, argv);
#endif
    const Options opt = parse(argc, argv);
    ompl::RNG::setSeed(opt.seed); // before any RNG exists: fixed seeds for every planner and run
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);

    const auto field = std::make_shared<MeanderingJet>();
    std::vector<CampaignProblem> problems;
    for (const CampaignProblem &p : makeCampaignProblems(field))
        if (selected(opt, p))
            problems.push_back(p);
    for (const CampaignProblem &p : makeStrongCurrentProblems())
        if (selected(opt, p))
            problems.push_back(p);
    for (const std::string &name : opt.problems) // a misspelt name must not be dropped in silence
    {
        bool known = name == "all";
        for (const auto &list : {makeCampaignProblems(field), makeStrongCurrentProblems()})
            for (const CampaignProblem &p : list)
                known = known || name == p.name || name == p.set;
        if (!known)
            usage("unknown problem '" + name + "' in --problems");
    }
    if (problems.empty())
        usage("no problem selected");
    {
        std::error_code ec; // the logs go into OUTDIR: made here, or refused before any run
        std::filesystem::create_directories(opt.outdir, ec);
        if (ec || !std::filesystem::is_directory(opt.outdir))
            usage("cannot make the output directory '" + opt.outdir + "': " + (ec ? ec.message() : "a file is there"));
    }
    int status = 0;
    std::string failure;
    TaskSpreader *spread = activeTaskSpreader(); // an MPI job of several ranks, or null
    try
    {
        if (spread)
            runSpread(*spread, opt, problems);
        else
            runHere(opt, problems);
    }
    catch (const std::exception &e)
    {
        if (!spread || spread->rank() == 0)
            std::cerr << "\nglider_campaign: " << e.what() << (spread ? "; no log written\n" : "\n");
        failure = e.what();
        status = 1;
    }
#if OMPL_GLIDER_WITH_MPI
    // a rank that failed alone must not leave the others waiting for it (MpiTaskSpreader::endJob())
    return mpi.end(status, failure);
#else
    return status;
#endif
}
