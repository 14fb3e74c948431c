/// @file Ensembles.cpp
/// @brief Robust plans over the members of an ensemble current (planRobust(), used by planRoute()): candidates
/// planned on the members' mean and on every member, each flown in every member (retimePath()) and judged by the
/// mission's objective over the members (ensembleObjective()); in an MPI job the candidates are spread over the
/// ranks (TaskSpread.h).

#include <algorithm>
#include <cmath>
#include <functional>

#include "PlanningInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/TaskSpread.h"
#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/cost/TravelTimeCalculator.h"

namespace ompl_glider
{
namespace planning_detail
{
namespace
{
/// The candidates planned on the processes of a job: each task plans one candidate and returns what the choice
/// needs (solved, the member travel times, the counters); the paths stay where they were planned.
void spreadCandidates(TaskSpreader &spread, std::vector<PlannedPath> &plans, std::vector<std::vector<double>> &times,
                      const std::function<void(std::size_t)> &candidate)
{
    const std::vector<std::string> out = spread.run("ensemble candidate", plans.size(), [&](std::size_t c) {
        candidate(c);
        const PlannedPath &p = plans[c];
        ByteWriter w;
        w.put(p.solved);
        w.put(times[c]);
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
        r.get(times[c]);
        r.get(p.searchCostFunctionCalls);
        r.get(p.postprocessCostFunctionCalls);
        r.get(p.currentModelCalls);
        r.get(p.expandedVertices);
        r.get(p.planningSeconds);
        r.get(p.postprocessSeconds);
    }
}
} // namespace

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
    const auto flyInMembers = [&](std::size_t c) {
        for (std::size_t k = 0; k < n && plans[c].solved; ++k)
        {
            const std::vector<TimedPoint> flown = retimePath(problem, members[k], speed, plans[c].path);
            times[c][k] = flown.empty() ? kInf : flown.back().t - departure;
        }
    };
    const auto candidate = [&](std::size_t c) {
        plans[c] = c == 0 ? planOnField(problem, departure, o) : planOnField(problem.withMember(c - 1), departure, o);
        flyInMembers(c);
    };
    TaskSpreader *spread = activeTaskSpreader();
    if (spread)
        spreadCandidates(*spread, plans, times, candidate);
    else
    {
        ThreadPool pool(0);
        pool.parallelFor(n + 1, candidate);
    }
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
    if (spread && plans[best].solved)
    {
        // the chosen candidate is planned again on every rank (the same planning on the same field: the same path,
        // for the deterministic planners), and flown in the members again
        const PlannedPath counted = plans[best];
        candidate(best);
        plans[best].searchCostFunctionCalls = counted.searchCostFunctionCalls;
        plans[best].postprocessCostFunctionCalls = counted.postprocessCostFunctionCalls;
        plans[best].currentModelCalls = counted.currentModelCalls;
        plans[best].expandedVertices = counted.expandedVertices;
        plans[best].planningSeconds = counted.planningSeconds;
        plans[best].postprocessSeconds = counted.postprocessSeconds;
        e.candidates[best].memberTravelTimes = times[best];
        e.candidates[best].objectiveValue = ensembleObjective(times[best], e.objective, e.quantile);
    }
    PlannedPath r = plans[best];
    e.chosen = e.candidates[best].name;
    e.objectiveValue = e.candidates[best].objectiveValue;
    e.memberTravelTimes = times[best];
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
    {
        // every candidate fails in some member: no plan is robust over the ensemble (exit 1, the members named)
        std::string failing;
        for (std::size_t k = 0; k < n; ++k)
            if (!std::isfinite(times[best][k]))
                failing += (failing.empty() ? "" : ", ") + std::string("member ") + std::to_string(k) + " (" +
                           members[k]->name() + ")";
        r.solved = false;
        r.status = PlanStatus::NoPath;
        const std::string objective = ensembleObjectiveName(e.objective);
        r.setNoPath({NoPathCause::NotRobust, "not robust: no candidate plan can be flown in every member of the "
                                             "ensemble (objective " +
                                                 objective + "); the best, planned on the " + e.chosen +
                                                 ", is impassable in " + failing});
    }
    r.ensemble = e;
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
