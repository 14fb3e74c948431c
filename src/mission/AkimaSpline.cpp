#include "ompl_glider/mission/AkimaSpline.h"

#include <algorithm>
#include <cmath>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
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
    // Secants m[k + 2] = slope of interval k, k = -2 .. n, with two extrapolated secants at each end.
    std::vector<double> m(n + 3);
    for (std::size_t k = 0; k + 1 < n; ++k)
        m[k + 2] = (y_[k + 1] - y_[k]) / (x_[k + 1] - x_[k]);
    if (n == 2)
    {
        m[1] = m[0] = m[3] = m[4] = m[2];
    }
    else
    {
        m[1] = 2.0 * m[2] - m[3];
        m[0] = 2.0 * m[1] - m[2];
        m[n + 1] = 2.0 * m[n] - m[n - 1];
        m[n + 2] = 2.0 * m[n + 1] - m[n];
    }
    t_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        // Around node i: m_{i-2} = m[i], m_{i-1} = m[i+1], m_i = m[i+2], m_{i+1} = m[i+3].
        const double w1 = std::abs(m[i + 3] - m[i + 2]);
        const double w2 = std::abs(m[i + 1] - m[i]);
        const double den = w1 + w2;
        const double scale = std::abs(m[i + 1]) + std::abs(m[i + 2]);
        if (den <= 1e-14 * std::max(1.0, scale))
            t_[i] = 0.5 * (m[i + 1] + m[i + 2]);
        else
            t_[i] = (w1 * m[i + 1] + w2 * m[i + 2]) / den;
    }
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
}  // namespace ompl_glider
