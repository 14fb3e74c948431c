#pragma once
/// @file TimeSE2StateSpace.h
/// @brief SE(2) plus time: the state space on which glider routes are planned with OMPL.

#include <memory>

#include <ompl/base/StateSpace.h>
#include <ompl/base/spaces/RealVectorBounds.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>

namespace ompl_glider
{
/// @brief Position (x, y), heading (yaw) and time t of a glider.
///
/// A compound of two subspaces, built in the constructor and locked:
///   - index 0, "SE2": ompl::base::SE2StateSpace with the given x/y bounds (its own R2 weight 1, SO2 weight =
///     yawWeight, see below);
///   - index 1, "Time": ompl::base::RealVectorStateSpace of dimension 1 bounded by [tMin, tMax].
///
/// Distance (a metric; OMPL's compound distance is the weighted sum of the subspace distances):
///     d = |xy1 - xy2| + yawWeight * |yaw1 - yaw2|_SO2 + timeWeight * |t1 - t2|.
/// - timeWeight (default 1, set with setTimeWeight()) converts time into length. The setup helper sets it to
///   V + max|c|, the fastest ground speed, so that a time difference weighs as much as the farthest the glider
///   could travel in it: nearest-neighbour searches of sampling planners then prefer states that are close both
///   in position and in time (a state far in time cannot be reached from a near one).
/// - yawWeight (default 0.01, set with setYawWeight()) keeps the yaw in the metric only barely: the glider's
///   motions are straight legs whose heading follows from the end points, so yaw is informational (the heading
///   of the leg a planner used to reach the state). It is kept positive so that different states have a positive
///   distance (OMPL's STATESPACE_DISTANCE_DIFFERENT_STATES check).
///
/// Interpolation is linear in x, y and t and along the shortest arc in yaw (OMPL's SE2 and RealVector
/// interpolation), so a motion between two states passes its points at times linear in the arc length, the
/// convention of ompl_glider::Environment::legFree().
class TimeSE2StateSpace : public ompl::base::CompoundStateSpace
{
public:
    /// @brief A state of TimeSE2StateSpace with typed access to x, y, yaw and time.
    class StateType : public ompl::base::CompoundStateSpace::StateType
    {
    public:
        StateType() = default;

        /// @brief x coordinate (easting, field units).
        double getX() const { return as<ompl::base::SE2StateSpace::StateType>(0)->getX(); }
        /// @brief y coordinate (northing, field units).
        double getY() const { return as<ompl::base::SE2StateSpace::StateType>(0)->getY(); }
        /// @brief Heading in (-pi, pi] (informational, see the class documentation).
        double getYaw() const { return as<ompl::base::SE2StateSpace::StateType>(0)->getYaw(); }
        /// @brief Time at which the glider is at (x, y).
        double getTime() const { return as<ompl::base::RealVectorStateSpace::StateType>(1)->values[0]; }
        /// @brief Set x.
        void setX(double x) { as<ompl::base::SE2StateSpace::StateType>(0)->setX(x); }
        /// @brief Set y.
        void setY(double y) { as<ompl::base::SE2StateSpace::StateType>(0)->setY(y); }
        /// @brief Set x and y.
        void setXY(double x, double y) { as<ompl::base::SE2StateSpace::StateType>(0)->setXY(x, y); }
        /// @brief Set the heading. Not normalised: a yaw outside [-pi, pi] fails satisfiesBounds() (so the state is
        /// invalid) until the space's enforceBounds() wraps it; std::atan2 results are in range.
        void setYaw(double yaw) { as<ompl::base::SE2StateSpace::StateType>(0)->setYaw(yaw); }
        /// @brief Set the time.
        void setTime(double t) { as<ompl::base::RealVectorStateSpace::StateType>(1)->values[0] = t; }
        /// @brief Set x, y and time (yaw unchanged).
        void setXYT(double x, double y, double t)
        {
            setXY(x, y);
            setTime(t);
        }
    };

    /// @brief Space over the x/y box @p xyBounds (dimension 2) and the time window [@p tMin, @p tMax].
    /// @throws ompl_glider::Error when the bounds are not 2-D, empty or not finite, or tMin >= tMax.
    TimeSE2StateSpace(const ompl::base::RealVectorBounds &xyBounds, double tMin, double tMax);

    ~TimeSE2StateSpace() override = default;

    /// @brief The x/y bounds.
    const ompl::base::RealVectorBounds &getXYBounds() const;
    /// @brief The time bounds (dimension 1: [tMin, tMax]).
    const ompl::base::RealVectorBounds &getTimeBounds() const;
    /// @brief Earliest time of the window.
    double tMin() const { return getTimeBounds().low[0]; }
    /// @brief Latest time of the window.
    double tMax() const { return getTimeBounds().high[0]; }

    /// @brief Weight of time in the distance (length per time unit, e.g. V + max|c|). Must be > 0.
    void setTimeWeight(double w);
    /// @brief Current time weight.
    double getTimeWeight() const;
    /// @brief Weight of the heading in the distance (length per radian). Must be > 0.
    void setYawWeight(double w);
    /// @brief Current yaw weight.
    double getYawWeight() const;

    /// @brief The xy (Euclidean) distance between two states, ignoring yaw and time.
    static double xyDistance(const ompl::base::State *a, const ompl::base::State *b);

    /// @brief Allocate a state (of type StateType).
    ompl::base::State *allocState() const override;
    /// @brief Free a state allocated by allocState().
    void freeState(ompl::base::State *state) const override;
    /// @brief Registers the default projection (x, y, t), cells of 1/20 of each extent (for KPIECE-like planners).
    void registerProjections() override;
};

/// @brief Shared pointer to a TimeSE2StateSpace.
using TimeSE2StateSpacePtr = std::shared_ptr<TimeSE2StateSpace>;
} // namespace ompl_glider
