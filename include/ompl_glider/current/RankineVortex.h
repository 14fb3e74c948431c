#pragma once
/// @file RankineVortex.h
/// @brief The Rankine vortex, optionally in a uniform stream: [LollaLevelSet]'s benchmark flow with an analytic answer.

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief Parameters of the Rankine vortex; the defaults are a unit vortex at the origin in still water.
struct RankineVortexParams
{
    double x0{0.0};     ///< centre, x
    double y0{0.0};     ///< centre, y
    double radius{1.0}; ///< core radius R (> 0)
    double vmax{1.0};   ///< azimuthal speed at the core radius; > 0 counter-clockwise, < 0 clockwise
    double u{0.0};      ///< uniform background current, x component
    double v{0.0};      ///< uniform background current, y component
};

/// @brief Steady Rankine vortex plus a uniform stream: with r the distance from the centre (x0, y0) and e_theta the
/// counter-clockwise unit vector, c = w(r) e_theta + (u, v), w(r) = vmax r / R inside the core (r <= R, solid-body
/// rotation at the angular speed vmax / R) and w(r) = vmax R / r outside (irrotational). The velocity is continuous,
/// its Jacobian jumps at r = R (the core's value is used on the circle itself). Stream function
/// psi = vmax r^2 / (2R) inside, vmax R (1/2 + ln(r / R)) outside, plus v x - u y. Divergence-free.
/// [LollaLevelSet] validates its level-set planner on a Rankine vortex, a flow with an analytic answer. Without
/// background stream the flow has no radial component, which gives closed-form travel times: from the centre every
/// point at distance d is reached at best in d / V, whatever vmax (see tests/current/TestAnalyticVortexGyre.cpp for
/// these facts and their derivation).
class RankineVortex : public CurrentField
{
public:
    /// @throws Error when the radius is not > 0 or a parameter is not finite.
    explicit RankineVortex(RankineVortexParams params = {});

    /// @brief Exact maximum of the vortex speed over the region plus |(u, v)| (a tight bound when the region holds
    /// the whole circle of the relevant radius): the vortex speed depends on r only, rises to |vmax| at r = R and
    /// falls beyond, so its maximum over the distances [dMin, dMax] of the region from the centre is taken at the
    /// distance nearest to R. At most |vmax| + |(u, v)| (times 1 + 1e-12 against rounding), finite for every
    /// region.
    double maxSpeed(const Region &region) const override;
    std::optional<double> streamFunction(double x, double y, double z, double t) const override;
    bool divergenceFree() const override { return true; }
    std::string name() const override { return "rankine vortex"; }
    /// @brief The parameters in use.
    const RankineVortexParams &params() const { return p_; }
    /// @brief Azimuthal speed of the vortex (without background) at distance r from the centre (signed as vmax).
    double azimuthalSpeed(double r) const;

protected:
    Velocity evaluate(double x, double y, double z, double t) const override;
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override;

private:
    RankineVortexParams p_;
};
} // namespace ompl_glider
