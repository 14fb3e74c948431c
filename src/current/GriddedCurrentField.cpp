#include "ompl_glider/current/GriddedCurrentField.h"

#include "CoastEdges.h"
#include "../io/TextUtil.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "ompl_glider/Exception.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{
std::atomic<std::uint64_t> nextFieldId{1};

std::vector<double> indexAxis(std::size_t n)
{
    std::vector<double> a(n);
    for (std::size_t i = 0; i < n; ++i)
        a[i] = static_cast<double>(i);
    return a;
}
} // namespace

GriddedCurrentField::GriddedCurrentField(GriddedData d, GriddedFieldOptions options)
    : options_(std::move(options)), id_(nextFieldId.fetch_add(1))
{
    const std::string who = "gridded field '" + options_.name + "'";
    nx_ = d.nx;
    ny_ = d.ny;
    if (nx_ < 2 || ny_ < 2)
        throw Error(who + ": expected at least 2 nodes along x and along y, got " + std::to_string(nx_) + " x " +
                    std::to_string(ny_));
    curvilinear_ = d.x.empty() && d.y.empty();
    const std::size_t nh = nx_ * ny_;
    if (curvilinear_)
    {
        if (d.nodeX.size() != nh || d.nodeY.size() != nh)
            throw Error(who + ": expected either x/y axes of sizes nx, ny or nodeX/nodeY of size nx*ny = " +
                        std::to_string(nh));
        for (std::size_t n = 0; n < nh; ++n)
            if (!std::isfinite(d.nodeX[n]) || !std::isfinite(d.nodeY[n]))
                throw Error(who + ": node position " + std::to_string(n) + " is not finite");
        x_ = Axis(indexAxis(nx_), who + " i index");
        y_ = Axis(indexAxis(ny_), who + " j index");
        nodeX_ = std::move(d.nodeX);
        nodeY_ = std::move(d.nodeY);
    }
    else
    {
        if (d.x.size() != nx_ || d.y.size() != ny_)
            throw Error(who + ": x axis has " + std::to_string(d.x.size()) + " nodes and y axis " +
                        std::to_string(d.y.size()) + ", expected nx = " + std::to_string(nx_) +
                        " and ny = " + std::to_string(ny_));
        x_ = Axis(std::move(d.x), who + " x axis");
        y_ = Axis(std::move(d.y), who + " y axis");
    }
    depth_ = Axis(std::move(d.depth), who + " depth axis");
    time_ = Axis(std::move(d.time), who + " time axis");
    const std::size_t nz = depth_.size(), nt = time_.size();
    const std::size_t total = nt * nz * nh;
    if (d.u.size() != total || d.v.size() != total)
        throw Error(who + ": expected " + std::to_string(total) + " velocity values (nt*nz*ny*nx), got u " +
                    std::to_string(d.u.size()) + " and v " + std::to_string(d.v.size()));
    if (!d.water.empty() && d.water.size() != nz * nh)
        throw Error(who + ": water mask has " + std::to_string(d.water.size()) +
                    " values, expected nz*ny*nx = " + std::to_string(nz * nh));
    if (d.water.empty())
        d.water.assign(nz * nh, 1);

    storeVelocities(d, who);

    const Interp1D hs = axisScheme(options_.xy);
    lamXY_ = overshootFactor(x_, hs) * overshootFactor(y_, hs);
    lamZ_ = overshootFactor(depth_, options_.depth);
    lamT_ = overshootFactor(time_, options_.time);
    overshoot_ = lamXY_ * lamZ_ * lamT_;
    computeStencilDiameters();
    computeMinCell(who);
    const std::size_t cx = nx_ - 1, cy = ny_ - 1;
    if (curvilinear_)
    {
        xMin_ = *std::min_element(nodeX_.begin(), nodeX_.end());
        xMax_ = *std::max_element(nodeX_.begin(), nodeX_.end());
        yMin_ = *std::min_element(nodeY_.begin(), nodeY_.end());
        yMax_ = *std::max_element(nodeY_.begin(), nodeY_.end());
        buildLocator();
        buildBlocks();
        fdStep_ = 1e-4 * std::sqrt((xMax_ - xMin_) * (yMax_ - yMin_) / double(cx * cy));
    }
    else
    {
        xMin_ = x_.front();
        xMax_ = x_.back();
        yMin_ = y_.front();
        yMax_ = y_.back();
        fdStep_ = 1e-4 * std::min((xMax_ - xMin_) / double(cx), (yMax_ - yMin_) / double(cy));
    }
    auto coast = std::make_shared<detail::CoastEdges>();
    coast->build(
        nx_, ny_, nz, cellWater_,
        [this](std::size_t n, double &x, double &y) {
            x = curvilinear_ ? nodeX_[n] : x_[n % nx_];
            y = curvilinear_ ? nodeY_[n] : y_[n / nx_];
        },
        xMin_, xMax_, yMin_, yMax_);
    coast_ = std::move(coast);
}

