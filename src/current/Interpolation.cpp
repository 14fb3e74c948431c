#include "ompl_glider/current/Interpolation.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "../io/TextUtil.h"
#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
using text::lower;

/// Lagrange basis weights (and derivative weights when dw is not null) on nodes x[0..n-1] at q.
void lagrange(const double *x, int n, double q, double *w, double *dw)
{
    for (int i = 0; i < n; ++i)
    {
        double p = 1.0;
        for (int j = 0; j < n; ++j)
            if (j != i)
                p *= (q - x[j]) / (x[i] - x[j]);
        w[i] = p;
        if (!dw)
            continue;
        double d = 0.0;
        for (int m = 0; m < n; ++m)
        {
            if (m == i)
                continue;
            double t = 1.0 / (x[i] - x[m]);
            for (int j = 0; j < n; ++j)
                if (j != i && j != m)
                    t *= (q - x[j]) / (x[i] - x[j]);
            d += t;
        }
        dw[i] = d;
    }
}

/// max |l_i(q)| over [a, b] of the Lagrange basis polynomial i of nodes x[0..n-1] (n <= 4): at the ends and at the
/// critical points of prod_{j != i} (q - x_j).
double maxAbsBasis(const double *x, int n, int i, double a, double b)
{
    double r[3];
    int d = 0;
    for (int j = 0; j < n; ++j)
        if (j != i)
            r[d++] = x[j];
    std::vector<double> cand{a, b};
    if (d == 2)
        cand.push_back(0.5 * (r[0] + r[1]));
    else if (d == 3)
    {
        const double s1 = r[0] + r[1] + r[2], s2 = r[0] * r[1] + r[0] * r[2] + r[1] * r[2];
        const double disc = 4 * s1 * s1 - 12 * s2;
        if (disc >= 0)
        {
            cand.push_back((2 * s1 + std::sqrt(disc)) / 6);
            cand.push_back((2 * s1 - std::sqrt(disc)) / 6);
        }
    }
    double best = 0.0;
    double w[4], dw[4];
    for (double q : cand)
        if (q >= a && q <= b)
        {
            lagrange(x, n, q, w, dw);
            best = std::max(best, std::abs(w[i]));
        }
    return best;
}

/// Nodes of the m-node cubic stencil of interval k (k-1 .. k+2, shifted inside at the ends of the axis) into x;
/// returns the first.
std::size_t cubicNodes(const Axis &axis, std::size_t k, int m, double *x)
{
    std::size_t first = k >= 1 ? k - 1 : 0;
    if (first + m > axis.size())
        first = axis.size() - m;
    for (int i = 0; i < m; ++i)
        x[i] = axis[first + i];
    return first;
}

/// A scheme and one of its names; the first entry of a scheme is the name toString() gives, later ones are
/// aliases that parsing accepts.
template <typename E> struct SchemeName
{
    E scheme;
    const char *name;
};

constexpr SchemeName<Interp2D> kInterp2DNames[] = {{Interp2D::Nearest, "nearest"},
                                                   {Interp2D::Bilinear, "bilinear"},
                                                   {Interp2D::Bicubic, "bicubic"},
                                                   {Interp2D::Bilinear, "linear"},
                                                   {Interp2D::Bicubic, "cubic"}};
constexpr SchemeName<Interp1D> kInterp1DNames[] = {{Interp1D::Nearest, "nearest"},
                                                   {Interp1D::Linear, "linear"},
                                                   {Interp1D::Cubic, "cubic"},
                                                   {Interp1D::Akima, "akima"}};

/// The scheme named (lower case) `name` in the table; false when none is.
template <typename E, std::size_t N>
bool findScheme(const SchemeName<E> (&table)[N], const std::string &name, E &scheme)
{
    for (const SchemeName<E> &e : table)
        if (name == e.name)
        {
            scheme = e.scheme;
            return true;
        }
    return false;
}

/// The first name of the scheme in the table, "?" for a value outside the enumeration.
template <typename E, std::size_t N> std::string schemeName(const SchemeName<E> (&table)[N], E scheme)
{
    for (const SchemeName<E> &e : table)
        if (e.scheme == scheme)
            return e.name;
    return "?";
}
} // namespace

Interp2D parseInterp2D(const std::string &name)
{
    Interp2D s{};
    if (!findScheme(kInterp2DNames, lower(name), s))
        throw Error("x/y interpolation scheme '" + name + "': expected nearest, bilinear or bicubic");
    return s;
}

Interp1D parseInterp1D(const std::string &name)
{
    Interp1D s{};
    if (!findScheme(kInterp1DNames, lower(name), s))
        throw Error("depth/time interpolation scheme '" + name + "': expected nearest, linear, cubic or akima");
    return s;
}

std::string toString(Interp2D s)
{
    return schemeName(kInterp2DNames, s);
}

std::string toString(Interp1D s)
{
    return schemeName(kInterp1DNames, s);
}

