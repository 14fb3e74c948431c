#pragma once
/// @file MissionLegs.h
/// @brief Missions of several legs: a start, via points (MissionSpec::waypoints) and a goal, planned as a list of the
/// same one-leg problems on one clock (MissionProblem::withLeg(), planRoute()): leg k departs at leg k-1's arrival
/// plus the stay at its via point. In a time-varying current a leg's best route depends on when it starts, so the
/// legs are planned in sequence, never independently and summed. With `order: free` the fastest visiting order of the
/// via points is found exactly by a branch and bound over orders with the planned leg times.

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/mission/Planning.h"

namespace ompl_glider
{
/// @brief A mission's plan: the whole route and its legs.
struct MissionPlan
{
    /// The whole route: the legs' paths in turn, a stay as a hold (a zero-length leg), times on one clock; solved only
    /// when every leg is. Without via points: planRoute()'s plan itself.
    PlannedPath plan;
    std::vector<PlannedLeg> legs;   ///< every leg planned, in the order flown (empty without via points)
    std::vector<std::size_t> order; ///< the via points in the order visited (indices into MissionSpec::waypoints)
    std::optional<OrderSearch> orderSearch; ///< with `order: free`
};

/// @brief The one planning function of a mission from @p departure: planRoute() for a mission of one leg; with via
/// points each leg in turn (withLeg(), planRoute() with the pipeline's global check and safety rules; the leg's end
/// window from the via point's `arrive`), a stay checked to be possible (|c| < V at the via point over the whole stay,
/// MissionProblem's hold test) and held, the next leg departing at the arrival plus the stay. A leg without a route
/// ends the mission: the plan is not solved and its reason names the leg ("leg 3, B to C: ..."). With `order: free`
/// the order is searched (branch and bound, see OrderSearch), else the order listed.
MissionPlan planMission(const MissionProblem &problem, double departure, const PlanOptions &options = {});

/// @brief The optimal-control reference of a mission of several legs (RunOptions::optimum): optimumReference() leg by
/// leg in the order of @p result's legs, each leg departing at the reference's arrival at the previous via point (no
/// earlier than its window's opening) plus the stay; found only when every leg's extremal is.
OptimumReference missionOptimumReference(const MissionProblem &problem, const MissionResult &result);

/// @brief Admissible lower bound of the time still needed from @p at (planning frame) at time @p t through the via
/// points @p remaining (indices) in any order and on to the goal, at speed @p speed in currents no faster than
/// @p maxCurrent: the shortest straight-line tour through them (exact over their orders) at V + max|c|, plus their
/// stays, and no earlier than any remaining point's window opening plus what follows it. Used by the free-order
/// search; exposed for tests.
double remainingTimeBound(const MissionProblem &problem, Point2 at, double t, const std::vector<std::size_t> &remaining,
                          double speed, double maxCurrent);
} // namespace ompl_glider
