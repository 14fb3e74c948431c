#include "ompl_glider/mission/Planning.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <mutex>
#include <cmath>
#include <cstdio>

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ResourceLimits.h"
#include "ompl_glider/cost/DiveProfilePool.h"
#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/planners/Lattice.h"
#include "ompl_glider/planners/PathSmoother.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#include "ompl_glider/planners/Wavefront.h"
#include "ompl_glider/planners/WaypointRefiner.h"
#include "ompl_glider/planners/ZAStarTVE.h"
#include "ompl_glider/reachability/LevelSetPlanner.h"
#include "ompl_glider/ompl/TravelTimeMotionValidator.h"
#include "ompl_glider/reference/ZermeloReference.h"
#include "ompl_glider/stints/PathToStints.h"
#include "ompl_glider/stints/StintPlanner.h"

namespace ompl_glider
{
namespace
{
/// The status of a well-formed problem whose search ended without a path for want of one, not of time.
const char *const kNoPathStatus = "No path";

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Time limit of planners that use all the time they get (sampling planners) when the mission gives none.
constexpr double kDefaultSamplingTimeLimit = 10.0;

double secondsSince(std::chrono::steady_clock::time_point a)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

/// Pipeline settings that a mission gives as planner fields, not as planner parameters.
bool pipelineParameter(const std::string &name)
{
    return name == "refiner_max_evaluations";
}

std::string parameterPlace(const MissionSpec &m, const std::string &name)
{
    const auto it = m.planner.parameterMarks.find(name);
    const SourceMark mark = it != m.planner.parameterMarks.end() ? it->second : SourceMark{m.file, 0};
    return (mark.line > 0 ? mark.file + ":" + std::to_string(mark.line) : mark.file) + ": field 'planner.parameters." +
           name + "'";
}

/// Sets the mission's planner parameters through OMPL's ParamSet (the names of declareParam).
void applyParameters(const MissionSpec &m, ompl::base::Planner &planner)
{
    ompl::base::ParamSet &params = planner.params();
    for (const auto &[name, value] : m.planner.parameters)
    {
        if (name == "grid_size" || name == "sectors" || name == "smooth" || name == "refine")
            throw Error(parameterPlace(m, name) + ": set it as planner." +
                        (name == "smooth" ? std::string("smoothing") :
                         name == "refine" ? std::string("refinement") : name) +
                        ", which every planner of the pipeline honours");
        if (params.hasParam(name))
        {
            const std::string range = params[name].getRangeSuggestion();
            // OMPL reads any text other than "true"/"1" as false for a bool parameter (range "0,1")
            if (range == "0,1" && value != "0" && value != "1" && value != "true" && value != "false")
                throw Error(parameterPlace(m, name) + ": planner " + planner.getName() +
                            " expects true or false, got '" + value + "'");
            bool accepted = false;
            try
            {
                accepted = params.setParam(name, value);
            }
            catch (const std::exception &e)  // a setter that refuses the value with its own reason
            {
                throw Error(parameterPlace(m, name) + ": " + e.what());
            }
            if (!accepted)
                throw Error(parameterPlace(m, name) + ": planner " + planner.getName() + " rejects the value '" +
                            value + "' (range " + range + ")");
            // OMPL converts leniently ("1e12" becomes 1 for an integer): read the value back and refuse a change.
            const std::string stored = params[name].getValue();
            char *endA = nullptr, *endB = nullptr;
            const double want = std::strtod(value.c_str(), &endA), got = std::strtod(stored.c_str(), &endB);
            if (endA != value.c_str() && *endA == '\0' && endB != stored.c_str() &&
                !(std::abs(want - got) <= 1e-9 * std::max(1.0, std::abs(want))))
                throw Error(parameterPlace(m, name) + ": planner " + planner.getName() + " rejects the value '" +
                            value + "' (it would be read as " + stored + "; range " + range + ")");
        }
        else if (!pipelineParameter(name))
        {
            std::vector<std::string> names;
            params.getParamNames(names);
            std::string list;
            for (const std::string &n : names)
                if (n != "grid_size" && n != "sectors" && n != "smooth" && n != "refine")
                    list += (list.empty() ? "" : ", ") + n;
            throw Error(parameterPlace(m, name) + ": planner " + planner.getName() + " has no parameter '" + name +
                        "' (it has: " + (list.empty() ? std::string("none") : list) + ")");
        }
    }
}

RefinerParams refinerParams(const MissionSpec &m)
{
    RefinerParams rp;
    const auto it = m.planner.parameters.find("refiner_max_evaluations");
    if (it != m.planner.parameters.end())
    {
        char *end = nullptr;
        const double v = std::strtod(it->second.c_str(), &end);
        if (end == it->second.c_str() || *end != '\0' || !(v >= 1.0 && v <= 1e8) || v != std::floor(v))
            throw Error(parameterPlace(m, it->first) + ": expected an integer in 1..100000000, got '" + it->second +
                        "'");
        rp.maxEvaluations = static_cast<unsigned>(v);
    }
    return rp;
}

/// The configured planner of the mission on the setup's space information.
ompl::base::PlannerPtr makePlanner(const MissionProblem &problem, const ompl::base::SpaceInformationPtr &si,
                                   const std::shared_ptr<const GliderContext> &ctx, double grid, int sectors,
                                   double departure)
{
    const MissionSpec &m = problem.getSpec();
    const PlannerEntry &entry = plannerEntry(m.planner.name);
    ompl::base::PlannerPtr planner = entry.make(si, ctx);
    if (auto st = std::dynamic_pointer_cast<StintPlanner>(planner))
    {
        if (!m.stints.set)
            throw Error(m.place("planner.name") + ": planner '" + entry.name +
                        "' flies constant-bearing stints: give a 'stints' section (duration, mission_duration)");
        st->setStintSettings(stintSettings(problem, departure));
    }
    if (auto z = std::dynamic_pointer_cast<ZAStarTVE>(planner))
    {
        z->setGridSize(grid);
        z->setSectors(static_cast<unsigned>(sectors));
        z->setSmooth(false);  // the pipeline smooths and refines every planner's path alike
        z->setRefine(false);
    }
    if (auto w = std::dynamic_pointer_cast<Wavefront>(planner))
    {
        w->setGridSize(grid);
        w->setSectors(static_cast<unsigned>(sectors));
    }
    applyParameters(m, *planner);
    if (auto w = std::dynamic_pointer_cast<Wavefront>(planner))
    {
        // the interval count its search would refuse, named here by the field that set the interval
        const double intervals = (ctx->region.tMax - departure) / w->effectiveTimeStep();
        if (!(intervals <= Wavefront::kMaxIntervals))
        {
            const bool given = m.planner.parameters.count("time_step") > 0;
            char text[160];
            std::snprintf(text, sizeof text, ": %.4g time intervals of %g over the planning window (at most %g)",
                          intervals, w->effectiveTimeStep(), Wavefront::kMaxIntervals);
            throw Error((given ? parameterPlace(m, "time_step") : m.place("planner.grid_size")) + text +
                        ": use a larger time_step");
        }
    }
    return planner;
}

std::string noPathReason(const ompl::base::PlannerStatus &status, const ompl::base::Planner &planner,
                         const GliderSimpleSetup *setup, double timeLimit)
{
    if (setup && !setup->lastCheckMessage().empty())
        return setup->lastCheckMessage();
    if (const auto *z = dynamic_cast<const ZAStarTVE *>(&planner))
    {
        const TveResult &r = z->lastResult();
        switch (r.outcome)
        {
            case TveOutcome::InvalidStart:
                return "invalid start: " + r.message;
            case TveOutcome::InvalidGoal:
                return "invalid goal: " + r.message;
            case TveOutcome::Exhausted:
                return "no path exists on this lattice (" + std::to_string(r.expansions) +
                       " vertices expanded; a finer grid, more sectors or a higher speed may find one)";
            case TveOutcome::Terminated:
                return "the time limit (" + std::to_string(timeLimit) + " s) ended the search: raise it";
            default:
                break;
        }
    }
    if (const auto *l = dynamic_cast<const LevelSetPlanner *>(&planner);
        l && status == ompl::base::PlannerStatus::ABORT)
        return l->lastReachability().goalReached ?
                   "the level-set path cannot be flown as straight legs at this resolution: try a finer one" :
                   "the reachable front never reaches the goal within the time window (walled in by land or "
                   "forbidden regions, or a closure that does not open in time)";
    if (const auto *w = dynamic_cast<const Wavefront *>(&planner))
    {
        switch (w->lastOutcome())
        {
            case WavefrontOutcome::InvalidStart:
                return "invalid start: " + w->lastMessage();
            case WavefrontOutcome::InvalidGoal:
                return "invalid goal: " + w->lastMessage();
            case WavefrontOutcome::Exhausted:
                return "no path exists on this lattice: " + w->lastMessage();
            case WavefrontOutcome::BadWindow:
                return w->lastMessage();
            case WavefrontOutcome::Terminated:
                return "the time limit (" + std::to_string(timeLimit) + " s) ended the search: raise it";
            default:
                break;
        }
    }
    if (status == ompl::base::PlannerStatus::APPROXIMATE_SOLUTION)
        return "the planner reached only an approximate solution within the time limit";
    if (status == ompl::base::PlannerStatus::TIMEOUT)
        return "the planner found no path within the time limit";
    return std::string("planner status: ") + status.asString();
}
/// What bounds the arrival of an exhausted search: the end of the forecast or the planning horizon.
std::string horizonNote(const MissionProblem &problem, const GliderProblem &gp)
{
    const double seconds = gp.horizon * problem.getSpec().timeUnitSeconds;
    char text[160];
    if (seconds >= 2.0 * 86400.0)
        std::snprintf(text, sizeof text, "%.6g time units (%.3g days, %.0f h)", gp.horizon, seconds / 86400.0,
                      seconds / 3600.0);
    else
        std::snprintf(text, sizeof text, "%.6g time units (%.3g h)", gp.horizon, seconds / 3600.0);
    const double fieldEnd = problem.getField()->timeEnd();
    if (std::isfinite(fieldEnd) && gp.t0 + gp.horizon >= fieldEnd - 1e-9 * std::max(1.0, std::abs(fieldEnd)))
        return std::string("; the path must arrive before the forecast ends, ") + text +
               " after departure: depart earlier, or hold the last forecast time past its end (current.horizon: hold_last, --beyond hold)";
    return std::string("; the path must arrive within the planning horizon, ") + text +
           " after departure (planner.horizon)";
}
/// The problem of one departure, its departure time checked first so that the error names where it was given.
GliderProblem checkedProblem(const MissionProblem &problem, double departure, double speed)
{
    GliderProblem gp = problem.gliderProblem(departure, speed);
    if (const std::string why = departureProblem(gp); !why.empty())
        throw Error(problem.getSpec().place("departure.time") + ": " + why);
    return gp;
}

/// The lattice planners keep dense arrays over the whole lattice (a travel time and a predecessor per vertex,
/// TveSearch): refuse, naming the field or flag, a spacing whose lattice would not fit in memory.
void checkLatticeSize(const MissionSpec &m, const GliderProblem &gp, double grid, const std::string &field)
{
    const double nx = std::floor((gp.xMax - gp.xMin) / grid + 1e-9) + 1.0;
    const double ny = std::floor((gp.yMax - gp.yMin) / grid + 1e-9) + 1.0;
    char what[160];
    std::snprintf(what, sizeof what, ": a lattice spacing of %g gives %.0f x %.0f = %.3g vertices, which", grid, nx,
                  ny, nx * ny);
    if (nx * ny > 2147483648.0)
        throw Error(m.place(field) + what + " is more than the 2^31 a lattice can hold: use a larger spacing");
    checkMemory(nx * ny * static_cast<double>(sizeof(double) + sizeof(Lattice::VertexId)), m.place(field) + what,
                "use a larger spacing");
}
}  // namespace

StintSettings stintSettings(const MissionProblem &problem, double departure)
{
    const MissionSpec &m = problem.getSpec();
    StintSettings s;
    s.duration = m.stints.duration;
    s.missionDuration = m.stints.missionDuration;
    s.bearingStep = m.stints.bearingStep;
    s.objective = m.stints.objective == "earliest_arrival" ? StintObjective::EarliestArrival
                                                           : StintObjective::RemainingDistance;
    s.radius = m.stints.radius;
    s.step = m.stints.step;
    s.depth = m.vehicle.depth;
    const double end = problem.getField()->timeEnd();
    if (std::isfinite(end) && departure + s.missionDuration > end * (1.0 + 1e-12))
        throw Error(m.place("stints.mission_duration") + ": the mission would end at t = " +
                    std::to_string(departure + s.missionDuration) + ", after the forecast (it ends at t = " +
                    std::to_string(end) + "): shorten it, depart earlier, or hold the last forecast time "
                    "(current.horizon: hold_last)");
    return s;
}

namespace
{
/// The final path of a (non-stint) planner flown as stints: the heading per surfacing that follows it best and
/// what that loses (stintsFromPath()); earliest arrival within the section's radius (0: 1e-4 of the start-goal
/// distance), over a mission long enough to arrive (1.5 times the path's time plus one stint, within the forecast).
StintOutcome convertToStints(const MissionProblem &problem, const PlannedPath &r)
{
    const MissionSpec &m = problem.getSpec();
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
    o.duration = s.duration;
    o.missionDuration = s.missionDuration;
    o.objective = stintObjectiveName(s.objective);
    o.radius = s.radius;
    o.pathTravelTime = c.pathTravelTime;
    o.stintTravelTime = c.stintTravelTime;
    o.loss = c.loss;
    (void)m;
    return o;
}
}  // namespace

namespace
{
/// planRoute() on the problem's one field.
PlannedPath planOnField(const MissionProblem &problem, double departure, const PlanOptions &o)
{
    const MissionSpec &m = problem.getSpec();
    PlannedPath r;
    r.departure = departure;
    r.speed = std::isnan(o.speed) ? m.vehicle.speed : o.speed;
    r.planner = plannerEntry(m.planner.name).name;
    const double grid = o.gridSize > 0 ? o.gridSize : m.planner.gridSize;
    const int sectors = o.sectors > 0 ? o.sectors : m.planner.sectors;
    const bool smoothing = o.smoothing.value_or(m.planner.smoothing);
    const bool refinement = o.refinement.value_or(m.planner.refinement);
    const Point2 s = problem.getStart(), g = problem.getGoal();
    r.straightLineLength = std::hypot(g.x - s.x, g.y - s.y);
    const GliderProblem gp = checkedProblem(problem, departure, r.speed);
    if (plannerEntry(m.planner.name).lattice && grid > 0)
        checkLatticeSize(m, gp, grid, o.gridSize > 0 ? "departure.window.coarse_grid_size" : "planner.grid_size");
    if (!(gp.horizon > 0))
    {
        r.status = "Invalid start";
        r.reason = "departure after the end of the forecast";
        r.badInput = "departure.time";
        return r;
    }
    std::shared_ptr<GliderContext> ctx;
    const ompl::geometric::SimpleSetupPtr ss = makeSimpleSetup(gp, &ctx);
    const ompl::base::PlannerPtr planner = makePlanner(problem, ss->getSpaceInformation(), ctx, grid, sectors, departure);
    ss->setPlanner(planner);
    r.straightLineTime = legTravelTime(*ctx, s.x, s.y, g.x, g.y, departure);

    const bool lattice = plannerEntry(m.planner.name).lattice;
    const bool stints = plannerEntry(m.planner.name).stints;  // its own caps bound the work, as the lattice's
    const bool exhaustive = plannerEntry(m.planner.name).exhaustive;
    const double limit = m.planner.timeLimit > 0 ? m.planner.timeLimit :
                         (lattice || stints || exhaustive ? 0.0 : kDefaultSamplingTimeLimit);
    const std::uint64_t cfc0 = ctx->travel->costFunctionCalls(), cmc0 = ctx->field->callCount();
    const auto tA = std::chrono::steady_clock::now();
    const ompl::base::PlannerStatus status =
        ss->solve(limit > 0 ? ompl::base::timedPlannerTerminationCondition(limit)
                            : ompl::base::plannerNonTerminatingCondition());
    r.planningSeconds = secondsSince(tA);
    r.status = status.asString();
    r.searchCostFunctionCalls = ctx->travel->costFunctionCalls() - cfc0;
    r.currentModelCalls = ctx->field->callCount() - cmc0;
    if (auto z = std::dynamic_pointer_cast<ZAStarTVE>(planner))
        r.expandedVertices = z->getExpandedVertices();
    if (auto st = std::dynamic_pointer_cast<StintPlanner>(planner))
        if (ss->haveSolutionPath() && !st->lastPlan().surfacings.empty())
        {
            // a stint plan is flown, not smoothed: its surfacings are the path
            StintOutcome o;
            o.plan = st->lastPlan();
            o.duration = m.stints.duration;
            o.missionDuration = m.stints.missionDuration;
            o.objective = m.stints.objective;
            o.radius = m.stints.radius;
            r.solved = true;
            r.raw = r.smoothed = r.path = o.plan.surfacings;
            r.rawTravelTime = r.smoothedTravelTime = r.travelTime = r.path.back().t - departure;
            r.rawPathLength = r.pathLength = pathLength(o.plan.track);
            r.pathChecked = !o.plan.grounded;
            r.stints = std::move(o);
            return r;
        }
    r.solved = ss->haveExactSolutionPath();
    if (!r.solved)
    {
        r.reason = noPathReason(status, *planner, dynamic_cast<const GliderSimpleSetup *>(ss.get()), limit);
        if (status == ompl::base::PlannerStatus::INVALID_START || status == ompl::base::PlannerStatus::INVALID_GOAL)
        {
            const bool start = status == ompl::base::PlannerStatus::INVALID_START;
            r.badInput = start ? "start" : "goal";
            if (problem.isGeographic())
            {
                // the planner speaks in its plane; the pilot gave lon/lat
                const LonLat p = problem.toGeographic(start ? s : g);
                char where[96];
                std::snprintf(where, sizeof where, " (lon %.5f, lat %.5f)", p.lon, p.lat);
                r.reason += std::string("; the ") + r.badInput + where;
            }
        }
        if (r.reason.rfind("no path exists", 0) == 0)
        {
            r.status = kNoPathStatus;  // OMPL's ABORT or TIMEOUT would send the user after a longer time limit
            r.reason += horizonNote(problem, gp);
        }
        return r;
    }
    ompl::geometric::PathGeometric path = ss->getSolutionPath();
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
    if (m.stints.set)
    {
        const auto tS = std::chrono::steady_clock::now();
        r.stints = convertToStints(problem, r);
        r.stints->seconds = secondsSince(tS);
    }
    return r;
}

/// A robust plan over the members of an ensemble (see planRoute()).
PlannedPath planRobust(const MissionProblem &problem, double departure, const PlanOptions &o)
{
    const MissionSpec &m = problem.getSpec();
    const auto &members = problem.getMembers();
    const std::size_t n = members.size();
    const double speed = std::isnan(o.speed) ? m.vehicle.speed : o.speed;
    // candidates: the mean field's plan, then each member's, planned in parallel
    std::vector<PlannedPath> plans(n + 1);
    std::vector<std::vector<double>> times(n + 1, std::vector<double>(n, kInf));
    DiveProfilePool pool(0);
    pool.parallelFor(n + 1, [&](std::size_t c) {
        plans[c] = c == 0 ? planOnField(problem, departure, o) : planOnField(problem.withMember(c - 1), departure, o);
        if (!plans[c].solved)
            return;
        for (std::size_t k = 0; k < n; ++k)
        {
            const std::vector<TimedPoint> flown = retimePath(problem, members[k], speed, plans[c].path);
            times[c][k] = flown.empty() ? kInf : flown.back().t - departure;
        }
    });
    EnsemblePlan e;
    e.objective = m.planner.objective;
    e.quantile = m.planner.quantile;
    std::size_t best = 0;
    for (std::size_t c = 0; c <= n; ++c)
    {
        EnsemblePlan::Candidate cand;
        cand.name = c == 0 ? "mean" : "member " + std::to_string(c - 1);
        cand.solved = plans[c].solved;
        cand.memberTravelTimes = times[c];
        cand.objectiveValue = plans[c].solved ? ensembleObjective(times[c], e.objective, e.quantile) : kInf;
        e.candidates.push_back(cand);
        const auto better = [&](std::size_t a, std::size_t b) {
            const auto &ca = e.candidates[a];
            const auto &cb = e.candidates[b];
            if (ca.solved != cb.solved)
                return ca.solved;
            return ca.objectiveValue < cb.objectiveValue;
        };
        if (c > 0 && better(c, best))
            best = c;
    }
    PlannedPath r = plans[best];
    e.chosen = e.candidates[best].name;
    e.objectiveValue = e.candidates[best].objectiveValue;
    e.memberTravelTimes = times[best];
    // every candidate's search counts
    r.searchCostFunctionCalls = r.postprocessCostFunctionCalls = r.currentModelCalls = r.expandedVertices = 0;
    r.planningSeconds = r.postprocessSeconds = 0.0;
    for (const PlannedPath &p : plans)
    {
        r.searchCostFunctionCalls += p.searchCostFunctionCalls;
        r.postprocessCostFunctionCalls += p.postprocessCostFunctionCalls;
        r.currentModelCalls += p.currentModelCalls;
        r.expandedVertices += p.expandedVertices;
        r.planningSeconds += p.planningSeconds;
        r.postprocessSeconds += p.postprocessSeconds;
    }
    if (best > 0 && r.solved)
    {
        // a member's plan: its times on the mean field, which the outputs describe
        const std::vector<TimedPoint> onMean = retimePath(problem, problem.getField(), speed, r.path);
        if (!onMean.empty())
        {
            r.path = onMean;
            r.travelTime = onMean.back().t - departure;
        }
    }
    r.ensemble = e;
    return r;
}
}  // namespace

double ensembleObjective(const std::vector<double> &t, const std::string &objective, double q)
{
    if (t.empty())
        return kInf;
    for (double x : t)
        if (!std::isfinite(x))
            return kInf;
    if (objective == "worst")
        return *std::max_element(t.begin(), t.end());
    if (objective == "quantile")
    {
        std::vector<double> s = t;
        std::sort(s.begin(), s.end());
        const double rank = std::ceil(q * static_cast<double>(s.size()));
        const std::size_t k = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(s.size())));
        return s[k - 1];
    }
    if (objective != "expected")
        throw Error("unknown ensemble objective '" + objective + "' (expected, worst, quantile)");
    double sum = 0.0;
    for (double x : t)
        sum += x;
    return sum / static_cast<double>(t.size());
}

