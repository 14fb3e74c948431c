// The boundary edges of the water of a gridded field and their bucket index (see CoastEdges.h).
#include "CoastEdges.h"

#include <algorithm>
#include <cmath>

namespace ompl_glider
{
namespace detail
{
namespace
{
/// A count of buckets from a real number: 1 for anything not finite, at most 2^14.
std::size_t bucketCount(double q)
{
    return std::isfinite(q) ? static_cast<std::size_t>(std::clamp(std::ceil(q), 1.0, 16384.0)) : std::size_t{1};
}

/// The bucket of coordinate v along an axis from o with inverse size inv and n buckets (NaN and far values
/// clamped).
std::size_t bucketOf(double v, double o, double inv, std::size_t n)
{
    const double q = (v - o) * inv;
    if (!(q > 0.0))
        return 0;
    return q >= double(n - 1) ? n - 1 : static_cast<std::size_t>(q);
}
} // namespace

void CoastEdges::build(std::size_t nx, std::size_t ny, std::size_t nz, const std::vector<std::uint8_t> &cellWater,
                       const NodeXY &node, double x0, double x1, double y0, double y1)
{
    const std::size_t cx = nx - 1, cy = ny - 1;
    layers_.assign(nz, {});
    // buckets: about one per 4 cells, square, over the nodes' bounding box
    const double w = std::max(x1 - x0, 1e-300), h = std::max(y1 - y0, 1e-300);
    const double cells = std::max<double>(1.0, double(cx) * double(cy) / 4.0);
    const double side = std::sqrt(w * h / cells);
    bnx_ = bucketCount(w / side);
    bny_ = bucketCount(h / side);
    x0_ = x0;
    y0_ = y0;
    inv_ = std::min(double(bnx_) / w, double(bny_) / h); // 0 for an infinite extent: one bucket holds all
    if (!std::isfinite(inv_) || !(inv_ >= 0.0))
        inv_ = 0.0;
    bnx_ = bucketCount(w * inv_) + 1;
    bny_ = bucketCount(h * inv_) + 1;

    auto pushEdge = [&](Layer &L, std::size_t n1, std::size_t n2) {
        Edge e{};
        node(n1, e.ax, e.ay);
        node(n2, e.bx, e.by);
        L.edges.push_back(e);
    };
    for (std::size_t k = 0; k < nz; ++k)
    {
        Layer &L = layers_[k];
        auto wet = [&](std::size_t i, std::size_t j) { return cellWater[(k * cy + j) * cx + i] != 0; };
        // edges between cells (i-1, j) and (i, j): the node column i, from row j to j + 1; and the outer columns
        for (std::size_t j = 0; j < cy; ++j)
            for (std::size_t i = 0; i <= cx; ++i)
            {
                const bool left = i > 0 && wet(i - 1, j), right = i < cx && wet(i, j);
                if (left != right)
                    pushEdge(L, j * nx + i, (j + 1) * nx + i);
            }
        for (std::size_t j = 0; j <= cy; ++j)
            for (std::size_t i = 0; i < cx; ++i)
            {
                const bool below = j > 0 && wet(i, j - 1), above = j < cy && wet(i, j);
                if (below != above)
                    pushEdge(L, j * nx + i, j * nx + i + 1);
            }
        // bucket index (counting sort of the edges' bounding boxes)
        const std::size_t nb = bnx_ * bny_;
        L.start.assign(nb + 1, 0);
        auto range = [&](const Edge &e, std::size_t &i0, std::size_t &i1, std::size_t &j0, std::size_t &j1) {
            i0 = bucketOf(std::min(e.ax, e.bx), x0_, inv_, bnx_);
            i1 = bucketOf(std::max(e.ax, e.bx), x0_, inv_, bnx_);
            j0 = bucketOf(std::min(e.ay, e.by), y0_, inv_, bny_);
            j1 = bucketOf(std::max(e.ay, e.by), y0_, inv_, bny_);
        };
        for (const Edge &e : L.edges)
        {
            std::size_t i0, i1, j0, j1;
            range(e, i0, i1, j0, j1);
            for (std::size_t bj = j0; bj <= j1; ++bj)
                for (std::size_t bi = i0; bi <= i1; ++bi)
                    ++L.start[bj * bnx_ + bi + 1];
        }
        for (std::size_t b = 0; b < nb; ++b)
            L.start[b + 1] += L.start[b];
        L.ids.assign(L.start[nb], 0);
        std::vector<std::uint32_t> fill(L.start.begin(), L.start.end() - 1);
        for (std::size_t id = 0; id < L.edges.size(); ++id)
        {
            std::size_t i0, i1, j0, j1;
            range(L.edges[id], i0, i1, j0, j1);
            for (std::size_t bj = j0; bj <= j1; ++bj)
                for (std::size_t bi = i0; bi <= i1; ++bi)
                    L.ids[fill[bj * bnx_ + bi]++] = static_cast<std::uint32_t>(id);
        }
    }
}

namespace
{
double cross(double ax, double ay, double bx, double by)
{
    return ax * by - ay * bx;
}

/// Parameters s of segment P + s r (s in [0, 1]) where it meets edge A + u e (u in [0, 1]).
void meetEdge(double px, double py, double rx, double ry, double ax, double ay, double ex, double ey,
              std::vector<double> &out)
{
    const double rr = rx * rx + ry * ry, ee = ex * ex + ey * ey;
    const double d = cross(rx, ry, ex, ey);
    const double qx = ax - px, qy = ay - py;
    const double tol = 1e-12;
    if (std::abs(d) > tol * std::sqrt(rr * ee))
    {
        const double s = cross(qx, qy, ex, ey) / d, u = cross(qx, qy, rx, ry) / d;
        if (s >= -tol && s <= 1.0 + tol && u >= -tol && u <= 1.0 + tol)
            out.push_back(std::clamp(s, 0.0, 1.0));
        return;
    }
    // parallel: an overlap only when collinear
    if (std::abs(cross(qx, qy, rx, ry)) > tol * std::sqrt(rr) * std::sqrt(qx * qx + qy * qy + ee))
        return;
    const double sa = (qx * rx + qy * ry) / rr, sb = ((qx + ex) * rx + (qy + ey) * ry) / rr;
    const double lo = std::max(0.0, std::min(sa, sb)), hi = std::min(1.0, std::max(sa, sb));
    if (lo <= hi)
    {
        out.push_back(lo);
        out.push_back(hi);
    }
}
} // namespace

void CoastEdges::meet(std::size_t k, double ax, double ay, double bx, double by, std::vector<double> &s) const
{
    const Layer &L = layers_[k];
    if (L.edges.empty())
        return;
    const double rx = bx - ax, ry = by - ay;
    if (rx == 0.0 && ry == 0.0)
        return;
    auto col = [&](double x) { return bucketOf(x, x0_, inv_, bnx_); };
    auto row = [&](double y) { return bucketOf(y, y0_, inv_, bny_); };
    const std::size_t c0 = col(std::min(ax, bx)), c1 = col(std::max(ax, bx));
    // the candidate edges: a scratch list per thread, so a leg check allocates nothing once it has grown
    thread_local std::vector<std::uint32_t> seen;
    seen.clear();
    for (std::size_t c = c0; c <= c1; ++c)
    {
        // the part of the segment within this column of buckets (a little wider, so nothing at a border is lost)
        double ylo = std::min(ay, by), yhi = std::max(ay, by);
        if (rx != 0.0 && inv_ > 0.0)
        {
            const double cxa = x0_ + double(c) / inv_, cxb = x0_ + double(c + 1) / inv_;
            const double sa = std::clamp((cxa - ax) / rx, 0.0, 1.0), sb = std::clamp((cxb - ax) / rx, 0.0, 1.0);
            const double ya = ay + sa * ry, yb = ay + sb * ry;
            ylo = std::min(ya, yb);
            yhi = std::max(ya, yb);
        }
        const double pad = inv_ > 0.0 ? 1e-9 / inv_ : 0.0;
        const std::size_t r0 = row(ylo - pad), r1 = row(yhi + pad);
        const std::size_t cl = c > 0 ? c - 1 : c, ch = std::min(bnx_ - 1, c + 1);
        for (std::size_t r = r0; r <= r1; ++r)
            for (std::size_t cc = (c == c0 ? cl : c); cc <= (c == c1 ? ch : c); ++cc)
                for (std::uint32_t q = L.start[r * bnx_ + cc]; q < L.start[r * bnx_ + cc + 1]; ++q)
                    seen.push_back(L.ids[q]);
    }
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    for (std::uint32_t id : seen)
    {
        const Edge &e = L.edges[id];
        meetEdge(ax, ay, rx, ry, e.ax, e.ay, e.bx - e.ax, e.by - e.ay, s);
    }
}

std::size_t CoastEdges::memoryBytes() const
{
    std::size_t b = 0;
    for (const Layer &L : layers_)
        b += L.edges.size() * sizeof(Edge) + (L.start.size() + L.ids.size()) * sizeof(std::uint32_t);
    return b;
}
} // namespace detail
} // namespace ompl_glider
