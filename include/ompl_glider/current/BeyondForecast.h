#pragma once
/// @file BeyondForecast.h
/// @brief What a forecast field does after its last time: the policy of gridded fields, mission files
/// (`current.horizon`) and the command line (`--beyond`).

#include <string>

namespace ompl_glider
{
/// @brief What the field does after the last forecast time.
enum class BeyondForecast
{
    HoldLast, ///< keep the last forecast field for all later times (the paper's choice); timeEnd() = +inf
    Refuse    ///< timeEnd() = last forecast time: travel-time code reports legs that need later data infeasible
};

/// @brief Parses "hold" / "hold_last" / "hold-last" or "refuse" (case-insensitive). @throws Error otherwise.
BeyondForecast parseBeyondForecast(const std::string &name);
} // namespace ompl_glider
