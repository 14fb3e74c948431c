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
#include "ompl_glider/ompl/PipelinePlanner.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#include "../../core/Numbers.h"

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
    zp.groundSpeedBound = speed + 1.1 * ctx->maxCurrent(); // a margin for interpolation overshoot
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

/// The rescue where the sweep finds no extremal is bounded by its work, not by a clock, so that a problem gets the
/// same answer on any machine and under any load: the finer scans by construction (kZoomLevels windows of
/// kWindowHeadings headings about each centre), the level set by its node updates, in proportion to the plan's own
/// work (a coastal trip the lattice planned in a second does not wait half a minute for a level set): this many per
/// cost-function call of a lattice planner and per front point of the heading planner it switched to, at least
/// kLevelSetMinimumUpdates (about a second of the level set on two cores: the narrow band of a front that crosses a
/// 200-cell grid over some hundred steps).
constexpr std::uint64_t kLevelSetUpdatesPerCall = 100;
constexpr std::uint64_t kLevelSetUpdatesPerPoint = 2000;
constexpr std::uint64_t kLevelSetMinimumUpdates = 2500000;

/// The level set's budget after the plan @p r (its counts are its own, whichever threads share the field).
std::uint64_t levelSetBudget(const PlannedPath &r)
{
    std::uint64_t work = kLevelSetUpdatesPerCall * (r.searchCostFunctionCalls + r.postprocessCostFunctionCalls);
    if (!r.switchedFrom.empty()) // the heading planner's front points (the lattice's search is its own count)
        work += kLevelSetUpdatesPerPoint * r.expandedVertices;
    return std::max(kLevelSetMinimumUpdates, work);
}

/// Headings of each finer scan, and how many times a scan is narrowed about its nearest miss.
constexpr int kWindowHeadings = 360;
constexpr int kZoomLevels = 5;

/// A finer scan where the sweep found no extremal through the goal: windows of kWindowHeadings headings about
/// @p centre, each sixteen times narrower than the last and centred on the heading whose extremal came nearest the
/// goal, until one brackets an extremal through it. In strong currents the family of extremals through a far goal
/// can be far narrower than the sweep's spacing: the miss changes fast there, and the scan follows it down.
ZermeloSolution zoomOn(const std::shared_ptr<const CurrentField> &field, ZermeloParams zp, double centre, double width,
                       Point2 s, Point2 g, double departure, unsigned &shot)
{
    zp.headingSamples = kWindowHeadings;
    ZermeloSolution sol;
    sol.travelTime = kInf;
    for (int level = 0; level < kZoomLevels && !zp.stop(); ++level)
    {
        zp.headingFrom = centre - 0.5 * width;
        zp.headingSpan = std::min(width, 2.0 * kPi);
        sol = ZermeloReference(field, zp).solve(s.x, s.y, g.x, g.y, departure);
        shot += static_cast<unsigned>(sol.headingsShot);
        if (sol.found || !std::isfinite(sol.nearestMiss))
            break;
        centre = sol.nearestHeading;
        width /= 16.0;
    }
    return sol;
}

/// The level set's help where the sweep finds none: its first arrival at the goal and the steering directions of
/// its backtracked path's first steps ((p1 - p0) / dt - c: the front's normal is undefined at the start itself,
/// so the first few), the centres of finer scans. The level set is the registry's planner of that family
/// (plannerOfFamily()), asked through PipelinePlanner::firstArrival(); none where it has no answer.
struct LevelSetAid
{
    double time{kInf};
    std::vector<double> seeds;
};

