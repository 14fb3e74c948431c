#pragma once
/// @file StintSimulator.h
/// @brief What a glider actually flies: one heading through the water per stint between two surfacings
/// ([IsernObstacles] Sec. II: "the on-board navigation system simply tries to keep the last commanded heading or
/// bearing during the whole stint"). A plan is a list of bearings, one per surfacing; the simulator flies them in
/// the time-varying current with the one dive integrator (flyHeading(), execution/Dive.h: RK4, land and forbidden
/// regions checked along every step) and returns the surfacing positions.
///
/// Bearings are degrees clockwise from north (+y): the heading through the water, unit vector
/// (sin b, cos b). Units are those of the planning frame (x/y units, field time units).

#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/environment/Environment.h"
#include "ompl_glider/execution/Dive.h"
#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/execution/Stints.h"

namespace ompl_glider
{
/// @brief Flies stint plans from a start at a departure time toward a goal.
class StintSimulator
{
public:
    /// @brief @p maxCurrent bounds the current speed over the region and the mission (for the heuristic and the
    /// cost of an unfinished plan); @p forbidden may be null. @throws Error for bad settings, speed or bound.
    StintSimulator(std::shared_ptr<const CurrentField> field, std::shared_ptr<const Environment> forbidden,
                   double speed, double maxCurrent, Point2 start, double t0, Point2 goal, StintSettings settings);

    /// @brief Flies @p bearings (at most StintSettings::stintCount() are used) from the start; stops at the goal
    /// (radius), at a grounding or when the bearings or the mission run out. @p keepTrack: fill StintPlan::track.
    StintPlan simulate(const std::vector<double> &bearings, bool keepTrack = true) const;

    /// @brief One stint from (x, y) at t with @p bearing (degrees) until min(t + duration, mission end).
    DiveEnd flyStint(double x, double y, double t, double bearing, std::vector<TimedPoint> *track = nullptr) const;

    /// @brief Direct to goal ([IsernObstacles] Sec. III.A): at every surfacing, the bearing to the goal.
    StintPlan direct() const;

    /// @brief The objective value of a plan (lower is better): RemainingDistance: the final distance;
    /// EarliestArrival: arrival - t0 when reached, else the time of the closest approach - t0 plus the distance
    /// then left to the radius at a tenth of V (continuous with the arrival time where a plan starts to reach
    /// the radius, so that the optimiser can steer into it, and steep, so that a near miss does not pay).
    /// A grounded plan also pays for the time it cannot fly (max reach times the time left, or that time), so that
    /// the optimisers never prefer stopping on land.
    double cost(const StintPlan &plan) const;

    /// @brief A lower bound of the cost of every plan through (x, y) at time t (admissible heuristic of CTS-A*):
    /// RemainingDistance max(0, d - (V + max|c|) * time left); EarliestArrival (t - t0) + d / (V + max|c|).
    double lowerBound(double x, double y, double t) const;

    /// @brief The bearing (degrees clockwise from north) from (x, y) to the goal.
    double bearingToGoal(double x, double y) const;

    const StintSettings &settings() const { return settings_; }        ///< the settings
    double speed() const { return speed_; }                            ///< speed through water
    double maxReach() const { return speed_ + maxCurrent_; }           ///< V + max|c|
    Point2 start() const { return start_; }                            ///< start
    Point2 goal() const { return goal_; }                              ///< goal
    double t0() const { return t0_; }                                  ///< departure
    double endTime() const { return t0_ + settings_.missionDuration; } ///< end of the mission
    const CurrentField &field() const { return *field_; }              ///< the current
    /// @brief Number of simulate() and flyStint() calls so far (thread-safe counter; for benchmarks).
    std::uint64_t stintsFlown() const;

private:
    std::shared_ptr<const CurrentField> field_;
    std::shared_ptr<const Environment> forbidden_;
    double speed_, maxCurrent_;
    Point2 start_;
    double t0_;
    Point2 goal_;
    StintSettings settings_;
    DiveSettings dive_;
    std::shared_ptr<std::atomic<std::uint64_t>> flown_;
};

} // namespace ompl_glider
