/// @file HeadingRoutes.cpp
/// @brief Heading routes in the pipeline (issue 24): the result of a heading planner, and the default's switch to
/// one when straight legs find no path.

#include <algorithm>
#include <cmath>

#include "PlanningInternal.h"
#include "ompl_glider/planners/HeadingRefiner.h"
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
    s.radius = problem.gliderProblem(r.departure, r.speed).goalTolerance;
    s.tEnd = std::min(ctx.region.tMax, ctx.field->timeEnd());
    // the planner's check step: the reported times are those of this flight (checked against an accurate re-flight)
    s.step = route.step > 0.0 ? route.step : headingCheckStep(route.duration());
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
        r.status = kNoPathStatus;
        r.reason = "the heading route fails its check: " + why;
    }
    return r;
}

PlannedPath switchToHeadings(const MissionProblem &problem, double departure, const PlanOptions &o,
                             PlannedPath failed)
{
    if (failed.solved || !failed.badInput.empty() || !o.planner.empty() || !problem.getMembers().empty())
        return failed;
    const PlannerEntry &asked = plannerEntry(failed.planner);
    if (!asked.lattice())
        return failed;
    const std::string why = asked.name + " found no path of straight legs (" + failed.reason + ")";
    PlanOptions h = o;
    h.planner = "Isochrone";
    PlannedPath r = planOnField(problem, departure, h);
    if (!r.solved)
    {
        // the level set decides: a route of its headings, or the proof that the front never reaches the goal
        const std::string isochrone = r.reason;
        h.planner = "LevelSet";
        r = planOnField(problem, departure, h);
        if (r.solved)
            r.switchReason = why + "; Isochrone found none (" + isochrone + ")";
    }
    else
        r.switchReason = why;
    r.switchedFrom = asked.name;
    if (!r.solved && r.reason.empty())
        r.reason = failed.reason;
    r.planningSeconds += failed.planningSeconds;
    return r;
}
}  // namespace planning_detail
}  // namespace ompl_glider
