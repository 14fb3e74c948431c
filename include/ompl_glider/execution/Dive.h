#pragma once
/// @file Dive.h
/// @brief One dive with a held heading: the one integrator of a glider between two surfacings, shared by plan
/// execution (flyPlan(), Execution.h) and the constant-bearing stints (StintSimulator, [IsernObstacles] Sec. II).
///
/// The glider holds the unit heading (hx, hy) through the water at its speed while the current carries it: classic
/// RK4 on dx/dt = V h + c(x, t) with a fixed step (the last step shortened to end at the surfacing). Land of the
/// field (CurrentField::segmentInWater()) and the forbidden regions (Environment::legFree()) are checked along every
/// step: meeting them ends the dive there (grounded) at the start of that step. With a goal radius, the dive ends at
/// the first point of a step's chord within the radius of the goal.

#include <limits>
#include <string>
#include <vector>

#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/environment/Environment.h"
#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
/// @brief Settings of flyHeading().
struct DiveSettings
{
    double speed{0.5};  ///< speed through water (x/y units per time unit)
    double step{0.01};  ///< RK4 step (time units)
    double depth{0.0};  ///< depth at which the currents are read (m)
    double radius{0.0}; ///< > 0: the dive ends when the goal is within this distance
    Point2 goal;        ///< goal (used when radius > 0)
};

/// @brief Where a dive ended and why.
struct DiveEnd
{
    double x{0.0}, y{0.0}, t{0.0}; ///< last position and time (the surfacing, the arrival or the grounding)
    bool reached{false};           ///< the goal came within the radius (then x, y, t is the end of that step)
    double arrivalTime{std::numeric_limits<double>::quiet_NaN()}; ///< first time within the radius
    TimedPoint arrival;   ///< where and when (on the step's chord) the radius was first met, when reached
    bool grounded{false}; ///< land or a forbidden region ended the dive at (x, y, t)
    std::string why;      ///< what was met, and where (planning frame)
    /// With a goal radius: the closest approach to the goal on the dive's steps (chords) and its time
    double closestDistance{std::numeric_limits<double>::infinity()};
    double closestTime{std::numeric_limits<double>::quiet_NaN()}; ///< see closestDistance
};

/// @brief Flies the unit heading (hx, hy) from (x, y) at time t until @p tEnd through @p field, checking land and
/// @p forbidden (may be null) along every step, and the goal radius. Appends the end of every step to @p track
/// when it is not null. The step must be positive and finite (not checked here: callers check their options).
DiveEnd flyHeading(double x, double y, double t, double hx, double hy, double tEnd, const CurrentField &field,
                   const Environment *forbidden, const DiveSettings &settings,
                   std::vector<TimedPoint> *track = nullptr);
} // namespace ompl_glider
