#pragma once
/// @file SummaryJson.h
/// @brief summary.json: one schema for every mode (documented in examples/MISSION_FORMAT.md, "summary.json").

#include <string>
#include <vector>

#include "ompl_glider/mission/Planning.h"

namespace ompl_glider
{
/// @brief Version of the summary.json schema (the `schema` key).
constexpr const char *kSummarySchema = "ompl_glider-summary/1";

/// @brief The summary of a run on @p problem as JSON text (pretty-printed; infinite or undefined numbers are null),
/// listing @p files, the files written beside it (names relative to the output directory).
/// @throws Error naming the field when a number in it is not finite (NaN, infinity), written or printed in a text.
std::string summaryJson(const MissionResult &result, const MissionProblem &problem,
                        const std::vector<std::string> &files = {});
} // namespace ompl_glider
