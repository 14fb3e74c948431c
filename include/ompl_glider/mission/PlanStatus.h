#pragma once
/// @file PlanStatus.h
/// @brief How a plan ended: OMPL's planner status where the planner gave one, and the pipeline's own two outcomes
/// (no path exists, stopped on request).

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

namespace ompl_glider
{
/// @brief The status of a plan. The first nine are OMPL's ompl::base::PlannerStatus::StatusType in the same order
/// and with OMPL's texts; NoPath is the pipeline's word where a planner ran to its end (or a diagnosis proved) that
/// no path exists, so OMPL's Abort or Timeout would send the user after a longer time limit in vain; Stopped is a
/// stop request (Python's Ctrl-C) before a path was found.
enum class PlanStatus : std::uint8_t
{
    Unknown = 0,
    InvalidStart,
    InvalidGoal,
    UnrecognizedGoalType,
    Timeout,
    ApproximateSolution,
    ExactSolution,
    Crash,
    Abort,
    NoPath,
    Stopped
};

/// @brief The status as OMPL writes it (ompl::base::PlannerStatus::asString(): "Exact solution", "Invalid start",
/// ...; "Abort" for Abort, which OMPL 1.5 writes "Unknown status" like Unknown), "No path" and "Stopped" for the
/// pipeline's own; summary.json, fleet.csv and the report print this. Each status has its own text.
std::string statusText(PlanStatus status);

/// @brief The status whose statusText() is @p text; nullopt for any other text.
std::optional<PlanStatus> planStatusNamed(std::string_view text);

/// @brief The status of OMPL's StatusType value @p omplStatus (0 .. 8); Unknown for any other value.
PlanStatus planStatusOfOmpl(int omplStatus);

inline std::ostream &operator<<(std::ostream &out, PlanStatus status)
{
    return out << statusText(status);
}
} // namespace ompl_glider
