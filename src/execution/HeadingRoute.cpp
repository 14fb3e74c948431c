// A route of held headings flown segment by segment with the one dive integrator (see HeadingRoute.h).
#include "ompl_glider/execution/HeadingRoute.h"

#include <algorithm>
#include <cmath>

namespace ompl_glider
{
double bearingOf(double dx, double dy)
{
    double b = std::atan2(dx, dy) * 180.0 / 3.14159265358979323846;
    if (b < 0.0)
        b += 360.0;
    return b >= 360.0 ? 0.0 : b;
}

HeadingFlight flyHeadingRoute(const HeadingRoute &route, const CurrentField &field, const Environment *forbidden,
                              const DiveSettings &settings, bool keepTrack)
{
    HeadingFlight f;
    double x = route.start.x, y = route.start.y, t = route.departure;
    f.ends.push_back({x, y, t});
    if (keepTrack)
        f.track.push_back({x, y, t});
    if (settings.radius > 0.0)
    {
        f.closestDistance = std::hypot(x - settings.goal.x, y - settings.goal.y);
        f.closestTime = t;
        if (f.closestDistance <= settings.radius)
        {
            f.reached = true;
            f.arrivalTime = t;
            return f;
        }
    }
    for (const HeadingSegment &seg : route.segments)
    {
        if (!(seg.duration > 0.0))
            continue;
        const Point2 h = bearingVector(seg.bearing);
        ++f.segmentsFlown;
        const DiveEnd e =
            flyHeading(x, y, t, h.x, h.y, t + seg.duration, field, forbidden, settings, keepTrack ? &f.track : nullptr);
        if (e.closestDistance < f.closestDistance)
        {
            f.closestDistance = e.closestDistance;
            f.closestTime = e.closestTime;
        }
        x = e.x;
        y = e.y;
        t = e.t;
        if (e.reached)
        {
            // the arrival: the first point of the last step's chord within the radius
            f.reached = true;
            f.arrivalTime = e.arrivalTime;
            if (keepTrack)
                f.track.back() = e.arrival;
            f.ends.push_back(e.arrival);
            return f;
        }
        f.ends.push_back({x, y, t});
        if (e.grounded)
        {
            f.grounded = true;
            f.why = e.why;
            return f;
        }
    }
    return f;
}
} // namespace ompl_glider
