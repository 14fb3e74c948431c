/// @file GriddedBounds.cpp
/// @brief Speed and velocity bounds of GriddedCurrentField: the largest stencil-box diameters, maxSpeed(), the
/// blocks of curvilinear grids and velocityBounds().

#include "ompl_glider/current/GriddedCurrentField.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{
constexpr float kInfF = std::numeric_limits<float>::infinity();

/// Number of nodes per axis in one interpolation stencil of the scheme.
std::size_t stencilWidth(Interp1D s)
{
    switch (s)
    {
    case Interp1D::Nearest:
        return 1;
    case Interp1D::Linear:
        return 2;
    case Interp1D::Cubic:
        return 4;
    case Interp1D::Akima:
        return 6;
    }
    return 6;
}

/// Clamps the query range [lo, hi] to the axis; an end that is not finite becomes the axis' end.
void clampToAxis(const Axis &ax, double &lo, double &hi)
{
    lo = std::isfinite(lo) ? std::clamp(lo, ax.front(), ax.back()) : ax.front();
    hi = std::isfinite(hi) ? std::clamp(hi, ax.front(), ax.back()) : ax.back();
}

/// The region's time window, an end that is NaN taken as unbounded.
void timeWindow(const Region &region, double &lo, double &hi)
{
    lo = std::isnan(region.tMin) ? -kInf : region.tMin;
    hi = std::isnan(region.tMax) ? kInf : region.tMax;
}

/// Extremes {uMin, uMax, vMin, vMax} that any value widens.
void resetExtremes(float *e)
{
    e[0] = kInfF;
    e[1] = -kInfF;
    e[2] = kInfF;
    e[3] = -kInfF;
}

/// Widens the extremes e = {uMin, uMax, vMin, vMax} by the interleaved (u, v) nodes i0..i1 of a row.
void widenByRow(float *e, const float *row, std::size_t i0, std::size_t i1)
{
    for (std::size_t i = i0; i <= i1; ++i)
    {
        e[0] = std::min(e[0], row[2 * i]);
        e[1] = std::max(e[1], row[2 * i]);
        e[2] = std::min(e[2], row[2 * i + 1]);
        e[3] = std::max(e[3], row[2 * i + 1]);
    }
}

/// Widens the extremes e by the extremes f (both {uMin, uMax, vMin, vMax}).
void widen(float *e, const float *f)
{
    e[0] = std::min(e[0], f[0]);
    e[1] = std::max(e[1], f[1]);
    e[2] = std::min(e[2], f[2]);
    e[3] = std::max(e[3], f[3]);
}

/// Index of the bucket of width d (first at o, n in all) holding q, clamped to 0 .. n-1.
std::size_t bucketIndex(double q, double o, double d, std::size_t n)
{
    return static_cast<std::size_t>(std::clamp(std::floor((q - o) / d), 0.0, double(n - 1)));
}
} // namespace

