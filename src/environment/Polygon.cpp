#include "ompl_glider/environment/Polygon.h"

#include <algorithm>
#include <limits>
#include <cfloat>
#include <cmath>
#include <sstream>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
/// Orientation of c relative to the directed line a->b (twice the signed triangle area), with a rounding filter:
/// values within 8 eps (|t1| + |t2|) of zero are returned as exactly zero (collinear).
inline double orient(double ax, double ay, double bx, double by, double cx, double cy)
{
    const double t1 = (bx - ax) * (cy - ay);
    const double t2 = (by - ay) * (cx - ax);
    const double det = t1 - t2;
    const double bound = 8.0 * DBL_EPSILON * (std::fabs(t1) + std::fabs(t2));
    return std::fabs(det) <= bound ? 0.0 : det;
}

inline int sign(double v)
{
    return (v > 0) - (v < 0);
}

std::vector<Point2> cleanRing(std::vector<Point2> ring, const std::string &name, const std::string &which)
{
    for (std::size_t i = 0; i < ring.size(); ++i)
        if (!std::isfinite(ring[i].x) || !std::isfinite(ring[i].y))
        {
            std::ostringstream os;
            os << "polygon '" << name << "': " << which << " vertex " << i << " has a non-finite coordinate";
            throw Error(os.str());
        }
    std::vector<Point2> out;
    out.reserve(ring.size());
    for (const Point2 &p : ring)
        if (out.empty() || out.back().x != p.x || out.back().y != p.y)
            out.push_back(p);
    while (out.size() > 1 && out.front().x == out.back().x && out.front().y == out.back().y)
        out.pop_back();
    if (out.size() < 3)
        throw Error("polygon '" + name + "': " + which + " needs at least 3 distinct vertices, got " +
                    std::to_string(out.size()));
    return out;
}

/// Whether the closed segments p0-p1 and q0-q1 have a point in common.
bool segmentsMeet(const Point2 &p0, const Point2 &p1, const Point2 &q0, const Point2 &q1)
{
    const double d1 = orient(p0.x, p0.y, p1.x, p1.y, q0.x, q0.y), d2 = orient(p0.x, p0.y, p1.x, p1.y, q1.x, q1.y);
    const double d3 = orient(q0.x, q0.y, q1.x, q1.y, p0.x, p0.y), d4 = orient(q0.x, q0.y, q1.x, q1.y, p1.x, p1.y);
    if (sign(d1) * sign(d2) < 0 && sign(d3) * sign(d4) < 0)
        return true;
    auto on = [](const Point2 &a, const Point2 &b, const Point2 &c, double d) { // c on segment a-b
        return d == 0.0 && c.x >= std::min(a.x, b.x) && c.x <= std::max(a.x, b.x) && c.y >= std::min(a.y, b.y) &&
               c.y <= std::max(a.y, b.y);
    };
    return on(p0, p1, q0, d1) || on(p0, p1, q1, d2) || on(q0, q1, p0, d3) || on(q0, q1, p1, d4);
}

