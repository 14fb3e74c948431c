#pragma once
/// @file TravelTimeObjective.h
/// @brief Arrival-time objective on the time-augmented space.

#include <memory>

#include <ompl/base/OptimizationObjective.h>

#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief Minimises the arrival time. The cost of a motion (x1, y1, t1) -> (x2, y2, t2) is t2 - t1 when the
/// space information's motion validator accepts it (TravelTimeMotionValidator) and +inf otherwise; state costs are
/// zero, so the cost of a path from the start (time t0) to a state at time t is t - t0 ([EichhornRAS] Sec. 3: the
/// travel time). The cost is not symmetric (isSymmetric() is false).
///
/// Heuristics, with vMax = V + max|c| (the fastest possible ground speed, [EichhornRAS] Eq. 1; max|c| from
/// CurrentField::maxSpeed over the context's region and time window, computed once here):
///   - motionCostHeuristic(s1, s2) = max(|xy1 - xy2| / vMax, t2 - t1): a lower bound of the motion cost, since a
///     valid motion costs exactly t2 - t1 and needs at least |xy1 - xy2| / vMax;
///   - costToGo(s, goal) = max(0, d - tol) / vMax with d the xy distance to a PositionGoal's point and tol its
///     tolerance; for other GoalRegion goals max(0, distanceGoal - threshold) / vMax; zero for other goals.
/// Both are admissible. The default cost threshold is OMPL's (never satisfied: anytime planners use their whole
/// time); call setCostThreshold() to stop at the first path arriving within a given travel time.
class TravelTimeObjective : public ompl::base::OptimizationObjective
{
public:
    /// @throws ompl_glider::Error when @p ctx is null or has no field / travel-time calculator.
    TravelTimeObjective(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx);

    /// @brief Zero (identity): only motions cost time.
    ompl::base::Cost stateCost(const ompl::base::State *s) const override;
    /// @brief t2 - t1 if the motion is valid, else +inf.
    ompl::base::Cost motionCost(const ompl::base::State *s1, const ompl::base::State *s2) const override;
    /// @brief max(|xy1 - xy2| / vMax, t2 - t1), admissible.
    ompl::base::Cost motionCostHeuristic(const ompl::base::State *s1, const ompl::base::State *s2) const override;
    /// @brief False: the motion s2 -> s1 does not cost what s1 -> s2 costs.
    bool isSymmetric() const override { return false; }
    /// @brief The fastest ground speed V + max|c| used by the heuristics.
    double maxGroundSpeed() const { return vMax_; }

private:
    std::shared_ptr<const GliderContext> ctx_;
    double vMax_;
};
} // namespace ompl_glider
