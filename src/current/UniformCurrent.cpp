#include "ompl_glider/current/UniformCurrent.h"

#include <cmath>

namespace ompl_glider
{
double UniformCurrent::maxSpeed(const Region & /*region*/) const
{
    return std::hypot(c_.u, c_.v);
}

std::optional<double> UniformCurrent::streamFunction(double x, double y, double /*z*/, double /*t*/) const
{
    // u = -psi_y, v = psi_x
    return c_.v * x - c_.u * y;
}

Velocity UniformCurrent::evaluate(double, double, double, double) const
{
    return c_;
}

Jacobian UniformCurrent::evaluateJacobian(double, double, double, double) const
{
    return {};
}
} // namespace ompl_glider
