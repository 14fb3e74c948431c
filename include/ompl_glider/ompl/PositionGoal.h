#pragma once
/// @file PositionGoal.h
/// @brief Goal: be at a position (within a tolerance) at any time of the window.

#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <ompl/base/PlannerStatus.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/util/RandomNumbers.h>

#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
/// @brief Reach (x, y) within an xy tolerance at any time. distanceGoal() is the xy distance to (x, y) and the
/// goal is satisfied when it is <= the tolerance (the GoalRegion threshold). sampleGoal() returns (x, y) exactly,
/// yaw 0, with a time drawn uniformly in [tEarliest, tLatest]; the setup helper uses tEarliest = t0 + |start -
/// goal| / (V + max|c|) (no arrival can be earlier) and tLatest = t0 + horizon.
///
/// Validity: on first use the goal point is checked with the space information's validity checker at 257 times
/// evenly spread over the window. maxSampleCount() is the number of valid ones (finite: planners that draw goal
/// states until that count, such as BIT* in its setup, terminate). If it is valid at none, maxSampleCount() is 0,
/// so OMPL planners that check GoalSampleableRegion::couldSample() (RRTConnect, PRM, ...) report INVALID_GOAL
/// ("Insufficient states in sampleable goal region"); GliderSimpleSetup (GliderSetup.h) reports INVALID_GOAL for
/// every planner, OMPL's RRT* included. Otherwise sampleGoal() redraws up to 20 times when the drawn time is
/// invalid, then falls back to a valid grid time.
class PositionGoal : public ompl::base::GoalSampleableRegion
{
public:
    /// @throws ompl_glider::Error when a value is not finite, tolerance < 0 or tEarliest > tLatest.
    PositionGoal(const ompl::base::SpaceInformationPtr &si, double x, double y, double tolerance, double tEarliest,
                 double tLatest);

    /// @brief xy distance from the state to (x, y).
    double distanceGoal(const ompl::base::State *st) const override;
    /// @brief (x, y), yaw 0, time uniform in [tEarliest, tLatest].
    void sampleGoal(ompl::base::State *st) const override;
    /// @brief The number of valid goal times on the 257-point grid over the window (0 when the goal point is invalid
    /// at every time). Finite, so planners that draw goal states up to this count (BIT*) stop drawing.
    unsigned int maxSampleCount() const override;

    /// @brief Why the goal point is invalid at time t ("inside island 'A'", ...); empty when it is valid there or
    /// the validity checker is not a GliderStateValidityChecker.
    std::string whyInvalidAt(double t) const;

    /// @brief Goal x.
    double getX() const { return x_; }
    /// @brief Goal y.
    double getY() const { return y_; }
    /// @brief xy tolerance (= the GoalRegion threshold).
    double getTolerance() const { return getThreshold(); }
    /// @brief Earliest time of sampled goal states.
    double getEarliestTime() const { return tEarliest_; }
    /// @brief Latest time of sampled goal states.
    double getLatestTime() const { return tLatest_; }
    /// @brief Change the window of sampled goal times. @throws ompl_glider::Error when tEarliest > tLatest.
    void setTimeWindow(double tEarliest, double tLatest);

private:
    /// Fills validTimes_ once (thread-safe).
    void checkValidity() const;

    double x_, y_;
    mutable std::once_flag once_;
    mutable std::vector<double> validTimes_;
    double tEarliest_, tLatest_;
    mutable ompl::RNG rng_;
};

/// @brief The goal position (x, y) of a goal on a TimeSE2StateSpace, as the lattice planners read it: a
/// PositionGoal's point, a GoalState's state, or one state sampled from a GoalSampleableRegion. Empty when the goal is
/// of another type or the region cannot be sampled; @p why (if non-null) then says which.
std::optional<Point2> goalPosition(const ompl::base::Goal &goal, std::string *why = nullptr);

/// @brief What the planners of this project read from a problem definition on a TimeSE2StateSpace: the first start
/// state (read directly, not through the planner's input states, so that a start the validity checker refuses is
/// still seen and solve() can be called again; its time is the departure) and the goal position (goalPosition()).
struct StartAndGoal
{
    double sx{0.0}, sy{0.0}, t0{0.0}; ///< start position and departure time
    Point2 goal;                      ///< goal position
};

/// @brief The start and goal of @p pdef, or nullopt with @p status set to INVALID_START (no start state) or
/// UNRECOGNIZED_GOAL_TYPE (a goal without a position), the reason logged by OMPL_ERROR under @p planner's name.
std::optional<StartAndGoal> startAndGoal(const ompl::base::ProblemDefinition &pdef, const std::string &planner,
                                         ompl::base::PlannerStatus &status);
} // namespace ompl_glider
