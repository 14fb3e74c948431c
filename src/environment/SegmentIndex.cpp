// Segments in a bucket index and distances to them (see SegmentIndex.h).
#include "SegmentIndex.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace environment_detail
{
namespace
{

double orient(Point2 a, Point2 b, Point2 c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}
bool onSegment(Point2 p, Point2 a, Point2 b)
{
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}
int sign(double v)
{
    return (v > 0) - (v < 0);
}
} // namespace

double pointSegmentDistance(Point2 p, Point2 a, Point2 b)
{
    const double ex = b.x - a.x, ey = b.y - a.y, ll = ex * ex + ey * ey;
    double s = ll > 0.0 ? ((p.x - a.x) * ex + (p.y - a.y) * ey) / ll : 0.0;
    s = std::clamp(s, 0.0, 1.0);
    return std::hypot(p.x - (a.x + s * ex), p.y - (a.y + s * ey));
}

double segmentDistance(Point2 p, Point2 q, Point2 a, Point2 b)
{
    const int o1 = sign(orient(p, q, a)), o2 = sign(orient(p, q, b)), o3 = sign(orient(a, b, p)),
              o4 = sign(orient(a, b, q));
    if (o1 != o2 && o3 != o4)
        return 0.0;
    if ((o1 == 0 && onSegment(a, p, q)) || (o2 == 0 && onSegment(b, p, q)) || (o3 == 0 && onSegment(p, a, b)) ||
        (o4 == 0 && onSegment(q, a, b)))
        return 0.0;
    return std::min({pointSegmentDistance(p, a, b), pointSegmentDistance(q, a, b), pointSegmentDistance(a, p, q),
                     pointSegmentDistance(b, p, q)});
}

SegmentIndex::SegmentIndex(std::vector<Segment2> segments, double cellHint) : segments_(std::move(segments))
{
    if (segments_.empty())
        return;
    double x1 = -kInf, y1 = -kInf, len = 0.0;
    x0_ = y0_ = kInf;
    for (const Segment2 &s : segments_)
    {
        x0_ = std::min({x0_, s.a.x, s.b.x});
        y0_ = std::min({y0_, s.a.y, s.b.y});
        x1 = std::max({x1, s.a.x, s.b.x});
        y1 = std::max({y1, s.a.y, s.b.y});
        len += std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
    }
    const double w = std::max(x1 - x0_, 1e-300), h = std::max(y1 - y0_, 1e-300);
    diag_ = std::hypot(w, h);
    // buckets: about the mean segment length (or the hint), at most 2^20 of them
    double side = cellHint > 0.0 ? cellHint : len / double(segments_.size());
    side = std::max({side, std::sqrt(w * h / double(1u << 20)), 1e-9 * diag_});
    if (!std::isfinite(side) || !(side > 0.0))
        side = 1.0;
    side_ = side;
    nx_ = static_cast<std::size_t>(std::min(w / side_, 4096.0 * 1024.0)) + 1;
    ny_ = static_cast<std::size_t>(std::min(h / side_, 4096.0 * 1024.0)) + 1;
    while (nx_ * ny_ > (std::size_t(1) << 22))
    {
        side_ *= 2.0;
        nx_ = static_cast<std::size_t>(w / side_) + 1;
        ny_ = static_cast<std::size_t>(h / side_) + 1;
    }
    start_.assign(nx_ * ny_ + 1, 0);
    auto each = [&](const Segment2 &s, auto &&f) {
        const std::size_t i0 = column(std::min(s.a.x, s.b.x)), i1 = column(std::max(s.a.x, s.b.x));
        const std::size_t j0 = row(std::min(s.a.y, s.b.y)), j1 = row(std::max(s.a.y, s.b.y));
        for (std::size_t j = j0; j <= j1; ++j)
            for (std::size_t i = i0; i <= i1; ++i)
                f(j * nx_ + i);
    };
    for (const Segment2 &s : segments_)
        each(s, [&](std::size_t b) { ++start_[b + 1]; });
    for (std::size_t b = 0; b + 1 < start_.size(); ++b)
        start_[b + 1] += start_[b];
    ids_.assign(start_.back(), 0);
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t id = 0; id < segments_.size(); ++id)
        each(segments_[id], [&](std::size_t b) { ids_[fill[b]++] = static_cast<std::uint32_t>(id); });
}

std::size_t SegmentIndex::column(double x) const
{
    const double q = (x - x0_) / side_;
    return !(q > 0.0) ? 0 : std::min(nx_ - 1, static_cast<std::size_t>(std::min(q, 1e15)));
}

std::size_t SegmentIndex::row(double y) const
{
    const double q = (y - y0_) / side_;
    return !(q > 0.0) ? 0 : std::min(ny_ - 1, static_cast<std::size_t>(std::min(q, 1e15)));
}

double SegmentIndex::within(Point2 p, Point2 q, double radius) const
{
    if (segments_.empty())
        return kInf;
    const std::size_t i0 = column(std::min(p.x, q.x) - radius), i1 = column(std::max(p.x, q.x) + radius);
    const std::size_t j0 = row(std::min(p.y, q.y) - radius), j1 = row(std::max(p.y, q.y) + radius);
    double best = kInf;
    if ((i1 - i0 + 1) * (j1 - j0 + 1) > segments_.size())
    {
        for (const Segment2 &s : segments_)
            best = std::min(best, segmentDistance(p, q, s.a, s.b));
        return best;
    }
    // only the buckets the segment pq, widened by radius, can reach: per column, the rows its y range covers
    const double dx = q.x - p.x, dy = q.y - p.y;
    for (std::size_t i = i0; i <= i1; ++i)
    {
        std::size_t r0 = j0, r1 = j1;
        if (std::abs(dx) > 0.0)
        {
            const double xa = x0_ + double(i) * side_ - radius, xb = x0_ + double(i + 1) * side_ + radius;
            const double sa = std::clamp((xa - p.x) / dx, 0.0, 1.0), sb = std::clamp((xb - p.x) / dx, 0.0, 1.0);
            const double ya = p.y + sa * dy, yb = p.y + sb * dy;
            r0 = std::max(j0, row(std::min(ya, yb) - radius));
            r1 = std::min(j1, row(std::max(ya, yb) + radius));
        }
        for (std::size_t j = r0; j <= r1; ++j)
            for (std::uint32_t k = start_[j * nx_ + i]; k < start_[j * nx_ + i + 1]; ++k)
            {
                const Segment2 &s = segments_[ids_[k]];
                best = std::min(best, segmentDistance(p, q, s.a, s.b));
                if (best == 0.0)
                    return 0.0;
            }
    }
    return best;
}

double SegmentIndex::distance(Point2 p, Point2 q) const
{
    if (segments_.empty())
        return kInf;
    for (double r = side_; r < 4.0 * diag_ + 4.0 * std::hypot(q.x - p.x, q.y - p.y); r *= 4.0)
    {
        const double d = within(p, q, r);
        if (d <= r)
            return d;
    }
    double best = kInf;
    for (const Segment2 &s : segments_)
        best = std::min(best, segmentDistance(p, q, s.a, s.b));
    return best;
}
} // namespace environment_detail
} // namespace ompl_glider