/// A polygon's rings must be simple and must not touch each other: no two edges meet except consecutive edges of
/// one ring at their shared vertex. A sweep over the edges sorted by their smallest x (a coastline of 10^4
/// vertices compares each edge with its few neighbours in x). Throws Error naming the two edges.
void checkSimple(const std::vector<std::vector<Point2>> &rings, const std::string &name)
{
    struct E
    {
        Point2 a, b;
        std::size_t ring, index, size;
    };
    std::vector<E> edges;
    for (std::size_t r = 0; r < rings.size(); ++r)
        for (std::size_t i = 0; i < rings[r].size(); ++i)
            edges.push_back({rings[r][i], rings[r][(i + 1) % rings[r].size()], r, i, rings[r].size()});
    std::sort(edges.begin(), edges.end(),
              [](const E &u, const E &v) { return std::min(u.a.x, u.b.x) < std::min(v.a.x, v.b.x); });
    auto ringName = [&](const E &e) {
        return e.ring == 0 ? std::string("outer ring") : "hole " + std::to_string(e.ring - 1);
    };
    for (std::size_t i = 0; i < edges.size(); ++i)
    {
        const E &u = edges[i];
        const double uMax = std::max(u.a.x, u.b.x);
        for (std::size_t j = i + 1; j < edges.size() && std::min(edges[j].a.x, edges[j].b.x) <= uMax; ++j)
        {
            const E &v = edges[j];
            const bool neighbours =
                u.ring == v.ring && ((u.index + 1) % u.size == v.index || (v.index + 1) % v.size == u.index);
            if (neighbours && u.size > 3)
            {
                // consecutive edges share one vertex; they may not overlap beyond it
                const Point2 &shared = (u.index + 1) % u.size == v.index ? u.b : u.a;
                const Point2 &uFar = (u.index + 1) % u.size == v.index ? u.a : u.b;
                const Point2 &vFar = (u.index + 1) % u.size == v.index ? v.b : v.a;
                if (orient(uFar.x, uFar.y, shared.x, shared.y, vFar.x, vFar.y) != 0.0 ||
                    (vFar.x - shared.x) * (uFar.x - shared.x) + (vFar.y - shared.y) * (uFar.y - shared.y) <= 0.0)
                    continue;
            }
            else if (neighbours ||
                     std::max(std::min(u.a.y, u.b.y), std::min(v.a.y, v.b.y)) >
                         std::min(std::max(u.a.y, u.b.y), std::max(v.a.y, v.b.y)) ||
                     !segmentsMeet(u.a, u.b, v.a, v.b))
                continue;
            std::ostringstream os;
            os << "polygon '" << name << "': " << ringName(u) << " edge " << u.index << " (" << u.a.x << ", " << u.a.y
               << ")-(" << u.b.x << ", " << u.b.y << ") meets " << ringName(v) << " edge " << v.index << " (" << v.a.x
               << ", " << v.a.y << ")-(" << v.b.x << ", " << v.b.y
               << "): a ring must not cross or touch itself or another ring";
            throw Error(os.str());
        }
    }
}

double signedArea(const std::vector<Point2> &r)
{
    double a = 0.0;
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
        a += r[j].x * r[i].y - r[i].x * r[j].y;
    return 0.5 * a;
}
} // namespace

Polygon::Polygon(std::vector<Point2> outer, std::vector<std::vector<Point2>> holes, const std::string &name,
                 RingCheck check)
{
    outer_ = cleanRing(std::move(outer), name, "outer ring");
    {
        std::vector<std::vector<Point2>> rings{outer_};
        for (std::size_t h = 0; h < holes.size(); ++h)
            rings.push_back(cleanRing(holes[h], name, "hole " + std::to_string(h)));
        if (check == RingCheck::strict)
            checkSimple(rings, name);
    }
    const double outerArea = std::fabs(signedArea(outer_));
    if (!(outerArea > 0))
        throw Error("polygon '" + name + "': outer ring has zero area (collinear vertices)");
    area_ = outerArea;
    auto addRing = [this](const std::vector<Point2> &r) {
        for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
            edges_.push_back(Edge{r[j].x, r[j].y, r[i].x, r[i].y});
    };
    addRing(outer_);
    box_ = Box{outer_[0].x, outer_[0].x, outer_[0].y, outer_[0].y};
    for (const Point2 &p : outer_)
    {
        box_.xMin = std::min(box_.xMin, p.x);
        box_.xMax = std::max(box_.xMax, p.x);
        box_.yMin = std::min(box_.yMin, p.y);
        box_.yMax = std::max(box_.yMax, p.y);
    }
    for (std::size_t h = 0; h < holes.size(); ++h)
    {
        std::vector<Point2> r = cleanRing(std::move(holes[h]), name, "hole " + std::to_string(h));
        area_ -= std::fabs(signedArea(r));
        addRing(r);
    }
    holes_ = holes.size();
    if (!(area_ > 0))
        throw Error("polygon '" + name + "': holes cover the whole outer ring (area <= 0)");
    buildIndex();
}

