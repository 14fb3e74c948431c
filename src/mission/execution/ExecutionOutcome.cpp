// What a flight came to, said for a pilot, and each strategy's spread over the runs (ExecutionOutcome.h;
// measureSpread() of MissionExecution.h).
#include "ExecutionOutcome.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ompl_glider/mission/MissionProblem.h"
#include "ExecutionOracle.h"

namespace ompl_glider
{
namespace execution_detail
{
namespace
{
/// A time as a pilot reads it: the date where the mission has dates, else "t = T".
std::string when(const MissionProblem &problem, double t)
{
    const std::string iso = problem.isoTime(t);
    if (!iso.empty())
        return iso;
    char buf[48];
    std::snprintf(buf, sizeof buf, "t = %.6g", t);
    return buf;
}

/// A length as a pilot reads it: m or km where the frame is in metres, else the field's number.
std::string lengthText(const MissionProblem &problem, double d)
{
    const MissionSpec &m = problem.getSpec();
    char buf[48];
    if (!m.physicalUnits().length)
        std::snprintf(buf, sizeof buf, "%.4g", d);
    else if (d * m.metresPerUnit() < 1000.0)
        std::snprintf(buf, sizeof buf, "%.0f m", d * m.metresPerUnit());
    else
        std::snprintf(buf, sizeof buf, "%.2f km", d * m.metresPerUnit() / 1000.0);
    return buf;
}
} // namespace

RunEnd runEnd(const MissionProblem &problem, double departure, double planned)
{
    const ExecutionSpec &e = problem.getSpec().execution;
    RunEnd end;
    end.time = departure + (std::isnan(e.duration) ? 2.0 * planned : e.duration);
    end.why = std::isnan(e.duration) ? "twice the planned trip" : "execution.duration";
    const double truthEnd = problem.getTruth()->timeEnd();
    if (truthEnd < end.time)
    {
        end.time = truthEnd; // never beyond the truth (checkTruthTimes())
        end.why = "the end of the truth's data";
    }
    return end;
}

std::string lateText(const MissionProblem &problem, const ExecutionStop &stop, double arrival)
{
    return "station " + stop.name + " reached " + when(problem, arrival) + ", after its window closed at " +
           when(problem, stop.windowEnd);
}

std::string notReachedWhy(const MissionProblem &problem, const FlownTrack &f, const std::string &target, double radius,
                          const RunEnd &end, const std::string &late)
{
    if (f.reached)
        return "";
    std::string why;
    if (f.grounded)
        why = "grounded (" + f.groundedWhy + ")";
    else if (!target.empty())
        why = target + " not reached: not within " + lengthText(problem, radius) + " of it by " +
              when(problem, end.time) + ", when the run ended (" + end.why + ")";
    if (!late.empty())
        why += (why.empty() ? "" : "; ") + late;
    if (target.empty() && !f.grounded && std::isfinite(f.arrivalTime))
        why += " (the run ended inside the goal's radius, " + when(problem, f.arrivalTime) + ")";
    return why.empty() ? "not reached" : why;
}

std::vector<StrategySpread> strategySpreads(const ExecutionResult &r)
{
    std::vector<StrategySpread> out;
    for (std::size_t k = 0; k < r.strategies.size(); ++k)
    {
        StrategySpread s;
        s.strategy = controlStrategyName(r.strategies[k]);
        std::vector<double> dist, delay, speed;
        for (const ExecutionRun &run : r.runs)
        {
            if (!run.planned)
                continue;
            const FlownTrack &f = run.flown[k];
            ++s.runs;
            s.reached += f.reached ? 1 : 0;
            s.grounded += f.grounded ? 1 : 0;
            dist.push_back(f.finalDistance);
            if (f.reached)
                delay.push_back(f.arrivalTime - f.plannedArrival);
            speed.push_back(f.madeGoodSpeed);
        }
        s.finalDistance = measureSpread(dist);
        s.arrivalDelay = measureSpread(delay);
        s.madeGoodSpeed = measureSpread(speed);
        s.overOracle = overOracle(r, k); // empty without an oracle
        out.push_back(s);
    }
    return out;
}
} // namespace execution_detail

MeasureSpread measureSpread(std::vector<double> v)
{
    v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
    MeasureSpread s;
    s.count = v.size();
    if (v.empty())
        return s;
    std::sort(v.begin(), v.end());
    auto quantile = [&](double q) {
        const double pos = q * static_cast<double>(v.size() - 1);
        const std::size_t i = static_cast<std::size_t>(std::floor(pos));
        const std::size_t j = std::min(i + 1, v.size() - 1);
        return v[i] + (pos - static_cast<double>(i)) * (v[j] - v[i]);
    };
    s.min = v.front();
    s.q1 = quantile(0.25);
    s.median = quantile(0.5);
    s.q3 = quantile(0.75);
    s.max = v.back();
    double sum = 0.0;
    for (double x : v)
        sum += x;
    s.mean = sum / static_cast<double>(v.size());
    return s;
}
} // namespace ompl_glider