LevelSetAid levelSetAid(const ompl::base::SpaceInformationPtr &si, const std::shared_ptr<GliderContext> &ctx, Point2 s,
                        Point2 g, double departure, double tEnd, const std::function<bool()> &stop, GlobalCheck &check)
{
    LevelSetAid aid;
    const PlannerEntry *entry = findPlannerOfFamily(PlannerFamily::LevelSet);
    if (!entry)
        return aid;
    const ompl::base::PlannerPtr planner = entry->make(si, ctx);
    PipelineSetup setup;
    setup.departure = departure;
    setup.start = s;
    setup.goal = g;
    setup.region = ctx->region;
    const std::optional<FirstArrival> r = pipelineView(*planner).firstArrival(setup, tEnd, check.levelSetBudget, stop);
    if (!r)
        return aid;
    check.levelSetUpdates = r->work;
    check.levelSetBudgetSpent = r->budgetSpent;
    if (!r->reached || stop())
        return aid;
    aid.time = r->time - departure;
    const double depth = ctx->travel->params().depth;
    for (std::size_t i = 0; i + 1 < r->path.size() && aid.seeds.size() < 3; ++i)
    {
        const TimedPoint &a = r->path[i], &b = r->path[i + 1];
        const double dt = b.t - a.t;
        if (!(dt > 0.0))
            continue;
        const Velocity c = ctx->field->velocity(0.5 * (a.x + b.x), 0.5 * (a.y + b.y), depth, 0.5 * (a.t + b.t));
        const double wx = (b.x - a.x) / dt - c.u, wy = (b.y - a.y) / dt - c.v;
        if (std::hypot(wx, wy) > 1e-9 * ctx->speed())
            aid.seeds.push_back(std::atan2(wy, wx));
    }
    return aid;
}

/// The extremal through the goal: the sweep over the circle (360 headings, then four or eight times as many), then
/// finer scans about its nearest miss and, with the level set's first arrival, about the level set's initial
/// headings. Fills the check's counts.
ZermeloSolution findExtremal(const ompl::base::SpaceInformationPtr &si, const std::shared_ptr<GliderContext> &ctx,
                             ZermeloParams &zp, bool planned, Point2 s, Point2 g, double departure, double span,
                             GlobalCheck &check)
{
    ZermeloSolution sol = ZermeloReference(ctx->field, zp).solve(s.x, s.y, g.x, g.y, departure);
    check.headings = static_cast<unsigned>(sol.headingsShot);
    if (!sol.found && !zp.stop())
    {
        // in strong or sensitive currents the headings that reach a far goal can lie within a fraction of a degree:
        // sweep finer before giving up (eight times where there is no route at all, else four)
        zp.headingSamples *= planned ? 4 : 8;
        sol = ZermeloReference(ctx->field, zp).solve(s.x, s.y, g.x, g.y, departure);
        check.headings = static_cast<unsigned>(sol.headingsShot);
    }
    if (sol.found || zp.stop())
        return sol;
    // the rescue (finer scans, the level set) within its work budget (levelSetBudget())
    const double spacing = 2.0 * kPi / zp.headingSamples;
    if (std::isfinite(sol.nearestMiss))
    {
        const ZermeloSolution z =
            zoomOn(ctx->field, zp, sol.nearestHeading, 16.0 * spacing, s, g, departure, check.finerHeadings);
        if (z.found)
            return z;
    }
    // the level set over the whole window (the extremal may be slower than the planner's route's bound)
    if (zp.stop())
        return sol;
    const LevelSetAid aid = levelSetAid(si, ctx, s, g, departure, departure + span, zp.stop, check);
    check.levelSetTime = aid.time;
    ZermeloParams wide = zp;
    wide.maxTime = std::isfinite(aid.time) ? std::min(span, 1.25 * aid.time) : zp.maxTime;
    for (const double seed : aid.seeds)
    {
        const ZermeloSolution z =
            zoomOn(ctx->field, wide, seed, 40.0 * kPi / 180.0, s, g, departure, check.finerHeadings);
        if (z.found && (!sol.found || z.travelTime < sol.travelTime))
            sol = z;
    }
    return sol;
}

/// The level set's first arrival is first order in its cell and never early by much: a route within this fraction of
/// it is kept without planning the level set's route.
constexpr double kLevelSetMargin = 0.02;

