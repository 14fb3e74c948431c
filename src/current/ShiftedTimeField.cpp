#include "ompl_glider/current/ShiftedTimeField.h"

#include <cmath>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
ShiftedTimeField::ShiftedTimeField(std::shared_ptr<const CurrentField> inner, double shift)
    : inner_(std::move(inner)), shift_(shift)
{
    if (!inner_)
        throw Error("ShiftedTimeField: no field");
    if (!std::isfinite(shift_))
        throw Error("ShiftedTimeField: the time shift must be finite");
    innerGrid_ = inner_->grid();
    if (innerGrid_)
        for (double t : innerGrid_->recordTimes())
            recordTimes_.push_back(t - shift_);
}

bool ShiftedTimeField::velocityBounds(const Region &region, double &uMin, double &uMax, double &vMin,
                                      double &vMax) const
{
    Region r = region;
    r.tMin += shift_;
    r.tMax += shift_;
    return inner_->velocityBounds(r, uMin, uMax, vMin, vMax);
}

Region ShiftedTimeField::extent() const
{
    Region r = innerGrid_->extent();
    r.tMin -= shift_;
    r.tMax -= shift_;
    return r;
}

double ShiftedTimeField::maxSpeed(const Region &region) const
{
    Region r = region;
    r.tMin += shift_;
    r.tMax += shift_;
    return inner_->maxSpeed(r);
}
} // namespace ompl_glider
