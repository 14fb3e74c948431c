/// @file Planning.cpp
/// @brief The one planning pipeline: planRoute() (one plan on a field through OMPL's SimpleSetup, then smoothing,
/// refinement and the stint conversion; robust plans over an ensemble and goal windows in Ensembles.cpp and
/// GoalWindow.cpp) and runMission() (the checks before any search, the departure, the plan and its evaluations).
/// The planner itself is made in PlannerSetup.cpp (makePlanner()); see PlanningInternal.h for the other files.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>

#include "PlanningInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/routes/PathSmoother.h"
#include "ompl_glider/routes/WaypointRefiner.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#include "ompl_glider/routes/PathToStints.h"
#include "ompl_glider/ompl/PipelinePlanner.h"
#include "ompl_glider/mission/MissionLegs.h"
#include "ompl_glider/Config.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/mission/Observations.h"
#endif

namespace ompl_glider
{
namespace planning_detail
{
/// The final path of a (non-stint) planner flown as stints: the heading per surfacing that follows it best and
/// what that loses (stintsFromPath()); earliest arrival within the section's radius (0: 1e-4 of the start-goal
/// distance), over a mission long enough to arrive (1.5 times the path's time plus one stint, within the forecast).
StintOutcome convertToStints(const MissionProblem &problem, const PlannedPath &r)
{
    StintSettings s = stintSettings(problem, r.departure);
    s.objective = StintObjective::EarliestArrival;
    if (!(s.radius > 0.0))
        s.radius = std::max(1e-4 * r.straightLineLength, 1e-9);
    s.missionDuration = 1.5 * r.travelTime + s.duration;
    const double end = problem.getField()->timeEnd();
    if (std::isfinite(end))
        s.missionDuration = std::min(s.missionDuration, end - r.departure);
    Region box = problem.getBox();
    box.tMin = r.departure;
    box.tMax = r.departure + s.missionDuration;
    const Point2 start{r.path.front().x, r.path.front().y}, goal = problem.getGoal();
    const StintSimulator sim(problem.getField(), problem.getEnvironment(), r.speed, problem.getField()->maxSpeed(box),
                             start, r.departure, goal, s);
    const PathToStintsResult c = stintsFromPath(sim, r.path);
    StintOutcome o;
    o.plan = c.plan;
    o.converted = true;
    o.settings = s;
    o.pathTravelTime = c.pathTravelTime;
    o.stintTravelTime = c.stintTravelTime;
    o.loss = c.loss;
    return o;
}

namespace
{

/// Finds the planner and sets its parameters once before any search, so that a bad name or parameter is an
/// error naming the mission file, not a failed search.
void checkPlanner(const MissionProblem &problem, double departure)
{
    const MissionSpec &m = problem.getSpec();
    const GliderProblem gp = checkedProblem(problem, departure, m.vehicle.speed);
    if (!(gp.horizon > 0))
        return;
    std::shared_ptr<GliderContext> ctx;
    const ompl::geometric::SimpleSetupPtr ss = makeSimpleSetup(gp, &ctx);
    makePlanner(problem, ss->getSpaceInformation(), ctx, m.planner.gridSize, m.planner.sectors, departure);
    refinerParams(m);
}

/// The goal's arrival window must lie within reach: it must not end before the (earliest) departure, and must open
/// before the planning horizon of the latest departure ends (the end of the forecast, or planner.horizon).
void checkGoalWindow(const MissionProblem &problem)
{
    const MissionSpec &m = problem.getSpec();
    const GoalWindowSpec &w = m.goalWindow;
    if (!w.set)
        return;
    const double first = m.departure.window ? m.departure.begin : m.departure.time;
    const double last = m.departure.window ? m.departure.end : m.departure.time;
    if (w.end < first)
        throw Error(m.place("goal.window.end") + ": the arrival window ends at " + timeText(problem, w.end) +
                    ", before the departure (" + timeText(problem, first) + "): no plan can arrive in it");
    // (the departure itself is checked where it is planned: a window's end may lie past the forecast)
    const GliderProblem gp = problem.gliderProblem(last, m.vehicle.speed);
    const double fieldEnd = problem.getField()->timeEnd();
    const double horizonEnd = std::min(gp.t0 + gp.horizon, std::isfinite(fieldEnd) ? fieldEnd : kInf);
    if (w.begin > horizonEnd)
        throw Error(m.place("goal.window.begin") + ": the arrival window opens at " + timeText(problem, w.begin) +
                    ", after the planning horizon ends (" + timeText(problem, horizonEnd) +
                    (std::isfinite(problem.getField()->timeEnd()) && horizonEnd >= problem.getField()->timeEnd() - 1e-9
                         ? ": the end of the forecast"
                         : ": planner.horizon") +
                    ")");
}

/// A via point's arrival window must not close before the mission could get there: the straight line through the
/// via points before it at the glider's speed plus the fastest current, and their stays.
void checkViaWindows(const MissionProblem &problem)
{
    const MissionSpec &m = problem.getSpec();
    if (m.waypoints.empty())
        return;
    Region box = problem.getBox();
    const double fastest = m.vehicle.speed + problem.getField()->maxSpeed(box);
    const double departure = m.departure.window ? m.departure.begin : m.departure.time;
    double t = departure;
    Point2 at = problem.getStart();
    for (std::size_t i = 0; i < m.waypoints.size(); ++i)
    {
        const ViaPointSpec &v = m.waypoints[i];
        const Point2 p = problem.getViaPoints()[i];
        // in the listed order the via points before it come first; in a free order it may be the first one
        if (m.order == VisitOrder::Free)
            t = departure + std::hypot(p.x - problem.getStart().x, p.y - problem.getStart().y) / fastest;
        else
            t += std::hypot(p.x - at.x, p.y - at.y) / fastest;
        const std::string field = "waypoints[" + std::to_string(i) + "]";
        if (v.arrive.set && v.arrive.end < t)
            throw Error(m.place(field + ".arrive.end") + " (via point '" + v.name +
                        "'): the arrival window closes at " + timeText(problem, v.arrive.end) +
                        ", before the glider can get there (no earlier than " + timeText(problem, t) +
                        " at its speed plus the fastest current)");
        t = std::max(t, v.arrive.set ? v.arrive.begin : t) + v.stay;
        at = p;
    }
}

double chooseDeparture(const MissionProblem &problem, const RunOptions &options, MissionResult &result)
{
    const MissionSpec &m = problem.getSpec();
    if (!m.departure.window)
        return m.departure.time;
    DepartureSearchParams p;
    p.windowBegin = m.departure.begin;
    p.windowEnd = m.departure.end;
    p.spacing = m.departure.spacing;
    p.tolerance = m.departure.tolerance;
    p.horizon = problem.getField()->timeEnd();
    p.minTripDuration = problem.minTripDuration(m.vehicle.speed);
    p.threads = m.departure.threads;
    p.progress = options.progress;
    const TravelTimeOfDeparture fine = departureFunction(problem);
    TravelTimeOfDeparture coarse;
    if (m.departure.coarseGridSize > 0)
        coarse = departureFunction(problem, m.departure.coarseGridSize, m.departure.coarseSectors);
    result.departureSearch = optimalDepartureTime(fine, p, coarse);
    return result.departureSearch->found ? result.departureSearch->departure : m.departure.begin;
}

/// Refuses (in @p r) a start or goal that land's keep-off band, shallow water or another static region forbids, in
/// the pilot's terms (lon/lat, km) before the planner would refuse it in its plane; true when one is refused.
bool refuseBlockedEndpoint(const MissionProblem &problem, double departure, PlannedPath &r)
{
    const std::shared_ptr<const Environment> &env = problem.getEnvironment();
    if (!env || !problem.isGeographic())
        return false;
    const Point2 s = problem.getStart(), g = problem.getGoal();
    for (const bool start : {true, false})
    {
        const Point2 q = start ? s : g;
        const std::string why = start || env->isStatic() ? env->whyBlocked(q.x, q.y, departure) : std::string();
        if (why.empty())
            continue;
        const LonLat p = problem.toGeographic(q);
        char where[96];
        std::snprintf(where, sizeof where, " (lon %.5f, lat %.5f)", p.lon, p.lat);
        r.status = start ? PlanStatus::InvalidStart : PlanStatus::InvalidGoal;
        r.badInput = {start ? BadInput::Input::Start : BadInput::Input::Goal};
        r.setNoPath({NoPathCause::BadInput, "the " + r.badInput.field() + where + " is " + why});
        return true;
    }
    return false;
}

/// The result of a planner that planned stints (@p plan): flown, not smoothed, its surfacings the path.
void takeStintPlan(const MissionProblem &problem, const StintPlan &plan, double departure, PlannedPath &r)
{
    StintOutcome o;
    o.plan = plan;
    o.settings = stintSettings(problem, departure);
    r.solved = true;
    r.raw = r.smoothed = r.path = o.plan.surfacings;
    r.rawTravelTime = r.smoothedTravelTime = r.travelTime = r.path.back().t - departure;
    r.rawPathLength = r.pathLength = pathLength(o.plan.track);
    r.pathChecked = !o.plan.grounded;
    r.stints = std::move(o);
}

/// Why the search ended without a path: a start or goal the planner refused (@p r's bad input, in lon/lat where the
/// pilot gave them), or a lattice searched to its end (@p r's status, and a bound on the arrival).
NoPath noPathOfSearch(const MissionProblem &problem, const GliderProblem &gp, const ompl::base::PlannerStatus &status,
                      const ompl::base::Planner &planner, const GliderSimpleSetup &ss, double limit, PlannedPath &r)
{
    NoPath why = noPathReason(status, planner, ss, limit, problem.getSpec());
    if (status == ompl::base::PlannerStatus::INVALID_START || status == ompl::base::PlannerStatus::INVALID_GOAL)
    {
        const bool start = status == ompl::base::PlannerStatus::INVALID_START;
        r.badInput = {start ? BadInput::Input::Start : BadInput::Input::Goal};
        why.cause = NoPathCause::BadInput;
        if (problem.isGeographic())
        {
            // the planner speaks in its plane; the pilot gave lon/lat
            const LonLat p = problem.toGeographic(start ? problem.getStart() : problem.getGoal());
            char where[96];
            std::snprintf(where, sizeof where, " (lon %.5f, lat %.5f)", p.lon, p.lat);
            why.what += std::string("; the ") + r.badInput.field() + where;
        }
    }
    if (why.cause == NoPathCause::LatticeExhausted)
    {
        r.status = PlanStatus::NoPath; // OMPL's ABORT or TIMEOUT would send the user after a longer time limit
        boundArrival(problem, gp, why);
    }
    return why;
}

/// The search's @p path smoothed and refined (as the mission asks) into @p r's raw, smoothed and final waypoints,
/// their times and lengths, and the work and time it took.
void postProcess(ompl::geometric::PathGeometric path, const std::shared_ptr<GliderContext> &ctx, const MissionSpec &m,
                 double departure, bool smoothing, bool refinement, PlannedPath &r)
{
    r.raw = waypointsFromPath(path);
    r.rawTravelTime = r.raw.back().t - departure;
    r.rawPathLength = pathLength(r.raw);
    const std::uint64_t cfc1 = ctx->travel->costFunctionCalls();
    const auto tC = std::chrono::steady_clock::now();
    if (smoothing)
        PathSmoother(ctx).smooth(path);
    r.smoothed = waypointsFromPath(path);
    if (refinement)
        WaypointRefiner(ctx, refinerParams(m)).refine(path);
    r.path = waypointsFromPath(path);
    r.postprocessSeconds = secondsSince(tC);
    r.postprocessCostFunctionCalls = ctx->travel->costFunctionCalls() - cfc1;
    r.smoothedTravelTime = r.smoothed.back().t - departure;
    r.travelTime = r.path.back().t - departure;
    r.pathLength = pathLength(r.path);
    r.pathChecked = path.check();
}
} // namespace

/// planRoute() on the problem's one field.
PlannedPath planOnField(const MissionProblem &problem, double departure, const PlanOptions &o)
{
    const MissionSpec &m = problem.getSpec();
    PlannedPath r;
    r.departure = departure;
    r.speed = std::isnan(o.speed) ? m.vehicle.speed : o.speed;
    const PlannerEntry &entry = plannerEntry(o.planner.empty() ? m.planner.name : o.planner);
    r.planner = entry.name;
    const double grid = o.gridSize > 0 ? o.gridSize : m.planner.gridSize;
    const int sectors = o.sectors > 0 ? o.sectors : m.planner.sectors;
    const bool smoothing = o.smoothing.value_or(m.planner.smoothing);
    const bool refinement = o.refinement.value_or(m.planner.refinement);
    const Point2 s = problem.getStart(), g = problem.getGoal();
    r.straightLineLength = std::hypot(g.x - s.x, g.y - s.y);
    const GliderProblem gp = checkedProblem(problem, departure, r.speed);
    if (!(gp.horizon > 0))
    {
        r.status = PlanStatus::InvalidStart;
        r.setNoPath({NoPathCause::BadInput, "departure after the end of the forecast"});
        r.badInput = {BadInput::Input::DepartureTime};
        return r;
    }
    if (refuseBlockedEndpoint(problem, departure, r))
        return r;
    std::shared_ptr<GliderContext> ctx;
    const std::shared_ptr<GliderSimpleSetup> ss = makeSimpleSetup(gp, &ctx);
    const ompl::base::PlannerPtr planner =
        makePlanner(problem, ss->getSpaceInformation(), ctx, grid, sectors, departure, o.planner,
                    o.gridSize > 0 ? "departure.window.coarse_grid_size" : "planner.grid_size");
    const PipelinePlanner &answers = pipelineView(*planner);
    ss->setPlanner(planner);
    r.straightLineTime = legTravelTime(*ctx, s.x, s.y, g.x, g.y, departure);

    const double limit = o.timeLimit > 0           ? o.timeLimit
                         : m.planner.timeLimit > 0 ? m.planner.timeLimit
                                                   : (entry.runsToItsEnd() ? 0.0 : kDefaultSamplingTimeLimit);
    const std::uint64_t cfc0 = ctx->travel->costFunctionCalls(), cmc0 = ctx->field->callCount();
    const auto tA = std::chrono::steady_clock::now();
    // the time limit, or a stop request (StopRequest.h: Python's Ctrl-C)
    const ompl::base::PlannerStatus status = ss->solve(ompl::base::plannerOrTerminationCondition(
        limit > 0 ? ompl::base::timedPlannerTerminationCondition(limit) : ompl::base::plannerNonTerminatingCondition(),
        ompl::base::PlannerTerminationCondition([] { return stopRequested(); })));
    r.planningSeconds = secondsSince(tA);
    r.status = r.plannerStatus = planStatusOfOmpl(ompl::base::PlannerStatus::StatusType(status));
    r.searchCostFunctionCalls = ctx->travel->costFunctionCalls() - cfc0;
    r.currentModelCalls = ctx->field->callCount() - cmc0;
    r.expandedVertices = answers.expandedVertices();
    if (const StintPlan *plan = answers.lastStintPlan())
        if (ss->haveSolutionPath())
        {
            takeStintPlan(problem, *plan, departure, r);
            return r;
        }
    r.solved = ss->haveExactSolutionPath();
    if (const HeadingRoute *route = answers.lastHeadingRoute())
        if (r.solved)
        {
            r = headingResult(problem, *ctx, *route, std::move(r));
            reflyRoute(problem, *ctx, r);
            return r;
        }
    if (!r.solved && stopRequested())
    {
        r.status = PlanStatus::Stopped;
        r.setNoPath({NoPathCause::Stopped, "stopped on request (Ctrl-C) before a path was found"});
        return r;
    }
    if (!r.solved)
    {
        r.setNoPath(noPathOfSearch(problem, gp, status, *planner, *ss, limit, r));
        return r;
    }
    postProcess(ss->getSolutionPath(), ctx, m, departure, smoothing, refinement, r);
    reflyRoute(problem, *ctx, r);
    if (!r.solved)
        return r;
    if (m.stints.set)
    {
        const auto tS = std::chrono::steady_clock::now();
        r.stints = convertToStints(problem, r);
        r.stints->seconds = secondsSince(tS);
    }
    return r;
}
} // namespace planning_detail

PlannedPath planRoute(const MissionProblem &problem, double departure, const PlanOptions &o)
{
    using namespace planning_detail;
    PlannedPath r =
        problem.getMembers().empty() ? planOnField(problem, departure, o) : planRobust(problem, departure, o);
    r = switchToHeadings(problem, departure, o, std::move(r));
    r = checkGlobally(problem, departure, o, std::move(r));
    timeArrival(problem, r);
    if (r.solved)
        r.holdTime = holdTimeOf(r.path);
    return r;
}

TravelTimeOfDeparture departureFunction(const MissionProblem &problem, double gridSize, int sectors)
{
    using namespace planning_detail;
    return [&problem, gridSize, sectors](double tDep) {
        PlanOptions o;
        o.gridSize = gridSize;
        o.sectors = sectors;
        o.smoothing = false;
        o.refinement = false;
        o.globalCheck = false; // the departure's supporting points compare the planner's raw times
        try
        {
            const PlannedPath p = planMission(problem, tDep, o).plan;
            // with a goal window the travel time includes the holds that move the arrival into it, and a mission of
            // several legs is timed as flown (each leg departs at the previous one's arrival)
            const MissionSpec &m = problem.getSpec();
            return !p.solved ? kInf : m.goalWindow.set || !m.waypoints.empty() ? p.travelTime : p.rawTravelTime;
        }
        catch (const Error &)
        {
            return kInf; // e.g. a departure outside the forecast: no trip from there
        }
    };
}

MissionResult runMission(const MissionProblem &problem, const RunOptions &options)
{
    using namespace planning_detail;
    const auto start = std::chrono::steady_clock::now();
    MissionResult result;
    result.spec = problem.getSpec();
    const MissionSpec &m = result.spec;
    if (!m.fleet.empty())
        throw Error(m.place("fleet") + ": a fleet is planned glider by glider: runFleet() (mission/Fleet.h)");
    checkPlanner(problem, m.departure.window ? m.departure.begin : m.departure.time);
    checkGoalWindow(problem);
    checkViaWindows(problem);
    if (m.outputs.wants(OutputFormatId::Reachability))
        checkReachProbabilityMemory(problem); // refused now, not after the plan
    const double tDep = chooseDeparture(problem, options, result);
    if (result.departureSearch && !result.departureSearch->found)
    {
        result.plan.departure = m.departure.begin;
        result.plan.speed = m.vehicle.speed;
        result.plan.planner = plannerEntry(m.planner.name).name;
        result.plan.status = PlanStatus::NoPath;
        result.plan.setNoPath({NoPathCause::NoDeparture, "no departure in the window has a path within the forecast"});
        result.departureIso = problem.isoTime(result.plan.departure);
        result.wallSeconds = secondsSince(start);
        return result;
    }
    MissionPlan mission = planMission(problem, tDep);
    result.plan = std::move(mission.plan);
    result.legs = std::move(mission.legs);
    result.order = std::move(mission.order);
    result.orderSearch = std::move(mission.orderSearch);
    result.departureIso = problem.isoTime(result.plan.departure);
    if (result.legs.empty())
        diagnoseNoPath(problem, tDep, result.plan); // (each leg of a longer mission was diagnosed as planned)
    if (result.plan.solved)
    {
        PilotWaypoints w = missionWaypoints(problem, result.plan, result.legs);
        result.waypoints = std::move(w.waypoints);
        for (const PlannedLeg &l : result.legs)
            for (std::size_t i = l.firstPoint; i <= l.lastPoint && i < result.waypoints.size(); ++i)
                if (result.waypoints[i].missionLeg == 0)
                    result.waypoints[i].missionLeg = static_cast<int>(l.index + 1);
        result.diveProfiles = m.dive.enabled;
        if (m.dive.enabled)
            result.profileSet = makeDiveProfiles(m.dive.params);
        result.diveTravelTime = w.travelTime;
    }
    result.safetyNote = problem.safetyNote();
    result.forecastNotes = problem.forecastNotes();
    if (const std::string run = planning_detail::forecastRunNote(problem, result.plan); !run.empty())
        result.forecastNotes.insert(result.forecastNotes.begin(), run);
    for (const std::string &note : problem.endpointNotes())
        result.forecastNotes.push_back(note);
    // how the glider's DAC corrected the forecast: the report's words for a pilot (correctionLines()), summary.json's
    // figures
    result.observations = problem.observations();
    if (const std::string frozen = planning_detail::frozenFieldNote(problem, result.plan); !frozen.empty())
        result.forecastNotes.push_back(frozen);
    result.coastlineNote = problem.coastlineNote();
    if (result.plan.solved && problem.getLand())
    {
        const PlannedPath &p = result.plan;
        result.closestLand = closestApproach(*problem.getLand(), p.track.size() > 1 ? p.track : p.path);
        if (problem.isGeographic() && std::isfinite(result.closestLand.distance))
            result.closestLandLonLat = problem.toGeographic(result.closestLand.where);
    }
    if (options.optimum && !result.legs.empty())
        result.optimum = missionOptimumReference(problem, result);
    else if (options.optimum)
    {
        // Any flown path bounds the optimum; without one, the planning horizon does.
        const double horizon = problem.horizon(tDep, result.plan.speed);
        result.optimum =
            optimumReference(problem, tDep, result.plan.speed,
                             result.plan.solved ? std::min(horizon, 1.2 * result.plan.travelTime) : horizon);
    }
    const std::vector<double> speeds = options.speeds ? *options.speeds : m.speeds;
    if (!speeds.empty())
        result.speedSweep = speedSweep(problem, tDep, speeds, options.progress);
    if (m.execution.enabled)
    {
        std::vector<ExecutionLeg> legs; // a mission of several legs: each leg's end and held headings
        for (const PlannedLeg &l : result.legs)
            legs.push_back({l.lastPoint, l.plan.headings});
        result.execution = executeMission(problem, result.plan, legs, options.progress);
    }
    if (m.outputs.wants(OutputFormatId::Isochrones))
        result.isochrones = computeIsochrones(problem, result.plan, tDep, m.outputs.isochroneInterval);
    if (m.outputs.wants(OutputFormatId::Reachability))
        result.reachability = computeReachProbability(problem, result.plan, tDep);
    result.wallSeconds = secondsSince(start);
    return result;
}
} // namespace ompl_glider