std::vector<TimedPoint> retimePath(const MissionProblem &problem, std::shared_ptr<const CurrentField> field,
                                      double speed, const std::vector<TimedPoint> &path)
{
    if (path.empty())
        return {};
    TravelTimeParams tp = problem.getSpec().travel;
    tp.speed = speed;
    const TravelTimeCalculator travel(std::move(field), tp);
    const auto &env = problem.getEnvironment();
    std::vector<TimedPoint> out{path.front()};
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        const TimedPoint &a = out.back(), &w = path[i];
        const double dt = travel.travelTime(a.x, a.y, w.x, w.y, a.t);
        if (!std::isfinite(dt) || (env && !env->legFree(a.x, a.y, a.t, w.x, w.y, a.t + dt)))
            return {};
        out.push_back({w.x, w.y, a.t + dt});
    }
    return out;
}


namespace
{
/// Total time spent holding position: the zero-length legs of a timed path.
double holdTimeOf(const std::vector<TimedPoint> &path)
{
    double hold = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i)
        if (path[i].x == path[i - 1].x && path[i].y == path[i - 1].y)
            hold += path[i].t - path[i - 1].t;
    return hold;
}

std::string timeText(const MissionProblem &problem, double t)
{
    char text[64];
    std::snprintf(text, sizeof text, "t = %.6g", t);
    const std::string iso = problem.isoTime(t);
    return iso.empty() ? std::string(text) : std::string(text) + " (" + iso + ")";
}

