// The oracle of an execution: each run's pair planned on the truth (ExecutionOracle.h), and every strategy's arrival
// measured against the oracle's.
#include "ExecutionOracle.h"

#include <cmath>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionLegs.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

namespace ompl_glider::execution_detail
{
void planPair(const MissionProblem &problem, ExecutionRun &run, bool stations)
{
    const MissionProblem pair = problem.withEndpoints(run.start, run.goal);
    if (stations)
    {
        const MissionPlan p = planMission(pair, run.departure);
        run.planned = p.plan.solved;
        run.reason = p.plan.reason;
        if (p.plan.solved)
        {
            run.plan = p.plan.path;
            for (const PlannedLeg &l : p.legs)
                run.legs.push_back({l.lastPoint, l.plan.headings});
        }
        return;
    }
    const PlannedPath p = planRoute(pair, run.departure);
    run.planned = p.solved;
    run.reason = p.reason;
    if (p.solved)
    {
        run.plan = p.path;
        run.headings = p.headings;
    }
}

ExecutionRun oraclePlan(const MissionProblem &onTruth, const ExecutionRun &run, bool stations)
{
    ExecutionRun o;
    o.index = run.index;
    o.start = run.start;
    o.goal = run.goal;
    o.departure = run.departure;
    o.radius = run.radius;
    try
    {
        planPair(onTruth, o, stations);
    }
    catch (const Error &e)
    {
        // e.g. an end the truth puts on land: no oracle for this pair, the strategies are not judged against it
        o.planned = false;
        o.reason = e.what();
    }
    return o;
}

MeasureSpread overOracle(const ExecutionResult &r, std::size_t k)
{
    std::vector<double> ratios;
    if (!r.oracle)
        return measureSpread(ratios);
    for (const ExecutionRun &run : r.runs)
    {
        if (!run.planned || !std::isfinite(run.oracleArrival) || !(run.oracleArrival > run.departure))
            continue;
        const FlownTrack &f = run.flown[k];
        if (f.reached && std::isfinite(f.arrivalTime))
            ratios.push_back((f.arrivalTime - run.departure) / (run.oracleArrival - run.departure));
    }
    return measureSpread(ratios);
}
} // namespace ompl_glider::execution_detail
