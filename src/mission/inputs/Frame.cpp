// The planning frame (ProblemInputs.h): lon/lat <-> x/y through the projection, and the planning box the mission's
// inputs are read in.
#include "InputsInternal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "../../core/Numbers.h"
#include "../../io/NumberText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/io/GeoBox.h"

namespace ompl_glider
{
LonLat PlanningFrame::toGeographic(Point2 p) const
{
    if (!projection)
        throw Error(file + ": no projection: longitudes and latitudes are unknown");
    return projection->inverse(p.x * projectionScale, p.y * projectionScale); // longitude in -180..180
}

Point2 PlanningFrame::toLocal(LonLat g) const
{
    if (!projection)
        throw Error(file + ": no projection: longitudes and latitudes cannot be used");
    Point2 p = projection->forward(g.lon, g.lat);
    p.x /= projectionScale;
    p.y /= projectionScale;
    return p;
}

namespace inputs_detail
{
Region planningBox(const ProblemInputs &in)
{
    const MissionSpec &m = in.spec;
    const PlanningFrame &frame = in.frame;
    Region box;
    if (m.region.set && !m.region.geographic)
    {
        box.xMin = m.region.xy.xMin * frame.xyScale; // a Cartesian forecast's region in its own x/y units
        box.xMax = m.region.xy.xMax * frame.xyScale;
        box.yMin = m.region.xy.yMin * frame.xyScale;
        box.yMax = m.region.xy.yMax * frame.xyScale;
    }
    else if (m.region.set)
    {
        // Start and goal in the region, in geographic terms (longitudes in either convention).
        const GeoBox &region = m.region.lonLat;
        for (const auto &[name, p] : {std::pair<const char *, const PointSpec *>{"start", &m.start}, {"goal", &m.goal}})
            if (p->geographic && !region.contains(p->lonLat))
                throw Error(m.place(name) + ": lon,lat " + text::number(p->lonLat.lon) + "," +
                            text::number(p->lonLat.lat) + " lies outside the region (" + m.place("region") + ": " +
                            region.text() + ")");
        // The planning box: the projected bounding box of the region's outline, sampled along its four edges at
        // least every degree (a parallel bows in the plane).
        box.xMin = box.yMin = kInf;
        box.xMax = box.yMax = -kInf;
        const int n = std::max(
            8, static_cast<int>(std::ceil(std::max(region.lonMax - region.lonMin, region.latMax - region.latMin))));
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
            {
                if (i != 0 && i != n && j != 0 && j != n)
                    continue;
                const Point2 q = frame.toLocal({region.lonMin + (region.lonMax - region.lonMin) * i / double(n),
                                                region.latMin + (region.latMax - region.latMin) * j / double(n)});
                box.xMin = std::min(box.xMin, q.x);
                box.xMax = std::max(box.xMax, q.x);
                box.yMin = std::min(box.yMin, q.y);
                box.yMax = std::max(box.yMax, q.y);
            }
    }
    else if (const FieldGrid *g = (in.members.empty() ? in.field : in.members.front())->grid())
    {
        const Region e = g->extent();
        box.xMin = e.xMin;
        box.xMax = e.xMax;
        box.yMin = e.yMin;
        box.yMax = e.yMax;
    }
    else
        throw Error(sourcePlace(m) + "field 'region': missing");
    box.tMin = in.field->timeBegin();
    box.tMax = in.field->timeEnd();
    box.zMin = 0.0;
    box.zMax = m.dive.enabled ? m.dive.params.zMax : m.vehicle.depth;
    return box;
}
} // namespace inputs_detail
} // namespace ompl_glider
