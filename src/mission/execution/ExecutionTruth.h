#pragma once
// The truth an execution flies in, checked against the flights and compared with the forecast (MissionExecution.cpp).
#include "ompl_glider/mission/MissionExecution.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

namespace ompl_glider::execution_truth
{
/// A truth that does not cover the flights in time is never extrapolated: refused when it starts after the departure
/// or ends before the plan arrives, else the flights stop at its end and a note says so.
void checkTruthTimes(const MissionProblem &problem, const PlannedPath &plan, double window, ExecutionResult &r);
/// A gridded truth that covers only part of the region: refused when the plan leaves its grid (where, when); else a
/// note says that a flight leaving the grid stops there (it is not land).
void checkTruthSpace(const MissionProblem &problem, const PlannedPath &plan, ExecutionResult &r);
/// The truth against the forecast over the planning box and the time window of the runs (ExecutionResult's
/// rmsDifference, maxPointRmsDifference and their window).
void modelDifference(const MissionProblem &problem, const PlannedPath &plan, ExecutionResult &r);
} // namespace ompl_glider::execution_truth