void GriddedCurrentField::storeVelocities(const GriddedData &d, const std::string &who)
{
    const std::size_t nz = depth_.size(), nt = time_.size(), nh = nx_ * ny_;
    const std::size_t total = nt * nz * nh;
    uv_.resize(2 * total);
    layerMaxSpeed_.assign(nt * nz, 0.0);
    layerMaxU_.assign(nt * nz, 0.0);
    layerMaxV_.assign(nt * nz, 0.0);
    for (std::size_t it = 0; it < nt; ++it)
        for (std::size_t k = 0; k < nz; ++k)
        {
            double ms = 0, mu = 0, mv = 0;
            for (std::size_t n = 0; n < nh; ++n)
            {
                const std::size_t idx = (it * nz + k) * nh + n;
                float u = d.u[idx], v = d.v[idx];
                if (!d.water[k * nh + n])
                    u = v = 0.0f;
                else if (!std::isfinite(u) || !std::isfinite(v))
                    throw Error(who + ": non-finite velocity at water node (t " + std::to_string(it) + ", z " +
                                std::to_string(k) + ", j " + std::to_string(n / nx_) + ", i " +
                                std::to_string(n % nx_) + "); mark fill values as land");
                uv_[2 * idx] = u;
                uv_[2 * idx + 1] = v;
                ms = std::max(ms, std::hypot(double(u), double(v)));
                mu = std::max(mu, std::abs(double(u)));
                mv = std::max(mv, std::abs(double(v)));
            }
            layerMaxSpeed_[it * nz + k] = ms;
            layerMaxU_[it * nz + k] = mu;
            layerMaxV_[it * nz + k] = mv;
        }
    const std::size_t cx = nx_ - 1, cy = ny_ - 1;
    cellWater_.assign(nz * cx * cy, 0);
    for (std::size_t k = 0; k < nz; ++k)
        for (std::size_t j = 0; j < cy; ++j)
            for (std::size_t i = 0; i < cx; ++i)
            {
                const std::uint8_t *w = &d.water[k * nh];
                cellWater_[(k * cy + j) * cx + i] =
                    w[j * nx_ + i] && w[j * nx_ + i + 1] && w[(j + 1) * nx_ + i] && w[(j + 1) * nx_ + i + 1];
            }
}

void GriddedCurrentField::computeMinCell(const std::string &who)
{
    minCell_ = kInf;
    if (curvilinear_)
    {
        for (std::size_t j = 0; j < ny_; ++j)
            for (std::size_t i = 0; i < nx_; ++i)
            {
                const std::size_t n = j * nx_ + i;
                if (i + 1 < nx_)
                    minCell_ = std::min(minCell_, std::hypot(nodeX_[n + 1] - nodeX_[n], nodeY_[n + 1] - nodeY_[n]));
                if (j + 1 < ny_)
                    minCell_ = std::min(minCell_, std::hypot(nodeX_[n + nx_] - nodeX_[n], nodeY_[n + nx_] - nodeY_[n]));
            }
    }
    else
    {
        for (std::size_t i = 0; i + 1 < nx_; ++i)
            minCell_ = std::min(minCell_, x_[i + 1] - x_[i]);
        for (std::size_t j = 0; j + 1 < ny_; ++j)
            minCell_ = std::min(minCell_, y_[j + 1] - y_[j]);
    }
    if (!(minCell_ > 0.0))
        throw Error(who + ": two neighbouring nodes coincide");
}

template <bool Deriv>
GriddedCurrentField::Sample GriddedCurrentField::spatial(const Horizontal &h, std::size_t it, std::size_t iz) const
{
    Sample s;
    const std::size_t base = (it * depth_.size() + iz) * ny_ * nx_;
    for (int b = 0; b < h.sy.n; ++b)
    {
        const float *row = &uv_[2 * (base + (h.sy.first + b) * nx_ + h.sx.first)];
        double ru = 0, rv = 0, rdu = 0, rdv = 0;
        for (int a = 0; a < h.sx.n; ++a)
        {
            ru += h.sx.w[a] * row[2 * a];
            rv += h.sx.w[a] * row[2 * a + 1];
            if (Deriv)
            {
                rdu += h.sx.dw[a] * row[2 * a];
                rdv += h.sx.dw[a] * row[2 * a + 1];
            }
        }
        s.u += h.sy.w[b] * ru;
        s.v += h.sy.w[b] * rv;
        if (Deriv)
        {
            s.ui += h.sy.w[b] * rdu;
            s.vi += h.sy.w[b] * rdv;
            s.uj += h.sy.dw[b] * ru;
            s.vj += h.sy.dw[b] * rv;
        }
    }
    return s;
}

