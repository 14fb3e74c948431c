#pragma once
/// @file ExecutionOutcome.h
/// @brief Internal to the library (not installed): what a flight came to, said for a pilot (why a run does not
/// count as reached: FlownTrack::notReachedWhy) and each strategy's spread over the runs (ExecutionResult::spread).

#include <string>
#include <vector>

#include "ompl_glider/mission/MissionExecution.h"

namespace ompl_glider
{
class MissionProblem;

namespace execution_detail
{
/// @brief When a run's flights end at the latest, and why then.
struct RunEnd
{
    double time{0.0}; ///< field time
    std::string why;  ///< "twice the planned trip", "execution.duration", "the end of the truth's data"
};

/// @brief The end of the flights of a run departing at @p departure whose plan takes @p planned: the mission's
/// `execution.duration` after the departure, else twice the planned trip, never past the truth's data.
RunEnd runEnd(const MissionProblem &problem, double departure, double planned);

/// @brief "station C reached 2026-03-17T04:10:00Z, after its window closed at 2026-03-17T02:00:00Z": @p stop reached
/// at @p arrival after its window.
std::string lateText(const MissionProblem &problem, const ExecutionStop &stop, double arrival);

/// @brief Why @p f does not count as reached (empty when it does): grounded; @p target ("the goal", "station B", the
/// first one not reached; empty when every one was) not within @p radius of it by the run's end @p end; @p late (the
/// stations reached after their window, lateText()) with, when the run ended inside the goal's radius, that too.
std::string notReachedWhy(const MissionProblem &problem, const FlownTrack &f, const std::string &target, double radius,
                          const RunEnd &end, const std::string &late);

/// @brief What each strategy did over the runs flown.
std::vector<StrategySpread> strategySpreads(const ExecutionResult &r);
} // namespace execution_detail
} // namespace ompl_glider
