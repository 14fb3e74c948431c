#include "ompl_glider/mission/Isochrones.h"

#include <algorithm>
#include <cmath>

#include "PlanningInternal.h"
#include "../../io/NumberText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/ompl/PipelinePlanner.h"
#include "ompl_glider/registry/PlannerRegistry.h"

namespace ompl_glider
{
namespace
{
/// The reachable set from the registry's level-set planner (plannerOfFamily(), PipelinePlanner::reachableSet()).
std::optional<ReachableSet> reachableSetOf(const MissionProblem &problem, const GliderSimpleSetup &ss,
                                           const std::shared_ptr<GliderContext> &ctx, double departure,
                                           const ReachRequest &request)
{
    PipelineSetup setup;
    setup.departure = departure;
    setup.start = problem.getStart();
    setup.goal = problem.getGoal();
    setup.region = ctx->region;
    const ompl::base::PlannerPtr planner = plannerOfFamily(PlannerFamily::LevelSet).make(ss.getSpaceInformation(), ctx);
    if (std::optional<ReachableSet> r = pipelineView(*planner).reachableSet(setup, request))
        return r;
    throw Error("isochrones: the level-set planner computes no reachable set");
}
} // namespace

std::vector<std::vector<LonLat>> planning_detail::linesToGeographic(const MissionProblem &problem,
                                                                    const std::vector<std::vector<Point2>> &lines)
{
    std::vector<std::vector<LonLat>> out;
    if (!problem.isGeographic())
        return out;
    for (const auto &line : lines)
    {
        std::vector<LonLat> g;
        g.reserve(line.size());
        for (const Point2 &p : line)
            g.push_back(problem.toGeographic(p));
        out.push_back(std::move(g));
    }
    return out;
}

IsochroneSet computeIsochrones(const MissionProblem &problem, const PlannedPath &plan, double departure,
                               double interval)
{
    const MissionSpec &m = problem.getSpec();
    const double speed = plan.speed > 0.0 ? plan.speed : m.vehicle.speed;
    const GliderProblem gp = problem.gliderProblem(departure, speed);
    std::shared_ptr<GliderContext> ctx; // one context: the horizon's and the planner's
    const std::shared_ptr<GliderSimpleSetup> ss = makeSimpleSetup(gp, &ctx);
    const double horizon = std::min(gp.horizon, ctx->field->timeEnd() - departure);
    const double span = plan.solved && std::isfinite(plan.travelTime) ? std::min(plan.travelTime, horizon) : horizon;
    std::vector<double> times;
    if (std::isfinite(interval) && interval > 0.0)
    {
        const double count = std::floor(span * (1 + 1e-9) / interval);
        if (count > static_cast<double>(planning_detail::kMaxIsochrones))
        {
            throw Error(m.place("outputs.isochrone_interval") + ": an interval of " + text::number(interval) +
                        " gives " + text::number(count, 4) + " isochrones over the " + text::number(span, 4) +
                        " the plan takes, more than the limit of " + std::to_string(planning_detail::kMaxIsochrones) +
                        ": use a longer interval");
        }
        for (double t = interval; t <= span * (1 + 1e-9); t += interval)
            times.push_back(t);
    }
    else
        for (int k = 1; k <= 8; ++k)
            times.push_back(span * k / 8.0);

    // the reachable set is the level-set planner's answer: asked through the registry and PipelinePlanner, so the
    // pipeline names no planner type. Contours for a pilot's map: a cell of 1/100 of the region's larger side (the
    // planner's default is 1/200; this is eight times less work, about 1 % of the region's size in position)
    std::vector<double> absolute;
    for (double dt : times)
        absolute.push_back(departure + dt);
    ReachRequest request;
    request.times = absolute;
    request.cellScale = 2.0;
    const std::optional<ReachableSet> r = reachableSetOf(problem, *ss, ctx, departure, request);
    IsochroneSet out;
    out.resolution = r->resolution;
    out.seconds = r->seconds;
    out.x0 = r->x0;
    out.y0 = r->y0;
    out.h = r->h;
    out.nx = r->nx;
    out.ny = r->ny;
    out.arrival = r->arrival;
    for (std::size_t k = 0; k < absolute.size(); ++k)
    {
        Isochrone c;
        c.time = absolute[k];
        c.lines = r->lines[k];
        c.iso = problem.isoTime(c.time); // empty without dates
        c.lonLat = planning_detail::linesToGeographic(problem, c.lines);
        out.contours.push_back(std::move(c));
    }
    return out;
}
} // namespace ompl_glider
