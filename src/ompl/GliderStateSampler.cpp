#include "ompl_glider/ompl/GliderStateSampler.h"

#include <algorithm>
#include <cmath>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"

namespace ob = ompl::base;

namespace ompl_glider
{
GliderStateSampler::GliderStateSampler(const ob::StateSpace *space, double startX, double startY, double t0,
                                       double vMax)
    : ob::StateSampler(space), base_(space->allocDefaultStateSampler()), startX_(startX), startY_(startY), t0_(t0),
      vMax_(vMax)
{
    if (dynamic_cast<const TimeSE2StateSpace *>(space) == nullptr)
        throw Error("GliderStateSampler: the state space must be a TimeSE2StateSpace");
    if (!(vMax > 0.0) || !std::isfinite(vMax))
        throw Error("GliderStateSampler: vMax must be finite and > 0");
}

double GliderStateSampler::earliestTime(double x, double y) const
{
    const auto *sp = static_cast<const TimeSE2StateSpace *>(space_);
    const double t = t0_ + std::hypot(x - startX_, y - startY_) / vMax_;
    return std::min(sp->tMax(), std::max(sp->tMin(), t));
}

void GliderStateSampler::sampleUniform(ob::State *state)
{
    const auto *sp = static_cast<const TimeSE2StateSpace *>(space_);
    const ob::RealVectorBounds &b = sp->getXYBounds();
    auto *s = state->as<TimeSE2StateSpace::StateType>();
    const double x = rng_.uniformReal(b.low[0], b.high[0]);
    const double y = rng_.uniformReal(b.low[1], b.high[1]);
    const double lo = earliestTime(x, y);
    s->setXYT(x, y, lo < sp->tMax() ? rng_.uniformReal(lo, sp->tMax()) : sp->tMax());
    s->setYaw(rng_.uniformReal(-M_PI, M_PI));
}

void GliderStateSampler::raiseTime(ob::State *state) const
{
    auto *s = state->as<TimeSE2StateSpace::StateType>();
    s->setTime(std::max(s->getTime(), earliestTime(s->getX(), s->getY())));
}

void GliderStateSampler::sampleUniformNear(ob::State *state, const ob::State *near, double distance)
{
    base_->sampleUniformNear(state, near, distance);
    raiseTime(state);
}

void GliderStateSampler::sampleGaussian(ob::State *state, const ob::State *mean, double stdDev)
{
    base_->sampleGaussian(state, mean, stdDev);
    raiseTime(state);
}
} // namespace ompl_glider