/// Goals in time (issue 12; [ThompsonICRA] Sec. III, the earliest valid arrival): moves the arrival of a solved plan
/// into the goal window [begin, end] of the mission. Early: hold at the goal where the glider can (|c| < V over the
/// hold, TravelTimeMotionValidator::canHold); else time the arrival: from the last waypoint before the goal back to
/// the start, hold there (where |c| < V) or fly the leg leaving it slower (any pace in its arrival window), the rest of the path flown
/// as fast as possible (legTravelTime), the delay found by bisection (the arrival of a fastest flight does not
/// decrease with its departure on each leg, FIFO); the first candidate whose arrival lands in the window and whose
/// path passes PathGeometric::check() is kept. Late, or no candidate: no path in the window (solved false).
void timeArrival(const MissionProblem &problem, PlannedPath &r)
{
    const MissionSpec &m = problem.getSpec();
    const GoalWindowSpec &w = m.goalWindow;
    if (!w.set || !r.solved || r.path.empty() || (r.stints && !r.stints->converted))
        return;
    const double B = w.begin, E = w.end;
    const double tol = 1e-9 * std::max({1.0, std::abs(B), std::abs(E)});
    const std::string window = "the goal's arrival window [" + timeText(problem, B) + ", " + timeText(problem, E) + "]";
    const double ta = r.path.back().t;
    auto fail = [&](const std::string &why) {
        r.solved = false;
        r.status = kNoPathStatus;
        r.reason = why;
        r.pathChecked = false;
    };
    if (ta > E + tol)
    {
        fail("the path reaches the goal at " + timeText(problem, ta) + ", after the end of " + window +
             ": no path arrives in the window (depart earlier, or widen the window)");
        return;
    }
    if (ta >= B - tol)
    {
        // already in the window (a lattice planner holds at the goal itself: TveOptions::waiting)
        if (r.path.size() >= 2 && lastHoldEnd(r.path) == r.path.size() - 1)
            r.arrivalTiming = "hold at the goal";
        return;
    }

    GliderProblem gp = checkedProblem(problem, r.departure, r.speed);
    if (B > gp.t0 + gp.horizon)
    {
        fail(window + " opens after the planning horizon ends (" + timeText(problem, gp.t0 + gp.horizon) + ")");
        return;
    }
    std::shared_ptr<GliderContext> ctx;
    const ompl::geometric::SimpleSetupPtr ss = makeSimpleSetup(gp, &ctx);
    const ompl::base::SpaceInformationPtr si = ss->getSpaceInformation();
    const auto mv = std::dynamic_pointer_cast<TravelTimeMotionValidator>(si->getMotionValidator());
    if (!mv)
        throw Error("planRoute: the space has no TravelTimeMotionValidator (internal error)");
    // sample the current of a hold at least 512 times over the trip's time
    mv->setHoldTimeStep(std::min(mv->getHoldTimeStep(), std::max(B - r.departure, 1e-9) / 512.0));
    const std::uint64_t cfc0 = ctx->travel->costFunctionCalls();
    const std::vector<TimedPoint> &P = r.path;
    const std::size_t n = P.size() - 1;  // index of the goal waypoint

    // a candidate path: checked by OMPL (every motion by the motion validator, every state valid)
    auto accept = [&](std::vector<TimedPoint> cand, const std::string &how) {
        // land exactly on the window's begin when the arrival is within rounding of it
        if (std::abs(cand.back().t - B) <= tol && cand.size() >= 2 && cand.back().t != B)
            cand.back().t = std::max(B, cand[cand.size() - 2].t);
        if (!(cand.back().t >= B - tol && cand.back().t <= E + tol))
            return false;
        ompl::geometric::PathGeometric path(si);
        waypointsToPath(cand, path);
        if (!path.check())
            return false;
        r.path = std::move(cand);
        r.travelTime = r.path.back().t - r.departure;
        r.pathChecked = true;
        r.arrivalTiming = how;
        return true;
    };
    const auto &env = ctx->environment;
    auto holdable = [&](const TimedPoint &p, double t1, double t2) {
        return mv->canHold(p.x, p.y, t1, t2) && (!env || env->legFree(p.x, p.y, t1, p.x, p.y, t2));
    };

    // 1. hold at the goal: the earliest valid arrival
    if (holdable(P[n], ta, B))
    {
        std::vector<TimedPoint> cand = P;
        cand.push_back({P[n].x, P[n].y, B});
        if (accept(std::move(cand), "hold at the goal"))
        {
            r.postprocessCostFunctionCalls += ctx->travel->costFunctionCalls() - cfc0;
            return;
        }
    }
    // 2. time the arrival: a slower leg or a hold at an earlier waypoint, latest first
    // waypoints 0..k as planned, then k -> k + 1 in duration d, then as fast as possible
    auto flyOn = [&](std::size_t k, double tDepart, double legDuration) {
        std::vector<TimedPoint> out(P.begin(), P.begin() + static_cast<std::ptrdiff_t>(k) + 1);
        if (tDepart > out.back().t)
            out.push_back({P[k].x, P[k].y, tDepart});
        out.push_back({P[k + 1].x, P[k + 1].y, tDepart + legDuration});
        for (std::size_t i = k + 2; i <= n && std::isfinite(out.back().t); ++i)
        {
            const TimedPoint &a = out.back();
            const double dt = legTravelTime(*ctx, a.x, a.y, P[i].x, P[i].y, a.t);
            out.push_back({P[i].x, P[i].y, a.t + dt});
        }
        return out;
    };
    // smallest x in [lo, hi] with arrival(x) >= B: a scan at 33 points for the first bracket [a, b] with a finite
    // arrival before B at a and in reach of B at b (the arrival jumps or is infeasible where the path meets the
    // current at other times), then bisection inside it (arrival non-decreasing in x there)
    auto bisect = [&](double lo, double hi, const std::function<std::vector<TimedPoint>(double)> &fly)
        -> std::vector<TimedPoint> {
        constexpr int kScan = 32;
        double a = lo;
        std::vector<TimedPoint> best;
        for (int i = 0; i <= kScan; ++i)
        {
            const double x = lo + (hi - lo) * i / kScan;
            std::vector<TimedPoint> c = fly(x);
            const double t = c.back().t;
            if (!std::isfinite(t))
                continue;
            if (t < B - tol)
                a = x;
            else if (t <= E + tol && x > a)
            {
                best = std::move(c);
                hi = x;
                break;
            }
        }
        if (best.empty())
            return {};
        lo = a;
        for (int it = 0; it < 60 && best.back().t > B + tol && hi - lo > 1e-12 * std::max(1.0, std::abs(hi)); ++it)
        {
            const double mid = 0.5 * (lo + hi);
            std::vector<TimedPoint> c = fly(mid);
            if (std::isfinite(c.back().t) && c.back().t >= B - tol)
            {
                hi = mid;
                if (c.back().t <= E + tol)
                    best = std::move(c);
            }
            else
                lo = mid;
        }
        return best;
    };
    for (std::size_t k = n; k-- > 0;)
    {
        const TimedPoint &a = P[k], &b = P[k + 1];
        const bool holdLeg = a.x == b.x && a.y == b.y;  // an existing hold: lengthen it below
        const double tk = a.t;
        // hold at waypoint k (k = 0: a later departure from the start), as long as the glider can
        double hMax = B - tk;
        if (!holdable(a, tk, tk + hMax))
        {
            double lo = 0.0, hi = hMax;
            for (int it = 0; it < 40; ++it)
            {
                const double mid = 0.5 * (lo + hi);
                (holdable(a, tk, tk + mid) ? lo : hi) = mid;
            }
            hMax = lo;
        }
        if (hMax > 0.0)
        {
            auto fly = [&](double h) {
                if (holdLeg)  // lengthen the hold k -> k + 1
                    return flyOn(k, tk, b.t - tk + h);
                const double dt = legTravelTime(*ctx, a.x, a.y, b.x, b.y, tk + h);
                return flyOn(k, tk + h, dt);
            };
            std::vector<TimedPoint> c = bisect(0.0, hMax, fly);
            const std::string how =
                k == 0 ? std::string("later departure (hold at the start)") : "hold at waypoint " + std::to_string(k);
            if (!c.empty() && accept(std::move(c), how))
                break;
        }
        if (!holdLeg)
        {
            // fly the leg k -> k + 1 slower: any duration in its arrival window
            const ArrivalWindow aw = ctx->travel->arrivalWindow(a.x, a.y, b.x, b.y, tk);
            if (std::isfinite(aw.earliest))
            {
                const double dMax = std::min(std::isfinite(aw.latest) ? aw.latest : kInf, B - tk);
                if (dMax > aw.earliest)
                {
                    std::vector<TimedPoint> c =
                        bisect(aw.earliest, dMax, [&](double d) { return flyOn(k, tk, d); });
                    char how[96];
                    std::snprintf(how, sizeof how, "slower leg %zu -> %zu", k, k + 1);
                    if (!c.empty() && accept(std::move(c), how))
                        break;
                }
            }
        }
    }
    r.postprocessCostFunctionCalls += ctx->travel->costFunctionCalls() - cfc0;
    if (r.arrivalTiming.empty())
        fail("the path reaches the goal at " + timeText(problem, ta) + ", before " + window +
             " opens; the glider cannot hold at the goal (the current reaches its speed there) and no slower leg or "
             "hold at an earlier waypoint lands the arrival in the window");
}
}  // namespace

