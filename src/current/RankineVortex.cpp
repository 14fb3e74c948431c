#include "ompl_glider/current/RankineVortex.h"

#include <algorithm>
#include <cmath>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
RankineVortex::RankineVortex(RankineVortexParams params) : p_(params)
{
    for (double q : {p_.x0, p_.y0, p_.radius, p_.vmax, p_.u, p_.v})
        if (!std::isfinite(q))
            throw Error("rankine_vortex: every parameter must be a finite number");
    if (!(p_.radius > 0.0))
        throw Error("rankine_vortex: the core radius must be > 0");
}

double RankineVortex::azimuthalSpeed(double r) const
{
    const double R = p_.radius;
    return r <= R ? p_.vmax * r / R : p_.vmax * R / r;
}

double RankineVortex::maxSpeed(const Region &region) const
{
    // Distances from the centre to the nearest and farthest points of the box (a connected set, so its distances
    // fill [dMin, dMax]); the vortex speed |w(r)| increases up to R and decreases beyond it.
    auto gap = [](double c, double lo, double hi) { return std::max({lo - c, 0.0, c - hi}); };
    const double dMin = std::hypot(gap(p_.x0, region.xMin, region.xMax), gap(p_.y0, region.yMin, region.yMax));
    const double dMax = std::hypot(std::max(std::abs(p_.x0 - region.xMin), std::abs(region.xMax - p_.x0)),
                                   std::max(std::abs(p_.y0 - region.yMin), std::abs(region.yMax - p_.y0)));
    const double r = std::clamp(p_.radius, dMin, std::max(dMin, dMax));
    // relative margin: the velocity's own rounding can put a computed speed a few ulps above the exact maximum
    return (std::abs(azimuthalSpeed(r)) + std::hypot(p_.u, p_.v)) * (1.0 + 1e-12);
}

std::optional<double> RankineVortex::streamFunction(double x, double y, double, double) const
{
    const double dx = x - p_.x0, dy = y - p_.y0;
    const double r2 = dx * dx + dy * dy, R = p_.radius;
    // psi_vortex(r) with d psi / dr = w(r): u = -psi_y = -w dy / r, v = psi_x = w dx / r
    const double vortex = r2 <= R * R ? 0.5 * p_.vmax * r2 / R : p_.vmax * R * (0.5 + 0.5 * std::log(r2 / (R * R)));
    return vortex + p_.v * x - p_.u * y;
}

Velocity RankineVortex::evaluate(double x, double y, double, double) const
{
    const double dx = x - p_.x0, dy = y - p_.y0;
    const double r2 = dx * dx + dy * dy, R = p_.radius;
    // w(r) / r: vmax / R in the core, vmax R / r^2 outside
    const double k = r2 <= R * R ? p_.vmax / R : p_.vmax * R / r2;
    return {p_.u - k * dy, p_.v + k * dx};
}

Jacobian RankineVortex::evaluateJacobian(double x, double y, double, double) const
{
    const double dx = x - p_.x0, dy = y - p_.y0;
    const double r2 = dx * dx + dy * dy, R = p_.radius;
    if (r2 <= R * R)
    {
        const double om = p_.vmax / R; // solid-body rotation
        return {0.0, -om, om, 0.0};
    }
    // u = -K dy / r^2, v = K dx / r^2 with K = vmax R
    const double K = p_.vmax * R;
    const double r4 = r2 * r2;
    const double cross = 2.0 * K * dx * dy / r4;
    const double diff = K * (dx * dx - dy * dy) / r4;
    return {cross, -diff, -diff, -cross};
}
} // namespace ompl_glider
