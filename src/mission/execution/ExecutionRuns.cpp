// An execution through a stream of forecast runs (ExecutionRuns.h): the problem on the run of a time, the forecast a
// glider at sea steers on, the runs' arrivals, and the learning from the DAC across runs.
#include "ExecutionRuns.h"

#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "ompl_glider/current/EnsembleLearning.h"
#include "ompl_glider/current/ForecastRuns.h"
#include "ompl_glider/mission/MissionProblem.h"

namespace ompl_glider::execution_detail
{
/// With forecast runs (MissionProblem::runs()), @p problem on the newest run available at @p t (ForecastRuns::
/// runAt()), as a pilot plans then; else @p problem itself.
MissionProblem onRunAt(const MissionProblem &problem, double t)
{
    const auto &runs = problem.runs();
    if (!runs)
        return problem;
    const std::size_t k = runs->runAt(t);
    return k == problem.runIndex() ? problem.withField(problem.getField()) : problem.withField(runs->field(k));
}

/// The forecast a glider at sea steers on: with forecast runs, the current of the newest run available at each time
/// (RunStreamField); else the problem's field.
std::shared_ptr<const CurrentField> steeringField(const MissionProblem &problem)
{
    if (!problem.runs())
        return problem.getField();
    return std::make_shared<RunStreamField>(problem.runs());
}

/// With forecast runs, the times after @p t0 at which a newer run becomes available (the replanning strategies
/// replan then); else none.
std::vector<double> runArrivals(const MissionProblem &problem, double t0)
{
    return problem.runs() ? problem.runs()->arrivalsAfter(t0) : std::vector<double>{};
}

/// flightLearning() with forecast runs: the learning starts again on each new run (the newest available at the last
/// DAC), on the runs as known then (RunStreamField as of that time: the new run wherever it covers a DAC's time).
/// execution.across_runs carry: every DAC kept, those measured before the new run compared with it again (their
/// forecast read anew at their time and place); reset: only the DAC measured since the new run became available.
DacLearning runsLearning(const MissionProblem &problem)
{
    struct State
    {
        std::optional<std::size_t> run;
        std::shared_ptr<FlightLearning> learning;
    };
    auto state = std::make_shared<State>();
    const std::shared_ptr<const ForecastRuns> runs = problem.runs();
    const CorrectionParams params = problem.correctionParams();
    const bool reset = problem.getSpec().execution.acrossRuns == AcrossRuns::Reset;
    return [state, runs, params, reset](const std::vector<DacObservation> &measured) {
        const double now = measured.empty() ? -std::numeric_limits<double>::infinity() : measured.back().t;
        const std::size_t k = runs->runAt(now);
        if (!state->run || *state->run != k)
        {
            state->run = k;
            state->learning =
                std::make_shared<FlightLearning>(std::make_shared<RunStreamField>(runs, now),
                                                 std::vector<std::shared_ptr<const CurrentField>>{}, params);
        }
        const double since = (*runs)[k].available;
        std::vector<DacObservation> kept;
        for (const DacObservation &d : measured)
        {
            if (d.t >= since)
                kept.push_back(d); // compared with this run as it was measured
            else if (!reset)
            {
                kept.push_back(d);
                kept.back().forecast.reset(); // compared with the new run at its time and place
            }
        }
        return (*state->learning)(kept);
    };
}

} // namespace ompl_glider::execution_detail
