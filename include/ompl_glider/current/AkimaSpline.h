#pragma once
/// @file AkimaSpline.h
/// @brief Akima interpolation ([AkimaSpline]): a local cubic Hermite curve whose node slopes are weighted means of
/// the neighbouring secants, so that it does not overshoot at abrupt changes. The one implementation of the
/// library: AkimaSpline (a whole data set, e.g. travel time against departure time, [EichhornRAS] Sec. 5.2) and
/// detail::akimaFromNodes() (a window of at most six nodes, the depth and time schemes of the gridded current
/// model, see akimaInterpolate() in Interpolation.h) share the secants and node slopes of AkimaSpline.cpp.

#include <utility>
#include <vector>

namespace ompl_glider
{
/// @brief Akima spline through (x_i, y_i), x strictly increasing, at least 2 points ([AkimaSpline]).
///
/// Node slopes t_i = (|m_{i+1} - m_i| m_{i-1} + |m_{i-1} - m_{i-2}| m_i) / (|m_{i+1} - m_i| + |m_{i-1} - m_{i-2}|)
/// from the secant slopes m (the mean of m_{i-1} and m_i when both weights vanish); two secants are added beyond
/// each end with equal second differences ([AkimaSpline], end points). Reproduces straight lines exactly;
/// flat stretches in the data stay flat (no spurious minimum).
class AkimaSpline
{
public:
    /// @throws Error when the sizes differ, n < 2, x is not strictly increasing or a value is not finite.
    AkimaSpline(std::vector<double> x, std::vector<double> y);
    /// @brief Value at q (cubic extension of the end intervals outside [x_0, x_{n-1}]).
    double operator()(double q) const;
    /// @brief Node slopes t_i.
    const std::vector<double> &slopes() const { return t_; }
    /// @brief (argmin, min) of the spline over [x_0, x_{n-1}], each interval's cubic minimised exactly (roots of
    /// its derivative and its ends).
    std::pair<double, double> minimum() const;

private:
    std::vector<double> x_, y_, t_;
};

namespace detail
{
/// @brief Akima interpolation at q of the nodes (x[0..n-1], y[0..n-1]), n <= 6, q in the interval [x[k], x[k+1]]
/// (clamped to [x[0], x[n-1]]): constant for n = 1, linear for n = 2. The secants missing beyond the ends are
/// extrapolated as in AkimaSpline.
///
/// Differs from AkimaSpline in rounding only where the two were written differently, kept so that both give the
/// numbers they always gave: the node slope is the secants' mean when the weights sum to at most 1e-12 (|m_{i-1}| +
/// |m_i|) (AkimaSpline: 1e-14 max(1, |m_{i-1}| + |m_i|)); the Hermite basis is evaluated in expanded form; n = 2
/// uses the straight line; q is clamped instead of extending the end cubics.
double akimaFromNodes(const double *x, const double *y, int n, int k, double q);
} // namespace detail
} // namespace ompl_glider
