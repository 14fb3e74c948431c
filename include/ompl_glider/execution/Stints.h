#pragma once
/// @file Stints.h
/// @brief Constant-bearing stints ([IsernObstacles] Sec. II), the data: what a stint plan is judged by, the settings
/// of a mission's `stints` section (one struct for the mission, the stint planners and the conversion of a path) and
/// a flown plan. The stint planners and the simulator that flies a plan are in stints/.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"

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

/// @brief Stint settings (times in field units).
struct StintSettings
{
    double duration{1.0};        ///< time between two surfacings (8 h in [IsernObstacles] Sec. III)
    double missionDuration{4.0}; ///< the mission ends here after the departure (4 days in [IsernObstacles])
    double bearingStep{20.0};    ///< degrees between the bearings of the CTS-A* rose ([IsernObstacles] Sec. III.B)
    StintObjective objective{StintObjective::RemainingDistance}; ///< what plans are judged by
    double radius{0.0}; ///< > 0: the goal counts as reached within this distance and the stints end there
                        ///< (required > 0 by EarliestArrival)
    double step{0.0};   ///< RK4 step; 0: duration / 24
    double depth{0.0};  ///< depth at which the currents are read (m)

    /// @brief The RK4 step used.
    double rk4Step() const { return step > 0.0 ? step : duration / 24.0; }
    /// @brief Number of stints of the mission: ceil(missionDuration / duration) (the last may be shorter).
    std::size_t stintCount() const;
    /// @brief Throws Error naming the bad setting (duration, mission duration, step not positive and finite,
    /// bearing step not in (0, 180], radius < 0, earliest arrival without radius).
    void check() const;
};

/// @brief A flown stint plan.
struct StintPlan
{
    std::vector<double> bearings;       ///< degrees clockwise from north, one per stint flown
    std::vector<TimedPoint> surfacings; ///< the start, each surfacing, and the end (arrival, grounding)
    std::vector<TimedPoint> track;      ///< every integration step (start first)
    double remainingDistance{std::numeric_limits<double>::infinity()}; ///< goal distance at the end
    bool reached{false}; ///< within the radius of the goal before the mission ended
    double arrivalTime{std::numeric_limits<double>::quiet_NaN()}; ///< first time within the radius
    /// With a radius: the closest approach to the goal over the stints flown, and its time
    double closestDistance{std::numeric_limits<double>::infinity()};
    double closestTime{std::numeric_limits<double>::quiet_NaN()}; ///< see closestDistance
    bool grounded{false};    ///< a stint met land or a forbidden region and ended there (the glider stops)
    std::string groundedWhy; ///< what, and where
    double cost{std::numeric_limits<double>::infinity()}; ///< StintSimulator::cost() of this plan
};

} // namespace ompl_glider