namespace
{
/// Akima interpolation of the u and v components of samples f(i) on the axis at q.
template <typename S, typename F> S akimaSample(const Axis &axis, double q, F &&f)
{
    if (axis.size() == 1)
        return f(std::size_t{0});
    const AkimaWindow w = akimaWindow(axis, std::clamp(q, axis.front(), axis.back()));
    double xs[6], us[6], vs[6];
    int m = 0;
    for (std::size_t i = w.lo; i <= w.hi; ++i, ++m)
    {
        const S s = f(i);
        xs[m] = axis[i];
        us[m] = s.u;
        vs[m] = s.v;
    }
    S r;
    r.u = detail::akimaFromNodes(xs, us, m, w.k, q);
    r.v = detail::akimaFromNodes(xs, vs, m, w.k, q);
    return r;
}

/// Adds w times the sample s to r (with the derivatives when Deriv).
template <bool Deriv, typename S> void addWeighted(S &r, double w, const S &s)
{
    r.u += w * s.u;
    r.v += w * s.v;
    if (Deriv)
    {
        r.ui += w * s.ui;
        r.uj += w * s.uj;
        r.vi += w * s.vi;
        r.vj += w * s.vj;
    }
}
} // namespace

double GriddedCurrentField::clampTime(double t) const
{
    if (!(t >= time_.front()))
        return time_.front();
    if (t > time_.back())
        return time_.back();
    return t;
}

template <bool Deriv>
GriddedCurrentField::Sample GriddedCurrentField::full(double x, double y, double z, double t) const
{
    if (!std::isfinite(x))
        x = xMin_;
    if (!std::isfinite(y))
        y = yMin_;
    if (!std::isfinite(z))
        z = depth_.front();
    const Horizontal h = horizontal(x, y, Deriv);
    const double tq = clampTime(t);
    const bool akimaZ = options_.depth == Interp1D::Akima, akimaT = options_.time == Interp1D::Akima;
    Stencil sz;
    if (!akimaZ)
        sz = makeStencil(depth_, options_.depth, z, false);
    auto atTime = [&](std::size_t it) -> Sample {
        if (akimaZ)
            return akimaSample<Sample>(depth_, z, [&](std::size_t k) { return spatial<false>(h, it, k); });
        if (sz.n == 1)
            return spatial<Deriv>(h, it, sz.first);
        Sample r;
        for (int c = 0; c < sz.n; ++c)
            addWeighted<Deriv>(r, sz.w[c], spatial<Deriv>(h, it, sz.first + c));
        return r;
    };
    Sample r;
    if (akimaT)
        r = akimaSample<Sample>(time_, tq, atTime);
    else
    {
        const Stencil st = makeStencil(time_, options_.time, tq, false);
        for (int c = 0; c < st.n; ++c)
            addWeighted<Deriv>(r, st.w[c], atTime(st.first + c));
    }
    if (Deriv && curvilinear_)
    {
        const Sample q = r;
        r.ui = q.ui * h.m[0] + q.uj * h.m[2]; // du/dx
        r.uj = q.ui * h.m[1] + q.uj * h.m[3]; // du/dy
        r.vi = q.vi * h.m[0] + q.vj * h.m[2];
        r.vj = q.vi * h.m[1] + q.vj * h.m[3];
    }
    return r;
}

Velocity GriddedCurrentField::evaluate(double x, double y, double z, double t) const
{
    const Sample s = full<false>(x, y, z, t);
    return {s.u, s.v};
}

Jacobian GriddedCurrentField::evaluateJacobian(double x, double y, double z, double t) const
{
    if (options_.depth == Interp1D::Akima || options_.time == Interp1D::Akima)
    {
        const double hs = fdStep_;
        const Sample xp = full<false>(x + hs, y, z, t), xm = full<false>(x - hs, y, z, t);
        const Sample yp = full<false>(x, y + hs, z, t), ym = full<false>(x, y - hs, z, t);
        return {(xp.u - xm.u) / (2 * hs), (yp.u - ym.u) / (2 * hs), (xp.v - xm.v) / (2 * hs), (yp.v - ym.v) / (2 * hs)};
    }
    const Sample s = full<true>(x, y, z, t);
    return {s.ui, s.uj, s.vi, s.vj};
}