void GriddedCurrentField::computeStencilDiameters()
{
    // Per-component max and min of the nodes over every stencil box (window widths: nearest 1, linear 2, cubic
    // 4, Akima 6 nodes per axis), by separable sliding windows; then the largest Euclidean diameter bound
    // sqrt(range_u^2 + range_v^2) of the boxes starting at each time index.
    const std::size_t nz = depth_.size(), nt = time_.size(), nh = nx_ * ny_, n = nt * nz * nh;
    const std::size_t wxy = stencilWidth(axisScheme(options_.xy));
    const std::size_t w[4] = {wxy, wxy, stencilWidth(options_.depth), stencilWidth(options_.time)};
    const std::size_t len[4] = {nx_, ny_, nz, nt};
    const std::size_t stride[4] = {1, nx_, nh, nh * nz};
    std::vector<float> hi[2], lo[2];
    for (int c = 0; c < 2; ++c)
    {
        hi[c].resize(n);
        lo[c].resize(n);
        for (std::size_t q = 0; q < n; ++q)
            hi[c][q] = lo[c][q] = uv_[2 * q + c];
    }
    std::vector<float> tmpHi, tmpLo;
    for (int d = 0; d < 4; ++d)
    {
        if (w[d] <= 1 || len[d] <= 1)
            continue;
        for (int c = 0; c < 2; ++c)
        {
            tmpHi = hi[c];
            tmpLo = lo[c];
            for (std::size_t q = 0; q < n; ++q)
            {
                const std::size_t pos = (q / stride[d]) % len[d];
                const std::size_t last = std::min(len[d] - 1, pos + w[d] - 1);
                float mx = tmpHi[q], mn = tmpLo[q];
                for (std::size_t k = pos + 1; k <= last; ++k)
                {
                    mx = std::max(mx, tmpHi[q + (k - pos) * stride[d]]);
                    mn = std::min(mn, tmpLo[q + (k - pos) * stride[d]]);
                }
                hi[c][q] = mx;
                lo[c][q] = mn;
            }
        }
    }
    boxDiameter_.assign(nt, 0.0);
    for (std::size_t q = 0; q < n; ++q)
    {
        const double du = double(hi[0][q]) - double(lo[0][q]), dv = double(hi[1][q]) - double(lo[1][q]);
        const std::size_t it = q / (nh * nz);
        boxDiameter_[it] = std::max(boxDiameter_[it], std::hypot(du, dv));
    }
}

double GriddedCurrentField::maxSpeed(const Region &region) const
{
    const std::size_t nz = depth_.size();
    // nodes a..b of an axis whose stencils (at most k-2 .. k+3 around the interval k) can serve [lo, hi]
    auto range = [](const Axis &ax, double lo, double hi, std::size_t &a, std::size_t &b) {
        if (ax.size() == 1)
        {
            a = b = 0;
            return;
        }
        clampToAxis(ax, lo, hi);
        if (lo > hi)
            std::swap(lo, hi);
        const std::size_t ka = ax.interval(lo), kb = ax.interval(hi);
        a = ka >= 2 ? ka - 2 : 0;
        b = std::min(ax.size() - 1, kb + 3);
    };
    std::size_t t0, t1;
    double tlo, thi;
    timeWindow(region, tlo, thi);
    range(time_, tlo, thi, t0, t1);
    // All loaded depth layers (the loader keeps only those the glider reaches): planners often leave the region's
    // depth range at 0 while the travel-time code reads the current at another depth.
    const bool akima = options_.depth == Interp1D::Akima || options_.time == Interp1D::Akima;
    double ms = 0, mu = 0, mv = 0;
    for (std::size_t it = t0; it <= t1; ++it)
        for (std::size_t k = 0; k < nz; ++k)
        {
            ms = std::max(ms, layerMaxSpeed_[it * nz + k]);
            mu = std::max(mu, layerMaxU_[it * nz + k]);
            mv = std::max(mv, layerMaxV_[it * nz + k]);
        }
    const double base = akima ? std::hypot(mu, mv) : ms;
    const double product = base * overshoot_;
    // Data-dependent bound: each stage maps (max |input| M, max difference D of the inputs in a stencil) to
    // M + (L - 1) / 2 * D and L * D (L: the stage's overshoot factor; for linear weights w with sum 1,
    // sum w c = A + W- (A - B) with A, B convex combinations and W- = (L - 1) / 2; for Akima, the convex Hermite
    // part plus at most (L - 1) / 2 * D). Smooth data have small D, so this is close to the node maximum.
    double D = 0;
    const std::size_t wt = options_.time == Interp1D::Akima ? 6 : 4;
    for (std::size_t it = t0 >= wt ? t0 - wt : 0; it <= t1; ++it)
        D = std::max(D, boxDiameter_[it]);
    const double data =
        ms + D * (0.5 * (lamXY_ - 1.0) + 0.5 * (lamZ_ - 1.0) * lamXY_ + 0.5 * (lamT_ - 1.0) * lamXY_ * lamZ_);
    // tiny relative margin for float storage and rounding of the weights
    return std::min(product, data) * (1.0 + 1e-9) + 1e-300;
}

