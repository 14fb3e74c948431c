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
}

double ShiftedTimeField::maxSpeed(const Region &region) const
{
    Region r = region;
    r.tMin += shift_;
    r.tMax += shift_;
    return inner_->maxSpeed(r);
}
} // namespace ompl_glider
