#include "ompl_glider/current/DoubleGyre.h"

#include <cmath>

namespace ompl_glider
{
double DoubleGyre::maxSpeed(const Region &) const
{
    return M_PI * std::abs(A_) / L_;
}

std::optional<double> DoubleGyre::streamFunction(double x, double y, double, double) const
{
    return A_ * std::sin(M_PI * x / L_) * std::sin(M_PI * y / L_);
}

Velocity DoubleGyre::evaluate(double x, double y, double, double) const
{
    const double w = M_PI / L_;
    return {-A_ * w * std::sin(w * x) * std::cos(w * y), A_ * w * std::cos(w * x) * std::sin(w * y)};
}

Jacobian DoubleGyre::evaluateJacobian(double x, double y, double, double) const
{
    const double w = M_PI / L_;
    const double a = A_ * w * w;
    const double sx = std::sin(w * x), cx = std::cos(w * x), sy = std::sin(w * y), cy = std::cos(w * y);
    return {-a * cx * cy, a * sx * sy, -a * sx * sy, a * cx * cy};
}
}  // namespace ompl_glider
