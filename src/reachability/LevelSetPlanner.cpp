#include "ompl_glider/reachability/LevelSetPlanner.h"
#include "../io/NumberText.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <ompl/base/goals/GoalRegion.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ResourceLimits.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/execution/Reflight.h"
#include "ompl_glider/routes/HeadingRefiner.h"
#include "ompl_glider/planners/IsochroneSearch.h"
#include "ompl_glider/routes/CurveLegs.h"
#include "ompl_glider/routes/PathSmoother.h"
#include "LevelSetInternal.h"

namespace ompl_glider
{
namespace
{
using TimeState = TimeSE2StateSpace::StateType;

/// The steering directions along a backtracked level-set path: the path followed by held headings piece
/// by piece (targets about @p spacing apart; where a piece cannot be flown, e.g. where the backtrack broke off near
/// the start, an isochrone search from where the glider stopped links it to the goal: followWithRestarts()), then
/// refined whole by direct shooting where that is faster and still valid. When the path cannot be followed, the
/// steering directions themselves (the bearing of the velocity through the water, (p1 - p0) / dt - c, between
/// backtracked points) are refined instead.
RefinedHeadings levelSetHeadings(const GliderContext &ctx, const std::vector<TimedPoint> &path, Point2 goal,
                                 double tolerance, double tEnd, double spacing, unsigned threads,
                                 const ompl::base::PlannerTerminationCondition &ptc)
{
    RefinedHeadings none;
    if (path.size() < 2)
    {
        none.why = "the backtracked path has fewer than two points";
        return none;
    }
    const double depth = ctx.travel->params().depth;
    HeadingRefineSettings s;
    s.depth = depth;
    s.radius = std::max(tolerance, 1e-12);
    s.tEnd = tEnd;
    s.threads = threads;
    s.step = headingCheckStep(path.back().t - path.front().t, ctx);
    ThreadPool pool(threads);
    RefinedHeadings tracked =
        followWithRestarts(path, nullptr, goal, ctx, s, spacing, makeIsochroneSetup(ctx, goal, s.radius), pool, ptc);
    s.step = 0.0;
    HeadingRoute route;
    if (tracked.ok)
        route = tracked.route;
    else
    {
        route.start = {path.front().x, path.front().y};
        route.departure = path.front().t;
        for (std::size_t i = 0; i + 1 < path.size(); ++i)
        {
            const TimedPoint &a = path[i], &b = path[i + 1];
            const double dt = b.t - a.t;
            if (!(dt > 0.0))
                continue;
            const Velocity c = ctx.field->velocity(0.5 * (a.x + b.x), 0.5 * (a.y + b.y), depth, 0.5 * (a.t + b.t));
            route.segments.push_back({bearingOf((b.x - a.x) / dt - c.u, (b.y - a.y) / dt - c.v), dt});
        }
    }
    s.segments = static_cast<unsigned>(std::clamp<std::size_t>(route.segments.size(), 16, 64));
    RefinedHeadings refined = refineHeadingRoute(route, goal, ctx, s);
    if (tracked.ok && (!refined.ok || refined.flight.arrivalTime > tracked.flight.arrivalTime))
        return tracked;
    if (!refined.ok && !tracked.ok)
        refined.why = tracked.why + "; " + refined.why;
    return refined;
}
} // namespace

namespace
{
/// The work of a front from @p departure to @p until on cells of @p h with a step of @p cfl cells (the automatic
/// one's shortest when 0: kForbiddenCfl, near a forbidden set, gives the most steps).
ReachWork frontWork(const GliderContext &ctx, const Region &r, double h, double cfl, double departure, double until)
{
    ReachWork w;
    w.cell = h;
    w.nodes = (std::floor((r.xMax - r.xMin) / h + 1e-9) + 1.0) * (std::floor((r.yMax - r.yMin) / h + 1e-9) + 1.0);
    w.dt = (cfl > 0.0 ? cfl : levelset_detail::kForbiddenCfl) * h / (ctx.speed() + std::max(ctx.maxCurrent(), 0.0));
    w.steps = std::isfinite(until) ? std::ceil(std::max(until - departure, 0.0) / w.dt)
                                   : std::numeric_limits<double>::infinity();
    w.bytesPerNode = 3.0 * sizeof(double); // arrival, level set and its update
    return w;
}
} // namespace

std::optional<ReachWork> LevelSetPlanner::reachWork(const PipelineSetup &setup, const ReachRequest &request) const
{
    const double h = request.cellSize > 0.0 ? request.cellSize : request.cellScale * defaultLevelSetResolution(*ctx_);
    const double until =
        std::isnan(request.until) ? (request.times.empty() ? setup.departure : request.times.back()) : request.until;
    return frontWork(*ctx_, setup.region, h, 0.0, setup.departure, until); // (reachableSet()'s step is automatic)
}

void LevelSetPlanner::prepare(const PipelineSetup &setup)
{
    const Region &r = setup.region;
    const double tEnd = std::min(r.tMax, ctx_->field->timeEnd());
    const ReachWork w = frontWork(*ctx_, r, resolution_ > 0.0 ? resolution_ : defaultLevelSetResolution(*ctx_),
                                  params_.cfl, setup.departure, tEnd);
    const double h = w.cell, nodes = w.nodes, dt = w.dt, steps = w.steps, work = w.work();
    const double cfl = params_.cfl > 0.0 ? params_.cfl : levelset_detail::kForbiddenCfl;
    if (steps <= kMaxLevelSetSteps && work <= kMaxLevelSetWork)
        return;
    // the steps the glider's own speed needs: within the limits, the currents are at fault (a forecast's velocities
    // read wrong: units, scale_factor, a fill value not declared), not the planner's settings
    const double calmSteps = std::isfinite(tEnd) && ctx_->speed() > 0.0
                                 ? std::ceil(std::max(tEnd - setup.departure, 0.0) / (cfl * h / ctx_->speed()))
                                 : std::numeric_limits<double>::infinity();
    if (calmSteps <= kMaxLevelSetSteps && nodes * calmSteps <= kMaxLevelSetWork && ctx_->maxCurrent() > ctx_->speed())
        throw Error(setup.where("current") +
                    text::formatted(": the currents reach %.3g (%.3g times the vehicle's speed of %.3g): the level "
                                    "set would take up to %.3g time steps",
                                    ctx_->maxCurrent(), ctx_->maxCurrent() / ctx_->speed(), ctx_->speed(), steps) +
                    text::formatted(", more than the limit of %.3g steps and %.3g node updates; check the current's "
                                    "velocities (their units, scale_factor, fill values)",
                                    kMaxLevelSetSteps, kMaxLevelSetWork));
    // too many steps: the window is at fault first; too much work: the resolution
    const std::string where =
        !(steps <= kMaxLevelSetSteps) && setup.isGiven("planner.horizon")
            ? setup.where("planner.horizon")
            : setup.placeOfFirstGiven({"planner.parameters.resolution", "planner.parameters.cfl", "planner.horizon"},
                                      "planner.name");
    throw Error(where +
                text::formatted(": the level set would take up to %.3g time steps of %.3g over the planning window "
                                "of %.4g, on %.4g grid nodes (%.3g node updates)",
                                steps, dt, tEnd - setup.departure, nodes, work) +
                text::formatted(", more than the limit of %.3g steps and %.3g node updates: use a coarser "
                                "resolution, a larger cfl or a shorter planner.horizon",
                                kMaxLevelSetSteps, kMaxLevelSetWork));
}

NoPath LevelSetPlanner::noPathReason(const ompl::base::PlannerStatus &status, double) const
{
    NoPath n;
    if (status != ompl::base::PlannerStatus::ABORT)
        return n;
    if (last_.goalReached)
    {
        n.cause = NoPathCause::NotFlyable;
        n.what = reason_;
    }
    else if (last_.goalWalledOff)
    {
        n.cause = NoPathCause::WalledOff;
        n.what = "the reachable front never reaches the goal: no water links it to the start (land or forbidden "
                 "regions wall it in; a flood fill of the level set's grid, before any step)";
    }
    else
    {
        n.cause = NoPathCause::Unreachable;
        n.what = "the reachable front never reaches the goal within the time window (the current carries the glider "
                 "off faster than it makes way, or land, forbidden regions or a closure wall it in)";
    }
    return n;
}

LevelSetPlanner::LevelSetPlanner(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx)
    : ompl::base::Planner(si, "LevelSet"), ctx_(std::move(ctx))
{
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error("LevelSet: the problem context is null or has no field");
    specs_.approximateSolutions = false;
    specs_.optimizingPaths = true;
    specs_.multithreaded = true;
    declareParam<double>("resolution", this, &LevelSetPlanner::setResolution, &LevelSetPlanner::getResolution,
                         "0:0.001:1000000");
    declareParam<double>("cfl", this, &LevelSetPlanner::setCfl, &LevelSetPlanner::getCfl, "0.1:0.1:8");
    declareParam<unsigned>("threads", this, &LevelSetPlanner::setThreads, &LevelSetPlanner::getThreads, "0:1:64");
    addPlannerProgressProperty("level set time REAL", [this] { return std::to_string(levelSetTime_); });
    addPlannerProgressProperty("resolution REAL", [this] { return std::to_string(usedResolution_); });
}

LevelSetPlanner::~LevelSetPlanner() = default;

void LevelSetPlanner::setResolution(double h)
{
    if (!(h >= 0.0) || !std::isfinite(h))
        throw Error("LevelSet: resolution must be >= 0 (0: automatic), got " + text::number(h));
    resolution_ = h;
}

void LevelSetPlanner::setCfl(double c)
{
    if (!(c > 0.0 && c <= 8.0))
        throw Error("LevelSet: cfl must be in (0, 8], got " + text::number(c));
    params_.cfl = c;
}

void LevelSetPlanner::clear()
{
    Planner::clear();
    last_ = Reachability();
    waypoints_.clear();
    headings_ = HeadingRoute();
    reason_.clear();
    levelSetTime_ = 0.0;
}

ompl::base::PlannerStatus LevelSetPlanner::solve(const ompl::base::PlannerTerminationCondition &ptc)
{
    checkValidity();
    ompl::base::PlannerStatus status;
    const std::optional<StartAndGoal> sg = startAndGoal(*pdef_, getName(), status);
    if (!sg)
        return status;
    const double sx = sg->sx, sy = sg->sy, t0 = sg->t0, gx = sg->goal.x, gy = sg->goal.y;
    const Region &r = ctx_->region;
    const auto inRegion = [&](double x, double y) { return x >= r.xMin && x <= r.xMax && y >= r.yMin && y <= r.yMax; };
    if (!inRegion(sx, sy))
        return ompl::base::PlannerStatus::INVALID_START;
    if (!inRegion(gx, gy))
        return ompl::base::PlannerStatus::INVALID_GOAL;

    LevelSetParams p = params_;
    p.cellSize = resolution_ > 0.0 ? resolution_ : defaultLevelSetResolution(*ctx_);
    usedResolution_ = p.cellSize;
    p.clearance = 0.5 * p.cellSize; // the legs between backtracked points must clear the forbidden regions
    const LevelSetSolver solver(ctx_, p);
    const double tEnd = std::min(r.tMax, ctx_->field->timeEnd());
    headings_ = HeadingRoute();
    reason_.clear();
    last_ = solver.solve(sx, sy, t0, tEnd, Point2{gx, gy}, true, [&ptc] { return ptc(); });
    waypoints_.clear();
    if (!last_.goalReached)
    {
        levelSetTime_ = std::numeric_limits<double>::infinity();
        if (ptc())
            return ompl::base::PlannerStatus::TIMEOUT;
        OMPL_INFORM("%s: the front never reaches the goal before the end of the time window (%llu steps)",
                    getName().c_str(), static_cast<unsigned long long>(last_.stats.steps));
        return ompl::base::PlannerStatus::ABORT;
    }
    levelSetTime_ = last_.goalTime - t0;
    std::string why;
    waypoints_ = legsAlongCurve(*ctx_, last_.path, p.cellSize / 3.0, &why);
    if (!waypoints_.empty())
    {
        // the legs must also fly when timed accurately (near-stalls that the travel-time code's tolerance passes)
        ReflightSettings rs;
        rs.speed = ctx_->speed();
        rs.depth = ctx_->travel->params().depth;
        rs.keepSlowLegs = true;
        const PathReflight check = reflyPath(waypoints_, *ctx_->field, ctx_->environment.get(), rs);
        if (!check.feasible)
        {
            why = "re-flown accurately, " + check.why;
            waypoints_.clear();
        }
    }
    if (waypoints_.empty())
    {
        // no straight legs: the steering directions along the backtracked path, as held headings
        OMPL_INFORM("%s: the backtracked path cannot be flown as straight legs (resolution %g): %s; flying its "
                    "headings",
                    getName().c_str(), p.cellSize, why.c_str());
        const auto *goal = pdef_->getGoal()->as<ompl::base::GoalRegion>();
        const RefinedHeadings h = levelSetHeadings(*ctx_, last_.path, Point2{gx, gy}, goal->getThreshold(), tEnd,
                                                   4.0 * p.cellSize, params_.threads, ptc);
        if (!h.ok)
        {
            reason_ = "the level set reached the goal, but neither straight legs nor its headings could be flown to "
                      "it: " +
                      why + "; " + h.why;
            return ompl::base::PlannerStatus::ABORT;
        }
        headings_ = h.route;
        waypoints_ = h.flight.ends;
    }
    auto path = std::make_shared<ompl::geometric::PathGeometric>(si_);
    waypointsToPath(waypoints_, *path);
    const double cost = waypoints_.back().t - t0;
    ompl::base::PlannerSolution sol(path);
    sol.setPlannerName(getName());
    if (pdef_->getOptimizationObjective())
        sol.setOptimized(pdef_->getOptimizationObjective(), ompl::base::Cost(cost), true);
    pdef_->addSolutionPath(sol);
    return ompl::base::PlannerStatus::EXACT_SOLUTION;
}

std::optional<ReachableSet> LevelSetPlanner::reachableSet(const PipelineSetup &setup, const ReachRequest &request) const
{
    LevelSetParams lp;
    lp.cellSize = request.cellSize > 0.0 ? request.cellSize : request.cellScale * defaultLevelSetResolution(*ctx_);
    lp.threads = request.threads;
    const LevelSetSolver solver(ctx_, lp);
    const double until =
        std::isnan(request.until) ? (request.times.empty() ? setup.departure : request.times.back()) : request.until;
    bool stopped = false;
    const std::function<bool()> stop = [&request, &stopped] { return stopped = stopped || request.stop(); };
    const Reachability r = solver.solve(setup.start.x, setup.start.y, setup.departure, until, request.goal, false,
                                        request.stop ? stop : std::function<bool()>());
    ReachableSet out;
    out.resolution = lp.cellSize;
    out.seconds = r.stats.seconds;
    out.x0 = r.x0;
    out.y0 = r.y0;
    out.h = r.h;
    out.nx = r.nx;
    out.ny = r.ny;
    out.arrival = r.arrival;
    out.goalReached = r.goalReached;
    out.goalTime = r.goalTime;
    out.stopped = stopped;
    for (const double t : request.times)
        out.lines.push_back(r.isochrone(t));
    return out;
}

std::optional<std::vector<std::vector<std::vector<Point2>>>> LevelSetPlanner::isochronesOf(
    const ReachableSet &grid, const std::vector<double> &times) const
{
    Reachability r; // the field as a solve's, drawn by the one marching squares
    r.x0 = grid.x0;
    r.y0 = grid.y0;
    r.h = grid.h;
    r.nx = grid.nx;
    r.ny = grid.ny;
    r.arrival = grid.arrival;
    if (r.arrival.size() != static_cast<std::size_t>(r.nx) * static_cast<std::size_t>(std::max(r.ny, 0)))
        throw Error("LevelSet: an arrival field of " + std::to_string(r.arrival.size()) + " values on a grid of " +
                    std::to_string(r.nx) + " x " + std::to_string(r.ny) + " nodes");
    std::vector<std::vector<std::vector<Point2>>> out;
    for (const double t : times)
        out.push_back(r.isochrone(t));
    return out;
}

std::optional<FirstArrival> LevelSetPlanner::firstArrival(const PipelineSetup &setup, double tEnd,
                                                          std::uint64_t maxWork,
                                                          const std::function<bool()> &stop) const
{
    LevelSetParams p;
    p.cellSize = defaultLevelSetResolution(*ctx_);
    p.clearance = 0.5 * p.cellSize;
    p.maxNodeUpdates = maxWork;
    const Reachability r =
        LevelSetSolver(ctx_, p).solve(setup.start.x, setup.start.y, setup.departure, tEnd, setup.goal, true, stop);
    FirstArrival out;
    out.reached = r.goalReached;
    out.time = r.goalTime;
    out.path = r.path;
    out.work = r.stats.nodeUpdates;
    out.budgetSpent = r.stats.budgetSpent;
    return out;
}
} // namespace ompl_glider
