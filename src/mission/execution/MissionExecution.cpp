// The mission's execution in another ocean: plans flown with each control strategy in the truth field,
// for the mission's own pair and a batch of random pairs, in parallel (in threads, or spread over the ranks of an MPI
// job: TaskSpread.h).
#include "ompl_glider/mission/MissionExecution.h"
#include "ompl_glider/mission/MissionLegs.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <mutex>
#include <random>

#include "ompl_glider/Exception.h"
#include "ompl_glider/TaskSpread.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/current/EnsembleLearning.h"
#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "../../io/NumberText.h"
#include "ExecutionOracle.h"
#include "ExecutionOutcome.h"
#include "ExecutionPacking.h"
#include "ExecutionRuns.h"
#include "ExecutionTruth.h"
#include "../planning/PlanningInternal.h"

namespace ompl_glider
{
namespace
{
/// Surfacing interval of the mission: given, else one hour in its time unit; a mission without a time unit (its
/// numbers are no seconds) gets a twentieth of the planned trip @p trip. @p source says which.
double surfacingInterval(const MissionSpec &m, double trip, std::string &source)
{
    if (!std::isnan(m.execution.surfacingInterval))
    {
        source = "given";
        return m.execution.surfacingInterval;
    }
    if (m.hasTimeUnit())
    {
        source = "default: 1 h";
        return 3600.0 / m.timeUnitSeconds;
    }
    source = "default: a twentieth of the planned trip (the mission has no time unit)";
    return trip / 20.0;
}

bool freeAt(const MissionProblem &problem, Point2 p, double t)
{
    const double z = problem.getSpec().vehicle.depth;
    if (!problem.getField()->inWater(p.x, p.y, z) || !problem.getTruth()->inWater(p.x, p.y, z))
        return false;
    const auto &env = problem.getEnvironment();
    return !env || env->pointFree(p.x, p.y, t);
}

/// The rest of @p plan flown from the fix (x, y) at t, re-timed on the forecast: the fix, a leg to one of the
/// plan's waypoints after t, then the plan's later waypoints. The waypoint joined is the one giving the earliest
/// arrival (a fix a little off the plan in a strong current may not reach the next waypoint, but a later one or
/// the goal). Empty when no choice is passable (land, forbidden, beyond the forecast).
std::vector<TimedPoint> continuation(const MissionProblem &problem, double x, double y, double t,
                                     const std::vector<TimedPoint> &plan)
{
    std::size_t first = 0;
    while (first < plan.size() && plan[first].t <= t)
        ++first;
    if (first == plan.size())
        first = plan.size() - 1; // late: the goal is the only waypoint left
    std::vector<TimedPoint> best;
    for (std::size_t k = first; k < plan.size(); ++k)
    {
        std::vector<TimedPoint> via{{x, y, t}};
        via.insert(via.end(), plan.begin() + static_cast<std::ptrdiff_t>(k), plan.end());
        std::vector<TimedPoint> rest = retimePath(problem, problem.getField(), problem.getSpec().vehicle.speed, via);
        if (!rest.empty() && (best.empty() || rest.back().t < best.back().t))
            best = std::move(rest);
    }
    return best;
}

/// Plans of the replan strategy: from the fix to the run's goal on the forecast (smoothing as the mission asks,
/// no refinement, no global check, no switch to heading planners where straight legs find none: a plan per
/// surfacing must be quick, and the plan being flown is kept when there is no new one). The new plan is taken only
/// when the forecast says it arrives earlier, by more than @p margin (the surfacing interval), than the rest of the
/// current plan flown from the fix (re-timed on the forecast): a lattice anchored at an arbitrary fix can be much
/// coarser than the plan it would replace, and a plan's times assume a heading adjusted all along each leg, which a
/// glider holding one heading per dive cannot fly exactly (a new plan that gains less than a dive on paper is noise).
Replanner replanner(const MissionProblem &mission, Point2 goal, double margin)
{
    return [&mission, goal, margin](double x, double y, double t,
                                    const std::vector<TimedPoint> &current) -> std::vector<TimedPoint> {
        const MissionProblem problem =
            execution_detail::onRunAt(mission, t); // with forecast runs, the newest available now
        std::vector<TimedPoint> rest = continuation(problem, x, y, t, current);
        const Region &box = problem.getBox();
        if (x < box.xMin || x > box.xMax || y < box.yMin || y > box.yMax)
            return rest; // drifted out of the planning box: no new plan
        PlanOptions o;
        o.refinement = false;
        o.globalCheck = false; // a replan at every surfacing: the lattice alone, judged against the plan being flown
        o.headingFallback = false; // nor the heading planners where it finds none (the level set can take minutes)
        try
        {
            const PlannedPath p = planRoute(problem.withEndpoints({x, y}, goal), t, o);
            if (p.solved && (rest.empty() || p.path.back().t < rest.back().t - margin))
                return p.path;
        }
        catch (const Error &)
        {
            // e.g. the fix lies where the lattice cannot start: keep the current plan
        }
        return rest;
    };
}

/// @p problem without its ensemble's members (planned on their mean), or itself for one forecast.
MissionProblem planningOnMean(const MissionProblem &problem)
{
    return problem.getMembers().empty() ? problem : problem.withField(problem.getField());
}

/// Plans of the replan_observed strategy: as replanner(), on the forecast the DAC measured so far make (the flight's
/// learning: flightLearning()). Without a measurement, or with innovations that are all zero (a truth equal to the
/// forecast), that forecast is the forecast to the bit.
ObservedReplanner observedReplanner(const MissionProblem &problem, Point2 goal, double margin)
{
    return [&problem, goal, margin](double x, double y, double t, const std::vector<TimedPoint> &current,
                                    const std::shared_ptr<const CurrentField> &learned) {
        return replanner(problem.withField(learned), goal, margin)(x, y, t, current);
    };
}

/// The forecast the DAC of one flight make, learned as they arrive (FlightLearning: the mission's correction
/// parameters; an ensemble's members weighed and updated); a new one for each flight (its estimates are the flight's).
DacLearning flightLearning(const MissionProblem &problem)
{
    if (problem.runs())
        return execution_detail::runsLearning(problem);
    auto learning =
        std::make_shared<FlightLearning>(problem.getField(), problem.getMembers(), problem.correctionParams());
    return [learning](const std::vector<DacObservation> &measured) { return (*learning)(measured); };
}

/// The settings of one flight of @p run's plan (or a leg of it) with @p settings.
ExecutionOptions flightOptions(const MissionProblem &problem, const ExecutionResult &settings, double radius)
{
    const MissionSpec &m = problem.getSpec();
    ExecutionOptions o;
    o.surfacingInterval = settings.surfacingInterval;
    o.step = settings.step;
    o.radius = radius;
    o.depth = m.vehicle.depth;
    o.replanEvery = settings.replanEvery;
    o.dacNoise = m.execution.dacNoise;
    o.correction = problem.correctionParams();
    o.learn = flightLearning(problem);
    // with an ensemble the dac strategy aims off with the members weighed by the DAC, not the last DAC alone
    o.learnSteersDac = !problem.getMembers().empty();
    return o;
}

/// The plan of a leg from where and when the glider is (@p at): the planned leg re-timed from there (continuation()),
/// else, where the current of the new hour makes its legs impassable, a new plan of the leg as a pilot would make it
/// at the surfacing (the lattice, as the replan strategy plans), else the straight line at the planned pace.
std::vector<TimedPoint> legFrom(const MissionProblem &problem, TimedPoint at, Point2 to,
                                const std::vector<TimedPoint> &planned)
{
    std::vector<TimedPoint> moved = continuation(problem, at.x, at.y, at.t, planned);
    if (!moved.empty())
        return moved;
    PlanOptions o;
    o.refinement = false;
    o.globalCheck = false;
    o.headingFallback = false;
    try
    {
        const PlannedPath p = planRoute(problem.withEndpoints({at.x, at.y}, to), at.t, o);
        if (p.solved)
            return p.path;
    }
    catch (const Error &)
    {
        // e.g. the fix lies where the lattice cannot start: the straight line below
    }
    return {at, {to.x, to.y, at.t + (planned.back().t - planned.front().t)}};
}

/// Flies a mission of several legs with strategy @p s: each leg's plan re-timed from the glider's fix, its station
/// the goal, holds at the stations (window, stay), the legs' flights joined into one track.
FlownTrack flyMission(const MissionProblem &problem, const ExecutionResult &settings, const ExecutionRun &run,
                      ControlStrategy s)
{
    // an ensemble's forecast-only flights and plans are on the members' mean (MissionProblem::withField() leaves the
    // members out); the learning of the DAC strategies weighs the members themselves
    const MissionProblem onMean = planningOnMean(problem);
    const MissionSpec &m = problem.getSpec();
    const double speed = m.vehicle.speed;
    const execution_detail::RunEnd runEnd =
        execution_detail::runEnd(problem, run.plan.front().t, run.plan.back().t - run.plan.front().t);
    const double end = runEnd.time;
    FlownTrack out;
    std::string notReached, late; // the first station (or the goal) not reached; the stations reached late
    double notReachedRadius = 0.0;
    out.plannedArrival = run.plan.back().t;
    out.fixes.push_back(run.plan.front());
    out.track.push_back(run.plan.front());
    std::vector<DacObservation> measured;
    TimedPoint at = run.plan.front();
    std::size_t first = 0;                                // the leg's first point in the plan
    const DacLearning learning = flightLearning(problem); // one for the whole flight: the DAC of every leg
    const std::shared_ptr<const CurrentField> steering = execution_detail::steeringField(problem);
    for (std::size_t k = 0; k < run.legs.size(); ++k)
    {
        const bool last = k + 1 == run.legs.size();
        const ExecutionLeg &leg = run.legs[k];
        const Point2 to = last ? run.goal : settings.stops[k].at;
        const double radius = last ? run.radius : settings.stops[k].radius;
        const auto missed = [&] {
            notReached = last ? std::string("the goal") : "station " + settings.stops[k].name;
            notReachedRadius = radius;
        };
        if (at.t >= end) // the run ended at the last station (its hold): this leg is not flown
        {
            missed();
            break;
        }
        // the leg as planned, flown from where and when the glider is (the plan's own times where it is on time)
        std::vector<TimedPoint> legPlan(run.plan.begin() + static_cast<std::ptrdiff_t>(first),
                                        run.plan.begin() + static_cast<std::ptrdiff_t>(leg.end) + 1);
        if (at.x != legPlan.front().x || at.y != legPlan.front().y || at.t != legPlan.front().t)
            legPlan = legFrom(execution_detail::onRunAt(problem, at.t), at, to, legPlan);
        ExecutionOptions o = flightOptions(problem, settings, radius);
        o.endTime = end;
        o.headings = leg.headings && at.x == leg.headings->start.x && at.y == leg.headings->start.y &&
                             at.t == leg.headings->departure
                         ? &*leg.headings
                         : nullptr; // held headings from where they were planned to begin
        o.measuredBefore = measured;
        o.learn = learning;
        if (s == ControlStrategy::Replan)
            o.replan = replanner(onMean, to, settings.surfacingInterval);
        if (s == ControlStrategy::ReplanObserved)
            o.replanObserved = observedReplanner(problem, to, settings.surfacingInterval);
        // planned_headings on a leg of straight legs (or one begun elsewhere) steers as current_sensitive does
        const ControlStrategy flown =
            s == ControlStrategy::PlannedHeadings && !o.headings ? ControlStrategy::CurrentSensitive : s;
        o.replanAt = execution_detail::runArrivals(problem, at.t);
        const FlownTrack f =
            flyPlan(legPlan, speed, *steering, *problem.getTruth(), problem.getEnvironment().get(), flown, o);
        out.fixes.insert(out.fixes.end(), f.fixes.begin() + 1, f.fixes.end());
        out.track.insert(out.track.end(), f.track.begin() + 1, f.track.end());
        out.headings.insert(out.headings.end(), f.headings.begin(), f.headings.end());
        out.replans += f.replans;
        measured = f.measured;
        out.grounded = f.grounded;
        out.groundedWhy = f.groundedWhy;
        if (!f.reached)
        {
            missed();
            break;
        }
        at = f.track.back();
        if (last)
        {
            out.reached = out.windowsMissed == 0;
            out.arrivalTime = f.arrivalTime;
            break;
        }
        const ExecutionStop &stop = settings.stops[k];
        ++out.stationsReached;
        if (stop.window && f.arrivalTime > stop.windowEnd)
        {
            ++out.windowsMissed;
            late += (late.empty() ? "" : "; ") + execution_detail::lateText(problem, stop, f.arrivalTime);
        }
        // held in place until the window opens, then for the stay; the run's end ends the hold too (no flight of
        // the run outlasts it: the next leg, begun there, flies no more)
        const double leave = std::min(std::max(at.t, stop.window ? stop.windowBegin : at.t) + stop.stay, end);
        if (leave > at.t)
        {
            at.t = leave;
            out.fixes.push_back(at);
            out.track.push_back(at);
        }
        first = leg.end;
    }
    out.measured = std::move(measured);
    out.notReachedWhy = execution_detail::notReachedWhy(problem, out, notReached, notReachedRadius, runEnd, late);
    const TimedPoint endPoint = out.track.back();
    const TimedPoint then = planAt(out.track, out.plannedArrival);
    out.finalDistance = std::hypot(then.x - run.goal.x, then.y - run.goal.y);
    const double flownFor = endPoint.t - run.plan.front().t;
    out.madeGoodSpeed =
        flownFor > 0.0 ? std::hypot(endPoint.x - run.plan.front().x, endPoint.y - run.plan.front().y) / flownFor : 0.0;
    return out;
}

/// Flies one planned run with every strategy.
void flyRun(const MissionProblem &problem, const ExecutionResult &settings, ExecutionRun &run)
{
    // an ensemble's forecast-only flights and plans are on the members' mean (MissionProblem::withField() leaves the
    // members out); the learning of the DAC strategies weighs the members themselves
    const MissionProblem onMean = planningOnMean(problem);
    const MissionSpec &m = problem.getSpec();
    const double speed = m.vehicle.speed;
    const double planned = run.plan.back().t - run.plan.front().t;
    if (!run.legs.empty())
    {
        for (ControlStrategy s : settings.strategies)
            run.flown.push_back(flyMission(problem, settings, run, s));
        return;
    }
    ExecutionOptions o = flightOptions(problem, settings, run.radius);
    const execution_detail::RunEnd end = execution_detail::runEnd(problem, run.plan.front().t, planned);
    o.endTime = end.time; // never beyond the truth (checkTruthTimes())
    o.headings = run.headings ? &*run.headings : nullptr;
    o.replanAt = execution_detail::runArrivals(problem, run.plan.front().t);
    const std::shared_ptr<const CurrentField> steering = execution_detail::steeringField(problem);
    for (ControlStrategy s : settings.strategies)
    {
        o.learn = flightLearning(problem); // each flight learns from its own DAC
        if (s == ControlStrategy::Replan)
            o.replan = replanner(onMean, run.goal, settings.surfacingInterval);
        if (s == ControlStrategy::ReplanObserved)
            o.replanObserved = observedReplanner(problem, run.goal, settings.surfacingInterval);
        run.flown.push_back(
            flyPlan(run.plan, speed, *steering, *problem.getTruth(), problem.getEnvironment().get(), s, o));
        run.flown.back().notReachedWhy =
            execution_detail::notReachedWhy(problem, run.flown.back(), "the goal", run.radius, end, "");
    }
}
/// The oracle of @p run (ExecutionRun::oracleArrival): its pair planned on the truth as the run was on the forecast,
/// flown in the truth with the truth as its forecast by @p oracle's one strategy (current_sensitive); the arrival
/// when it reached the goal, else NaN.
void flyOracle(const MissionProblem &problem, const ExecutionResult &oracle, ExecutionRun &run)
{
    const auto t0 = std::chrono::steady_clock::now();
    const MissionProblem onTruth = problem.withField(problem.getTruth());
    ExecutionRun o = execution_detail::oraclePlan(onTruth, run, !oracle.stops.empty());
    if (o.planned)
    {
        flyRun(onTruth, oracle, o);
        if (o.flown.front().reached)
            run.oracleArrival = o.flown.front().arrivalTime;
    }
    run.oracleSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The settings of the oracle's flights (flyOracle()): @p r's, with current_sensitive its one strategy.
ExecutionResult oracleSettings(const ExecutionResult &r)
{
    ExecutionResult oracle;
    oracle.strategies = {ControlStrategy::CurrentSensitive};
    oracle.surfacingInterval = r.surfacingInterval;
    oracle.step = r.step;
    oracle.replanEvery = r.replanEvery;
    oracle.stops = r.stops;
    return oracle;
}

/// A mission of several legs: its via points as the stations every run flies to (empty for one leg).
std::vector<ExecutionStop> executionStops(const MissionProblem &problem, double goalRadius)
{
    const MissionSpec &m = problem.getSpec();
    const std::vector<Point2> &via = problem.getViaPoints();
    std::vector<ExecutionStop> stops;
    if (m.waypoints.empty())
        return stops;
    for (std::size_t i = 0; i < via.size(); ++i)
    {
        const ViaPointSpec &v = m.waypoints[i];
        ExecutionStop stop;
        stop.name = v.name;
        stop.at = via[i];
        // the via point's radius, else the goal's (execution.radius, or 1 % of the start-goal distance)
        stop.radius = std::isfinite(v.radius) ? v.radius : goalRadius;
        stop.window = v.arrive.set;
        stop.windowBegin = v.arrive.begin;
        stop.windowEnd = v.arrive.end;
        stop.stay = v.stay;
        stops.push_back(stop);
    }
    return stops;
}

} // namespace

double rmsDifference(const CurrentField &a, const CurrentField &b, double x, double y, double z, double t0, double t1,
                     int samples)
{
    if (!a.inWater(x, y, z) || !b.inWater(x, y, z))
        return std::numeric_limits<double>::quiet_NaN();
    double sum = 0.0;
    const int n = std::max(1, samples);
    for (int k = 0; k < n; ++k)
    {
        const double t = n == 1 ? t0 : t0 + (t1 - t0) * k / (n - 1);
        const Velocity ca = a.velocity(x, y, z, t), cb = b.velocity(x, y, z, t);
        sum += (ca.u - cb.u) * (ca.u - cb.u) + (ca.v - cb.v) * (ca.v - cb.v);
    }
    return std::sqrt(sum / n);
}

std::vector<std::pair<Point2, Point2>> executionPairs(const MissionProblem &problem, unsigned count, unsigned seed,
                                                      double minDistance, double departure)
{
    const Region &box = problem.getBox();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> ux(box.xMin, box.xMax), uy(box.yMin, box.yMax);
    std::vector<std::pair<Point2, Point2>> pairs;
    for (unsigned k = 0; k < count; ++k)
    {
        bool found = false;
        for (int attempt = 0; attempt < 1000 && !found; ++attempt)
        {
            const Point2 a{ux(rng), uy(rng)}, b{ux(rng), uy(rng)};
            if (std::hypot(b.x - a.x, b.y - a.y) < minDistance || !freeAt(problem, a, departure) ||
                !freeAt(problem, b, departure))
                continue;
            pairs.emplace_back(a, b);
            found = true;
        }
        if (!found)
            throw Error(problem.getSpec().place("execution.batch") + ": no start/goal pair " +
                        text::number(minDistance) +
                        " or more apart with both ends in water found in 1000 tries "
                        "(pair " +
                        std::to_string(k + 1) + "): lower execution.batch.min_distance");
    }
    return pairs;
}

/// The control strategies of the mission's execution section, the plan's own headings first for a heading route
/// (unless the mission lists its strategies).
std::vector<ControlStrategy> executionStrategies(const MissionSpec &m, const PlannedPath &plan,
                                                 const std::vector<ExecutionLeg> &legs)
{
    const ExecutionSpec &e = m.execution;
    std::vector<ControlStrategy> strategies;
    for (const std::string &name : e.strategies)
    {
        const auto s = parseControlStrategy(name);
        if (!s)
            throw Error(m.place("execution.strategies") + ": unknown strategy '" + name + "'");
        strategies.push_back(*s);
    }
    // a heading route is flown by its own headings too, unless the mission lists its strategies
    bool headingLegs = false;
    for (const ExecutionLeg &l : legs)
        headingLegs = headingLegs || l.headings.has_value();
    if ((plan.headingRoute() || headingLegs) && e.strategies == ExecutionSpec().strategies)
        strategies.insert(strategies.begin(), ControlStrategy::PlannedHeadings);
    return strategies;
}

/// The runs of the start/goal @p pairs, the mission's own first (with its @p plan and @p legs, or why it has none),
/// each with its goal radius (@p radius, NaN: 1 % of its start-goal distance).
std::vector<ExecutionRun> executionRuns(const std::vector<std::pair<Point2, Point2>> &pairs, const PlannedPath &plan,
                                        const std::vector<ExecutionLeg> &legs, double radius)
{
    std::vector<ExecutionRun> runs(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i)
    {
        ExecutionRun &run = runs[i];
        run.index = static_cast<unsigned>(i);
        run.start = pairs[i].first;
        run.goal = pairs[i].second;
        run.departure = plan.departure;
        const double d = std::hypot(run.goal.x - run.start.x, run.goal.y - run.start.y);
        run.radius = std::isnan(radius) ? 0.01 * d : radius;
    }
    if (plan.solved)
    {
        runs[0].planned = true;
        runs[0].plan = plan.path;
        runs[0].headings = plan.headings;
        runs[0].legs = legs;
    }
    else
        runs[0].reason = plan.reason;
    return runs;
}

ExecutionResult executeMission(const MissionProblem &problem, const PlannedPath &plan,
                               const std::vector<ExecutionLeg> &legs, const ProgressSink &progress)
{
    // an ensemble's forecast-only flights and plans are on the members' mean (MissionProblem::withField() leaves the
    // members out); the learning of the DAC strategies weighs the members themselves
    const MissionProblem onMean = planningOnMean(problem);
    const auto t0 = std::chrono::steady_clock::now();
    const MissionSpec &m = problem.getSpec();
    const ExecutionSpec &e = m.execution;
    ExecutionResult r;
    r.strategies = executionStrategies(m, plan, legs);
    r.truth = e.truth ? problem.getTruth()->name() : kTruthIsForecast;
    const double trip = plan.solved ? plan.path.back().t - plan.departure : problem.minTripDuration(m.vehicle.speed);
    r.surfacingInterval = surfacingInterval(m, trip, r.surfacingIntervalSource);
    if (!(r.surfacingInterval > 0.0) || !std::isfinite(r.surfacingInterval))
        throw Error(m.place("execution.surfacing_interval") + ": expected a duration > 0");
    // 30 RK4 steps per dive: the truth is smooth on that scale for every field here (checked against the closed
    // form in the tests: drift errors far below the goal radius)
    r.step = r.surfacingInterval / 30.0;
    r.replanEvery = e.replanEvery;

    const Region &box = problem.getBox();
    const double diagonal = std::hypot(box.xMax - box.xMin, box.yMax - box.yMin);
    const double minDistance = std::isnan(e.minDistance) ? 0.25 * diagonal : e.minDistance;
    std::vector<std::pair<Point2, Point2>> pairs{{problem.getStart(), problem.getGoal()}};
    if (e.pairs > 0)
    {
        const auto more = executionPairs(problem, e.pairs, e.seed, minDistance, plan.departure);
        pairs.insert(pairs.end(), more.begin(), more.end());
    }
    {
        // surfacings per flight over its window (the mission's duration, else twice the planned trip)
        const double window = std::isnan(e.duration) ? 2.0 * trip : e.duration;
        planning_detail::checkExecutionWork(m, r.surfacingInterval, window, pairs.size(), r.strategies.size());
        execution_truth::checkTruthTimes(problem, plan, window, r);
        execution_truth::checkTruthSpace(problem, plan, r);
    }
    r.runs = executionRuns(pairs, plan, legs, e.radius);
    r.stops = executionStops(problem, r.runs[0].radius); // a mission of several legs: the stations of every run
    r.oracle = e.truth.has_value(); // where the truth is the forecast there is nothing to measure against
    const ExecutionResult oracle = oracleSettings(r);

    const auto planAndFly = [&](ExecutionRun &run) {
        if (run.index > 0) // a pair of the batch, planned as the mission is (through its stations, in its order)
            execution_detail::planPair(onMean, run, !r.stops.empty());
        if (run.planned)
            flyRun(problem, r, run);
        if (r.oracle)
            flyOracle(problem, oracle, run);
    };
    const auto report = [&](std::size_t n) {
        char line[96];
        std::snprintf(line, sizeof line, "execution: %zu/%zu runs flown", n, r.runs.size());
        progress(line, n == r.runs.size());
    };
    if (TaskSpreader *spread = activeTaskSpreader())
    {
        // the runs spread over the processes of a job, each returned whole
        const std::vector<std::string> out = spread->run(
            "execution run", r.runs.size(),
            [&](std::size_t i) {
                ExecutionRun run = r.runs[i];
                planAndFly(run);
                return execution_detail::packRun(run);
            },
            [&](std::size_t n, std::size_t) {
                if (progress)
                    report(n);
            });
        for (std::size_t i = 0; i < out.size(); ++i)
            execution_detail::unpackRun(out[i], r.runs[i]);
        r.threads =
            static_cast<unsigned>(std::min<std::size_t>(static_cast<std::size_t>(spread->size()), r.runs.size()));
    }
    else
    {
        ThreadPool pool(e.threads);
        r.threads = std::min<unsigned>(pool.size(), static_cast<unsigned>(r.runs.size()));
        std::atomic<std::size_t> done{0};
        std::mutex printMutex;
        pool.parallelFor(r.runs.size(), [&](std::size_t i) {
            planAndFly(r.runs[i]);
            if (progress)
            {
                std::lock_guard<std::mutex> lock(printMutex);
                report(++done);
            }
        });
    }

    for (const ExecutionRun &run : r.runs)
        r.oracleSeconds += run.oracleSeconds;
    r.spread = execution_detail::strategySpreads(r);
    execution_truth::modelDifference(problem, plan,
                                     r); // the truth against the forecast over the box and the runs' time window
    r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}
} // namespace ompl_glider
