#pragma once
/// @file PathToStints.h
/// @brief From any plan to what a glider flies: the heading per surfacing that follows a timed path (a lattice
/// ZA*TVE path, a refined path, a sampling planner's path) best, and what the stint version loses against it.
///
/// At each surfacing the glider aims at the point the path reaches one stint after the glider's progress along it
/// (the path's time at the path point nearest the glider, so that a glider ahead of the path's clock does not wait):
/// the current-sensitive heading
/// ([ThompsonICRA] Sec. III, crabHeading()) with the current at the fix, refined by a golden-section search over
/// +-45 degrees around it on the flown stint (the end of the stint nearest that point). The whole bearing vector is
/// then optimised for the earliest arrival (optimiseBearings(), [IsernObstacles] Sec. II.2).

#include <limits>
#include <vector>

#include "ompl_glider/routes/BearingOptimizer.h"
#include "ompl_glider/routes/StintSimulator.h"

namespace ompl_glider
{
/// @brief What stintsFromPath() found.
struct PathToStintsResult
{
    StintPlan tracking; ///< the path followed stint by stint (current-sensitive, refined per stint)
    StintPlan plan;     ///< after the optimisation of the whole bearing vector (never worse than tracking)
    double pathTravelTime{std::numeric_limits<double>::infinity()};  ///< the path's arrival - departure
    double stintTravelTime{std::numeric_limits<double>::infinity()}; ///< plan's arrival - departure (+inf: none)
    /// stintTravelTime / pathTravelTime - 1 (what flying stints loses; +inf when the stints do not arrive)
    double loss{std::numeric_limits<double>::infinity()};
    unsigned evaluations{0}; ///< plans simulated by the optimisation
};

/// @brief Converts @p path (start first, times increasing; the last point is the goal) into stints flown by
/// @p sim, which must depart at the path's first time from its first point with the earliest-arrival objective
/// and a radius (StintSettings::radius > 0) and a mission long enough to arrive (e.g. 1.5 x the path's time).
/// @throws Error for a path with fewer than 2 points or a simulator without radius.
PathToStintsResult stintsFromPath(const StintSimulator &sim, const std::vector<TimedPoint> &path,
                                  const BearingOptimizerParams &params = {});
} // namespace ompl_glider