void GriddedCurrentField::waterLayers(double z, std::size_t &k0, std::size_t &k1) const
{
    k0 = k1 = 0;
    if (depth_.size() == 1)
        return;
    const double zc = std::isfinite(z) ? std::clamp(z, depth_.front(), depth_.back()) : depth_.front();
    const std::size_t k = depth_.interval(zc);
    const double frac = (zc - depth_[k]) / (depth_[k + 1] - depth_[k]);
    k0 = frac < 1.0 ? k : k + 1;
    k1 = frac > 0.0 ? k + 1 : k;
}

bool GriddedCurrentField::inWater(double x, double y, double z) const
{
    if (!std::isfinite(x) || !std::isfinite(y))
        return false;
    double fi, fj;
    if (!locate(x, y, fi, fj))
        return false;
    const std::size_t cx = nx_ - 1, cy = ny_ - 1;
    const std::size_t ci = std::min(static_cast<std::size_t>(fi), cx - 1);
    const std::size_t cj = std::min(static_cast<std::size_t>(fj), cy - 1);
    std::size_t k0, k1;
    waterLayers(z, k0, k1);
    for (std::size_t k = k0; k <= k1; ++k)
        if (!cellWater_[(k * cy + cj) * cx + ci])
            return false;
    return true;
}

bool GriddedCurrentField::segmentInWater(double x1, double y1, double x2, double y2, double z) const
{
    if (!inWater(x1, y1, z) || !inWater(x2, y2, z))
        return false;
    std::size_t k0, k1;
    waterLayers(z, k0, k1);
    thread_local std::vector<double> s;
    s.assign({0.0, 1.0});
    for (std::size_t k = k0; k <= k1; ++k)
        coast_->meet(k, x1, y1, x2, y2, s);
    if (s.size() == 2)
        return true;
    std::sort(s.begin(), s.end());
    // between two consecutive meeting points the segment is all in water or all on land: test each middle
    for (std::size_t q = 0; q + 1 < s.size(); ++q)
    {
        if (s[q + 1] - s[q] <= 1e-12)
            continue;
        const double m = 0.5 * (s[q] + s[q + 1]);
        if (!inWater(x1 + m * (x2 - x1), y1 + m * (y2 - y1), z))
            return false;
    }
    return true;
}

std::vector<Segment2> GriddedCurrentField::landBoundary(double z) const
{
    std::size_t k0, k1;
    waterLayers(z, k0, k1);
    const std::size_t cx = nx_ - 1, cy = ny_ - 1;
    auto wet = [&](std::size_t i, std::size_t j) {
        for (std::size_t k = k0; k <= k1; ++k)
            if (!cellWater_[(k * cy + j) * cx + i])
                return false;
        return true;
    };
    auto node = [&](std::size_t i, std::size_t j) {
        const std::size_t n = j * nx_ + i;
        return curvilinear_ ? Point2{nodeX_[n], nodeY_[n]} : Point2{x_[i], y_[j]};
    };
    std::vector<Segment2> out;
    for (std::size_t j = 0; j < cy; ++j)
        for (std::size_t i = 1; i < cx; ++i)
            if (wet(i - 1, j) != wet(i, j))
                out.push_back({node(i, j), node(i, j + 1)});
    for (std::size_t j = 1; j < cy; ++j)
        for (std::size_t i = 0; i < cx; ++i)
            if (wet(i, j - 1) != wet(i, j))
                out.push_back({node(i, j), node(i + 1, j)});
    return out;
}

BeyondForecast parseBeyondForecast(const std::string &name)
{
    const std::string s = text::lower(name);
    if (s == "hold" || s == "hold_last" || s == "hold-last" || s == "holdlast")
        return BeyondForecast::HoldLast;
    if (s == "refuse")
        return BeyondForecast::Refuse;
    throw Error("after-forecast policy '" + name + "': expected hold or refuse");
}

double GriddedCurrentField::timeBegin() const
{
    return time_.size() > 1 ? time_.front() : -kInf;
}

double GriddedCurrentField::timeEnd() const
{
    if (time_.size() == 1 || options_.beyond == BeyondForecast::HoldLast)
        return kInf;
    return time_.back();
}

Region GriddedCurrentField::extent() const
{
    Region r;
    r.xMin = xMin_;
    r.xMax = xMax_;
    r.yMin = yMin_;
    r.yMax = yMax_;
    r.zMin = depth_.front();
    r.zMax = depth_.back();
    r.tMin = timeBegin();
    r.tMax = time_.size() > 1 ? time_.back() : kInf;
    return r;
}

std::size_t GriddedCurrentField::memoryBytes() const
{
    return uv_.size() * sizeof(float) + cellWater_.size() + coast_->memoryBytes() +
           (nodeX_.size() + nodeY_.size()) * sizeof(double) + bucket_.size() * sizeof(std::int32_t) +
           (x_.size() + y_.size() + depth_.size() + time_.size()) * sizeof(double);
}
} // namespace ompl_glider