Polygon Polygon::rectangle(double xMin, double yMin, double xMax, double yMax, const std::string &name)
{
    if (!(xMin < xMax) || !(yMin < yMax))
        throw Error("rectangle '" + name + "': expected xMin < xMax and yMin < yMax");
    return Polygon({{xMin, yMin}, {xMax, yMin}, {xMax, yMax}, {xMin, yMax}}, {}, name);
}

Polygon Polygon::regular(double cx, double cy, double r, int n, double phase, const std::string &name)
{
    if (n < 3 || !(r > 0))
        throw Error("regular polygon '" + name + "': expected n >= 3 vertices and radius r > 0");
    std::vector<Point2> ring;
    ring.reserve(n);
    for (int i = 0; i < n; ++i)
    {
        const double a = phase + 2.0 * M_PI * i / n;
        ring.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    }
    return Polygon(std::move(ring), {}, name);
}

void Polygon::buildIndex()
{
    const double w = box_.xMax - box_.xMin, h = box_.yMax - box_.yMin;
    pad_ = 1e-9 * std::max(w, h);
    const std::size_t n = edges_.size();
    if (n <= 32)
    {
        nx_ = ny_ = 1;
    }
    else
    {
        nx_ = std::clamp(static_cast<int>(std::lround(std::sqrt(n * w / h))), 1, 1024);
        ny_ = std::clamp(static_cast<int>(std::lround(std::sqrt(n * h / w))), 1, 1024);
    }
    cellW_ = w / nx_;
    cellH_ = h / ny_;
    std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
    auto forCells = [this](const Edge &e, auto &&f) { forEachCell(e.ax, e.ay, e.bx, e.by, f); };
    for (const Edge &e : edges_)
        forCells(e, [&](std::size_t c) { ++count[c + 1]; });
    for (std::size_t c = 1; c < count.size(); ++c)
        count[c] += count[c - 1];
    cellStart_ = count;
    cellEdges_.assign(count.back(), 0);
    std::vector<std::uint32_t> fill(count.begin(), count.end() - 1);
    for (std::uint32_t i = 0; i < edges_.size(); ++i)
        forCells(edges_[i], [&](std::size_t c) { cellEdges_[fill[c]++] = i; });
}

int Polygon::column(double x) const
{
    const double f = std::floor((x - box_.xMin) / cellW_);
    return f < 0 ? 0 : (f >= nx_ ? nx_ - 1 : static_cast<int>(f));
}

int Polygon::row(double y) const
{
    const double f = std::floor((y - box_.yMin) / cellH_);
    return f < 0 ? 0 : (f >= ny_ ? ny_ - 1 : static_cast<int>(f));
}

bool Polygon::contains(double x, double y) const
{
    if (!std::isfinite(x) || !std::isfinite(y))
        return false;
    if (x < box_.xMin - pad_ || x > box_.xMax + pad_ || y < box_.yMin - pad_ || y > box_.yMax + pad_)
        return false;
    // Candidate edges: the cells of the point's row from its column to the east (those a ray to +x can meet).
    // A per-thread buffer: no allocation per query once it has grown.
    thread_local std::vector<std::uint32_t> cand;
    cand.clear();
    const int r = row(y);
    for (int c = column(x - pad_); c < nx_; ++c)
    {
        const std::size_t cell = static_cast<std::size_t>(r) * nx_ + c;
        cand.insert(cand.end(), cellEdges_.begin() + cellStart_[cell], cellEdges_.begin() + cellStart_[cell + 1]);
    }
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
    bool inside = false;
    for (std::uint32_t i : cand)
    {
        const Edge &e = edges_[i];
        const double o = orient(e.ax, e.ay, e.bx, e.by, x, y);
        if (o == 0.0 && x >= std::min(e.ax, e.bx) && x <= std::max(e.ax, e.bx) && y >= std::min(e.ay, e.by) &&
            y <= std::max(e.ay, e.by))
            return true; // on the boundary: the polygon is closed
        if ((e.ay > y) != (e.by > y))
        {
            const bool upward = e.by > e.ay;
            if ((upward && o > 0) || (!upward && o < 0))
                inside = !inside;
        }
    }
    return inside;
}

