#pragma once
/// @file PathResimulation.h
/// @brief Re-fly a path's waypoints from t0 with the travel-time code and re-check it (benchmarks, tests).

#include <array>
#include <string>
#include <vector>

#include <ompl/geometric/PathGeometric.h>

#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief Result of resimulatePath().
struct PathResimulation
{
    double departureTime{0.0}; ///< t0
    double arrivalTime{0.0};   ///< earliest time at the last waypoint (+inf when it cannot be reached)
    double travelTime{0.0};    ///< arrivalTime - t0
    std::vector<double> times; ///< earliest time at each waypoint (times[0] = t0; +inf where unreachable)
    bool finite{true};         ///< the last waypoint is reached (arrivalTime finite)
    bool valid{true};          ///< finite, and every waypoint and leg free and inside the region / time window
    int firstBadLeg{-1};       ///< index i of the first leg (waypoint i -> i + 1) that is not valid; -1 if none
    std::string reason;        ///< why firstBadLeg is bad; empty when valid
    bool waited{false};        ///< the direct flight failed and the arrival needed waiting (see ResimulationOptions)
};

/// @brief How resimulatePath() flies the waypoints.
struct ResimulationOptions
{
    /// First every leg is flown as fast as possible from the arrival at its first waypoint (a glider flying the
    /// waypoint list). When that fails (a leg infeasible or blocked at those times) and allowWaiting is set, the
    /// earliest arrival is searched over every schedule the motion model allows: on each leg any pace between the
    /// two roots (duration in TravelTimeCalculator::arrivalWindow), and holding at waypoints where |c| < V. Plans
    /// of sampling planners on TimeSE2StateSpace use such waiting (their legs are valid at their own times), and
    /// the direct flight can meet the jet at the wrong time. The reachable times at each waypoint are kept as
    /// intervals; departures are tried at the interval starts and on a grid of holdStep inside them, and the
    /// environment is checked on the fast flight of each tried departure.
    bool allowWaiting{true};
    double holdStep{0.0}; ///< grid of tried departure / holding times; 0: (region.tMax - region.tMin) / 512
};

/// @brief Flies the waypoints in order from t0, each leg as fast as possible (TravelTimeCalculator::travelTime,
/// one CFC per leg), and re-checks every waypoint (region box, time window [region.tMin, region.tMax], inWater,
/// Environment::pointFree) and every leg (Environment::legFree at the flown times, constant pace). When that
/// fails and options.allowWaiting is set (default), the earliest arrival with waiting is searched (see
/// ResimulationOptions; up to a few hundred CFC per leg) and reported with waited = true; then firstBadLeg is the
/// first leg after which no time is reachable. Fewer than 2 waypoints: travel time 0, valid iff the single waypoint (if
/// any) is valid at t0.
PathResimulation resimulatePath(const GliderContext &ctx, const std::vector<std::array<double, 2>> &waypoints,
                                double t0, const ResimulationOptions &options = {});

/// @brief The same for an OMPL path on TimeSE2StateSpace; uses its states' x and y only (not their times).
PathResimulation resimulatePath(const GliderContext &ctx, const ompl::geometric::PathGeometric &path, double t0,
                                const ResimulationOptions &options = {});
} // namespace ompl_glider
