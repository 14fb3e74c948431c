/// @file GlobalCheck.cpp
/// @brief The default pipeline's global check of the route class (GlobalCheck, Planning.h): extremals of Zermelo's
/// heading law shot from the start ([EichhornRAS] Eq. 2, Eq. 10), stopped where they meet land, a forbidden region or
/// the region's edge; the fastest one through the goal flown as straight legs or held headings, and the faster
/// flyable route kept. Also the admissible set of the optimal-control reference (optimumReference()).

#include <algorithm>
#include <chrono>
#include <cmath>

#include <ompl/geometric/PathGeometric.h>

#include "PlanningInternal.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/routes/HeadingRefiner.h"
#include "ompl_glider/routes/HeadingTracker.h"
#include "ompl_glider/routes/PathSmoother.h"
#include "ompl_glider/routes/WaypointRefiner.h"
#include "ompl_glider/routes/CurveLegs.h"
#include "ompl_glider/reference/ZermeloReference.h"
#include "ompl_glider/registry/PlannerRegistry.h"

namespace ompl_glider
{
namespace planning_detail
{
std::function<bool(double, double, double, double, double, double)> admissibleSet(
    const std::shared_ptr<const GliderContext> &ctx)
{
    return [ctx](double x1, double y1, double t1, double x2, double y2, double t2) {
        const Region &r = ctx->region;
        if (!(x2 >= r.xMin && x2 <= r.xMax && y2 >= r.yMin && y2 <= r.yMax))
            return false;
        if (!ctx->field->segmentInWater(x1, y1, x2, y2, ctx->travel->params().depth))
            return false;
        return !ctx->environment || ctx->environment->legFree(x1, y1, t1, x2, y2, t2);
    };
}

ZermeloParams checkedExtremalParams(const MissionProblem &problem, const std::shared_ptr<const GliderContext> &ctx,
                                    double speed, double maxTime)
{
    ZermeloParams zp;
    zp.speed = speed;
    zp.depth = ctx->travel->params().depth;
    zp.maxTime = maxTime;
    zp.admissible = admissibleSet(ctx);
    zp.threads = 0;
    // a seed for the routes flown after it, not a reference to 1e-10: half the reference's headings, looser tolerances
    zp.headingSamples = 360;
    zp.scanRelTol = 1e-5;
    zp.relTol = 1e-9;
    zp.groundSpeedBound = speed + 1.1 * ctx->maxCurrent();  // a margin for interpolation overshoot
    const Point2 s = problem.getStart(), g = problem.getGoal();
    // the miss accepted as "through the goal": far below the goal tolerance, relative to the trip in metres too
    zp.goalTolerance = std::max(1e-9, 1e-9 * std::hypot(g.x - s.x, g.y - s.y));
    return zp;
}

namespace
{
/// The relative gain below which the planner's route is kept without building the extremal's routes: the
/// refinement's own resolution.
constexpr double kCheckTolerance = 1e-3;

/// The planner's route's candidate row.
RouteCandidate plannerCandidate(const PlannedPath &r)
{
    RouteCandidate c;
    c.name = r.planner;
    c.solved = r.solved;
    c.travelTime = r.solved ? r.travelTime : kInf;
    c.why = r.solved ? std::string() : r.reason;
    return c;
}

/// The extremal's track (start first, ending on the goal) flown as straight legs: thinned within a small tolerance of
/// the curve (legsAlongCurve(): timed by the travel-time code, holds where needed), refined as the planner's path
/// is, checked as an OMPL path and re-flown accurately.
PlannedPath straightLegsAlong(const MissionProblem &problem, const std::shared_ptr<const GliderContext> &ctx,
                              const ompl::base::SpaceInformationPtr &si, const std::vector<TimedPoint> &curve,
                              PlannedPath base)
{
    const MissionSpec &m = problem.getSpec();
    PlannedPath c = std::move(base);
    std::string why;
    const double tolerance = 2e-3 * c.straightLineLength;
    std::vector<TimedPoint> legs = legsAlongCurve(*ctx, curve, tolerance, &why);
    if (legs.size() < 2)
    {
        c.solved = false;
        c.reason = "its track cannot be flown as straight legs: " + why;
        return c;
    }
    c.raw = c.smoothed = legs;
    c.rawTravelTime = c.smoothedTravelTime = legs.back().t - c.departure;
    c.rawPathLength = pathLength(legs);
    if (m.planner.refinement)
    {
        const RefinementResult rr = WaypointRefiner(ctx, refinerParams(m)).refine(legs);
        if (rr.waypoints.size() >= 2 && rr.arrivalAfter <= legs.back().t)
            legs = rr.waypoints;
        c.postprocessCostFunctionCalls = rr.costFunctionCalls;
    }
    c.path = legs;
    c.travelTime = legs.back().t - c.departure;
    c.pathLength = pathLength(legs);
    ompl::geometric::PathGeometric path(si);
    waypointsToPath(legs, path);
    c.pathChecked = path.check();
    c.solved = c.pathChecked;
    if (!c.solved)
    {
        c.reason = "its straight legs fail the path check";
        return c;
    }
    reflyRoute(problem, *ctx, c);
    return c;
}

/// The extremal flown as held headings: its own heading schedule, one segment per integrator step (the bearing at the
/// step's middle), closed on the goal by direct shooting (refineHeadingRoute() from that schedule); where that fails,
/// the track followed piece by piece (trackPathWithHeadings()). The result is checked and re-flown as every heading
/// route is.
PlannedPath headingsAlong(const MissionProblem &problem, const std::shared_ptr<const GliderContext> &ctx,
                          const std::vector<ZermeloState> &extremal, const std::vector<TimedPoint> &curve,
                          PlannedPath base)
{
    PlannedPath c = std::move(base);
    const Point2 g = problem.getGoal();
    HeadingRefineSettings s;
    s.depth = ctx->travel->params().depth;
    s.radius = problem.gliderProblem(c.departure, c.speed).goalTolerance;
    s.tEnd = std::min(ctx->region.tMax, ctx->field->timeEnd());
    constexpr double kDeg = 180.0 / 3.14159265358979323846;
    HeadingRoute schedule;
    schedule.start = {extremal.front().x, extremal.front().y};
    schedule.departure = extremal.front().t;
    for (std::size_t i = 0; i + 1 < extremal.size(); ++i)
    {
        const double dt = extremal[i + 1].t - extremal[i].t;
        if (dt > 0.0)  // heading theta from +x, counter-clockwise -> bearing clockwise from north
            schedule.segments.push_back({90.0 - 0.5 * (extremal[i].theta + extremal[i + 1].theta) * kDeg, dt});
    }
    s.segments = 64;
    RefinedHeadings h = refineHeadingRoute(schedule, g, *ctx, s);
    if (!h.ok)
    {
        s.step = headingCheckStep(curve.back().t - curve.front().t, *ctx);
        const RefinedHeadings tracked = trackPathWithHeadings(curve, g, *ctx, s, pathLength(curve) / 48.0);
        if (!tracked.ok)
        {
            c.solved = false;
            c.reason = "its headings cannot be closed on the goal (" + h.why + "), nor its track followed by held "
                       "headings (" + tracked.why + ")";
            return c;
        }
        h = tracked;
    }
    c.solved = true;
    c = headingResult(problem, *ctx, h.route, std::move(c));
    if (c.solved)
        reflyRoute(problem, *ctx, c);
    return c;
}
}  // namespace

PlannedPath checkGlobally(const MissionProblem &problem, double departure, const PlanOptions &o, PlannedPath r)
{
    const MissionSpec &m = problem.getSpec();
    // the check belongs to the post-processing: without refinement the planner's own path is what was asked for
    if (!o.globalCheck.value_or(m.planner.globalCheck) || !o.refinement.value_or(m.planner.refinement) ||
        !o.planner.empty() || !r.badInput.empty() ||
        !problem.getMembers().empty() || (r.stints && !r.stints->converted))
        return r;
    const PlannerEntry &asked = plannerEntry(r.switchedFrom.empty() ? r.planner : r.switchedFrom);
    if (!asked.lattice())
        return r;
    // a front that never reaches the goal proves that no route exists: nothing to look for; nor after a stop request
    if ((!r.solved && r.reason.rfind("no path exists", 0) == 0) || stopRequested())
        return r;
    const auto t0 = std::chrono::steady_clock::now();
    const GliderProblem gp = problem.gliderProblem(departure, r.speed);
    std::shared_ptr<GliderContext> ctx;
    const ompl::geometric::SimpleSetupPtr ss = makeSimpleSetup(gp, &ctx);
    const double fieldEnd = ctx->field->timeEnd();
    const double span = std::min(gp.horizon, std::isfinite(fieldEnd) ? fieldEnd - departure : kInf);
    // extremals followed a quarter past the planner's time: a neighbour of the extremal through the goal passes it
    // later, and the sign change between the two brackets it
    const double bound = r.solved ? std::min(1.25 * r.travelTime, span) : span;
    const std::uint64_t cmc0 = ctx->field->callCount();

    // with an arrival window every candidate is judged as it would be flown: timed into the window (a hold, a slower
    // leg) or not a route; the planner's own route first, so that a route meeting the window is never lost to a
    // faster one that cannot meet it
    const bool window = m.goalWindow.set;
    if (window)
        timeArrival(problem, r);
    GlobalCheck check;
    check.candidates.push_back(plannerCandidate(r));
    ZermeloParams zp = checkedExtremalParams(problem, ctx, r.speed, bound);
    const Point2 s = problem.getStart(), g = problem.getGoal();
    ZermeloSolution sol = ZermeloReference(ctx->field, zp).solve(s.x, s.y, g.x, g.y, departure);
    if (!sol.found)
    {
        // in strong or sensitive currents the headings that reach a far goal can lie within a fraction of a degree:
        // sweep finer before giving up (eight times where there is no route at all, else four)
        zp.headingSamples *= r.solved ? 4 : 8;
        sol = ZermeloReference(ctx->field, zp).solve(s.x, s.y, g.x, g.y, departure);
    }
    check.headings = static_cast<unsigned>(zp.headingSamples);
    const ZermeloReference ref(ctx->field, zp);
    check.extremalFound = sol.found;
    check.extremalTime = sol.found ? sol.travelTime : kInf;
    PlannedPath best = std::move(r);
    const double planned = best.solved ? best.travelTime : kInf;
    if (sol.found && sol.travelTime < planned * (1.0 - kCheckTolerance))
    {
        const std::vector<ZermeloState> extremal =
            ref.trajectory(s.x, s.y, sol.initialHeading, departure, sol.travelTime);
        std::vector<TimedPoint> curve;
        for (const ZermeloState &z : extremal)
            curve.push_back({z.x, z.y, z.t});
        curve.back().x = g.x;  // within the goal tolerance of it: the route ends on the goal
        curve.back().y = g.y;
        PlannedPath base;
        base.departure = departure;
        base.speed = best.speed;
        base.planner = best.planner;
        base.status = PlanStatus::ExactSolution;
        base.straightLineTime = best.straightLineTime;
        base.straightLineLength = best.straightLineLength;
        base.planningSeconds = best.planningSeconds;
        base.searchCostFunctionCalls = best.searchCostFunctionCalls;
        base.expandedVertices = best.expandedVertices;
        base.switchedFrom = best.switchedFrom;
        base.switchReason = best.switchReason;
        const auto consider = [&](PlannedPath c, const std::string &name) {
            if (window)
                timeArrival(problem, c);
            RouteCandidate row;
            row.name = name;
            row.solved = c.solved;
            row.travelTime = c.solved ? c.travelTime : kInf;
            row.why = c.solved ? std::string() : c.reason;
            check.candidates.push_back(row);
            if (c.solved && !(c.travelTime >= best.travelTime && best.solved))
            {
                c.currentModelCalls = best.currentModelCalls;
                if (!best.raw.empty())
                {
                    // raw and smoothed stay the planner's own stages; the route is the extremal's
                    c.raw = best.raw;
                    c.smoothed = best.smoothed;
                    c.rawTravelTime = best.rawTravelTime;
                    c.smoothedTravelTime = best.smoothedTravelTime;
                    c.rawPathLength = best.rawPathLength;
                }
                best = std::move(c);
                check.winner = name;
            }
            return row.solved;
        };
        const bool legs = consider(straightLegsAlong(problem, ctx, ss->getSpaceInformation(), curve, base),
                                   "extremal as straight legs");
        // held headings where straight legs cannot follow the extremal, or arrive clearly later than it
        if (!legs || best.travelTime > sol.travelTime * (1.0 + 2.0 * kCheckTolerance))
            consider(headingsAlong(problem, ctx, extremal, curve, base), "extremal as headings");
    }
    if (check.winner.empty() && best.solved)
        check.winner = check.candidates.front().name;
    if (best.solved && std::isfinite(planned))
        check.gain = 1.0 - best.travelTime / planned;
    else if (best.solved)
        check.gain = 1.0;
    if (best.solved && check.winner != check.candidates.front().name)
    {
        best.status = PlanStatus::ExactSolution;
        best.reason.clear();
        if (m.stints.set)
        {
            const auto tS = std::chrono::steady_clock::now();
            best.stints = convertToStints(problem, best);
            best.stints->seconds = secondsSince(tS);
        }
    }
    check.currentModelCalls = ctx->field->callCount() - cmc0;
    check.seconds = secondsSince(t0);
    best.globalCheck = std::move(check);
    return best;
}
}  // namespace planning_detail
}  // namespace ompl_glider