/// The level set's route through the pipeline (the registry's level-set planner, its time limit the plan's or the
/// fallback's), carrying the planner's outcome's identity like the extremal's routes.
PlannedPath levelSetRoute(const MissionProblem &problem, double departure, const PlanOptions &o,
                          const PlannedPath &base)
{
    const MissionSpec &m = problem.getSpec();
    PlanOptions h = o;
    h.planner = plannerOfFamily(PlannerFamily::LevelSet).name;
    h.timeLimit = o.timeLimit > 0 ? o.timeLimit : m.planner.timeLimit > 0 ? m.planner.timeLimit : kFallbackTimeLimit;
    PlannedPath c = planOnField(problem, departure, h);
    c.planner = base.planner;
    c.switchedFrom = base.switchedFrom;
    c.switchReason = base.switchReason;
    c.straightLineTime = base.straightLineTime;
    c.straightLineLength = base.straightLineLength;
    if (c.solved)
        c.status = PlanStatus::ExactSolution;
    return c;
}

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
        c.setNoPath({NoPathCause::NotFlyable, "its track cannot be flown as straight legs: " + why});
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
        c.postprocessCostFunctionCalls += rr.costFunctionCalls;
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
        c.setNoPath({NoPathCause::NotFlyable, "its straight legs fail the path check"});
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
    s.radius = problem.goalTolerance();
    s.tEnd = std::min(ctx->region.tMax, ctx->field->timeEnd());
    HeadingRoute schedule;
    schedule.start = {extremal.front().x, extremal.front().y};
    schedule.departure = extremal.front().t;
    for (std::size_t i = 0; i + 1 < extremal.size(); ++i)
    {
        const double dt = extremal[i + 1].t - extremal[i].t;
        if (dt > 0.0) // heading theta from +x, counter-clockwise -> bearing clockwise from north
            schedule.segments.push_back({90.0 - 0.5 * (extremal[i].theta + extremal[i + 1].theta) * kDegPerRad, dt});
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
            c.setNoPath({NoPathCause::NotFlyable, "its headings cannot be closed on the goal (" + h.why +
                                                      "), nor its track followed by held headings (" + tracked.why +
                                                      ")"});
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

/// Whether the plan @p r is checked: after a lattice planner, with refinement, on one field, not after a proof that no
/// route exists or a stop request.
bool isChecked(const MissionProblem &problem, const PlanOptions &o, const PlannedPath &r)
{
    const MissionSpec &m = problem.getSpec();
    // the check belongs to the post-processing: without refinement the planner's own path is what was asked for
    if (!o.globalCheck.value_or(m.planner.globalCheck) || !o.refinement.value_or(m.planner.refinement) ||
        !o.planner.empty() || r.badInput.any() || !problem.getMembers().empty() || (r.stints && !r.stints->converted))
        return false;
    const PlannerEntry &asked = plannerEntry(r.switchedFrom.empty() ? r.planner : r.switchedFrom);
    if (!asked.lattice())
        return false;
    // a front that never reaches the goal proves that no route exists: nothing to look for; nor where the lattice was
    // exhausted and no heading planner asked after it, nor after a stop request
    return !((!r.solved && (r.noPath.cause == NoPathCause::LatticeExhausted || r.noPath.proven())) || stopRequested());
}

/// What a candidate route inherits from the planner's outcome @p best: its speed, planner, straight line and the
/// work of its search, smoothing and refinement (done whichever route wins; a mission's legs add them up).
PlannedPath candidateBase(const PlannedPath &best, double departure)
{
    PlannedPath base;
    base.departure = departure;
    base.speed = best.speed;
    base.planner = best.planner;
    base.status = PlanStatus::ExactSolution;
    base.straightLineTime = best.straightLineTime;
    base.straightLineLength = best.straightLineLength;
    base.planningSeconds = best.planningSeconds;
    base.postprocessSeconds = best.postprocessSeconds;
    base.postprocessCostFunctionCalls = best.postprocessCostFunctionCalls;
    base.searchCostFunctionCalls = best.searchCostFunctionCalls;
    base.expandedVertices = best.expandedVertices;
    base.switchedFrom = best.switchedFrom;
    base.switchReason = best.switchReason;
    return base;
}

/// The check's figures once the candidates are in: the winner (the planner's own route when no other was faster),
/// the gain over the planner's time @p planned; a route of another class is exact and, on a stint mission, converted
/// to stints.
void settleWinner(const MissionProblem &problem, GlobalCheck &check, PlannedPath &best, double planned)
{
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
        if (problem.getSpec().stints.set)
        {
            const auto tS = std::chrono::steady_clock::now();
            best.stints = convertToStints(problem, best);
            best.stints->seconds = secondsSince(tS);
        }
    }
}
} // namespace

