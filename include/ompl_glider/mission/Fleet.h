#pragma once
/// @file Fleet.h
/// @brief A fleet of gliders (mission `fleet`): one mission per glider (fleetGliderMission()), each planned by
/// runMission() (the one pipeline) on its own MissionProblem. The gliders are planned in threads, or spread over the
/// processes of a job (TaskSpread.h: each rank plans whole gliders; the results come back to every rank).

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "ompl_glider/mission/Planning.h"

namespace ompl_glider
{
/// @brief One glider's line of the fleet table.
struct FleetRow
{
    std::string name;                       ///< the glider's name (its folder)
    bool solved{false};                     ///< a route was found
    PlanStatus status{PlanStatus::Unknown}; ///< how the glider's plan ended (PlannedPath::status)
    std::string reason;                     ///< why there is no route (empty when solved)
    /// The bad input when the glider's problem itself is bad (PlannedPath::badInput placed by MissionSpec::place():
    /// "m.yaml:12: field 'start'"); empty for a well-formed problem
    std::string badInput;
    double departure{0.0};                                       ///< departure time (field units)
    double travelTime{std::numeric_limits<double>::infinity()};  ///< PlannedPath::travelTime
    double pathLength{std::numeric_limits<double>::quiet_NaN()}; ///< PlannedPath::pathLength (NaN: no route)
    double arrival{std::numeric_limits<double>::quiet_NaN()};    ///< the last waypoint's time (NaN: no route)
    std::string departureIso; ///< ISO 8601 when the mission has a calendar, else empty
    std::string arrivalIso;   ///< see departureIso
};

/// @brief What runFleet() keeps of one glider: its row and what the keep function made of its result.
struct FleetGlider
{
    FleetRow row;
    std::string kept;
};

/// @brief Called on the process (and thread) that planned a glider, with its result and problem: the bytes to keep
/// of it (the output layer renders the glider's files here, so that only bytes travel between processes).
using FleetKeep = std::function<std::string(const MissionResult &, const MissionProblem &)>;

/// @brief The mission of glider @p i of @p mission's fleet: the mission with the glider's start, goal, speed and
/// departure (a fixed time in place of the mission's time or window), named after the glider, its outputs in the
/// folder named after it under the mission's output directory, and the places of its values (MissionSpec::place())
/// those of its fleet entry.
MissionSpec fleetGliderMission(const MissionSpec &mission, std::size_t i);

/// @brief Plans every glider of @p mission's fleet with runMission() (@p options for each; progress: one line per
/// glider planned) and returns them in the fleet's order. @p keep (when given) is called for every glider whose
/// problem is well-formed.
/// @throws Error "glider 'NAME': ..." when a glider's mission is bad input found while planning (in a job:
/// "rank R, fleet glider I: glider 'NAME': ...", TaskSpreader::run()).
std::vector<FleetGlider> runFleet(const MissionSpec &mission, const RunOptions &options, const FleetKeep &keep = {});
} // namespace ompl_glider
