#pragma once
/// @file Interpolation.h
/// @brief One- and two-dimensional interpolation schemes of the gridded ocean-current model ([EichhornOceans] Sec.
/// II.C, [EichhornRAS] Sec. 3.4.2): x/y nearest, bilinear, bicubic; depth and time nearest, linear, cubic, Akima.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "ompl_glider/current/AkimaSpline.h"

namespace ompl_glider
{
/// @brief Horizontal (x/y) interpolation scheme ([EichhornOceans] Sec. II.C, first step of Fig. 2).
enum class Interp2D
{
    Nearest,  ///< value of the nearest node (piecewise constant)
    Bilinear, ///< tensor product of linear interpolation: reproduces a + bx + cy + dxy exactly
    Bicubic   ///< tensor product of 4-point Lagrange cubics: reproduces every polynomial of degree <= 3 in x and in y
};

/// @brief Depth or time interpolation scheme ([EichhornOceans] Sec. II.C, second and third steps of Fig. 2).
enum class Interp1D
{
    Nearest, ///< nearest node
    Linear,  ///< linear between the two bracketing nodes
    Cubic,   ///< local 4-point Lagrange cubic (nodes k-1..k+2, shifted inside at the ends): exact for cubics
    Akima    ///< [AkimaSpline] local cubic Hermite; no overshoot at an abrupt step (tides, layered streams)
};

/// @brief Parses "nearest", "bilinear", "bicubic" (case-insensitive; "linear"/"cubic" accepted as aliases).
/// @throws Error naming the text and the accepted names.
Interp2D parseInterp2D(const std::string &name);
/// @brief Parses "nearest", "linear", "cubic", "akima" (case-insensitive). @throws Error otherwise.
Interp1D parseInterp1D(const std::string &name);
/// @brief Lower-case name of the scheme.
std::string toString(Interp2D s);
/// @brief Lower-case name of the scheme.
std::string toString(Interp1D s);

/// @brief A strictly increasing coordinate axis (x, y, depth or time nodes). Locates a query in O(1) on
/// uniform axes (relative spacing deviation < 1e-9) and by binary search otherwise.
class Axis
{
public:
    Axis() = default;
    /// @brief @throws Error when the values are empty, not finite or not strictly increasing.
    explicit Axis(std::vector<double> nodes, const std::string &what = "axis");

    /// @brief Number of nodes.
    std::size_t size() const { return c_.size(); }
    /// @brief Node i.
    double operator[](std::size_t i) const { return c_[i]; }
    /// @brief First node.
    double front() const { return c_.front(); }
    /// @brief Last node.
    double back() const { return c_.back(); }
    /// @brief All nodes.
    const std::vector<double> &nodes() const { return c_; }
    /// @brief True when the nodes are equally spaced.
    bool uniform() const { return uniform_; }
    /// @brief Index k of the interval [c_k, c_k+1] holding q, clamped to [0, size-2] (0 for a single node).
    std::size_t interval(double q) const;

private:
    std::vector<double> c_;
    bool uniform_{false};
    double h_{1.0}, invH_{1.0};
};

/// @brief Weights of a scheme that is linear in the data (nearest, linear, cubic): value = sum w_i f(first + i),
/// derivative = sum dw_i f(first + i). Queries outside the axis are clamped to its ends (no extrapolation).
struct Stencil
{
    std::size_t first{0};       ///< first node
    int n{0};                   ///< number of nodes (1 .. 4)
    std::array<double, 4> w{};  ///< weights (sum 1)
    std::array<double, 4> dw{}; ///< weights of the derivative d/dq (0 outside the axis)
};

/// @brief Stencil of nearest (n = 1), linear (n = 2) or cubic Lagrange (n = min(4, size)) interpolation at q.
/// @param scheme Interp1D::Akima is not linear in the data and is rejected (use akimaInterpolate()).
/// @param derivative false skips the derivative weights (dw stays 0), which saves time for cubics.
Stencil makeStencil(const Axis &axis, Interp1D scheme, double q, bool derivative = true);
/// @brief The 2-D scheme's 1-D factor: Nearest -> nearest, Bilinear -> linear, Bicubic -> cubic.
Interp1D axisScheme(Interp2D scheme);

/// @brief The nodes lo..hi that Akima interpolation at q reads: k-2..k+3 around the interval k holding q, cut at the
/// ends of the axis; k - lo is the interval's index among them. For an axis of at least two nodes.
struct AkimaWindow
{
    std::size_t lo{0}; ///< first node
    std::size_t hi{0}; ///< last node
    int k{0};          ///< interval holding q, counted from lo
};

/// @brief The window of Akima interpolation at q on the axis (axis.size() >= 2).
inline AkimaWindow akimaWindow(const Axis &axis, double q)
{
    const std::size_t n = axis.size();
    const std::size_t k = axis.interval(q);
    AkimaWindow w;
    w.lo = k >= 2 ? k - 2 : 0;
    w.hi = k + 3 < n ? k + 3 : n - 1;
    w.k = static_cast<int>(k - w.lo);
    return w;
}

/// @brief [AkimaSpline] interpolation at q of the data values f(0..size-1) on the axis; `f(i)` is called only for
/// the nodes of akimaWindow(). Secants missing beyond the ends are extrapolated as in [AkimaSpline]
/// (m_{-1} = 2 m_0 - m_1, ...); with two nodes it is linear, with one constant. q is clamped to the axis.
template <typename F> double akimaInterpolate(const Axis &axis, double q, F &&f);

/// @brief Upper bound of the Lebesgue constant (sum of |weights|) of the scheme on the axis, i.e. the factor
/// by which the interpolant can exceed the largest |data|: 1 for nearest and linear; for cubic the maximum over
/// the intervals of sum_i max_interval |l_i| (each cubic's maximum found at the ends and at its critical
/// points: rigorous); 1.25 in the interior of a uniform axis. For Akima (applied per component, nonlinear):
/// 1 + (4/27) h_k (S_{k-1,k} + S_{k,k+1}), where S bounds |slope| / max|data| from the secants (Hermite
/// basis functions h10, h11 never exceed 4/27); about 1.59 in the interior of a uniform axis.
double overshootFactor(const Axis &axis, Interp1D scheme);

// ---- implementation of the template ----
template <typename F> double akimaInterpolate(const Axis &axis, double q, F &&f)
{
    if (axis.size() == 1)
        return f(std::size_t{0});
    const AkimaWindow w = akimaWindow(axis, q);
    double xs[6], ys[6];
    int m = 0;
    for (std::size_t i = w.lo; i <= w.hi; ++i, ++m)
    {
        xs[m] = axis[i];
        ys[m] = f(i);
    }
    return detail::akimaFromNodes(xs, ys, m, w.k, q);
}
} // namespace ompl_glider