void GriddedCurrentField::buildBlocks()
{
    Blocks &b = blocks_;
    const std::size_t B = Blocks::kBlock, cx = nx_ - 1, cy = ny_ - 1, nz = depth_.size(), nt = time_.size();
    b.nbi = (cx + B - 1) / B;
    b.nbj = (cy + B - 1) / B;
    const std::size_t nb = b.nbi * b.nbj;
    b.box.assign(4 * nb, 0.0);
    b.edge.assign(nb, 0);
    b.ext.assign(4 * nb * nt, 0.0f);
    b.all.assign(4 * nt, 0.0f);
    for (std::size_t it = 0; it < nt; ++it)
        resetExtremes(&b.all[4 * it]);
    for (std::size_t bj = 0; bj < b.nbj; ++bj)
        for (std::size_t bi = 0; bi < b.nbi; ++bi)
        {
            const std::size_t k = bi + bj * b.nbi;
            const std::size_t i0 = bi * B, i1 = std::min(cx, (bi + 1) * B);
            const std::size_t j0 = bj * B, j1 = std::min(cy, (bj + 1) * B);
            b.edge[k] = bi == 0 || bj == 0 || i1 == cx || j1 == cy;
            double x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
            for (std::size_t j = j0; j <= j1; ++j)
                for (std::size_t i = i0; i <= i1; ++i)
                {
                    x0 = std::min(x0, nodeX_[j * nx_ + i]);
                    x1 = std::max(x1, nodeX_[j * nx_ + i]);
                    y0 = std::min(y0, nodeY_[j * nx_ + i]);
                    y1 = std::max(y1, nodeY_[j * nx_ + i]);
                }
            b.box[4 * k] = x0;
            b.box[4 * k + 1] = x1;
            b.box[4 * k + 2] = y0;
            b.box[4 * k + 3] = y1;
            for (std::size_t it = 0; it < nt; ++it)
            {
                float *out = &b.ext[4 * (it * nb + k)];
                resetExtremes(out);
                for (std::size_t iz = 0; iz < nz; ++iz)
                    for (std::size_t j = j0; j <= j1; ++j)
                        widenByRow(out, &uv_[2 * (((it * nz + iz) * ny_ + j) * nx_)], i0, i1);
                widen(&b.all[4 * it], out);
            }
        }
    // buckets: about one block per bucket
    b.bnx = std::max<std::size_t>(1, b.nbi);
    b.bny = std::max<std::size_t>(1, b.nbj);
    b.bx0 = xMin_;
    b.by0 = yMin_;
    b.bdx = std::max(1e-300, (xMax_ - xMin_) / double(b.bnx));
    b.bdy = std::max(1e-300, (yMax_ - yMin_) / double(b.bny));
    b.buckets.assign(b.bnx * b.bny, {});
    for (std::size_t k = 0; k < nb; ++k)
    {
        const std::size_t a0 = bucketIndex(b.box[4 * k], b.bx0, b.bdx, b.bnx);
        const std::size_t a1 = bucketIndex(b.box[4 * k + 1], b.bx0, b.bdx, b.bnx);
        const std::size_t c0 = bucketIndex(b.box[4 * k + 2], b.by0, b.bdy, b.bny);
        const std::size_t c1 = bucketIndex(b.box[4 * k + 3], b.by0, b.bdy, b.bny);
        for (std::size_t c = c0; c <= c1; ++c)
            for (std::size_t a = a0; a <= a1; ++a)
                b.buckets[a + c * b.bnx].push_back(static_cast<std::uint32_t>(k));
    }
}

bool GriddedCurrentField::hasVelocityBounds() const
{
    return options_.xy != Interp2D::Bicubic &&
           (options_.depth == Interp1D::Nearest || options_.depth == Interp1D::Linear) &&
           (options_.time == Interp1D::Nearest || options_.time == Interp1D::Linear);
}

