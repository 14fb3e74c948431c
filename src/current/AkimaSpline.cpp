#include "ompl_glider/current/AkimaSpline.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
/// When the two weights of a node slope count as vanishing: their sum is at most rel * max(floor, |m_{i-1}| +
/// |m_i|), or zero.
struct FlatTest
{
    double rel;
    double floor;
};
constexpr FlatTest kSplineFlat{1e-14, 1.0}; // AkimaSpline
constexpr FlatTest kNodesFlat{1e-12, 0.0};  // detail::akimaFromNodes

/// Secants of the nodes (x[0..n-1], y[0..n-1]), n >= 2, into m[0..n+2]: m[j + 2] is the slope of interval j,
/// j = -2 .. n, the two beyond each end extrapolated with equal second differences ([AkimaSpline]); with two
/// nodes all five equal the one secant.
void secants(const double *x, const double *y, std::size_t n, double *m)
{
    for (std::size_t k = 0; k + 1 < n; ++k)
        m[k + 2] = (y[k + 1] - y[k]) / (x[k + 1] - x[k]);
    if (n == 2)
    {
        m[1] = m[0] = m[3] = m[4] = m[2];
        return;
    }
    m[1] = 2.0 * m[2] - m[3];
    m[0] = 2.0 * m[1] - m[2];
    m[n + 1] = 2.0 * m[n] - m[n - 1];
    m[n + 2] = 2.0 * m[n + 1] - m[n];
}

/// Akima slope at node i from the secants of secants(): m_{i-2} = m[i], m_{i-1} = m[i+1], m_i = m[i+2],
/// m_{i+1} = m[i+3].
double nodeSlope(const double *m, std::size_t i, const FlatTest &flat)
{
    const double w1 = std::abs(m[i + 3] - m[i + 2]);
    const double w2 = std::abs(m[i + 1] - m[i]);
    const double den = w1 + w2;
    const double scale = std::abs(m[i + 1]) + std::abs(m[i + 2]);
    if (den <= flat.rel * std::max(flat.floor, scale) || den == 0.0)
        return 0.5 * (m[i + 1] + m[i + 2]);
    return (w1 * m[i + 1] + w2 * m[i + 2]) / den;
}
} // namespace

AkimaSpline::AkimaSpline(std::vector<double> x, std::vector<double> y) : x_(std::move(x)), y_(std::move(y))
{
    const std::size_t n = x_.size();
    if (n != y_.size() || n < 2)
        throw Error("AkimaSpline: need at least 2 points and as many x as y values");
    for (std::size_t i = 0; i < n; ++i)
    {
        if (!std::isfinite(x_[i]) || !std::isfinite(y_[i]))
            throw Error("AkimaSpline: non-finite data at point " + std::to_string(i));
        if (i > 0 && !(x_[i] > x_[i - 1]))
            throw Error("AkimaSpline: x must be strictly increasing (point " + std::to_string(i) + ")");
    }
    std::vector<double> m(n + 3);
    secants(x_.data(), y_.data(), n, m.data());
    t_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        t_[i] = nodeSlope(m.data(), i, kSplineFlat);
}

double AkimaSpline::operator()(double q) const
{
    const std::size_t n = x_.size();
    std::size_t k = static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), q) - x_.begin());
    k = k == 0 ? 0 : std::min(k - 1, n - 2);
    const double h = x_[k + 1] - x_[k];
    const double s = (q - x_[k]) / h;
    const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
    const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
    return h00 * y_[k] + h10 * h * t_[k] + h01 * y_[k + 1] + h11 * h * t_[k + 1];
}

std::pair<double, double> AkimaSpline::minimum() const
{
    double bestX = x_[0], bestY = y_[0];
    auto consider = [&](double q) {
        const double v = (*this)(q);
        if (v < bestY)
        {
            bestY = v;
            bestX = q;
        }
    };
    for (std::size_t k = 0; k + 1 < x_.size(); ++k)
    {
        consider(x_[k + 1]);
        // p(s) = y0 h00 + h t0 h10 + y1 h01 + h t1 h11; dp/ds = a s^2 + b s + c
        const double h = x_[k + 1] - x_[k];
        const double y0 = y_[k], y1 = y_[k + 1], d0 = h * t_[k], d1 = h * t_[k + 1];
        const double a = 6 * y0 + 3 * d0 - 6 * y1 + 3 * d1;
        const double b = -6 * y0 - 4 * d0 + 6 * y1 - 2 * d1;
        const double c = d0;
        std::vector<double> roots;
        if (std::abs(a) < 1e-300)
        {
            if (std::abs(b) > 0)
                roots.push_back(-c / b);
        }
        else
        {
            const double disc = b * b - 4 * a * c;
            if (disc >= 0)
            {
                const double sq = std::sqrt(disc);
                roots.push_back((-b - sq) / (2 * a));
                roots.push_back((-b + sq) / (2 * a));
            }
        }
        for (double s : roots)
            if (s > 0 && s < 1)
                consider(x_[k] + s * h);
    }
    return {bestX, bestY};
}

namespace detail
{
double akimaFromNodes(const double *x, const double *y, int n, int k, double q)
{
    if (n == 1)
        return y[0];
    q = std::clamp(q, x[0], x[n - 1]);
    const double h = x[k + 1] - x[k];
    if (n == 2)
        return y[k] + (y[k + 1] - y[k]) * (q - x[k]) / h;
    double m[10];
    secants(x, y, static_cast<std::size_t>(n), m);
    const double t0 = nodeSlope(m, static_cast<std::size_t>(k), kNodesFlat);
    const double t1 = nodeSlope(m, static_cast<std::size_t>(k) + 1, kNodesFlat);
    const double s = (q - x[k]) / h;
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    return h00 * y[k] + h01 * y[k + 1] + h * (h10 * t0 + h11 * t1);
}
} // namespace detail
} // namespace ompl_glider
