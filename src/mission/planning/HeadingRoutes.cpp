/// @file HeadingRoutes.cpp
/// @brief Heading routes in the pipeline: the result of a heading planner, and the default's switch to
/// one when straight legs find no path.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "PlanningInternal.h"
#include "../../io/NumberText.h"
#include "ompl_glider/execution/Reflight.h"
#include "ompl_glider/routes/HeadingRefiner.h"
#include "ompl_glider/routes/HeadingTracker.h"
#include "ompl_glider/routes/PathSmoother.h"
#include "ompl_glider/registry/PlannerRegistry.h"

namespace ompl_glider
{
namespace planning_detail
{
PlannedPath headingResult(const MissionProblem &problem, const GliderContext &ctx, const HeadingRoute &route,
                          PlannedPath r)
{
    const Point2 g = problem.getGoal();
    HeadingRefineSettings s;
    s.depth = ctx.travel->params().depth;
    s.radius = problem.goalTolerance();
    s.tEnd = std::min(ctx.region.tMax, ctx.field->timeEnd());
    // the planner's check step: the reported times are those of this flight (checked against an accurate re-flight)
    s.step = route.step > 0.0 ? route.step : headingCheckStep(route.duration(), ctx);
    std::string why;
    const HeadingFlight f = verifyHeadingRoute(route, ctx, g, s, &why);
    r.headings = route;
    r.raw = r.smoothed = r.path = f.ends;
    r.track = f.track;
    r.rawTravelTime = r.smoothedTravelTime = r.travelTime = f.ends.back().t - r.departure;
    r.rawPathLength = r.pathLength = pathLength(f.track);
    r.pathChecked = f.reached;
    r.solved = f.reached;
    if (!f.reached)
    {
        r.status = PlanStatus::NoPath;
        r.setNoPath({NoPathCause::NotFlyable, "the heading route fails its check: " + why});
    }
    return r;
}

namespace
{
/// A heading route whose accurate re-flight ends farther from the goal than allowed: its last segment re-aimed on the
/// accurate flight (reaimOnReflight()); the route's waypoints and times become the accurate flight's. False when that
/// fails (nothing changed).
bool reaimLastSegment(const MissionProblem &problem, const GliderContext &ctx, const ReflightSettings &s, double radius,
                      PlannedPath &r)
{
    HeadingRoute route = *r.headings;
    const HeadingSegment before = route.segments.back();
    HeadingReflight f;
    if (!reaimOnReflight(route, problem.getGoal(), *ctx.field, ctx.environment.get(), s, radius, f))
        return false;
    char note[240];
    std::snprintf(note, sizeof note,
                  "the last segment re-aimed on the accurate re-flight (bearing %+.3g deg, duration %+.3g): the "
                  "planner's route ended %.3g from the goal when flown accurately",
                  route.segments.back().bearing - before.bearing, route.segments.back().duration - before.duration,
                  r.reflownEndDistance);
    r.reflightNote = note;
    r.reflightFallback = ReflightFallback::Reaimed;
    r.plannerTravelTime = r.travelTime;
    r.headings = route;
    r.path = r.raw = r.smoothed = f.ends;
    r.rawTravelTime = r.smoothedTravelTime = r.travelTime = f.end.t - r.departure;
    r.reflownTravelTime = r.travelTime;
    r.reflownEndDistance = std::hypot(f.end.x - problem.getGoal().x, f.end.y - problem.getGoal().y);
    return true;
}
} // namespace

void reflyRoute(const MissionProblem &problem, const GliderContext &ctx, PlannedPath &r)
{
    if (!r.solved || r.path.size() < 2 || (r.stints && !r.stints->converted))
        return;
    ReflightSettings s;
    s.speed = r.speed;
    s.depth = ctx.travel->params().depth;
    const Environment *forbidden = ctx.environment.get();
    r.reflown = true;
    if (r.headingRoute())
    {
        const HeadingReflight f = reflyHeadingRoute(*r.headings, *ctx.field, forbidden, s);
        const Point2 g = problem.getGoal();
        r.reflownEndDistance = std::hypot(f.end.x - g.x, f.end.y - g.y);
        r.reflownTravelTime = f.end.t - r.departure;
        // within the goal tolerance, or so close that still water would close the gap in 1e-6 of the trip (a long
        // route through a sensitive flow, where two accurate integrators part by more than a tight tolerance)
        const double radius = std::max(problem.goalTolerance(), 1e-6 * r.speed * r.travelTime);
        if (f.ok && !f.grounded && !(r.reflownEndDistance <= radius) && reaimLastSegment(problem, ctx, s, radius, r))
            return;
        if (!f.ok || f.grounded || !(r.reflownEndDistance <= radius))
        {
            r.solved = false;
            r.status = PlanStatus::NoPath;
            r.setNoPath({NoPathCause::NotFlyable,
                         "the heading route fails its accurate re-flight: " +
                             (f.grounded || !f.ok ? f.why
                                                  : "it ends " + text::number(r.reflownEndDistance) +
                                                        " from the goal (goal radius " + text::number(radius) + ")")});
        }
        return;
    }
    // straight legs, leg by leg from the re-flown time of the leg's start, the plan's waits kept
    s.keepSlowLegs = true;
    const auto retimed = [&](const std::vector<TimedPoint> &path, std::string *why) {
        std::vector<TimedPoint> out;
        if (path.size() < 2)
            return out;
        const PathReflight f = reflyPath(path, *ctx.field, forbidden, s);
        if (!f.feasible)
        {
            if (why)
                *why = f.why;
            return out;
        }
        out = path;
        for (std::size_t k = 0; k < out.size(); ++k)
            out[k].t = f.times[k];
        return out;
    };
    // Each stage re-flown; a post-processing stage is kept only where the re-flight confirms that it flies and does
    // not arrive later than the stage before it (the smoother and the refiner decide with the planner's integrator)
    std::string why;
    const std::vector<TimedPoint> raw = retimed(r.raw, &why);
    std::vector<TimedPoint> smoothed = retimed(r.smoothed, &why), path = retimed(r.path, &why);
    const auto later = [](const std::vector<TimedPoint> &a, const std::vector<TimedPoint> &b) {
        return !b.empty() && (a.empty() || a.back().t > b.back().t);
    };
    double planner = r.travelTime;
    if (later(smoothed, raw))
        smoothed = raw;
    if (later(path, smoothed))
    {
        r.reflightNote = path.empty() ? "the final path fails its accurate re-flight (" + why + ")"
                                      : "the final path arrives later than the path before it when re-flown";
        r.reflightNote += "; the earlier stage is flown instead";
        r.reflightFallback = ReflightFallback::EarlierStage;
        planner = smoothed.size() == r.smoothed.size() ? r.smoothedTravelTime : r.rawTravelTime;
        path = smoothed;
    }
    if (path.empty())
    {
        r.solved = false;
        r.status = PlanStatus::NoPath;
        r.setNoPath({NoPathCause::NotFlyable, "the path cannot be flown when re-flown accurately: " + why});
        return;
    }
    r.plannerTravelTime = planner;
    if (!raw.empty())
    {
        r.raw = raw;
        r.rawTravelTime = raw.back().t - r.departure;
    }
    if (!smoothed.empty())
    {
        r.smoothed = smoothed;
        r.smoothedTravelTime = smoothed.back().t - r.departure;
    }
    r.path = std::move(path);
    r.pathLength = pathLength(r.path);
    r.travelTime = r.path.back().t - r.departure;
    r.reflownTravelTime = r.travelTime;
    r.reflownEndDistance = 0.0;
}

PlannedPath switchToHeadings(const MissionProblem &problem, double departure, const PlanOptions &o, PlannedPath failed)
{
    if (failed.solved || failed.badInput.any() || !o.planner.empty() || !problem.getMembers().empty() ||
        !o.headingFallback.value_or(true))
        return failed;
    const PlannerEntry &asked = plannerEntry(failed.planner);
    if (!asked.lattice())
        return failed;
    bool byModelLand = false; // no heading reaches water the forecast's land cuts off
    if (!enclosure(problem, departure, &byModelLand).empty() && byModelLand)
        return failed;
    // the lattice's advice (a finer grid, ...) is moot once another planner has been asked
    const std::string why = asked.name + " found no path of straight legs: " + failed.noPath.what;
    // the planners asked after it, by family (the registry's first of each): the heading planner, then the level set
    const PlannerEntry &headings = plannerOfFamily(PlannerFamily::Headings);
    const PlannerEntry &levelSet = plannerOfFamily(PlannerFamily::LevelSet);
    PlanOptions h = o;
    h.planner = headings.name;
    const MissionSpec &m = problem.getSpec();
    h.timeLimit = o.timeLimit > 0 ? o.timeLimit : m.planner.timeLimit > 0 ? m.planner.timeLimit : kFallbackTimeLimit;
    PlannedPath r = planOnField(problem, departure, h);
    if (!r.solved)
    {
        // the level set decides: a route of its headings, or the proof that the front never reaches the goal
        const std::string headingsWhy = r.noPath.text();
        h.planner = levelSet.name;
        r = planOnField(problem, departure, h);
        if (r.solved)
            r.switchReason = why + "; " + headings.name + " found none (" + headingsWhy + ")";
    }
    else
        r.switchReason = why;
    r.planningSeconds += failed.planningSeconds;
    if (r.solved)
    {
        r.switchedFrom = asked.name;
        r.switchCause = failed.noPath.cause;
        return r;
    }
    // no route of either kind: the level set's cause and findings, with what the asked planner's search bounds
    const bool timedOut = r.noPath.cause == NoPathCause::TimeLimit;
    NoPath none = r.noPath;
    none.what =
        (none.proven() ? "no path exists: " : "no path found: ") +
        (timedOut ? "the level set, after " + headings.name + ", each with " +
                        std::string(o.timeLimit > 0 || m.planner.timeLimit > 0 ? "the time limit"
                                                                               : "the fallback's default time limit") +
                        ": "
                  : std::string()) +
        r.noPath.text() + " (" + asked.name + " found none on its lattice, nor " + headings.name +
        " with held headings)";
    none.advice.clear();
    none.bound = failed.noPath.bound;
    none.boundSpan = failed.noPath.boundSpan;
    none.boundText = failed.noPath.boundText;
    failed.setNoPath(std::move(none));
    failed.status = PlanStatus::NoPath;
    failed.planningSeconds = r.planningSeconds;
    return failed;
}
} // namespace planning_detail
} // namespace ompl_glider