double Polygon::signedDistance(double x, double y) const
{
    double best = std::numeric_limits<double>::infinity();
    for (const Edge &e : edges_)
    {
        const double ex = e.bx - e.ax, ey = e.by - e.ay;
        const double len2 = ex * ex + ey * ey;
        double s = len2 > 0.0 ? ((x - e.ax) * ex + (y - e.ay) * ey) / len2 : 0.0;
        s = std::clamp(s, 0.0, 1.0);
        const double dx = x - (e.ax + s * ex), dy = y - (e.ay + s * ey);
        best = std::min(best, dx * dx + dy * dy);
    }
    const double d = std::sqrt(best);
    return contains(x, y) ? d : -d;
}

template <typename F> void Polygon::forEachCell(double ax, double ay, double bx, double by, F &&f) const
{
    // Every cell that the segment, grown by pad_ in every direction, may touch: per row of the grid, the x-range of
    // the segment within the row's (padded) slab.
    const double yLo = std::max(std::min(ay, by), box_.yMin - pad_) - pad_;
    const double yHi = std::min(std::max(ay, by), box_.yMax + pad_) + pad_;
    if (yLo > yHi)
        return;
    const int r0 = row(yLo), r1 = row(yHi);
    for (int r = r0; r <= r1; ++r)
    {
        const double s0 = std::max(std::min(ay, by), box_.yMin + r * cellH_ - pad_);
        const double s1 = std::min(std::max(ay, by), box_.yMin + (r + 1) * cellH_ + pad_);
        double xa = std::min(ax, bx), xb = std::max(ax, bx);
        if (ay != by && s0 <= s1)
        {
            const double k = (bx - ax) / (by - ay);
            const double x0 = ax + (s0 - ay) * k, x1 = ax + (s1 - ay) * k;
            xa = std::max(std::min(x0, x1), xa);
            xb = std::min(std::max(x0, x1), xb);
        }
        const int c0 = column(xa - pad_), c1 = column(xb + pad_);
        for (int c = c0; c <= c1; ++c)
            f(static_cast<std::size_t>(r) * nx_ + c);
    }
}

