#include "ompl_glider/current/DoubleGyre.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ompl_glider
{
namespace
{
/// g = L f(x/L, t) and its x-derivatives, for s = s(t): g = s x^2 / L + (1 - 2 s) x, g' = f_X, g'' = 2 s / L.
/// For s = 0 exactly g = x, g' = 1, g'' = 0, so the steady expressions below are the historic ones.
struct Phase
{
    double g;
    double gx;
    double gxx;
};

Phase phase(double s, double x, double L)
{
    if (s == 0.0)
        return {x, 1.0, 0.0};
    return {s * x * x / L + (1.0 - 2.0 * s) * x, 2.0 * s * x / L + (1.0 - 2.0 * s), 2.0 * s / L};
}
} // namespace

double DoubleGyre::s(double t) const
{
    return steady() ? 0.0 : eps_ * std::sin(omega_ * t);
}

double DoubleGyre::maxSpeed(const Region &region) const
{
    const double steadyBound = M_PI * std::abs(A_) / L_;
    if (steady())
        return steadyBound;
    // max |X - 1| over the region's x range; |f_X| = |1 + 2 s (X - 1)| <= 1 + 2 |epsilon| |X - 1|
    const double m = std::max(std::abs(region.xMin / L_ - 1.0), std::abs(region.xMax / L_ - 1.0));
    if (!std::isfinite(m))
        return std::numeric_limits<double>::infinity();
    return steadyBound * (1.0 + 2.0 * std::abs(eps_) * m) * (1.0 + 1e-12);
}

std::optional<double> DoubleGyre::streamFunction(double x, double y, double, double t) const
{
    const Phase p = phase(s(t), x, L_);
    return A_ * std::sin(M_PI * p.g / L_) * std::sin(M_PI * y / L_);
}

Velocity DoubleGyre::evaluate(double x, double y, double, double t) const
{
    const double w = M_PI / L_;
    const Phase p = phase(s(t), x, L_);
    // u = -psi_y = -A w sin(w g) cos(w y); v = psi_x = A w cos(w g) sin(w y) g'
    return {-A_ * w * std::sin(w * p.g) * std::cos(w * y), A_ * w * std::cos(w * p.g) * std::sin(w * y) * p.gx};
}

Jacobian DoubleGyre::evaluateJacobian(double x, double y, double, double t) const
{
    const double w = M_PI / L_;
    const double a = A_ * w * w;
    const double sc = s(t);
    const Phase p = phase(sc, x, L_);
    const double sx = std::sin(w * p.g), cx = std::cos(w * p.g), sy = std::sin(w * y), cy = std::cos(w * y);
    Jacobian J{-a * cx * cy * p.gx, a * sx * sy, -a * sx * sy * p.gx * p.gx, a * cx * cy * p.gx};
    if (sc != 0.0)
        J.vx += A_ * w * cx * sy * p.gxx; // v = A w cos(w g) sin(w y) g': the g'' term
    return J;
}
} // namespace ompl_glider
