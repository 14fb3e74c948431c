#include "ompl_glider/ompl/GliderStateValidityChecker.h"

#include <cmath>
#include <sstream>

#include <ompl/base/SpaceInformation.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"

namespace ob = ompl::base;

namespace ompl_glider
{
GliderStateValidityChecker::GliderStateValidityChecker(const ob::SpaceInformationPtr &si,
                                                       std::shared_ptr<const GliderContext> ctx)
    : ob::StateValidityChecker(si), ctx_(std::move(ctx))
{
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error("GliderStateValidityChecker: the GliderContext must be non-null with a field and a travel-time "
                    "calculator");
}

bool GliderStateValidityChecker::isValidPoint(double x, double y, double t) const
{
    const Region &r = ctx_->region;
    if (!(x >= r.xMin && x <= r.xMax && y >= r.yMin && y <= r.yMax && t >= r.tMin && t <= r.tMax))
        return false;
    const CurrentField &f = *ctx_->field;
    if (t < f.timeBegin() || t > f.timeEnd())
        return false;
    if (!f.inWater(x, y, ctx_->travel->params().depth))
        return false;
    if (ctx_->environment && !ctx_->environment->pointFree(x, y, t))
        return false;
    return true;
}

bool GliderStateValidityChecker::isValid(const ob::State *state) const
{
    if (!si_->satisfiesBounds(state))
        return false;
    const auto *s = state->as<TimeSE2StateSpace::StateType>();
    return isValidPoint(s->getX(), s->getY(), s->getTime());
}

std::string GliderStateValidityChecker::whyInvalid(const ob::State *state) const
{
    const auto *s = state->as<TimeSE2StateSpace::StateType>();
    const double x = s->getX(), y = s->getY(), t = s->getTime();
    std::ostringstream os;
    const Region &r = ctx_->region;
    if (!si_->satisfiesBounds(state) || !(x >= r.xMin && x <= r.xMax && y >= r.yMin && y <= r.yMax))
    {
        if (!(t >= r.tMin && t <= r.tMax) && std::isfinite(t))
            os << "time " << t << " outside the window [" << r.tMin << ", " << r.tMax << "]";
        else
            os << "(" << x << ", " << y << ") at time " << t << " outside the state space bounds x in [" << r.xMin
               << ", " << r.xMax << "], y in [" << r.yMin << ", " << r.yMax << "], t in [" << r.tMin << ", " << r.tMax
               << "]";
        return os.str();
    }
    if (!(t >= r.tMin && t <= r.tMax))
    {
        os << "time " << t << " outside the window [" << r.tMin << ", " << r.tMax << "]";
        return os.str();
    }
    const CurrentField &f = *ctx_->field;
    if (t < f.timeBegin() || t > f.timeEnd())
    {
        os << "time " << t << " outside the current field's time span [" << f.timeBegin() << ", " << f.timeEnd() << "]";
        return os.str();
    }
    if (!f.inWater(x, y, ctx_->travel->params().depth))
    {
        os << "(" << x << ", " << y << ") is not in water (land in the field '" << f.name() << "')";
        return os.str();
    }
    if (ctx_->environment && !ctx_->environment->pointFree(x, y, t))
    {
        const std::string why = ctx_->environment->whyBlocked(x, y, t);
        os << "(" << x << ", " << y << ") at time " << t << " is in a forbidden region"
           << (why.empty() ? std::string() : ": " + why);
        return os.str();
    }
    return {};
}
} // namespace ompl_glider
