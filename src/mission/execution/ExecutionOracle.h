#pragma once
/// @file ExecutionOracle.h
/// @brief Internal to the library (not installed): the oracle of an execution (ExecutionResult::oracle), the fair
/// yardstick of a strategy's arrival: each run's pair planned on the truth as the run was planned on the forecast,
/// then flown in the truth with the truth as its forecast (MissionExecution.cpp flies it).

#include "ompl_glider/mission/MissionExecution.h"

namespace ompl_glider
{
class MissionProblem;

namespace execution_detail
{
/// @p run's pair (its start, goal and departure) planned on @p problem: as a mission through the stations when
/// @p stations (planMission()), else one leg (planRoute()); sets its `planned`, `reason`, `plan` and `legs` or
/// `headings`. The one way an execution plans a pair (the batch's on the forecast, the oracle's on the truth).
/// @throws Error as planning does.
void planPair(const MissionProblem &problem, ExecutionRun &run, bool stations);

/// @p run's pair (its start, goal, departure and radius) planned on @p onTruth (the mission's problem with the truth
/// as its field): as a mission through the stations when @p stations (planMission()), else one leg (planRoute()),
/// with the mission's planner and settings, as the batch's pairs are planned. Not flown; `planned` false and a
/// reason when there is no plan (also when planning refuses the pair).
ExecutionRun oraclePlan(const MissionProblem &onTruth, const ExecutionRun &run, bool stations);

/// (arrival - departure) / (oracle's arrival - departure) of strategy @p k over the runs of @p r that it and the
/// oracle reached (finite arrivals after the departure): their spread; empty without an oracle.
MeasureSpread overOracle(const ExecutionResult &r, std::size_t k);
} // namespace execution_detail
} // namespace ompl_glider
