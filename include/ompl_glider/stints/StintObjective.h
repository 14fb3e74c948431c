#pragma once
/// @file StintObjective.h
/// @brief What a stint plan is judged by (a mission's `stints.objective`; StintSimulator.h flies the plans).

#include <string>

namespace ompl_glider
{
/// @brief What a stint plan is judged by.
enum class StintObjective
{
    /// Distance to the goal at the end of the mission ([IsernObstacles] Sec. II.A: the Euclidean distance between
    /// the last surfacing and the target).
    RemainingDistance,
    /// Earliest arrival within StintSettings::radius of the goal (the stints end there).
    EarliestArrival
};

/// @brief "remaining_distance" / "earliest_arrival".
std::string stintObjectiveName(StintObjective o);
/// @brief The objective named @p name ("remaining_distance" / "earliest_arrival"). @throws Error for another name.
StintObjective parseStintObjective(const std::string &name);

}  // namespace ompl_glider