void GriddedCurrentField::curvilinearExtremes(const Region &region, std::size_t t0, std::size_t t1, float *e) const
{
    const Blocks &B = blocks_;
    const std::size_t nb = B.nbi * B.nbj;
    auto whole = [&] {
        for (std::size_t it = t0; it <= t1; ++it)
            widen(e, &B.all[4 * it]);
    };
    const double rx0 = region.xMin, rx1 = region.xMax, ry0 = region.yMin, ry1 = region.yMax;
    if (!(rx0 >= xMin_ && rx1 <= xMax_ && ry0 >= yMin_ && ry1 <= yMax_ && rx0 <= rx1 && ry0 <= ry1))
        return whole(); // reaches beyond the nodes (or not finite): points outside the grid are clamped
    double fi, fj;
    if (!locate(0.5 * (rx0 + rx1), 0.5 * (ry0 + ry1), fi, fj))
        return whole();
    const std::size_t a0 = bucketIndex(rx0, B.bx0, B.bdx, B.bnx), a1 = bucketIndex(rx1, B.bx0, B.bdx, B.bnx);
    const std::size_t c0 = bucketIndex(ry0, B.by0, B.bdy, B.bny), c1 = bucketIndex(ry1, B.by0, B.bdy, B.bny);
    std::vector<std::uint32_t> hit;
    for (std::size_t cc = c0; cc <= c1; ++cc)
        for (std::size_t aa = a0; aa <= a1; ++aa)
            for (const std::uint32_t k : B.buckets[aa + cc * B.bnx])
            {
                const double *bx = &B.box[4 * k];
                if (bx[0] > rx1 || bx[1] < rx0 || bx[2] > ry1 || bx[3] < ry0)
                    continue;
                if (B.edge[k])
                    return whole(); // the region may reach outside the grid
                hit.push_back(k);
            }
    if (hit.empty())
        return whole();
    for (std::size_t it = t0; it <= t1; ++it)
        for (const std::uint32_t k : hit)
            widen(e, &B.ext[4 * (it * nb + k)]);
}

bool GriddedCurrentField::velocityBounds(const Region &region, double &uMin, double &uMax, double &vMin,
                                         double &vMax) const
{
    if (!hasVelocityBounds())
        return false;
    // nodes a..b of an axis whose stencils can serve a query in [lo, hi] (queries are clamped to the axis; a
    // linear or nearest stencil uses the two nodes of the interval holding the query)
    auto range = [](const Axis &ax, double lo, double hi, std::size_t &a, std::size_t &b) {
        if (ax.size() == 1 || !(lo <= hi))
        {
            a = 0;
            b = ax.size() - 1;
            return;
        }
        clampToAxis(ax, lo, hi);
        a = ax.interval(lo);
        b = std::min(ax.size() - 1, ax.interval(hi) + 1);
    };
    std::size_t t0, t1;
    double tlo, thi;
    timeWindow(region, tlo, thi);
    range(time_, tlo, thi, t0, t1);
    float e[4];
    resetExtremes(e);
    if (curvilinear_)
        curvilinearExtremes(region, t0, t1, e);
    else
    {
        std::size_t i0, i1, j0, j1;
        range(x_, region.xMin, region.xMax, i0, i1);
        range(y_, region.yMin, region.yMax, j0, j1);
        const std::size_t nz = depth_.size();
        for (std::size_t it = t0; it <= t1; ++it)
            for (std::size_t k = 0; k < nz; ++k) // all loaded layers, as maxSpeed()
                for (std::size_t j = j0; j <= j1; ++j)
                    widenByRow(e, &uv_[2 * (((it * nz + k) * ny_ + j) * nx_)], i0, i1);
    }
    // (the interpolation's weights are rounded: a relative margin as in maxSpeed())
    const double m = 1e-9 * std::max({std::abs(e[0]), std::abs(e[1]), std::abs(e[2]), std::abs(e[3])}) + 1e-300;
    uMin = e[0] - m;
    uMax = e[1] + m;
    vMin = e[2] - m;
    vMax = e[3] + m;
    return true;
}
} // namespace ompl_glider
