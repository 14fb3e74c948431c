#pragma once
/// @file UniformCurrent.h
/// @brief A constant current (u, v) everywhere and always.

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief Uniform current c = (u, v); Jacobian zero. Closed-form travel times make it the first test case.
class UniformCurrent : public CurrentField
{
public:
    UniformCurrent(double u, double v) : c_{u, v} {}
    double maxSpeed(const Region &region) const override;
    std::optional<double> streamFunction(double x, double y, double z, double t) const override;
    bool divergenceFree() const override { return true; }
    std::string name() const override { return "uniform"; }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override;
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override;

private:
    Velocity c_;
};
} // namespace ompl_glider