PlannedPath planRoute(const MissionProblem &problem, double departure, const PlanOptions &o)
{
    PlannedPath r = problem.getMembers().empty() ? planOnField(problem, departure, o) : planRobust(problem, departure, o);
    timeArrival(problem, r);
    if (r.solved)
        r.holdTime = holdTimeOf(r.path);
    return r;
}

TravelTimeOfDeparture departureFunction(const MissionProblem &problem, double gridSize, int sectors)
{
    return [&problem, gridSize, sectors](double tDep) {
        PlanOptions o;
        o.gridSize = gridSize;
        o.sectors = sectors;
        o.smoothing = false;
        o.refinement = false;
        try
        {
            const PlannedPath p = planRoute(problem, tDep, o);
            // with a goal window the travel time includes the holds that move the arrival into it
            return !p.solved ? kInf : problem.getSpec().goalWindow.set ? p.travelTime : p.rawTravelTime;
        }
        catch (const Error &)
        {
            return kInf;  // e.g. a departure outside the forecast: no trip from there
        }
    };
}

std::vector<SpeedSweepRow> speedSweep(const MissionProblem &problem, double tDep, const std::vector<double> &speeds,
                                      const ProgressSink &progress)
{
    // one plan per speed, in parallel (planRoute() is thread-safe on one problem); rows in the order given
    std::vector<SpeedSweepRow> rows(speeds.size());
    std::mutex printMutex;
    std::size_t done = 0;
    DiveProfilePool pool(0);
    pool.parallelFor(speeds.size(), [&](std::size_t i) {
        PlanOptions o;
        o.speed = speeds[i];
        const PlannedPath p = planRoute(problem, tDep, o);
        rows[i] = {speeds[i], p.solved, p.travelTime, p.pathLength, p.straightLineTime, p.straightLineLength};
        if (progress)
        {
            std::lock_guard<std::mutex> lock(printMutex);
            char line[96];
            std::snprintf(line, sizeof line, "speed sweep: %zu/%zu speeds planned", ++done, speeds.size());
            progress(line, done == speeds.size());
        }
    });
    return rows;
}

