#pragma once
/// @file LinearShear.h
/// @brief Linear shear flow u = a*y, v = 0: Zermelo's classic problem ([BettsOC] Example 10.148).

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief u = a*y, v = 0. With V = 1, a = -1, the time-optimal trip (3.5, -1.8) -> (0, 0) takes 5.26493205.
class LinearShear : public CurrentField
{
public:
    explicit LinearShear(double a) : a_(a) {}
    /// @brief |a| * max |y| over the region (infinite for an unbounded region).
    double maxSpeed(const Region &region) const override;
    std::optional<double> streamFunction(double x, double y, double z, double t) const override;
    bool divergenceFree() const override { return true; }
    std::string name() const override { return "linear shear"; }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override;
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override;

private:
    double a_;
};
} // namespace ompl_glider