void Polygon::segmentCandidates(double ax, double ay, double bx, double by, std::vector<std::uint32_t> &out) const
{
    out.clear();
    if (nx_ == 1 && ny_ == 1)
    {
        out.resize(edges_.size());
        for (std::uint32_t i = 0; i < edges_.size(); ++i)
            out[i] = i;
        return;
    }
    forEachCell(ax, ay, bx, by, [&](std::size_t cell) {
        out.insert(out.end(), cellEdges_.begin() + cellStart_[cell], cellEdges_.begin() + cellStart_[cell + 1]);
    });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

bool Polygon::segmentIntersects(double ax, double ay, double bx, double by) const
{
    if (std::max(ax, bx) < box_.xMin - pad_ || std::min(ax, bx) > box_.xMax + pad_ ||
        std::max(ay, by) < box_.yMin - pad_ || std::min(ay, by) > box_.yMax + pad_)
        return false;
    if (ax == bx && ay == by)
        return contains(ax, ay);
    thread_local std::vector<std::uint32_t> cand; // per-thread buffer (segmentCandidates clears it)
    segmentCandidates(ax, ay, bx, by, cand);
    for (std::uint32_t i : cand)
    {
        const Edge &e = edges_[i];
        const int o1 = sign(orient(ax, ay, bx, by, e.ax, e.ay)), o2 = sign(orient(ax, ay, bx, by, e.bx, e.by));
        if (o1 * o2 > 0)
            continue;
        const int o3 = sign(orient(e.ax, e.ay, e.bx, e.by, ax, ay)), o4 = sign(orient(e.ax, e.ay, e.bx, e.by, bx, by));
        if (o3 * o4 > 0)
            continue;
        if (o1 == 0 && o2 == 0)
        {
            // collinear: overlap of the projections on the segment
            const double dx = bx - ax, dy = by - ay, L2 = dx * dx + dy * dy;
            const double sC = ((e.ax - ax) * dx + (e.ay - ay) * dy) / L2;
            const double sD = ((e.bx - ax) * dx + (e.by - ay) * dy) / L2;
            if (std::max(sC, sD) >= 0.0 && std::min(sC, sD) <= 1.0)
                return true;
            continue;
        }
        return true;
    }
    return contains(ax, ay); // no boundary met: wholly inside or wholly outside
}

std::vector<Interval> Polygon::segmentInsideIntervals(double ax, double ay, double bx, double by) const
{
    std::vector<Interval> result;
    if (std::max(ax, bx) < box_.xMin - pad_ || std::min(ax, bx) > box_.xMax + pad_ ||
        std::max(ay, by) < box_.yMin - pad_ || std::min(ay, by) > box_.yMax + pad_)
        return result;
    if (ax == bx && ay == by)
    {
        if (contains(ax, ay))
            result.push_back({0.0, 1.0});
        return result;
    }
    const double dx = bx - ax, dy = by - ay, L2 = dx * dx + dy * dy;
    std::vector<std::uint32_t> cand;
    segmentCandidates(ax, ay, bx, by, cand);
    std::vector<double> hits;       // parameters where the segment meets the boundary
    std::vector<Interval> overlaps; // parameter ranges where it runs along an edge
    for (std::uint32_t i : cand)
    {
        const Edge &e = edges_[i];
        const double o1 = orient(ax, ay, bx, by, e.ax, e.ay), o2 = orient(ax, ay, bx, by, e.bx, e.by);
        if (sign(o1) * sign(o2) > 0)
            continue;
        const double o3 = orient(e.ax, e.ay, e.bx, e.by, ax, ay), o4 = orient(e.ax, e.ay, e.bx, e.by, bx, by);
        if (sign(o3) * sign(o4) > 0)
            continue;
        if ((o1 == 0 && o2 == 0) || (o3 == 0 && o4 == 0))
        {
            const double sC = ((e.ax - ax) * dx + (e.ay - ay) * dy) / L2;
            const double sD = ((e.bx - ax) * dx + (e.by - ay) * dy) / L2;
            const double lo = std::max(0.0, std::min(sC, sD)), hi = std::min(1.0, std::max(sC, sD));
            if (lo <= hi)
            {
                overlaps.push_back({lo, hi});
                hits.push_back(lo);
                hits.push_back(hi);
            }
            continue;
        }
        hits.push_back(std::clamp(o3 / (o3 - o4), 0.0, 1.0));
    }
    std::vector<double> params = hits;
    params.push_back(0.0);
    params.push_back(1.0);
    std::sort(params.begin(), params.end());
    params.erase(std::unique(params.begin(), params.end()), params.end());
    std::sort(hits.begin(), hits.end());
    auto isHit = [&](double s) { return std::binary_search(hits.begin(), hits.end(), s); };
    auto pointInside = [&](double s) {
        if (isHit(s))
            return true;
        if (s == 0.0)
            return contains(ax, ay);
        if (s == 1.0)
            return contains(bx, by);
        return contains(ax + s * dx, ay + s * dy);
    };
    auto gapInside = [&](double lo, double hi) {
        for (const Interval &o : overlaps)
            if (o.lo <= lo && o.hi >= hi)
                return true;
        const double m = 0.5 * (lo + hi);
        return contains(ax + m * dx, ay + m * dy);
    };
    bool open = false;
    double start = 0.0;
    for (std::size_t i = 0; i < params.size(); ++i)
    {
        const double s = params[i];
        if (!open && pointInside(s))
        {
            open = true;
            start = s;
        }
        if (i + 1 == params.size())
            break;
        if (gapInside(s, params[i + 1]))
        {
            if (!open)
            {
                open = true;
                start = s;
            }
        }
        else if (open)
        {
            result.push_back({start, s});
            open = false;
        }
    }
    if (open)
        result.push_back({start, params.back()});
    return result;
}
} // namespace ompl_glider
