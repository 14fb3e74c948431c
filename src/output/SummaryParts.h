#pragma once
/// @file SummaryParts.h (internal to src/output, not installed)
/// @brief The parts of summary.json that SummaryJson.cpp takes from SummaryInputs.cpp: what went in (the forecast,
/// the current's ensemble, the glider's observations).

#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"
#include "JsonValues.h"

namespace ompl_glider
{
namespace summary_detail
{
using json = output_json::json;

/// The current's ensemble (null without one): each member's parameters or files, and how they were drawn.
json currentEnsembleJson(const CurrentSpec &c);
/// The forecast's kind of source, its files and its remote sources (current_source, forecast_files,
/// forecast_sources), into @p j.
void forecastJson(const MissionProblem &problem, json &j);
/// With forecast runs, the run planned on (null for one forecast): its file, number, reference time, where that
/// was read, when it became available, and the lead time at the plan's arrival (hours; null without a route).
json forecastRunJson(const MissionProblem &problem, const PlannedPath &plan);
/// The glider's observations: what was read, rejected and used, and the correction's size (null without them).
json observationsJson(const MissionProblem &problem);
/// The probability of reach (null without it): members, weights, grid, horizon, frames, the goal's probability,
/// the members' arrivals and the quantiles (ReachabilityFiles.cpp).
json reachabilityJson(const MissionResult &r);
} // namespace summary_detail
} // namespace ompl_glider
