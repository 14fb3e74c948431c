// The isochrone heading planner (see IsochronePlanner.h).
#include "ompl_glider/planners/IsochronePlanner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <ompl/base/goals/GoalRegion.h>
#include <ompl/geometric/PathGeometric.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/execution/Dive.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/routes/HeadingRefiner.h"
#include "ompl_glider/planners/IsochroneSearch.h"
#include "ompl_glider/routes/PathSmoother.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{

/// Closes the route on the goal: the search's points followed by held headings (searching again from where following
/// stops, followWithRestarts()), and the search's own route shot whole in N segments; the faster valid one.
bool closeOnGoal(const IsochroneSetup &setup, const IsochroneSearch &search, Point2 goal, HeadingRefineSettings rs,
                 ThreadPool &pool, const ompl::base::PlannerTerminationCondition &ptc, HeadingRoute &route,
                 std::string &why)
{
    const GliderContext &ctx = *setup.ctx;
    const HeadingRoute coarse = searchRoute(search);
    const RefinedHeadings shot = refineHeadingRoute(coarse, goal, ctx, rs);
    // one check step for every piece followed (new searches included), so that the pieces join as one route
    rs.step = headingCheckStep(coarse.duration(), ctx);
    std::vector<double> bearings;
    const std::vector<TimedPoint> chain = searchChain(search, goal, bearings);
    // new searches only where shooting failed too
    const RefinedHeadings followed =
        followWithRestarts(chain, &bearings, goal, ctx, rs, 0.0, setup, pool, ptc, shot.ok ? 0 : 4);
    if (!followed.ok && !shot.ok)
    {
        why = followed.why + "; " + shot.why;
        return false;
    }
    const bool useShot = shot.ok && (!followed.ok || shot.flight.arrivalTime <= followed.flight.arrivalTime);
    route = useShot ? shot.route : followed.route;
    OMPL_DEBUG("Isochrone: refinement: %u flights, %u segments, search %g -> shot %g, followed %g", shot.flights,
               rs.segments, coarse.duration(), shot.ok ? shot.route.duration() : kInf,
               followed.ok ? followed.route.duration() : kInf);
    return true;
}
} // namespace

IsochronePlanner::IsochronePlanner(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx)
    : ompl::base::Planner(si, "Isochrone"), ctx_(std::move(ctx))
{
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error("Isochrone: the problem context is null or has no field");
    specs_.approximateSolutions = false;
    specs_.optimizingPaths = true;
    specs_.multithreaded = true;
    declareParam<double>("resolution", this, &IsochronePlanner::setResolution, &IsochronePlanner::getResolution,
                         "0:0.001:1000000");
    declareParam<unsigned>("headings", this, &IsochronePlanner::setHeadings, &IsochronePlanner::getHeadings, "8:1:720");
    declareParam<double>("time_step", this, &IsochronePlanner::setTimeStep, &IsochronePlanner::getTimeStep,
                         "0:0.001:1000000");
    declareParam<unsigned>("segments", this, &IsochronePlanner::setSegments, &IsochronePlanner::getSegments,
                           "0:1:1000");
    declareParam<bool>("shooting", this, &IsochronePlanner::setRefine, &IsochronePlanner::getRefine, "0,1");
    declareParam<unsigned>("threads", this, &IsochronePlanner::setThreads, &IsochronePlanner::getThreads, "0:1:64");
}

IsochronePlanner::~IsochronePlanner() = default;

void IsochronePlanner::setResolution(double h)
{
    if (!(h >= 0.0) || !std::isfinite(h))
        throw Error("Isochrone: resolution must be >= 0 (0: automatic), got " + std::to_string(h));
    resolution_ = h;
}
void IsochronePlanner::setHeadings(unsigned k)
{
    if (k < 8 || k > 720)
        throw Error("Isochrone: headings must be in 8..720, got " + std::to_string(k));
    headings_ = k;
}
void IsochronePlanner::setTimeStep(double dt)
{
    if (!(dt >= 0.0) || !std::isfinite(dt))
        throw Error("Isochrone: time_step must be >= 0 (0: automatic), got " + std::to_string(dt));
    timeStep_ = dt;
}
void IsochronePlanner::setSegments(unsigned n)
{
    if (n > 1000)
        throw Error("Isochrone: segments must be in 0..1000 (0: automatic), got " + std::to_string(n));
    segments_ = n;
}
void IsochronePlanner::setThreads(unsigned n)
{
    if (n > 64)
        throw Error("Isochrone: threads must be in 0..64 (0: all cores), got " + std::to_string(n));
    threads_ = n;
}