PlannedPath checkGlobally(const MissionProblem &problem, double departure, const PlanOptions &o, PlannedPath r)
{
    const MissionSpec &m = problem.getSpec();
    if (!isChecked(problem, o, r))
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
    // the check keeps to the plan's time limit (the fallbacks' where none is set): its scans and its level set stop
    check.timeLimit = o.timeLimit > 0           ? o.timeLimit
                      : m.planner.timeLimit > 0 ? m.planner.timeLimit
                                                : kFallbackTimeLimit;
    const auto deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                   std::chrono::duration<double>(check.timeLimit));
    zp.stop = [deadline, &check] {
        if (stopRequested())
            return true;
        if (std::chrono::steady_clock::now() < deadline)
            return false;
        check.timedOut = true;
        return true;
    };
    check.levelSetBudget = levelSetBudget(r);
    const Point2 s = problem.getStart(), g = problem.getGoal();
    const ZermeloSolution sol =
        findExtremal(ss->getSpaceInformation(), ctx, zp, r.solved, s, g, departure, span, check);
    const ZermeloReference ref(ctx->field, zp);
    check.extremalFound = sol.found;
    check.extremalTime = sol.found ? sol.travelTime : kInf;
    PlannedPath best = std::move(r);
    const double planned = best.solved ? best.travelTime : kInf;
    const PlannedPath base = candidateBase(best, departure);
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
                // raw and smoothed stay the planner's own stages; the route is the candidate's
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
    if (sol.found && sol.travelTime < planned * (1.0 - kCheckTolerance))
    {
        const std::vector<ZermeloState> extremal =
            ref.trajectory(s.x, s.y, sol.initialHeading, departure, sol.travelTime);
        std::vector<TimedPoint> curve;
        for (const ZermeloState &z : extremal)
            curve.push_back({z.x, z.y, z.t});
        curve.back().x = g.x; // within the goal tolerance of it: the route ends on the goal
        curve.back().y = g.y;
        const bool legs = consider(straightLegsAlong(problem, ctx, ss->getSpaceInformation(), curve, base),
                                   "extremal as straight legs");
        // held headings where straight legs cannot follow the extremal, or arrive clearly later than it
        if (!legs || best.travelTime > sol.travelTime * (1.0 + 2.0 * kCheckTolerance))
            consider(headingsAlong(problem, ctx, extremal, curve, base), "extremal as headings");
    }
    // no extremal through the goal and the level set's front reached it earlier than the route in hand: the level
    // set's own route (its backtracked path as straight legs, or flown by its headings) is a candidate
    if (!sol.found && std::isfinite(check.levelSetTime) && !zp.stop() &&
        !(best.solved && best.travelTime <= check.levelSetTime * (1.0 + kLevelSetMargin)))
        consider(levelSetRoute(problem, departure, o, base), "level set");
    settleWinner(problem, check, best, planned);
    check.currentModelCalls = ctx->field->callCount() - cmc0;
    check.seconds = secondsSince(t0);
    best.globalCheck = std::move(check);
    return best;
}
} // namespace planning_detail
} // namespace ompl_glider
