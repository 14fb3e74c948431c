// The probability of reach over an ensemble's members: each member's first-arrival field by the registry's level-set
// planner (PipelinePlanner::reachableSet()), combined node by node ([SubramaniStochastic]: the Monte Carlo view of
// stochastic reachability, one level-set front ([LollaLevelSet]) per member).
#include "ompl_glider/mission/ReachProbability.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <thread>
#include <utility>

#include "PlanningInternal.h"
#include "../../core/Numbers.h"
#include "../../io/NumberText.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/ResourceLimits.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/ompl/PipelinePlanner.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/mission/Observations.h"
#endif

namespace ompl_glider
{
namespace
{
/// The registry's level-set planner (plannerOfFamily()) on one problem's context, with what the pipeline tells it.
struct LevelSetOn
{
    std::shared_ptr<GliderContext> ctx;
    std::shared_ptr<GliderSimpleSetup> ss;
    ompl::base::PlannerPtr planner;
    PipelineSetup setup;

    /// What the planner says reachableSet(@p request) would cost.
    ReachWork workOf(const ReachRequest &request) const
    {
        const std::optional<ReachWork> w = pipelineView(*planner).reachWork(setup, request);
        if (!w)
            throw Error("reachability: the level-set planner does not say what a reachable set costs");
        return *w;
    }
};

LevelSetOn levelSetOn(const MissionProblem &problem, double departure, double speed)
{
    LevelSetOn l;
    l.ss = makeSimpleSetup(problem.gliderProblem(departure, speed), &l.ctx);
    l.setup.departure = departure;
    l.setup.start = problem.getStart();
    l.setup.goal = problem.getGoal();
    l.setup.region = l.ctx->region;
    l.planner = plannerOfFamily(PlannerFamily::LevelSet).make(l.ss->getSpaceInformation(), l.ctx);
    return l;
}

/// The members' weights: the observations' where they weighed the members, else equal; normalised to sum 1.
std::vector<double> memberWeights(const MissionProblem &problem, std::size_t members, bool &weighed)
{
    std::vector<double> w(members, 1.0 / static_cast<double>(members));
    weighed = false;
#if OMPL_GLIDER_WITH_NETCDF
    if (members > 1 && problem.getMembers().empty() && problem.observations() &&
        problem.observations()->members.size() == members)
    {
        std::vector<double> o;
        for (const MemberScore &s : problem.observations()->members)
            o.push_back(std::isfinite(s.weight) && s.weight > 0.0 ? s.weight : 0.0);
        const double sum = std::accumulate(o.begin(), o.end(), 0.0);
        if (sum > 0.0)
        {
            for (double &x : o)
                x /= sum;
            w = o;
            weighed = true;
        }
    }
#else
    (void)problem;
#endif
    return w;
}

/// The horizon after the departure: the section's, else 1.5 times the plan's travel time, else the planning
/// horizon; capped at the field's end.
double horizonOf(const MissionProblem &problem, const PlannedPath &plan, double departure, double speed)
{
    const MissionSpec &m = problem.getSpec();
    double horizon = m.reachability.horizon;
    if (std::isnan(horizon))
        horizon =
            plan.solved && std::isfinite(plan.travelTime) ? 1.5 * plan.travelTime : problem.horizon(departure, speed);
    horizon = std::min(horizon, problem.getField()->timeEnd() - departure);
    if (!(horizon > 0.0) || !std::isfinite(horizon))
        throw Error(m.place("reachability.horizon") + ": the current's field ends at " +
                    text::number(problem.getField()->timeEnd()) + ", not after the departure at " +
                    text::number(departure) + ": no time to reach anywhere");
    return horizon;
}

/// The frames: every interval up to the horizon, and the horizon itself.
std::vector<double> framesOf(const MissionSpec &m, double departure, double horizon)
{
    const double interval = std::isnan(m.reachability.interval) ? horizon / 10.0 : m.reachability.interval;
    const double count = std::floor(horizon * (1 + 1e-9) / interval);
    if (count > static_cast<double>(planning_detail::kMaxIsochrones))
        throw Error(m.place("reachability.interval") + ": an interval of " + text::number(interval) + " gives " +
                    text::number(count, 4) + " frames over the horizon of " + text::number(horizon, 4) +
                    ", more than the limit of " + std::to_string(planning_detail::kMaxIsochrones) +
                    ": use a longer interval");
    std::vector<double> times;
    for (double k = 1.0; k <= count; k += 1.0)
        times.push_back(departure + std::min(k * interval, horizon));
    if (times.empty() || times.back() < departure + horizon * (1 - 1e-9))
        times.push_back(departure + horizon);
    times.back() = departure + horizon;
    return times;
}

/// Refuses, naming the cell (or the horizon's frames), a computation beyond the memory limit: the members' arrival
/// fields (8 bytes a node each), p per frame (4), the solves under way (the planner's bytes a node each) and the
/// quantile field of the contours; the grid is the planner's (ReachWork).
void checkMemoryOf(const MissionProblem &problem, const ReachWork &w, std::size_t members, std::size_t frames,
                   unsigned solving)
{
    const MissionSpec &m = problem.getSpec();
    const double bytes =
        w.nodes * (8.0 * static_cast<double>(members) + 4.0 * static_cast<double>(frames) +
                   w.bytesPerNode * static_cast<double>(std::min<std::size_t>(solving, members)) + 16.0);
    checkMemory(bytes,
                m.place(std::isnan(m.reachability.resolution) ? "reachability" : "reachability.resolution") +
                    ": the probability of reach over " + std::to_string(members) +
                    (members == 1 ? " member on " : " members on ") + text::number(w.nodes, 4) + " grid nodes",
                "use a coarser reachability.resolution");
}

/// Refuses, naming the horizon (or the cell when it was given), fronts beyond the level set's limits
/// (ResourceLimits.h): more than kMaxLevelSetSteps time steps, or more than kMaxLevelSetWork node updates over all
/// the members (what the planner says one front costs, ReachWork, times the members).
void checkWorkOf(const MissionProblem &problem, const ReachWork &w, std::size_t members, double horizon)
{
    const MissionSpec &m = problem.getSpec();
    const double steps = w.steps, work = w.work() * static_cast<double>(members);
    if (steps <= kMaxLevelSetSteps && work <= kMaxLevelSetWork)
        return;
    const bool cellGiven = !std::isnan(m.reachability.resolution) && steps <= kMaxLevelSetSteps;
    throw Error(m.place(cellGiven ? "reachability.resolution" : "reachability.horizon") +
                text::formatted(": the fronts of %g member(s) over a horizon of %.4g would take %.3g time steps of "
                                "%.3g on %.4g grid nodes",
                                static_cast<double>(members), horizon, steps, w.dt, w.nodes) +
                text::formatted(" (%.3g node updates)", work) +
                text::formatted(", more than the limit of %.3g steps and %.3g node updates: give a shorter "
                                "reachability.horizon or a coarser reachability.resolution",
                                kMaxLevelSetSteps, kMaxLevelSetWork));
}

/// p(x, t) at every frame: the weights of the members whose front came by t (equal weights: the count over M,
/// so that an ensemble of equal members gives exactly 0 or 1).
void probabilityFields(ReachProbability &out)
{
    const std::size_t nodes = static_cast<std::size_t>(out.nx) * static_cast<std::size_t>(out.ny);
    const std::size_t members = out.memberArrival.size();
    out.probability.assign(out.times.size(), std::vector<float>(nodes, 0.0f));
    std::vector<std::pair<double, double>> at(members);
    for (std::size_t n = 0; n < nodes; ++n)
    {
        for (std::size_t k = 0; k < members; ++k)
            at[k] = {out.memberArrival[k][n], out.weights[k]};
        std::sort(at.begin(), at.end());
        std::size_t k = 0, count = 0;
        double sum = 0.0;
        for (std::size_t f = 0; f < out.times.size(); ++f)
        {
            for (; k < members && at[k].first <= out.times[f]; ++k, ++count)
                sum += at[k].second;
            const double p = out.weighed ? std::min(sum, 1.0) : static_cast<double>(count) / members;
            out.probability[f][n] = static_cast<float>(p);
        }
    }
}

/// The contours of {p >= level} at every frame: the node field Q(x) = the members' weighted level-quantile of
/// T_m(x) is a first-arrival field ({p(x, t) >= level} = {Q(x) <= t}), drawn by the level-set planner's isochrones.
void contoursOf(ReachProbability &out, const MissionProblem &problem, const PipelinePlanner &drawer)
{
    const std::size_t nodes = static_cast<std::size_t>(out.nx) * static_cast<std::size_t>(out.ny);
    ReachableSet grid;
    grid.x0 = out.x0;
    grid.y0 = out.y0;
    grid.h = out.h;
    grid.nx = out.nx;
    grid.ny = out.ny;
    std::vector<std::vector<std::vector<std::vector<Point2>>>> byLevel;
    std::vector<double> values(out.memberArrival.size());
    for (const double level : out.levels)
    {
        grid.arrival.assign(nodes, kInf);
        for (std::size_t n = 0; n < nodes; ++n)
        {
            for (std::size_t k = 0; k < values.size(); ++k)
                values[k] = out.memberArrival[k][n];
            grid.arrival[n] = weightedQuantile(values, out.weights, level);
        }
        std::optional<std::vector<std::vector<std::vector<Point2>>>> lines = drawer.isochronesOf(grid, out.times);
        if (!lines)
            throw Error("reachability: the level-set planner draws no contours");
        byLevel.push_back(std::move(*lines));
    }
    for (std::size_t f = 0; f < out.times.size(); ++f)
        for (std::size_t l = 0; l < out.levels.size(); ++l)
        {
            ReachContour c;
            c.time = out.times[f];
            c.iso = out.iso[f];
            c.level = out.levels[l];
            c.lines = byLevel[l][f];
            c.lonLat = planning_detail::linesToGeographic(problem, c.lines);
            out.contours.push_back(std::move(c));
        }
}
} // namespace

double weightedQuantile(const std::vector<double> &values, const std::vector<double> &weights, double q)
{
    if (values.size() != weights.size())
        throw Error("weightedQuantile: " + std::to_string(values.size()) + " values and " +
                    std::to_string(weights.size()) + " weights");
    std::vector<std::size_t> order(values.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    double sum = 0.0;
    for (std::size_t i = 0; i < order.size(); ++i)
    {
        const double v = values[order[i]];
        if (!(v < kInf)) // +inf (never) and NaN: nothing further is attained
            return kInf;
        sum += weights[order[i]];
        // ties: the weight of every equal value counts at that value
        if (i + 1 < order.size() && values[order[i + 1]] == v)
            continue;
        if (sum >= q * (1 - 1e-12))
            return v;
    }
    return kInf;
}

namespace
{
/// A request on the section's cell: its resolution, else the level-set planner's default cell.
ReachRequest cellRequest(const ReachabilitySpec &rs)
{
    ReachRequest request;
    if (std::isnan(rs.resolution))
        request.cellScale = 1.0;
    else
        request.cellSize = rs.resolution;
    return request;
}
} // namespace

void checkReachProbabilityMemory(const MissionProblem &problem)
{
    const MissionSpec &m = problem.getSpec();
    const ReachabilitySpec &rs = m.reachability;
    const std::size_t members =
        std::max<std::size_t>(std::max(problem.getMembers().size(), problem.weighedMembers().size()), 1);
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    ReachRequest request = cellRequest(rs);
    // the frames known before the plan: the horizon over the interval when both are given, else the fewest (2)
    std::size_t frames = 2;
    if (!std::isnan(rs.horizon) && !std::isnan(rs.interval) && rs.interval > 0.0)
        frames = static_cast<std::size_t>(std::min(std::floor(rs.horizon / rs.interval) + 1.0,
                                                   static_cast<double>(planning_detail::kMaxIsochrones) + 1.0));
    // the planner's grid on the mission's departure (a problem it cannot set up is refused by the planning, which
    // says why; the probability of reach checks again before it runs)
    std::optional<LevelSetOn> l;
    try
    {
        l = levelSetOn(problem, m.departure.window ? m.departure.begin : m.departure.time, m.vehicle.speed);
    }
    catch (const Error &)
    {
        return;
    }
    checkMemoryOf(problem, l->workOf(request), members, frames, members >= cores ? cores : 1u);
}

ReachProbability computeReachProbability(const MissionProblem &problem, const PlannedPath &plan, double departure)
{
    const auto wall0 = std::chrono::steady_clock::now();
    const MissionSpec &m = problem.getSpec();
    const ReachabilitySpec &rs = m.reachability;
    const double speed = plan.speed > 0.0 ? plan.speed : m.vehicle.speed;
    ReachProbability out;
    out.departure = departure;
    const double horizon = horizonOf(problem, plan, departure, speed);
    out.horizon = departure + horizon;
    out.times = framesOf(m, departure, horizon);
    for (const double t : out.times)
        out.iso.push_back(problem.isoTime(t));
    out.levels = rs.levels.empty() ? std::vector<double>{0.5, 0.9} : rs.levels;
    const std::vector<double> qs = rs.quantiles.empty() ? std::vector<double>{0.1, 0.5, 0.9} : rs.quantiles;

    // the ensemble's members, or those the glider's observations weighed (the plan is then made on their forecast)
    const std::size_t ensemble = std::max(problem.getMembers().size(), problem.weighedMembers().size());
    const std::size_t members = std::max<std::size_t>(ensemble, 1);
    out.members = members;
    out.weights = memberWeights(problem, members, out.weighed);

    // the members side by side: one thread each when there are at least as many members as cores, else every core
    // to each member in turn
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const bool sideBySide = members >= cores;
    out.threadsPerSolve = sideBySide ? 1u : cores;
    ReachRequest request = cellRequest(rs);
    request.until = out.horizon;
    request.goal = problem.getGoal();
    request.threads = sideBySide ? 1u : 0u;
    request.stop = [] { return stopRequested(); };
    const LevelSetOn drawer = levelSetOn(problem, departure, speed); // also draws the contours
    const ReachWork work = drawer.workOf(request);
    checkMemoryOf(problem, work, members, out.times.size(), sideBySide ? cores : 1u);
    checkWorkOf(problem, work, members, horizon);
    std::vector<ReachableSet> sets(members);
    std::vector<char> done(members, 0);
    const auto solve = [&](std::size_t k) {
        if (stopRequested())
            return;
        const MissionProblem member = ensemble == 0 ? problem : problem.withMember(k);
        const LevelSetOn l = levelSetOn(member, departure, speed);
        std::optional<ReachableSet> r = pipelineView(*l.planner).reachableSet(l.setup, request);
        if (!r)
            throw Error("reachability: the level-set planner computes no reachable set");
        sets[k] = std::move(*r);
        done[k] = 1;
    };
    {
        ThreadPool pool(sideBySide ? cores : 1u);
        pool.parallelFor(members, solve);
    }
    for (std::size_t k = 0; k < members; ++k)
        out.stopped = out.stopped || !done[k] || sets[k].stopped;

    const ReachableSet *first = nullptr;
    for (std::size_t k = 0; k < members && !first; ++k)
        if (done[k])
            first = &sets[k];
    if (!first)
    {
        out.seconds = planning_detail::secondsSince(wall0);
        return out; // stopped before any member was solved
    }
    out.resolution = first->resolution;
    out.x0 = first->x0;
    out.y0 = first->y0;
    out.h = first->h;
    out.nx = first->nx;
    out.ny = first->ny;
    const std::size_t nodes = static_cast<std::size_t>(out.nx) * static_cast<std::size_t>(out.ny);
    for (std::size_t k = 0; k < members; ++k)
    {
        if (done[k] && (sets[k].nx != out.nx || sets[k].ny != out.ny || sets[k].x0 != out.x0 || sets[k].y0 != out.y0))
            throw Error("reachability: member " + std::to_string(k) + "'s grid differs from the first member's");
        // the front runs a step past the horizon (so that a contour at the horizon has arrivals on both sides): the
        // arrival fields keep what it reached then, p and the goal count only what came by the horizon
        out.memberArrival.push_back(done[k] ? std::move(sets[k].arrival) : std::vector<double>(nodes, kInf));
        out.goalTimes.push_back(done[k] && sets[k].goalReached && sets[k].goalTime <= out.horizon ? sets[k].goalTime
                                                                                                  : kInf);
    }
    if (problem.isGeographic())
    {
        out.lon.resize(nodes);
        out.lat.resize(nodes);
        for (int j = 0; j < out.ny; ++j)
            for (int i = 0; i < out.nx; ++i)
            {
                const LonLat g = problem.toGeographic({out.x0 + i * out.h, out.y0 + j * out.h});
                out.lon[static_cast<std::size_t>(j) * out.nx + i] = g.lon;
                out.lat[static_cast<std::size_t>(j) * out.nx + i] = g.lat;
            }
    }
    probabilityFields(out);
    std::size_t atGoal = 0; // equal weights: the count over M (exactly 1 when every member gets there)
    for (std::size_t k = 0; k < members; ++k)
        if (out.goalTimes[k] <= out.horizon)
            out.goalProbability += out.weights[k], ++atGoal;
    out.goalProbability =
        out.weighed ? std::min(out.goalProbability, 1.0) : static_cast<double>(atGoal) / static_cast<double>(members);
    for (const double q : qs)
    {
        ReachQuantile rq;
        rq.q = q;
        rq.arrival = weightedQuantile(out.goalTimes, out.weights, q);
        rq.reached = rq.arrival <= out.horizon;
        if (!rq.reached)
            rq.arrival = kInf;
        rq.travelTime = rq.reached ? rq.arrival - departure : kInf;
        rq.iso = rq.reached ? problem.isoTime(rq.arrival) : "";
        out.quantiles.push_back(rq);
    }
    contoursOf(out, problem, pipelineView(*drawer.planner));
    out.seconds = planning_detail::secondsSince(wall0);
    return out;
}
} // namespace ompl_glider
