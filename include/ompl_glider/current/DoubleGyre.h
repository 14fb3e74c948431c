#pragma once
/// @file DoubleGyre.h
/// @brief The double gyre, steady or time-dependent ([ShaddenLCS]).

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief The double gyre of [ShaddenLCS] on [0, 2L] x [0, L] (their [0, 2] x [0, 1] scaled by L):
/// psi = A sin(pi f(x/L, t)) sin(pi y/L), f(X, t) = s(t) X^2 + (1 - 2 s(t)) X, s(t) = epsilon sin(omega t);
/// u = -psi_y, v = psi_x. Two counter-rotating gyres separated by the line x = L (f = 1) when s = 0; for s != 0
/// the separatrix sits where f(X, t) = 1 and oscillates about x = L with period 2 pi / omega.
/// epsilon = 0 or omega = 0 gives the steady field psi = A sin(pi x/L) sin(pi y/L), evaluated with exactly the
/// same floating-point operations as before the time dependence was added (bit-identical values).
/// A standard test flow for planners in currents; with the flow several times the glider's speed, a strong-current
/// test.
class DoubleGyre : public CurrentField
{
public:
    /// @param amplitude A; @param length L; @param epsilon amplitude of the oscillation of the separatrix;
    /// @param omega angular frequency of the oscillation.
    explicit DoubleGyre(double amplitude = 0.1, double length = 1.0, double epsilon = 0.0, double omega = 0.0)
        : A_(amplitude), L_(length), eps_(epsilon), omega_(omega)
    {
    }
    /// @brief An upper bound of the speed over the region and all times:
    /// |c|^2 = (pi A / L)^2 [sin^2(pi f) cos^2(pi Y) + cos^2(pi f) sin^2(pi Y) f_X^2]
    ///       <= (pi A / L)^2 max(1, f_X^2)   (since p(1 - q) + (1 - p) q <= 1 for p, q in [0, 1]),
    /// with f_X = 1 + 2 s (X - 1), |s| <= |epsilon|, so |f_X| <= 1 + 2 |epsilon| max |x/L - 1| over the region's
    /// x range. Steady (s = 0): pi |A| / L, reached at (0, L/2). Time-dependent: pi |A| / L (1 + 2 |epsilon| m)
    /// (times 1 + 1e-12 against rounding), reached at x = 0 or 2L, y = L/2 when the region is [0, 2L] in x and its
    /// time window holds a full period; infinite when the region is unbounded in x.
    double maxSpeed(const Region &region) const override;
    std::optional<double> streamFunction(double x, double y, double z, double t) const override;
    bool divergenceFree() const override { return true; }
    /// @brief "double gyre" when steady, "time-dependent double gyre" otherwise.
    std::string name() const override { return steady() ? "double gyre" : "time-dependent double gyre"; }
    /// @brief True when the field does not depend on time (epsilon = 0 or omega = 0).
    bool steady() const { return eps_ == 0.0 || omega_ == 0.0; }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override;
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override;

private:
    /// s(t) = epsilon sin(omega t); exactly 0 for a steady field.
    double s(double t) const;
    double A_, L_, eps_, omega_;
};
} // namespace ompl_glider
