#include "ompl_glider/current/GriddedCurrentField.h"

#include "CoastEdges.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <deque>
#include <limits>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<double> indexAxis(std::size_t n)
{
    std::vector<double> a(n);
    for (std::size_t i = 0; i < n; ++i)
        a[i] = static_cast<double>(i);
    return a;
}
}  // namespace

namespace
{
std::atomic<std::uint64_t> nextFieldId{1};
}

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
        throw Error(who + ": water mask has " + std::to_string(d.water.size()) + " values, expected nz*ny*nx = " +
                    std::to_string(nz * nh));
    if (d.water.empty())
        d.water.assign(nz * nh, 1);

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
                cellWater_[(k * cy + j) * cx + i] = w[j * nx_ + i] && w[j * nx_ + i + 1] && w[(j + 1) * nx_ + i] &&
                                                    w[(j + 1) * nx_ + i + 1];
            }

    const Interp1D hs = axisScheme(options_.xy);
    lamXY_ = overshootFactor(x_, hs) * overshootFactor(y_, hs);
    lamZ_ = overshootFactor(depth_, options_.depth);
    lamT_ = overshootFactor(time_, options_.time);
    overshoot_ = lamXY_ * lamZ_ * lamT_;
    computeStencilDiameters();

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

void GriddedCurrentField::computeStencilDiameters()
{
    // Per-component max and min of the nodes over every stencil box (window widths: nearest 1, linear 2, cubic
    // 4, Akima 6 nodes per axis), by separable sliding windows; then the largest Euclidean diameter bound
    // sqrt(range_u^2 + range_v^2) of the boxes starting at each time index.
    const std::size_t nz = depth_.size(), nt = time_.size(), nh = nx_ * ny_, n = nt * nz * nh;
    auto width = [](Interp1D s) -> std::size_t {
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
    };
    const std::size_t wxy = width(axisScheme(options_.xy));
    const std::size_t w[4] = {wxy, wxy, width(options_.depth), width(options_.time)};
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

void GriddedCurrentField::buildLocator()
{
    const std::size_t cx = nx_ - 1, cy = ny_ - 1, nc = cx * cy;
    const double w = std::max(xMax_ - xMin_, 1e-300), h = std::max(yMax_ - yMin_, 1e-300);
    double s = std::sqrt(w * h / double(nc));
    bnx_ = static_cast<std::size_t>(std::ceil(w / s)) + 1;
    bny_ = static_cast<std::size_t>(std::ceil(h / s)) + 1;
    while (bnx_ * bny_ > 4 * nc + 16)
    {
        s *= 1.5;
        bnx_ = static_cast<std::size_t>(std::ceil(w / s)) + 1;
        bny_ = static_cast<std::size_t>(std::ceil(h / s)) + 1;
    }
    bx0_ = xMin_;
    by0_ = yMin_;
    bInv_ = 1.0 / s;
    bucket_.assign(bnx_ * bny_, -1);
    std::deque<std::size_t> queue;
    for (std::size_t j = 0; j < cy; ++j)
        for (std::size_t i = 0; i < cx; ++i)
        {
            const std::size_t n[4] = {j * nx_ + i, j * nx_ + i + 1, (j + 1) * nx_ + i, (j + 1) * nx_ + i + 1};
            double x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
            for (std::size_t q : n)
            {
                x0 = std::min(x0, nodeX_[q]);
                x1 = std::max(x1, nodeX_[q]);
                y0 = std::min(y0, nodeY_[q]);
                y1 = std::max(y1, nodeY_[q]);
            }
            const std::size_t bi0 = static_cast<std::size_t>((x0 - bx0_) * bInv_);
            const std::size_t bi1 = std::min(bnx_ - 1, static_cast<std::size_t>((x1 - bx0_) * bInv_));
            const std::size_t bj0 = static_cast<std::size_t>((y0 - by0_) * bInv_);
            const std::size_t bj1 = std::min(bny_ - 1, static_cast<std::size_t>((y1 - by0_) * bInv_));
            for (std::size_t bj = bj0; bj <= bj1; ++bj)
                for (std::size_t bi = bi0; bi <= bi1; ++bi)
                    if (bucket_[bj * bnx_ + bi] < 0)
                    {
                        bucket_[bj * bnx_ + bi] = static_cast<std::int32_t>(j * cx + i);
                        queue.push_back(bj * bnx_ + bi);
                    }
        }
    // Empty buckets (outside the mesh) get a neighbour's cell so that the walk starts nearby.
    while (!queue.empty())
    {
        const std::size_t b = queue.front();
        queue.pop_front();
        const std::size_t bi = b % bnx_, bj = b / bnx_;
        const std::size_t nb[4] = {bi > 0 ? b - 1 : b, bi + 1 < bnx_ ? b + 1 : b, bj > 0 ? b - bnx_ : b,
                                   bj + 1 < bny_ ? b + bnx_ : b};
        for (std::size_t q : nb)
            if (bucket_[q] < 0)
            {
                bucket_[q] = bucket_[b];
                queue.push_back(q);
            }
    }
}

bool GriddedCurrentField::cellInside(std::size_t ci, std::size_t cj, double px, double py, double &a, double &b) const
{
    const std::size_t n00 = cj * nx_ + ci, n10 = n00 + 1, n01 = n00 + nx_, n11 = n01 + 1;
    const double x00 = nodeX_[n00], y00 = nodeY_[n00];
    const double ex = nodeX_[n10] - x00, ey = nodeY_[n10] - y00;
    const double fx = nodeX_[n01] - x00, fy = nodeY_[n01] - y00;
    const double gx = nodeX_[n11] - nodeX_[n10] - nodeX_[n01] + x00;
    const double gy = nodeY_[n11] - nodeY_[n10] - nodeY_[n01] + y00;
    a = 0.5;
    b = 0.5;
    for (int iter = 0; iter < 16; ++iter)
    {
        const double rx = x00 + a * ex + b * fx + a * b * gx - px;
        const double ry = y00 + a * ey + b * fy + a * b * gy - py;
        const double j11 = ex + b * gx, j12 = fx + a * gx, j21 = ey + b * gy, j22 = fy + a * gy;
        const double det = j11 * j22 - j12 * j21;
        if (!(std::abs(det) > 0.0))
            return false;
        const double inv = 1.0 / det;
        const double da = (j22 * rx - j12 * ry) * inv, db = (-j21 * rx + j11 * ry) * inv;
        a -= da;
        b -= db;
        if (!std::isfinite(a) || !std::isfinite(b))
            return false;
        if (std::abs(da) + std::abs(db) < 1e-7)  // quadratic convergence: the error left is ~1e-14
            break;
    }
    return true;
}

bool GriddedCurrentField::locate(double x, double y, double &fi, double &fj) const
{
    if (!curvilinear_)
    {
        const bool inside = x >= xMin_ && x <= xMax_ && y >= yMin_ && y <= yMax_;
        auto frac = [](const Axis &ax, double q) {
            q = std::clamp(q, ax.front(), ax.back());
            const std::size_t k = ax.interval(q);
            return double(k) + (q - ax[k]) / (ax[k + 1] - ax[k]);
        };
        fi = frac(x_, x);
        fj = frac(y_, y);
        return inside;
    }
    const std::size_t cx = nx_ - 1, cy = ny_ - 1;
    // Consecutive queries of one thread are usually in the same or a neighbouring cell (the travel-time code
    // walks along legs): start from the last cell found by this thread in this field when it is close.
    struct Hint
    {
        std::uint64_t field{0};
        std::size_t ci{0}, cj{0};
    };
    thread_local Hint hint;
    constexpr double tol = 1e-10;
    double a = 0.5, b = 0.5;
    std::size_t ci, cj;
    if (hint.field == id_ && hint.ci < cx && hint.cj < cy && cellInside(hint.ci, hint.cj, x, y, a, b) &&
        a > -2.0 && a < 3.0 && b > -2.0 && b < 3.0)
    {
        ci = hint.ci;
        cj = hint.cj;
    }
    else
    {
        const double qx = std::clamp((x - bx0_) * bInv_, 0.0, double(bnx_ - 1));
        const double qy = std::clamp((y - by0_) * bInv_, 0.0, double(bny_ - 1));
        const std::int32_t start = bucket_[static_cast<std::size_t>(qy) * bnx_ + static_cast<std::size_t>(qx)];
        ci = static_cast<std::size_t>(start) % cx;
        cj = static_cast<std::size_t>(start) / cx;
        if (!cellInside(ci, cj, x, y, a, b))
            a = b = std::numeric_limits<double>::quiet_NaN();
    }
    const std::size_t maxSteps = 2 * (nx_ + ny_) + 8;
    for (std::size_t step = 0; step < maxSteps; ++step)
    {
        if (step > 0 && !cellInside(ci, cj, x, y, a, b))
            break;
        if (std::isnan(a))
            break;
        const int di = a < -tol ? -1 : (a > 1 + tol ? 1 : 0);
        const int dj = b < -tol ? -1 : (b > 1 + tol ? 1 : 0);
        if (di == 0 && dj == 0)
        {
            fi = double(ci) + std::clamp(a, 0.0, 1.0);
            fj = double(cj) + std::clamp(b, 0.0, 1.0);
            hint = {id_, ci, cj};
            return true;
        }
        const std::size_t ni = di < 0 ? (ci > 0 ? ci - 1 : ci) : (di > 0 ? std::min(ci + 1, cx - 1) : ci);
        const std::size_t nj = dj < 0 ? (cj > 0 ? cj - 1 : cj) : (dj > 0 ? std::min(cj + 1, cy - 1) : cj);
        if (ni == ci && nj == cj)
            break;  // wants to leave the mesh: outside
        ci = ni;
        cj = nj;
    }
    fi = double(ci) + (std::isfinite(a) ? std::clamp(a, 0.0, 1.0) : 0.5);
    fj = double(cj) + (std::isfinite(b) ? std::clamp(b, 0.0, 1.0) : 0.5);
    return false;
}

GriddedCurrentField::Horizontal GriddedCurrentField::horizontal(double x, double y, bool derivative) const
{
    Horizontal h;
    const Interp1D s = axisScheme(options_.xy);
    if (!curvilinear_)
    {
        h.sx = makeStencil(x_, s, x, derivative);
        h.sy = makeStencil(y_, s, y, derivative);
        return h;
    }
    double fi, fj;
    locate(x, y, fi, fj);
    h.sx = makeStencil(x_, s, fi, derivative);
    h.sy = makeStencil(y_, s, fj, derivative);
    if (!derivative)
        return h;
    // d(x, y)/d(fi, fj) of the cell's bilinear map at (a, b), inverted
    const std::size_t ci = std::min(static_cast<std::size_t>(fi), nx_ - 2);
    const std::size_t cj = std::min(static_cast<std::size_t>(fj), ny_ - 2);
    const double a = fi - double(ci), b = fj - double(cj);
    const std::size_t n00 = cj * nx_ + ci, n10 = n00 + 1, n01 = n00 + nx_, n11 = n01 + 1;
    const double ex = nodeX_[n10] - nodeX_[n00], ey = nodeY_[n10] - nodeY_[n00];
    const double fx = nodeX_[n01] - nodeX_[n00], fy = nodeY_[n01] - nodeY_[n00];
    const double gx = nodeX_[n11] - nodeX_[n10] - nodeX_[n01] + nodeX_[n00];
    const double gy = nodeY_[n11] - nodeY_[n10] - nodeY_[n01] + nodeY_[n00];
    const double j11 = ex + b * gx, j12 = fx + a * gx, j21 = ey + b * gy, j22 = fy + a * gy;
    const double det = j11 * j22 - j12 * j21;
    if (std::abs(det) > 0.0)
    {
        h.m[0] = j22 / det;   // dfi/dx
        h.m[1] = -j12 / det;  // dfi/dy
        h.m[2] = -j21 / det;  // dfj/dx
        h.m[3] = j11 / det;   // dfj/dy
    }
    else
        h.m[0] = h.m[1] = h.m[2] = h.m[3] = 0.0;
    return h;
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
template <typename S, typename F>
S akimaSample(const Axis &axis, double q, F &&f)
{
    const std::size_t n = axis.size();
    if (n == 1)
        return f(std::size_t{0});
    const std::size_t k = axis.interval(std::clamp(q, axis.front(), axis.back()));
    const std::size_t lo = k >= 2 ? k - 2 : 0;
    const std::size_t hi = k + 3 < n ? k + 3 : n - 1;
    double xs[6], us[6], vs[6];
    int m = 0;
    for (std::size_t i = lo; i <= hi; ++i, ++m)
    {
        const S s = f(i);
        xs[m] = axis[i];
        us[m] = s.u;
        vs[m] = s.v;
    }
    S r;
    r.u = detail::akimaFromNodes(xs, us, m, static_cast<int>(k - lo), q);
    r.v = detail::akimaFromNodes(xs, vs, m, static_cast<int>(k - lo), q);
    return r;
}
}  // namespace

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
        {
            const Sample s = spatial<Deriv>(h, it, sz.first + c);
            const double w = sz.w[c];
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
        return r;
    };
    Sample r;
    if (akimaT)
        r = akimaSample<Sample>(time_, tq, atTime);
    else
    {
        const Stencil st = makeStencil(time_, options_.time, tq, false);
        for (int c = 0; c < st.n; ++c)
        {
            const Sample s = atTime(st.first + c);
            const double w = st.w[c];
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
    }
    if (Deriv && curvilinear_)
    {
        const Sample q = r;
        r.ui = q.ui * h.m[0] + q.uj * h.m[2];  // du/dx
        r.uj = q.ui * h.m[1] + q.uj * h.m[3];  // du/dy
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
        return {(xp.u - xm.u) / (2 * hs), (yp.u - ym.u) / (2 * hs), (xp.v - xm.v) / (2 * hs),
                (yp.v - ym.v) / (2 * hs)};
    }
    const Sample s = full<true>(x, y, z, t);
    return {s.ui, s.uj, s.vi, s.vj};
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
    const std::size_t nz = depth_.size();
    auto water = [&](std::size_t k) { return cellWater_[(k * cy + cj) * cx + ci] != 0; };
    if (nz == 1)
        return water(0);
    const double zc = std::isfinite(z) ? std::clamp(z, depth_.front(), depth_.back()) : depth_.front();
    const std::size_t k = depth_.interval(zc);
    const double frac = (zc - depth_[k]) / (depth_[k + 1] - depth_[k]);
    if (frac < 1.0 && !water(k))
        return false;
    if (frac > 0.0 && !water(k + 1))
        return false;
    return true;
}

bool GriddedCurrentField::segmentInWater(double x1, double y1, double x2, double y2, double z) const
{
    if (!inWater(x1, y1, z) || !inWater(x2, y2, z))
        return false;
    // the layers inWater() looks at
    std::size_t k0 = 0, k1 = 0;
    if (depth_.size() > 1)
    {
        const double zc = std::isfinite(z) ? std::clamp(z, depth_.front(), depth_.back()) : depth_.front();
        const std::size_t k = depth_.interval(zc);
        const double frac = (zc - depth_[k]) / (depth_[k + 1] - depth_[k]);
        k0 = frac < 1.0 ? k : k + 1;
        k1 = frac > 0.0 ? k + 1 : k;
    }
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

BeyondForecast parseBeyondForecast(const std::string &name)
{
    std::string s;
    for (char c : name)
        s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
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

double GriddedCurrentField::maxSpeed(const Region &region) const
{
    const std::size_t nz = depth_.size(), nt = time_.size();
    auto range = [](const Axis &ax, double lo, double hi, std::size_t &a, std::size_t &b) {
        if (ax.size() == 1)
        {
            a = b = 0;
            return;
        }
        lo = std::isfinite(lo) ? std::clamp(lo, ax.front(), ax.back()) : ax.front();
        hi = std::isfinite(hi) ? std::clamp(hi, ax.front(), ax.back()) : ax.back();
        if (lo > hi)
            std::swap(lo, hi);
        const std::size_t ka = ax.interval(lo), kb = ax.interval(hi);
        a = ka >= 2 ? ka - 2 : 0;
        b = std::min(ax.size() - 1, kb + 3);
    };
    std::size_t t0, t1, z0, z1;
    double tlo = region.tMin, thi = region.tMax;
    if (std::isnan(tlo))
        tlo = -kInf;
    if (std::isnan(thi))
        thi = kInf;
    range(time_, tlo, thi, t0, t1);
    // All loaded depth layers (the loader keeps only those the glider reaches): planners often leave the region's
    // depth range at 0 while the travel-time code reads the current at another depth.
    z0 = 0;
    z1 = nz - 1;
    (void)nt;
    const bool akima = options_.depth == Interp1D::Akima || options_.time == Interp1D::Akima;
    double ms = 0, mu = 0, mv = 0;
    for (std::size_t it = t0; it <= t1; ++it)
        for (std::size_t k = z0; k <= z1; ++k)
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
    const double data = ms + D * (0.5 * (lamXY_ - 1.0) + 0.5 * (lamZ_ - 1.0) * lamXY_ + 0.5 * (lamT_ - 1.0) * lamXY_ * lamZ_);
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
    const float inf = std::numeric_limits<float>::infinity();
    for (std::size_t bj = 0; bj < b.nbj; ++bj)
        for (std::size_t bi = 0; bi < b.nbi; ++bi)
        {
            const std::size_t k = bi + bj * b.nbi;
            const std::size_t i0 = bi * B, i1 = std::min(cx, (bi + 1) * B), j0 = bj * B, j1 = std::min(cy, (bj + 1) * B);
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
                float a = inf, c = -inf, d = inf, e = -inf;
                for (std::size_t iz = 0; iz < nz; ++iz)
                    for (std::size_t j = j0; j <= j1; ++j)
                    {
                        const float *row = &uv_[2 * (((it * nz + iz) * ny_ + j) * nx_)];
                        for (std::size_t i = i0; i <= i1; ++i)
                        {
                            a = std::min(a, row[2 * i]);
                            c = std::max(c, row[2 * i]);
                            d = std::min(d, row[2 * i + 1]);
                            e = std::max(e, row[2 * i + 1]);
                        }
                    }
                float *out = &b.ext[4 * (it * nb + k)];
                out[0] = a;
                out[1] = c;
                out[2] = d;
                out[3] = e;
                float *g = &b.all[4 * it];
                if (k == 0)
                {
                    g[0] = a;
                    g[1] = c;
                    g[2] = d;
                    g[3] = e;
                }
                else
                {
                    g[0] = std::min(g[0], a);
                    g[1] = std::max(g[1], c);
                    g[2] = std::min(g[2], d);
                    g[3] = std::max(g[3], e);
                }
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
    auto bucketRange = [&](double lo, double hi, double o, double d, std::size_t n, std::size_t &a, std::size_t &c) {
        a = static_cast<std::size_t>(std::clamp(std::floor((lo - o) / d), 0.0, double(n - 1)));
        c = static_cast<std::size_t>(std::clamp(std::floor((hi - o) / d), 0.0, double(n - 1)));
    };
    for (std::size_t k = 0; k < nb; ++k)
    {
        std::size_t a0, a1, c0, c1;
        bucketRange(b.box[4 * k], b.box[4 * k + 1], b.bx0, b.bdx, b.bnx, a0, a1);
        bucketRange(b.box[4 * k + 2], b.box[4 * k + 3], b.by0, b.bdy, b.bny, c0, c1);
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
        lo = std::isfinite(lo) ? std::clamp(lo, ax.front(), ax.back()) : ax.front();
        hi = std::isfinite(hi) ? std::clamp(hi, ax.front(), ax.back()) : ax.back();
        a = ax.interval(lo);
        b = std::min(ax.size() - 1, ax.interval(hi) + 1);
    };
    std::size_t i0, i1, j0, j1, t0, t1;
    range(time_, std::isnan(region.tMin) ? -kInf : region.tMin, std::isnan(region.tMax) ? kInf : region.tMax, t0,
          t1);
    const std::size_t nz = depth_.size();
    float a = std::numeric_limits<float>::infinity(), b = -a, c = a, d = -a;
    auto finish = [&] {
        // (the interpolation's weights are rounded: a relative margin as in maxSpeed())
        const double m = 1e-9 * std::max({std::abs(a), std::abs(b), std::abs(c), std::abs(d)}) + 1e-300;
        uMin = a - m;
        uMax = b + m;
        vMin = c - m;
        vMax = d + m;
        return true;
    };
    if (curvilinear_)
    {
        const Blocks &B = blocks_;
        const std::size_t nb = B.nbi * B.nbj;
        auto whole = [&] {
            for (std::size_t it = t0; it <= t1; ++it)
            {
                const float *g = &B.all[4 * it];
                a = std::min(a, g[0]);
                b = std::max(b, g[1]);
                c = std::min(c, g[2]);
                d = std::max(d, g[3]);
            }
            return finish();
        };
        const double rx0 = region.xMin, rx1 = region.xMax, ry0 = region.yMin, ry1 = region.yMax;
        if (!(rx0 >= xMin_ && rx1 <= xMax_ && ry0 >= yMin_ && ry1 <= yMax_ && rx0 <= rx1 && ry0 <= ry1))
            return whole();  // reaches beyond the nodes (or not finite): points outside the grid are clamped
        double fi, fj;
        if (!locate(0.5 * (rx0 + rx1), 0.5 * (ry0 + ry1), fi, fj))
            return whole();
        auto bucket = [](double q, double o, double dq, std::size_t n) {
            return static_cast<std::size_t>(std::clamp(std::floor((q - o) / dq), 0.0, double(n - 1)));
        };
        const std::size_t a0 = bucket(rx0, B.bx0, B.bdx, B.bnx), a1 = bucket(rx1, B.bx0, B.bdx, B.bnx);
        const std::size_t c0 = bucket(ry0, B.by0, B.bdy, B.bny), c1 = bucket(ry1, B.by0, B.bdy, B.bny);
        std::vector<std::uint32_t> hit;
        for (std::size_t cc = c0; cc <= c1; ++cc)
            for (std::size_t aa = a0; aa <= a1; ++aa)
                for (const std::uint32_t k : B.buckets[aa + cc * B.bnx])
                {
                    const double *bx = &B.box[4 * k];
                    if (bx[0] > rx1 || bx[1] < rx0 || bx[2] > ry1 || bx[3] < ry0)
                        continue;
                    if (B.edge[k])
                        return whole();  // the region may reach outside the grid
                    hit.push_back(k);
                }
        if (hit.empty())
            return whole();
        for (std::size_t it = t0; it <= t1; ++it)
            for (const std::uint32_t k : hit)
            {
                const float *e = &B.ext[4 * (it * nb + k)];
                a = std::min(a, e[0]);
                b = std::max(b, e[1]);
                c = std::min(c, e[2]);
                d = std::max(d, e[3]);
            }
        return finish();
    }
    range(x_, region.xMin, region.xMax, i0, i1);
    range(y_, region.yMin, region.yMax, j0, j1);
    for (std::size_t it = t0; it <= t1; ++it)
        for (std::size_t k = 0; k < nz; ++k)  // all loaded layers, as maxSpeed()
            for (std::size_t j = j0; j <= j1; ++j)
            {
                const float *row = &uv_[2 * (((it * nz + k) * ny_ + j) * nx_)];
                for (std::size_t i = i0; i <= i1; ++i)
                {
                    a = std::min(a, row[2 * i]);
                    b = std::max(b, row[2 * i]);
                    c = std::min(c, row[2 * i + 1]);
                    d = std::max(d, row[2 * i + 1]);
                }
            }
    return finish();
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
    return uv_.size() * sizeof(float) + cellWater_.size() + coast_->memoryBytes() + (nodeX_.size() + nodeY_.size()) * sizeof(double) +
           bucket_.size() * sizeof(std::int32_t) + (x_.size() + y_.size() + depth_.size() + time_.size()) * sizeof(double);
}
}  // namespace ompl_glider