PilotWaypoints missionWaypoints(const MissionProblem &problem, const PlannedPath &plan)
{
    PilotWaypoints out;
    // a stint plan's legs between surfacings are not straight: its times are the flown ones
    const auto dive = plan.stints && !plan.stints->converted ? nullptr : problem.diveProfiles(plan.speed);
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
        if (i == 0)
            w.time = plan.departure;
        else if (dive && plan.path[i].x == plan.path[i - 1].x && plan.path[i].y == plan.path[i - 1].y)
        {
            // a hold (goal window, a lattice wait): as long as planned
            w.legTime = plan.path[i].t - plan.path[i - 1].t;
            t += w.legTime;
            w.time = t;
        }
        else if (dive)
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
            w.time = plan.path[i].t;
            w.legTime = plan.path[i].t - plan.path[i - 1].t;
        }
        w.iso = problem.isoTime(w.time);
        out.waypoints.push_back(w);
    }
    out.travelTime = out.waypoints.empty() ? kInf : out.waypoints.back().time - plan.departure;
    return out;
}

OptimumReference optimumReference(const MissionProblem &problem, double departure, double speed,
                                  double maxTravelTime)
{
    ZermeloParams zp;
    zp.speed = speed;
    zp.depth = problem.getSpec().vehicle.depth;
    zp.maxTime = maxTravelTime;
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
                    (std::isfinite(problem.getField()->timeEnd()) &&
                             horizonEnd >= problem.getField()->timeEnd() - 1e-9
                         ? ": the end of the forecast"
                         : ": planner.horizon") +
                    ")");
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
}  // namespace