Axis::Axis(std::vector<double> nodes, const std::string &what) : c_(std::move(nodes))
{
    if (c_.empty())
        throw Error(what + ": expected at least one node");
    for (std::size_t i = 0; i < c_.size(); ++i)
    {
        if (!std::isfinite(c_[i]))
            throw Error(what + ": node " + std::to_string(i) + " is not finite");
        if (i > 0 && !(c_[i] > c_[i - 1]))
            throw Error(what + ": expected strictly increasing values, but node " + std::to_string(i) + " (" +
                        std::to_string(c_[i]) + ") <= node " + std::to_string(i - 1) + " (" +
                        std::to_string(c_[i - 1]) + ")");
    }
    if (c_.size() >= 2)
    {
        h_ = (c_.back() - c_.front()) / static_cast<double>(c_.size() - 1);
        invH_ = 1.0 / h_;
        uniform_ = true;
        for (std::size_t i = 1; i < c_.size(); ++i)
            if (std::abs((c_[i] - c_[i - 1]) - h_) > 1e-9 * h_)
            {
                uniform_ = false;
                break;
            }
    }
}

std::size_t Axis::interval(double q) const
{
    const std::size_t n = c_.size();
    if (n < 2)
        return 0;
    if (uniform_)
    {
        const double f = (q - c_.front()) * invH_;
        if (!(f > 0.0))
            return 0;
        // clamped before the conversion: f is infinite for a query far out or a spacing too small to invert
        std::size_t k = f < static_cast<double>(n - 2) ? static_cast<std::size_t>(f) : n - 2;
        // guard against rounding at the nodes
        if (k > 0 && q < c_[k])
            --k;
        else if (k + 2 < n && q >= c_[k + 1])
            ++k;
        return k;
    }
    const auto it = std::upper_bound(c_.begin(), c_.end(), q);
    std::size_t k = it == c_.begin() ? 0 : static_cast<std::size_t>(it - c_.begin()) - 1;
    return std::min(k, n - 2);
}

Interp1D axisScheme(Interp2D scheme)
{
    switch (scheme)
    {
    case Interp2D::Nearest:
        return Interp1D::Nearest;
    case Interp2D::Bilinear:
        return Interp1D::Linear;
    case Interp2D::Bicubic:
        return Interp1D::Cubic;
    }
    return Interp1D::Linear;
}

Stencil makeStencil(const Axis &axis, Interp1D scheme, double q, bool derivative)
{
    Stencil s;
    const std::size_t n = axis.size();
    if (n == 1)
    {
        s.first = 0;
        s.n = 1;
        s.w[0] = 1.0;
        return s;
    }
    bool outside = false;
    if (q < axis.front())
    {
        q = axis.front();
        outside = true;
    }
    else if (q > axis.back())
    {
        q = axis.back();
        outside = true;
    }
    const std::size_t k = axis.interval(q);
    const double x0 = axis[k], x1 = axis[k + 1];
    switch (scheme)
    {
    case Interp1D::Nearest:
        s.n = 1;
        s.first = (q - x0 < x1 - q) ? k : k + 1;
        s.w[0] = 1.0;
        return s;
    case Interp1D::Linear: {
        const double h = x1 - x0;
        const double a = (q - x0) / h;
        s.n = 2;
        s.first = k;
        s.w[0] = 1.0 - a;
        s.w[1] = a;
        if (!outside && derivative)
        {
            s.dw[0] = -1.0 / h;
            s.dw[1] = 1.0 / h;
        }
        return s;
    }
    case Interp1D::Cubic: {
        const int m = static_cast<int>(std::min<std::size_t>(4, n));
        double x[4];
        s.first = cubicNodes(axis, k, m, x);
        s.n = m;
        lagrange(x, m, q, s.w.data(), derivative ? s.dw.data() : nullptr);
        if (outside)
            s.dw.fill(0.0);
        return s;
    }
    case Interp1D::Akima:
        break;
    }
    throw Error("makeStencil: Akima interpolation is not linear in the data; use akimaInterpolate()");
}

double overshootFactor(const Axis &axis, Interp1D scheme)
{
    const std::size_t n = axis.size();
    if (n <= 2 || scheme == Interp1D::Nearest || scheme == Interp1D::Linear)
        return 1.0;
    if (scheme == Interp1D::Cubic)
    {
        const int m = static_cast<int>(std::min<std::size_t>(4, n));
        double worst = 1.0;
        for (std::size_t k = 0; k + 1 < n; ++k)
        {
            double x[4];
            cubicNodes(axis, k, m, x);
            double sum = 0.0;
            for (int i = 0; i < m; ++i)
                sum += maxAbsBasis(x, m, i, axis[k], axis[k + 1]);
            worst = std::max(worst, sum);
        }
        return worst;
    }
    // Akima: |secant_j| <= 2 M / h_j; extrapolated secants by the triangle inequality.
    std::vector<double> S(n + 3); // S[j + 2] for j = -2 .. n
    for (std::size_t j = 0; j + 1 < n; ++j)
        S[j + 2] = 2.0 / (axis[j + 1] - axis[j]);
    S[1] = 2 * S[2] + S[3];
    S[0] = 2 * S[1] + S[2];
    S[n + 1] = 2 * S[n] + S[n - 1];
    S[n + 2] = 2 * S[n + 1] + S[n];
    double worst = 1.0;
    for (std::size_t k = 0; k + 1 < n; ++k)
    {
        const double h = axis[k + 1] - axis[k];
        // slope at node k is a convex combination of secants k-1 and k; at node k+1 of k and k+1
        const double t0 = std::max(S[k + 1], S[k + 2]), t1 = std::max(S[k + 2], S[k + 3]);
        worst = std::max(worst, 1.0 + 4.0 / 27.0 * h * (t0 + t1));
    }
    return worst;
}
} // namespace ompl_glider
