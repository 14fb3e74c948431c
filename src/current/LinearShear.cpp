#include "ompl_glider/current/LinearShear.h"

#include <algorithm>
#include <cmath>

namespace ompl_glider
{
double LinearShear::maxSpeed(const Region &region) const
{
    return std::abs(a_) * std::max(std::abs(region.yMin), std::abs(region.yMax));
}

std::optional<double> LinearShear::streamFunction(double, double y, double, double) const
{
    return -0.5 * a_ * y * y;
}

Velocity LinearShear::evaluate(double, double y, double, double) const
{
    return {a_ * y, 0.0};
}

Jacobian LinearShear::evaluateJacobian(double, double, double, double) const
{
    return {0.0, a_, 0.0, 0.0};
}
} // namespace ompl_glider
