#include "ompl_glider/ompl/TravelTimeObjective.h"

#include <algorithm>
#include <cmath>

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/goals/GoalRegion.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"

namespace ob = ompl::base;

namespace ompl_glider
{
TravelTimeObjective::TravelTimeObjective(const ob::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx)
    : ob::OptimizationObjective(si), ctx_(std::move(ctx))
{
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error(
            "TravelTimeObjective: the GliderContext must be non-null with a field and a travel-time calculator");
    vMax_ = ctx_->speed() + ctx_->maxCurrent();
    if (!(vMax_ > 0.0) || !std::isfinite(vMax_))
        throw Error("TravelTimeObjective: V + max|c| must be finite and > 0 (got " + std::to_string(vMax_) + ")");
    description_ = "Travel time (arrival time - t0)";
    const double vMax = vMax_;
    setCostToGoHeuristic([vMax](const ob::State *s, const ob::Goal *g) {
        if (const auto *pg = dynamic_cast<const PositionGoal *>(g))
        {
            const auto *st = s->as<TimeSE2StateSpace::StateType>();
            const double d = std::hypot(st->getX() - pg->getX(), st->getY() - pg->getY());
            return ob::Cost(std::max(0.0, d - pg->getTolerance()) / vMax);
        }
        if (const auto *gr = dynamic_cast<const ob::GoalRegion *>(g))
            return ob::Cost(std::max(0.0, gr->distanceGoal(s) - gr->getThreshold()) / vMax);
        return ob::Cost(0.0);
    });
}

ob::Cost TravelTimeObjective::stateCost(const ob::State * /*s*/) const
{
    return identityCost();
}

ob::Cost TravelTimeObjective::motionCost(const ob::State *s1, const ob::State *s2) const
{
    if (!si_->checkMotion(s1, s2))
        return infiniteCost();
    return ob::Cost(s2->as<TimeSE2StateSpace::StateType>()->getTime() -
                    s1->as<TimeSE2StateSpace::StateType>()->getTime());
}

ob::Cost TravelTimeObjective::motionCostHeuristic(const ob::State *s1, const ob::State *s2) const
{
    const double dt =
        s2->as<TimeSE2StateSpace::StateType>()->getTime() - s1->as<TimeSE2StateSpace::StateType>()->getTime();
    return ob::Cost(std::max(TimeSE2StateSpace::xyDistance(s1, s2) / vMax_, dt));
}
} // namespace ompl_glider
