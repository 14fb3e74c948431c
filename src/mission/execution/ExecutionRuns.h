#pragma once
/// @file ExecutionRuns.h
/// @brief Internal to the library (not installed): an execution through a stream of forecast runs
/// (MissionProblem::runs(); MissionExecution.cpp flies it). Without runs each is the one-forecast case.

#include <memory>
#include <vector>

#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/execution/Execution.h"

namespace ompl_glider
{
class MissionProblem;

namespace execution_detail
{
/// With forecast runs, @p problem on the newest run available at @p t (ForecastRuns::runAt()), as a pilot plans
/// then; else @p problem itself.
MissionProblem onRunAt(const MissionProblem &problem, double t);
/// The forecast a glider at sea steers on: with forecast runs, the current of the newest run available at each time
/// (RunStreamField); else the problem's field.
std::shared_ptr<const CurrentField> steeringField(const MissionProblem &problem);
/// With forecast runs, the times after @p t0 at which a newer run becomes available (the replanning strategies
/// replan then); else none.
std::vector<double> runArrivals(const MissionProblem &problem, double t0);
/// The learning from one flight's DAC with forecast runs: it starts again on each new run (the newest available at
/// the last DAC), on the runs as known then (RunStreamField as of that time: the new run wherever it covers a DAC's
/// time). execution.across_runs carry: every DAC kept, those measured before the new run compared with it again
/// (their forecast read anew at their time and place); reset: only the DAC measured since the new run arrived.
DacLearning runsLearning(const MissionProblem &problem);
} // namespace execution_detail
} // namespace ompl_glider
