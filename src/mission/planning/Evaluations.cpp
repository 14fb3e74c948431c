/// @file Evaluations.cpp
/// @brief The evaluations of a plan made by runMission(): the speed sweep, the waypoints for the pilot (with dive
/// profiles) and the optimal-control reference.

#include "ompl_glider/mission/MissionLegs.h"
#include <cmath>
#include <cstdio>
#include <mutex>

#include "PlanningInternal.h"
#include "ompl_glider/TaskSpread.h"
#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/reference/ZermeloReference.h"

namespace ompl_glider
{
std::vector<SpeedSweepRow> speedSweep(const MissionProblem &problem, double tDep, const std::vector<double> &speeds,
                                      const ProgressSink &progress)
{
    // one plan per speed, in parallel (planRoute() is thread-safe on one problem; in a job, spread over its
    // processes: TaskSpread.h); rows in the order given
    std::vector<SpeedSweepRow> rows(speeds.size());
    std::mutex printMutex;
    std::size_t done = 0;
    const auto report = [&](std::size_t n) {
        char line[96];
        std::snprintf(line, sizeof line, "speed sweep: %zu/%zu speeds planned", n, speeds.size());
        progress(line, n == speeds.size());
    };
    const auto row = [&](std::size_t i) {
        PlanOptions o;
        o.speed = speeds[i];
        const PlannedPath p = planMission(problem, tDep, o).plan;
        return SpeedSweepRow{speeds[i], p.solved, p.travelTime, p.pathLength, p.straightLineTime, p.straightLineLength};
    };
    if (TaskSpreader *spread = activeTaskSpreader())
    {
        const std::vector<std::string> out = spread->run(
            "speed sweep speed", speeds.size(),
            [&](std::size_t i) {
                const SpeedSweepRow r = row(i);
                ByteWriter w;
                w.put(r.solved);
                for (const double v : {r.travelTime, r.pathLength, r.straightLineTime, r.straightLineLength})
                    w.put(v);
                return w.take();
            },
            [&](std::size_t n, std::size_t) {
                if (progress)
                    report(n);
            });
        for (std::size_t i = 0; i < speeds.size(); ++i)
        {
            ByteReader in(out[i]);
            SpeedSweepRow &r = rows[i];
            r.speed = speeds[i];
            in.get(r.solved);
            for (double *v : {&r.travelTime, &r.pathLength, &r.straightLineTime, &r.straightLineLength})
                in.get(*v);
        }
        return rows;
    }
    ThreadPool pool(0);
    pool.parallelFor(speeds.size(), [&](std::size_t i) {
        rows[i] = row(i);
        if (progress)
        {
            std::lock_guard<std::mutex> lock(printMutex);
            report(++done);
        }
    });
    return rows;
}

namespace
{
/// The headings of @p route onto the waypoints @p first..@p last of @p out (the route's segment ends in turn): the
/// heading held from each waypoint and for how long; a step that stays in place (a hold a goal window added) takes
/// none.
void assignHeadings(const HeadingRoute &route, const std::vector<TimedPoint> &path, std::size_t first, std::size_t last,
                    std::vector<MissionWaypoint> &out)
{
    std::size_t k = 0;
    for (std::size_t i = first; i < last && i + 1 < path.size() && k < route.segments.size(); ++i)
    {
        const TimedPoint &a = path[i], &b = path[i + 1];
        if (a.x == b.x && a.y == b.y)
            continue;
        const double bearing = route.segments[k++].bearing; // a planner's bearing may be < 0 or >= 360
        out[i].heading = bearing - 360.0 * std::floor(bearing / 360.0);
        out[i].headingDuration = b.t - a.t;
    }
}
} // namespace

PilotWaypoints missionWaypoints(const MissionProblem &problem, const PlannedPath &plan,
                                const std::vector<PlannedLeg> &legs)
{
    PilotWaypoints out;
    // a stint plan's legs between surfacings are not straight, nor are a heading route's: their times are the
    // flown ones; in a mission of several legs, those of its legs flown as held headings
    const bool flown = (plan.stints && !plan.stints->converted) || plan.headingRoute();
    const auto dive = flown ? nullptr : problem.diveProfiles(plan.speed);
    // waypoint i is reached on a leg of held headings (its time is the flown one)
    const auto headingLeg = [&](std::size_t i) {
        for (const PlannedLeg &l : legs)
            if (l.plan.headingRoute() && i > l.firstPoint && i <= l.lastPoint)
                return true;
        return false;
    };
    double t = plan.departure;
    for (std::size_t i = 0; i < plan.path.size(); ++i)
    {
        MissionWaypoint w;
        w.position = {plan.path[i].x, plan.path[i].y};
        if (problem.isGeographic())
        {
            w.geographic = true;
            w.lonLat = problem.toGeographic(w.position);
        }
        const bool straight = dive && !headingLeg(i);
        if (i == 0)
            w.time = plan.departure;
        else if (straight && plan.path[i].x == plan.path[i - 1].x && plan.path[i].y == plan.path[i - 1].y)
        {
            // a hold (goal window, a lattice wait, a stay): as long as planned
            w.legTime = plan.path[i].t - plan.path[i - 1].t;
            t += w.legTime;
            w.time = t;
        }
        else if (straight)
        {
            const DiveLegResult leg =
                dive->bestProfile(plan.path[i - 1].x, plan.path[i - 1].y, w.position.x, w.position.y, t);
            w.profile = leg.profile;
            if (leg.profile >= 0)
                w.dive = dive->profiles()[leg.profile];
            w.legTime = leg.travelTime;
            t += leg.travelTime;
            w.time = t;
        }
        else
        {
            // flown as planned: a heading leg keeps its flown times (a delay before it would change its current)
            w.time = plan.path[i].t;
            w.legTime = plan.path[i].t - plan.path[i - 1].t;
            t = std::max(t, w.time);
        }
        w.iso = problem.isoTime(w.time);
        out.waypoints.push_back(w);
    }
    if (plan.headingRoute())
        assignHeadings(*plan.headings, plan.path, 0, plan.path.size() - 1, out.waypoints);
    else
        for (const PlannedLeg &l : legs)
            if (l.plan.headingRoute())
                assignHeadings(*l.plan.headings, plan.path, l.firstPoint, l.lastPoint, out.waypoints);
    out.travelTime = out.waypoints.empty() ? kInf : out.waypoints.back().time - plan.departure;
    return out;
}

OptimumReference optimumReference(const MissionProblem &problem, double departure, double speed, double maxTravelTime)
{
    // the reference is a route the glider can fly: extremals end at land, forbidden regions and the region's edge
    std::shared_ptr<GliderContext> ctx;
    makeSimpleSetup(problem.gliderProblem(departure, speed), &ctx);
    ZermeloParams zp = planning_detail::checkedExtremalParams(problem, ctx, speed, maxTravelTime);
    const ZermeloParams reference; // the reference's own accuracy
    zp.goalTolerance = reference.goalTolerance;
    zp.headingSamples = reference.headingSamples;
    zp.scanRelTol = reference.scanRelTol;
    zp.relTol = reference.relTol;
    const ZermeloReference ref(problem.getField(), zp);
    const Point2 s = problem.getStart(), g = problem.getGoal();
    const ZermeloSolution sol = ref.solve(s.x, s.y, g.x, g.y, departure);
    OptimumReference out;
    out.found = sol.found;
    if (!sol.found)
        return out;
    out.travelTime = sol.travelTime;
    for (const ZermeloState &z : ref.trajectory(s.x, s.y, sol.initialHeading, departure, sol.travelTime))
        out.path.push_back({z.x, z.y, z.t});
    return out;
}
void planning_detail::addPlanningWork(PlannedPath &to, const PlannedPath &from)
{
    to.searchCostFunctionCalls += from.searchCostFunctionCalls;
    to.postprocessCostFunctionCalls += from.postprocessCostFunctionCalls;
    to.currentModelCalls += from.currentModelCalls;
    to.expandedVertices += from.expandedVertices;
    to.planningSeconds += from.planningSeconds;
    to.postprocessSeconds += from.postprocessSeconds;
}

std::string planning_detail::frozenFieldNote(const MissionProblem &problem, const PlannedPath &plan)
{
    const MissionSpec &m = problem.getSpec();
    if (!plan.solved || plan.path.empty() || m.current.horizonPolicy != BeyondForecast::HoldLast || m.current.steady)
        return "";
    const auto &members = problem.getMembers();
    const FieldGrid *grid = (members.empty() ? problem.getField() : members.front())->grid();
    if (!grid || grid->recordTimes().size() < 2)
        return "";
    const double last = grid->recordTimes().back(), arrival = plan.path.back().t;
    if (!(arrival > last))
        return "";
    const double held = arrival - std::max(last, plan.departure);
    return "planned past the forecast's last time (" + timeText(problem, last) + ") on its last field, held frozen (" +
           m.term("current.horizon: hold_last") + ") for the last " +
           (m.physicalUnits().time ? text::durationText(held * m.timeUnitSeconds) : text::number(held)) +
           " of the route";
}

std::string planning_detail::forecastRunNote(const MissionProblem &problem, const PlannedPath &plan)
{
    if (!problem.runs())
        return "";
    const MissionSpec &m = problem.getSpec();
    const ForecastRun &run = (*problem.runs())[problem.runIndex()];
    std::string out = "planned on forecast run " + std::to_string(problem.runIndex() + 1) + " of " +
                      std::to_string(problem.runs()->size()) + ", '" + run.file + "': reference time " +
                      m.isoTime(run.reference) + " (" + run.referenceFrom + "), available since " +
                      m.isoTime(run.available) + ", the newest at the departure";
    if (plan.solved && !plan.path.empty())
        out += "; lead time at arrival " + m.durationText(plan.path.back().t - run.reference);
    return out;
}
} // namespace ompl_glider
