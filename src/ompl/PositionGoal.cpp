#include "ompl_glider/ompl/PositionGoal.h"

#include <cmath>
#include <limits>
#include <string>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"

namespace ob = ompl::base;

namespace ompl_glider
{
PositionGoal::PositionGoal(const ob::SpaceInformationPtr &si, double x, double y, double tolerance, double tEarliest,
                           double tLatest)
  : ob::GoalSampleableRegion(si), x_(x), y_(y), tEarliest_(tEarliest), tLatest_(tLatest)
{
    if (!std::isfinite(x) || !std::isfinite(y))
        throw Error("PositionGoal: goal position must be finite (got " + std::to_string(x) + ", " +
                    std::to_string(y) + ")");
    if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
        throw Error("PositionGoal: tolerance must be finite and >= 0 (got " + std::to_string(tolerance) + ")");
    setThreshold(tolerance);
    setTimeWindow(tEarliest, tLatest);
}

void PositionGoal::setTimeWindow(double tEarliest, double tLatest)
{
    if (!std::isfinite(tEarliest) || !std::isfinite(tLatest) || !(tEarliest <= tLatest))
        throw Error("PositionGoal: goal time window must be finite with tEarliest <= tLatest (got [" +
                    std::to_string(tEarliest) + ", " + std::to_string(tLatest) + "])");
    tEarliest_ = tEarliest;
    tLatest_ = tLatest;
}

double PositionGoal::distanceGoal(const ob::State *st) const
{
    const auto *s = st->as<TimeSE2StateSpace::StateType>();
    return std::hypot(s->getX() - x_, s->getY() - y_);
}

void PositionGoal::sampleGoal(ob::State *st) const
{
    auto *s = st->as<TimeSE2StateSpace::StateType>();
    s->setXYT(x_, y_, tEarliest_ == tLatest_ ? tEarliest_ : rng_.uniformReal(tEarliest_, tLatest_));
    s->setYaw(0.0);
}

unsigned int PositionGoal::maxSampleCount() const
{
    return std::numeric_limits<unsigned int>::max();
}
}  // namespace ompl_glider
