#pragma once
/// @file DoubleGyre.h
/// @brief The steady double gyre psi = A sin(pi x / L) sin(pi y / L).

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief Steady double gyre on [0, 2L] x [0, L]: psi = A sin(pi x/L) sin(pi y/L), u = -psi_y, v = psi_x.
/// Two counter-rotating gyres; a standard test flow for planners in currents.
class DoubleGyre : public CurrentField
{
public:
    explicit DoubleGyre(double amplitude = 0.1, double length = 1.0) : A_(amplitude), L_(length)
    {
    }
    /// @brief pi |A| / L, the global maximum of the speed.
    double maxSpeed(const Region &region) const override;
    std::optional<double> streamFunction(double x, double y, double z, double t) const override;
    bool divergenceFree() const override
    {
        return true;
    }
    std::string name() const override
    {
        return "double gyre";
    }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override;
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override;

private:
    double A_, L_;
};
}  // namespace ompl_glider