void IsochronePlanner::clear()
{
    Planner::clear();
    route_ = HeadingRoute();
    reason_.clear();
    reasonCause_ = NoPathCause::None;
    expanded_ = 0;
    searchTime_ = kInf;
}

ompl::base::PlannerStatus IsochronePlanner::solve(const ompl::base::PlannerTerminationCondition &ptc)
{
    checkValidity();
    route_ = HeadingRoute();
    reason_.clear();
    reasonCause_ = NoPathCause::None;
    expanded_ = 0;
    searchTime_ = kInf;
    ompl::base::PlannerStatus status;
    const std::optional<StartAndGoal> sg = startAndGoal(*pdef_, getName(), status);
    if (!sg)
        return status;
    const Region &r = ctx_->region;
    const auto inRegion = [&](double x, double y) { return x >= r.xMin && x <= r.xMax && y >= r.yMin && y <= r.yMax; };
    if (!inRegion(sg->sx, sg->sy))
        return ompl::base::PlannerStatus::INVALID_START;
    if (!inRegion(sg->goal.x, sg->goal.y))
        return ompl::base::PlannerStatus::INVALID_GOAL;
    const auto *goalRegion = pdef_->getGoal()->as<ompl::base::GoalRegion>();
    const Point2 start{sg->sx, sg->sy}, goal = sg->goal;
    const double t0 = sg->t0;
    const double tolerance =
        std::max(goalRegion->getThreshold(), 1e-12 * std::hypot(goal.x - start.x, goal.y - start.y));

    const IsochroneSetup setup = makeIsochroneSetup(*ctx_, goal, tolerance, resolution_, timeStep_, headings_);
    ThreadPool pool(threads_);
    const IsochroneSearch search = searchIsochrones(setup, {start.x, start.y, t0}, pool, ptc);
    expanded_ = search.expanded;
    if (!std::isfinite(search.hit.arrival))
    {
        if (search.timedOut)
            return ompl::base::PlannerStatus::TIMEOUT;
        reason_ = search.why;
        reasonCause_ = NoPathCause::SearchEnded;
        OMPL_INFORM("%s: %s (%zu points)", getName().c_str(), reason_.c_str(), search.points.size());
        return ompl::base::PlannerStatus::ABORT;
    }
    searchTime_ = search.hit.arrival - t0;

    HeadingRefineSettings rs;
    rs.depth = setup.dive.depth;
    rs.radius = tolerance;
    rs.tEnd = setup.tEnd;
    rs.threads = threads_;
    if (refine_)
    {
        std::size_t links = 0;
        for (long k = search.hit.parent; k >= 0; k = search.points[static_cast<std::size_t>(k)].parent)
            ++links;
        rs.segments = segments_ > 0 ? segments_ : static_cast<unsigned>(std::clamp<std::size_t>(links, 16, 32));
        std::string why;
        if (!closeOnGoal(setup, search, goal, rs, pool, ptc, route_, why))
        {
            reason_ = "the route could not be closed on the goal: " + why;
            reasonCause_ = NoPathCause::NotFlyable;
            OMPL_INFORM("%s: %s", getName().c_str(), reason_.c_str());
            return ompl::base::PlannerStatus::ABORT;
        }
    }
    else
    {
        route_ = searchRoute(search);
        route_.step = setup.dive.step;
    }
    std::string why;
    const HeadingFlight flight = verifyHeadingRoute(route_, *ctx_, goal, rs, &why);
    if (!flight.reached && refine_)
    {
        reason_ = "the refined route fails its check: " + why;
        reasonCause_ = NoPathCause::NotFlyable;
        route_ = HeadingRoute();
        return ompl::base::PlannerStatus::ABORT;
    }
    auto path = std::make_shared<ompl::geometric::PathGeometric>(si_);
    waypointsToPath(flight.ends, *path);
    const double cost = flight.ends.back().t - t0;
    ompl::base::PlannerSolution sol(path);
    sol.setPlannerName(getName());
    if (pdef_->getOptimizationObjective())
        sol.setOptimized(pdef_->getOptimizationObjective(), ompl::base::Cost(cost), true);
    if (!flight.reached)
        sol.setApproximate(flight.closestDistance);
    pdef_->addSolutionPath(sol);
    return flight.reached ? ompl::base::PlannerStatus::EXACT_SOLUTION : ompl::base::PlannerStatus::APPROXIMATE_SOLUTION;
}
} // namespace ompl_glider
