// The band within the keep-off distance of land (see KeepOffZone.h).
#include "ompl_glider/environment/KeepOffZone.h"

#include <cmath>

#include "SegmentIndex.h"
#include "ompl_glider/Exception.h"
#include "../io/NumberText.h"

namespace ompl_glider
{
using environment_detail::SegmentIndex;

KeepOffZone::KeepOffZone(std::vector<Segment2> edges, double distance, std::string name)
    : ForbiddenRegion(std::move(name), "keep-off zone"), d_(distance)
{
    if (!(distance >= 0.0) || !std::isfinite(distance))
        throw Error("keep-off distance must be finite and >= 0, got " + text::number(distance));
    index_ = std::make_unique<SegmentIndex>(std::move(edges), distance);
}

KeepOffZone::~KeepOffZone() = default;

bool KeepOffZone::empty() const
{
    return index_->empty();
}

bool KeepOffZone::pointFree(double x, double y, double) const
{
    if (!std::isfinite(x) || !std::isfinite(y))
        return false;
    return !(d_ > 0.0) || index_->within({x, y}, {x, y}, d_) >= d_;
}

bool KeepOffZone::legFree(double x1, double y1, double t1, double x2, double y2, double t2) const
{
    if (!std::isfinite(x1) || !std::isfinite(y1) || !std::isfinite(x2) || !std::isfinite(y2) || !std::isfinite(t1) ||
        !std::isfinite(t2))
        return false;
    return !(d_ > 0.0) || index_->within({x1, y1}, {x2, y2}, d_) >= d_;
}

std::string KeepOffZone::whyBlocked(double x, double y, double t) const
{
    if (pointFree(x, y, t))
        return {};
    const auto length = [&](double d) {
        if (!(metresPerUnit_ > 0.0))
            return text::number(d);
        const double m = d * metresPerUnit_;
        return m >= 1000.0 ? text::number(m / 1000.0, 4) + " km" : text::number(m, 4) + " m";
    };
    return "within the keep-off distance " + length(d_) + " of " + name() + " (" + length(distanceTo(x, y)) + " away)";
}

double KeepOffZone::distanceTo(double x, double y) const
{
    return index_->distance({x, y}, {x, y});
}

double KeepOffZone::legDistance(double x1, double y1, double x2, double y2) const
{
    return index_->distance({x1, y1}, {x2, y2});
}

LandApproach closestApproach(const KeepOffZone &zone, const std::vector<TimedPoint> &route)
{
    LandApproach c;
    if (zone.empty() || route.empty())
        return c;
    c.distance = zone.distanceTo(route.front().x, route.front().y);
    c.where = {route.front().x, route.front().y};
    for (std::size_t k = 1; k < route.size(); ++k)
    {
        const TimedPoint &a = route[k - 1], &b = route[k];
        const double d = zone.legDistance(a.x, a.y, b.x, b.y);
        if (d < c.distance)
        {
            // the leg's point nearest to land: a few golden-section steps on the distance along the leg
            c.distance = d;
            double lo = 0.0, hi = 1.0;
            for (int i = 0; i < 60; ++i)
            {
                const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
                const double d1 = zone.distanceTo(a.x + m1 * (b.x - a.x), a.y + m1 * (b.y - a.y));
                const double d2 = zone.distanceTo(a.x + m2 * (b.x - a.x), a.y + m2 * (b.y - a.y));
                (d1 < d2 ? hi : lo) = d1 < d2 ? m2 : m1;
            }
            const double s = 0.5 * (lo + hi);
            c.where = {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)};
        }
    }
    return c;
}
} // namespace ompl_glider
