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
    double departureTime{0.0};  ///< t0
    double arrivalTime{0.0};    ///< time at the last waypoint (+inf when a leg is infeasible)
    double travelTime{0.0};     ///< arrivalTime - t0
    std::vector<double> times;  ///< time at each waypoint (times[0] = t0; +inf from the first infeasible leg on)
    bool finite{true};          ///< every leg feasible
    bool valid{true};           ///< finite, and every waypoint and leg free and inside the region / time window
    int firstBadLeg{-1};        ///< index i of the first leg (waypoint i -> i + 1) that is not valid; -1 if none
    std::string reason;         ///< why firstBadLeg is bad; empty when valid
};

/// @brief Flies the waypoints in order from t0, each leg as fast as possible (TravelTimeCalculator::travelTime,
/// one CFC per leg), and re-checks every waypoint (region box, time window [region.tMin, region.tMax], inWater,
/// Environment::pointFree) and every leg (Environment::legFree at the flown times). Fewer than 2 waypoints:
/// travel time 0, valid iff the single waypoint (if any) is valid at t0.
PathResimulation resimulatePath(const GliderContext &ctx, const std::vector<std::array<double, 2>> &waypoints,
                                double t0);

/// @brief The same for an OMPL path on TimeSE2StateSpace; uses its states' x and y only (not their times).
PathResimulation resimulatePath(const GliderContext &ctx, const ompl::geometric::PathGeometric &path, double t0);
}  // namespace ompl_glider
