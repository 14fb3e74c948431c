/// @file Ensembles.cpp
/// @brief Robust plans over the members of an ensemble current (planRobust(), used by planRoute()): candidates
/// planned on the members' mean and on the members (every one of up to kMemberCandidates, else that many spread over
/// the ensemble), each flown in the screening members (retimePath()), the best there flown in every member and judged
/// by the mission's objective over the members (ensembleObjective()): the work grows with the members as the members
/// themselves, not as their square. Where no candidate arrives in every member, the plan is the one most likely to
/// arrive (mostLikelyToArrive()); no path only where none arrives in any member. The pilot's time limit bounds the
/// candidates' planning, a stop request (Ctrl-C) the planning and the flights. In an MPI job the candidates are
/// spread over the ranks (TaskSpread.h).

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>

#include "PlanningInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/TaskSpread.h"
#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/cost/TravelTimeCalculator.h"

namespace ompl_glider
{
namespace planning_detail
{
namespace
{
/// Members planned as candidates beside the mean: every member of an ensemble of up to this many, else this many
/// spread over it (member 0, the control run of a drawn ensemble, among them).
constexpr std::size_t kMemberCandidates = 32;
/// Members every candidate is flown in first: every member of an ensemble of up to this many (then nothing is left to
/// screen), else this many spread over it.
constexpr std::size_t kScreeningMembers = 32;
/// Candidates flown in every member after the screening: the best there, in turn, until this many are passable in
/// every member.
constexpr std::size_t kFinalists = 4;
/// A candidate's travel time in a member it was not flown in.
constexpr double kNotFlown = std::numeric_limits<double>::quiet_NaN();

/// @p k indices spread evenly over 0 .. n-1, 0 first; all of them when n <= k.
std::vector<std::size_t> spreadOver(std::size_t n, std::size_t k)
{
    const std::size_t m = std::min(n, k);
    std::vector<std::size_t> out(m);
    for (std::size_t i = 0; i < m; ++i)
        out[i] = i * n / m;
    return out;
}

/// The objective over the members a candidate was flown in (NaN: not flown there).
double objectiveOverFlown(const std::vector<double> &times, EnsembleObjective objective, double q)
{
    std::vector<double> flown;
    for (double t : times)
        if (!std::isnan(t))
            flown.push_back(t);
    return ensembleObjective(flown, objective, q);
}

/// The share of the members a candidate was flown in where it arrives (0 when flown in none).
double arrivingShare(const std::vector<double> &times)
{
    std::size_t flown = 0, arriving = 0;
    for (double t : times)
        if (!std::isnan(t))
        {
            ++flown;
            arriving += std::isfinite(t) ? 1 : 0;
        }
    return flown == 0 ? 0.0 : static_cast<double>(arriving) / static_cast<double>(flown);
}

/// The objective over the members a candidate was flown in and arrives in (+inf when none).
double objectiveOverArriving(const std::vector<double> &times, EnsembleObjective objective, double q)
{
    std::vector<double> arriving;
    for (double t : times)
        if (std::isfinite(t))
            arriving.push_back(t);
    return arriving.empty() ? kInf : ensembleObjective(arriving, objective, q);
}

/// Whether @p times holds a travel time (or +inf) for every member.
bool flownInEvery(const std::vector<double> &times)
{
    return std::none_of(times.begin(), times.end(), [](double t) { return std::isnan(t); });
}

/// The candidates planned on the processes of a job: each task plans one candidate and returns what the choice
/// needs (solved or left out, the member travel times, the path's points for the finalists' flights, the counters).
void spreadCandidates(TaskSpreader &spread, std::vector<PlannedPath> &plans, std::vector<std::vector<double>> &times,
                      std::vector<char> &leftOut, const std::function<void(std::size_t)> &candidate)
{
    const std::vector<std::string> out = spread.run("ensemble candidate", plans.size(), [&](std::size_t c) {
        candidate(c);
        const PlannedPath &p = plans[c];
        ByteWriter w;
        w.put(p.solved);
        w.put(leftOut[c] != 0);
        w.put(times[c]);
        std::vector<double> points;
        for (const TimedPoint &q : p.path)
            points.insert(points.end(), {q.x, q.y, q.t});
        w.put(points);
        w.put(p.searchCostFunctionCalls);
        w.put(p.postprocessCostFunctionCalls);
        w.put(p.currentModelCalls);
        w.put(p.expandedVertices);
        w.put(p.planningSeconds);
        w.put(p.postprocessSeconds);
        plans[c] = PlannedPath();
        return w.take();
    });
    for (std::size_t c = 0; c < plans.size(); ++c)
    {
        PlannedPath &p = plans[c];
        ByteReader r(out[c]);
        r.get(p.solved);
        bool skipped = false;
        r.get(skipped);
        leftOut[c] = skipped ? 1 : 0;
        r.get(times[c]);
        std::vector<double> points;
        r.get(points);
        p.path.clear();
        for (std::size_t i = 0; i + 2 < points.size(); i += 3)
            p.path.push_back({points[i], points[i + 1], points[i + 2]});
        r.get(p.searchCostFunctionCalls);
        r.get(p.postprocessCostFunctionCalls);
        r.get(p.currentModelCalls);
        r.get(p.expandedVertices);
        r.get(p.planningSeconds);
        r.get(p.postprocessSeconds);
    }
}

/// The candidates' flights in the members: each a retimePath() in one member; a stop request ends them
/// (cut() says so).
class MemberFlights
{
public:
    MemberFlights(const MissionProblem &problem, double departure, double speed, const std::vector<PlannedPath> &plans,
                  std::vector<std::vector<double>> &times)
        : problem_(problem), departure_(departure), speed_(speed), plans_(plans), times_(times)
    {
    }
    /// Candidate @p c flown in member @p k (nothing when it has no path or a stop was requested).
    void fly(std::size_t c, std::size_t k)
    {
        if (!plans_[c].solved || !std::isnan(times_[c][k]))
            return;
        if (stopRequested())
        {
            cut_ = true;
            return;
        }
        const std::vector<TimedPoint> flown = retimePath(problem_, problem_.getMembers()[k], speed_, plans_[c].path);
        times_[c][k] = flown.empty() ? kInf : flown.back().t - departure_;
    }
    /// Candidate @p c flown in every member of @p which.
    void flyIn(std::size_t c, const std::vector<std::size_t> &which)
    {
        for (std::size_t k : which)
            fly(c, k);
    }
    bool cut() const { return cut_; }

private:
    const MissionProblem &problem_;
    double departure_, speed_;
    const std::vector<PlannedPath> &plans_;
    std::vector<std::vector<double>> &times_;
    std::atomic<bool> cut_{false};
};

/// No candidate arrives in every member: the one that arrives in the largest share of those it was flown in (ties:
/// the better objective over the members it arrives in), flown in every member. Its index, or nullopt when no
/// candidate arrives in any member.
std::optional<std::size_t> mostLikelyToArrive(const std::vector<PlannedPath> &plans,
                                              const std::vector<std::vector<double>> &times,
                                              const std::vector<char> &leftOut, const EnsemblePlan &e,
                                              MemberFlights &flights, std::size_t members)
{
    std::optional<std::size_t> best;
    const auto key = [&](std::size_t c) {
        return std::make_pair(-arrivingShare(times[c]), objectiveOverArriving(times[c], e.objective, e.quantile));
    };
    for (std::size_t c = 0; c < plans.size(); ++c)
        if (plans[c].solved && !leftOut[c] && arrivingShare(times[c]) > 0.0 && (!best || key(c) < key(*best)))
            best = c;
    if (best)
    {
        std::vector<std::size_t> all(members);
        std::iota(all.begin(), all.end(), 0);
        flights.flyIn(*best, all);
    }
    return best;
}

/// The finalists: the candidates in the order of their objective over the screening members, each passable there
/// flown in every member (all of a round side by side) until kFinalists are passable in every member.
void flyFinalists(const std::vector<PlannedPath> &plans, const std::vector<std::vector<double>> &times,
                  const EnsemblePlan &e, std::size_t members, MemberFlights &flights)
{
    std::vector<std::size_t> rank(plans.size());
    std::iota(rank.begin(), rank.end(), 0);
    std::vector<double> screened(plans.size(), kInf);
    for (std::size_t c = 0; c < plans.size(); ++c)
        if (plans[c].solved)
            screened[c] = objectiveOverFlown(times[c], e.objective, e.quantile);
    std::stable_sort(rank.begin(), rank.end(), [&](std::size_t a, std::size_t b) { return screened[a] < screened[b]; });
    ThreadPool pool(0);
    std::size_t passable = 0, next = 0;
    while (passable < kFinalists && next < rank.size() && !flights.cut())
    {
        std::vector<std::size_t> round;
        while (passable + round.size() < kFinalists && next < rank.size() && std::isfinite(screened[rank[next]]))
            round.push_back(rank[next++]);
        if (round.empty())
            break; // the rest is impassable in a screening member already
        pool.parallelFor(round.size() * members, [&](std::size_t i) { flights.fly(round[i / members], i % members); });
        for (std::size_t c : round)
            passable += std::isfinite(ensembleObjective(times[c], e.objective, e.quantile)) ? 1 : 0;
    }
}

/// @p r without its path: every candidate fails in some member, no plan is robust over the ensemble (exit 1, the
/// members where the best, @p e's chosen, fails named from @p chosen, its travel times).
PlannedPath notRobust(const MissionProblem &problem, PlannedPath r, const EnsemblePlan &e,
                      const std::vector<double> &chosen)
{
    const auto &members = problem.getMembers();
    std::string failing;
    for (std::size_t k = 0; k < chosen.size(); ++k)
        if (std::isinf(chosen[k]))
            failing += (failing.empty() ? "" : ", ") + std::string("member ") + std::to_string(k) + " (" +
                       members[k]->name() + ")";
    r.solved = false;
    r.status = PlanStatus::NoPath;
    const std::string objective = ensembleObjectiveName(e.objective);
    r.setNoPath({NoPathCause::NotRobust, "no member of the ensemble is reached: no candidate plan (the mean's, the "
                                         "members' own) arrives in any of the " +
                                             std::to_string(members.size()) + " members (objective " + objective +
                                             "); the best, planned on the " + e.chosen + ", is impassable in " +
                                             failing});
    return r;
}

/// The candidates planned (not @p leftOut) noted in @p e, each with its times in the members and its objective; returns
/// the best: one that arrives in every member before one that does not, a plan before none, then by the objective
/// over the members flown (the mean's plan where none is better).
std::size_t bestCandidate(const std::vector<PlannedPath> &plans, const std::vector<std::vector<double>> &times,
                          const std::vector<char> &leftOut, const std::vector<std::size_t> &planned, EnsemblePlan &e)
{
    std::size_t best = 0;
    const auto eligible = [&](std::size_t c) { return plans[c].solved && flownInEvery(times[c]); };
    for (std::size_t c = 0; c < plans.size(); ++c)
    {
        if (leftOut[c])
            continue; // not planned: not a candidate
        EnsemblePlan::Candidate cand;
        cand.name = c == 0 ? "mean" : "member " + std::to_string(planned[c - 1]);
        cand.solved = plans[c].solved;
        cand.memberTravelTimes = times[c];
        cand.objectiveValue = plans[c].solved ? objectiveOverFlown(times[c], e.objective, e.quantile) : kInf;
        e.candidates.push_back(cand);
        const auto better = [&](std::size_t a, std::size_t b) {
            if (eligible(a) != eligible(b))
                return eligible(a);
            if (plans[a].solved != plans[b].solved)
                return plans[a].solved;
            return objectiveOverFlown(times[a], e.objective, e.quantile) <
                   objectiveOverFlown(times[b], e.objective, e.quantile);
        };
        if (c > 0 && better(c, best))
            best = c;
    }
    return best;
}

/// The plan of an ensemble whose flights a stop request cut: no path, with the work of the candidates planned.
PlannedPath stoppedEnsemble(const std::vector<PlannedPath> &plans, double departure, double speed, EnsemblePlan e)
{
    PlannedPath r;
    r.departure = departure;
    r.speed = speed;
    r.planner = plans[0].planner;
    r.straightLineLength = plans[0].straightLineLength;
    for (const PlannedPath &p : plans)
        addPlanningWork(r, p);
    r.status = PlanStatus::Stopped;
    r.setNoPath({NoPathCause::Stopped, "stopped on request (Ctrl-C) before the candidate plans were flown in "
                                       "every member of the ensemble"});
    r.ensemble = std::move(e);
    return r;
}

/// The chosen candidate @p chosen planned again on every rank (the same planning on the same field: the same path,
/// for the deterministic planners, flown in the members as before), with the counts of its first planning.
void planAgainOnEveryRank(const MissionProblem &problem, double departure, const PlanOptions &o,
                          const std::vector<std::size_t> &planned, std::size_t best, PlannedPath &chosen)
{
    const PlannedPath counted = chosen;
    chosen = best == 0 ? planOnField(problem, departure, o)
                       : planOnField(problem.withMember(planned[best - 1]), departure, o);
    chosen.searchCostFunctionCalls = counted.searchCostFunctionCalls;
    chosen.postprocessCostFunctionCalls = counted.postprocessCostFunctionCalls;
    chosen.currentModelCalls = counted.currentModelCalls;
    chosen.expandedVertices = counted.expandedVertices;
    chosen.planningSeconds = counted.planningSeconds;
    chosen.postprocessSeconds = counted.postprocessSeconds;
}
} // namespace

/// A robust plan over the members of an ensemble (see planRoute()).
PlannedPath planRobust(const MissionProblem &problem, double departure, const PlanOptions &o)
{
    const auto started = std::chrono::steady_clock::now();
    const MissionSpec &m = problem.getSpec();
    const auto &members = problem.getMembers();
    const std::size_t n = members.size();
    const double speed = std::isnan(o.speed) ? m.vehicle.speed : o.speed;
    const std::vector<std::size_t> planned = spreadOver(n, kMemberCandidates); // the members planned on
    const std::vector<std::size_t> screening = spreadOver(n, kScreeningMembers);
    // candidates: the mean field's plan, then the planned members', planned in parallel
    std::vector<PlannedPath> plans(planned.size() + 1);
    std::vector<std::vector<double>> times(plans.size(), std::vector<double>(n, kNotFlown));
    std::vector<char> leftOut(plans.size(), 0); // not planned: the time limit had passed, or a stop was requested
    MemberFlights flights(problem, departure, speed, plans, times);
    const double limit = o.timeLimit > 0 ? o.timeLimit : m.planner.timeLimit; // the pilot's, for the whole search
    const auto candidate = [&](std::size_t c) {
        PlanOptions co = o;
        if (limit > 0.0)
            co.timeLimit = std::max(limit - secondsSince(started), 1e-3); // each candidate within what is left
        if (c > 0 && (stopRequested() || (limit > 0.0 && secondsSince(started) >= limit)))
        {
            leftOut[c] = 1;
            return;
        }
        plans[c] = c == 0 ? planOnField(problem, departure, co)
                          : planOnField(problem.withMember(planned[c - 1]), departure, co);
        flights.flyIn(c, screening);
    };
    TaskSpreader *spread = activeTaskSpreader();
    if (spread)
        spreadCandidates(*spread, plans, times, leftOut, candidate);
    else
    {
        ThreadPool pool(0);
        pool.parallelFor(plans.size(), candidate);
    }
    EnsemblePlan e;
    e.objective = m.planner.objective;
    e.quantile = m.planner.quantile;
    if (screening.size() < n)
        flyFinalists(plans, times, e, n, flights);
    std::size_t best = bestCandidate(plans, times, leftOut, planned, e);
    const auto eligible = [&](std::size_t c) { return plans[c].solved && flownInEvery(times[c]); };
    // No candidate arrives in every member: the plan is the one most likely to arrive, with its share of the members
    // (never "no path" while members arrive); "no path" only when no candidate arrives in any member.
    if (plans[best].solved && !flights.cut() &&
        !(eligible(best) && std::isfinite(ensembleObjective(times[best], e.objective, e.quantile))))
        if (const std::optional<std::size_t> likely = mostLikelyToArrive(plans, times, leftOut, e, flights, n))
            best = *likely;
    if (flights.cut()) // a stop request (Ctrl-C) cut the flights: no candidate can be judged over every member
        return stoppedEnsemble(plans, departure, speed, std::move(e));
    if (spread && plans[best].solved)
        planAgainOnEveryRank(problem, departure, o, planned, best, plans[best]);
    PlannedPath r = plans[best];
    e.chosen = best == 0 ? "mean" : "member " + std::to_string(planned[best - 1]);
    e.objectiveValue = ensembleObjective(times[best], e.objective, e.quantile);
    e.memberTravelTimes = times[best];
    e.arrivalProbability = flownInEvery(times[best]) ? arrivingShare(times[best]) : 0.0;
    if (e.arrivalProbability > 0.0 && e.arrivalProbability < 1.0) // the objective over the members it arrives in
        e.objectiveValue = objectiveOverArriving(times[best], e.objective, e.quantile);
    // every candidate's search counts
    r.searchCostFunctionCalls = r.postprocessCostFunctionCalls = r.currentModelCalls = r.expandedVertices = 0;
    r.planningSeconds = r.postprocessSeconds = 0.0;
    for (const PlannedPath &p : plans)
        addPlanningWork(r, p);
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
    if (r.solved && !std::isfinite(e.objectiveValue))
        r = notRobust(problem, std::move(r), e, times[best]);
    else if (!r.solved && std::none_of(leftOut.begin(), leftOut.end(), [](char c) { return c != 0; }) &&
             (r.noPath.cause == NoPathCause::LatticeExhausted || r.noPath.cause == NoPathCause::SearchEnded ||
              r.noPath.cause == NoPathCause::Unreachable || r.noPath.cause == NoPathCause::NotFlyable ||
              r.noPath.cause == NoPathCause::Other))
        // neither the mean's plan nor any member's own has a path: no member is reached, said first
        r.setNoPath({NoPathCause::NotRobust, "no member of the ensemble is reached: neither the plan on the members' "
                                             "mean nor any member's own plan finds a path (on the mean: " +
                                                 r.reason + ")"});
    r.ensemble = std::move(e);
    return r;
}
} // namespace planning_detail

const char *ensembleObjectiveName(EnsembleObjective o)
{
    switch (o)
    {
    case EnsembleObjective::Worst:
        return "worst";
    case EnsembleObjective::Quantile:
        return "quantile";
    case EnsembleObjective::Expected:
        break;
    }
    return "expected";
}

EnsembleObjective parseEnsembleObjective(const std::string &name)
{
    for (EnsembleObjective o : {EnsembleObjective::Expected, EnsembleObjective::Worst, EnsembleObjective::Quantile})
        if (name == ensembleObjectiveName(o))
            return o;
    throw Error("unknown ensemble objective '" + name + "' (expected, worst, quantile)");
}

double ensembleObjective(const std::vector<double> &t, EnsembleObjective objective, double q)
{
    if (t.empty())
        return kInf;
    for (double x : t)
        if (!std::isfinite(x))
            return kInf;
    if (objective == EnsembleObjective::Worst)
        return *std::max_element(t.begin(), t.end());
    if (objective == EnsembleObjective::Quantile)
    {
        std::vector<double> s = t;
        std::sort(s.begin(), s.end());
        const double rank = std::ceil(q * static_cast<double>(s.size()));
        const std::size_t k = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(s.size())));
        return s[k - 1];
    }
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
} // namespace ompl_glider