MissionResult runMission(const MissionProblem &problem, const RunOptions &options)
{
    const auto start = std::chrono::steady_clock::now();
    MissionResult result;
    result.spec = problem.getSpec();
    const MissionSpec &m = result.spec;
    checkPlanner(problem, m.departure.window ? m.departure.begin : m.departure.time);
    checkGoalWindow(problem);
    const double tDep = chooseDeparture(problem, options, result);
    if (result.departureSearch && !result.departureSearch->found)
    {
        result.plan.departure = m.departure.begin;
        result.plan.speed = m.vehicle.speed;
        result.plan.planner = plannerEntry(m.planner.name).name;
        result.plan.status = kNoPathStatus;
        result.plan.reason = "no departure in the window has a path within the forecast";
        result.wallSeconds = secondsSince(start);
        return result;
    }
    result.plan = planRoute(problem, tDep);
    if (result.plan.solved)
    {
        PilotWaypoints w = missionWaypoints(problem, result.plan);
        result.waypoints = std::move(w.waypoints);
        result.diveProfiles = m.dive.enabled;
        if (m.dive.enabled)
            result.profileSet = makeDiveProfiles(m.dive.params);
        result.diveTravelTime = w.travelTime;
    }
    if (options.optimum)
    {
        // Any flown path bounds the optimum; without one, the planning horizon does.
        const double horizon = problem.gliderProblem(tDep, result.plan.speed).horizon;
        result.optimum = optimumReference(problem, tDep, result.plan.speed,
                                          result.plan.solved ? std::min(horizon, 1.2 * result.plan.travelTime)
                                                             : horizon);
    }
    const std::vector<double> speeds = options.speeds ? *options.speeds : m.speeds;
    if (!speeds.empty())
        result.speedSweep = speedSweep(problem, tDep, speeds, options.progress);
    if (m.execution.enabled)
        result.execution = executeMission(problem, result.plan, options.progress);
    if (std::find(m.outputs.files.begin(), m.outputs.files.end(), "isochrones") != m.outputs.files.end())
        result.isochrones = computeIsochrones(problem, result.plan, tDep, m.outputs.isochroneInterval);
    result.wallSeconds = secondsSince(start);
    return result;
}
}  // namespace ompl_glider
