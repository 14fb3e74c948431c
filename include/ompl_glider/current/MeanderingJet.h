#pragma once
/// @file MeanderingJet.h
/// @brief The meandering-jet model of the Gulf Stream ([EichhornRAS] Sec. 6.1, Eq. 7-9).

#include <mutex>

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief Parameters of the meandering jet; defaults are the paper's set ([EichhornRAS] Sec. 6.1).
struct MeanderingJetParams
{
    double B0{1.2};                   ///< mean meander amplitude
    double epsilon{0.3};              ///< amplitude of the oscillation of B(t)
    double omega{0.4};                ///< frequency of the oscillation of B(t)
    double theta{1.5707963267948966}; ///< phase of the oscillation (pi/2)
    double k{0.84};                   ///< wave number of the meander
    double c{0.12};                   ///< phase speed of the meander
};

/// @brief Stream function phi = 1 - tanh((y - B(t) cos(k(x - ct))) / sqrt(1 + k^2 B(t)^2 sin^2(k(x - ct)))),
/// B(t) = B0 + eps cos(omega t + theta), u = -dphi/dy, v = dphi/dx. Analytic velocity and Jacobian.
/// @note [EichhornRAS] Eq. 7-9. Peak speed 1.0 on the jet axis for the paper's parameters; depth-independent.
class MeanderingJet : public CurrentField
{
public:
    explicit MeanderingJet(MeanderingJetParams params = {});

    /// @brief Upper bound of the speed: the global maximum over all (x, y, t), found on the jet's invariant
    /// coordinates (phase, scaled cross-jet distance, amplitude), plus a 0.5% margin. Computed on the first call
    /// (about 25 ms), then cached.
    double maxSpeed(const Region &region) const override;
    std::optional<double> streamFunction(double x, double y, double z, double t) const override;
    bool divergenceFree() const override { return true; }
    std::string name() const override { return "meandering jet"; }
    /// @brief The parameters in use.
    const MeanderingJetParams &params() const { return p_; }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override;
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override;

private:
    MeanderingJetParams p_;
    mutable std::once_flag boundOnce_;
    mutable double speedBound_{0.0};
};
} // namespace ompl_glider
