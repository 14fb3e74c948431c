#pragma once
/// @file AkimaSpline.h
/// @brief Akima (1970) interpolation of scattered 1-D data: a local cubic Hermite curve that does not overshoot at
/// abrupt changes, used to approximate travel time against departure time ([EichhornRAS] Sec. 5.2).

#include <vector>

namespace ompl_glider
{
/// @brief Akima spline through (x_i, y_i), x strictly increasing, at least 2 points.
///
/// Node slopes t_i = (|m_{i+1} - m_i| m_{i-1} + |m_{i-1} - m_{i-2}| m_i) / (|m_{i+1} - m_i| + |m_{i-1} - m_{i-2}|)
/// from the secant slopes m (the mean of m_{i-1} and m_i when both weights vanish); two secants are added beyond
/// each end with equal second differences (Akima 1970, Eq. for the end points). Reproduces straight lines exactly;
/// flat stretches in the data stay flat (no spurious minimum).
class AkimaSpline
{
public:
    /// @throws Error when the sizes differ, n < 2, x is not strictly increasing or a value is not finite.
    AkimaSpline(std::vector<double> x, std::vector<double> y);
    /// @brief Value at q (cubic extension of the end intervals outside [x_0, x_{n-1}]).
    double operator()(double q) const;
    /// @brief Node slopes t_i.
    const std::vector<double> &slopes() const
    {
        return t_;
    }
    /// @brief (argmin, min) of the spline over [x_0, x_{n-1}], each interval's cubic minimised exactly (roots of
    /// its derivative and its ends).
    std::pair<double, double> minimum() const;

private:
    std::vector<double> x_, y_, t_;
};
}  // namespace ompl_glider
