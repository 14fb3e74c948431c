#include "ompl_glider/environment/StaticRegion.h"

#include <cmath>

namespace ompl_glider
{
StaticRegion::StaticRegion(std::string name, Polygon polygon, std::string kind)
    : ForbiddenRegion(std::move(name), std::move(kind)), polygon_(std::move(polygon))
{
}

bool StaticRegion::pointFree(double x, double y, double /*t*/) const
{
    if (!std::isfinite(x) || !std::isfinite(y))
        return false;
    return !polygon_.contains(x, y);
}

bool StaticRegion::legFree(double x1, double y1, double /*t1*/, double x2, double y2, double /*t2*/) const
{
    if (!std::isfinite(x1) || !std::isfinite(y1) || !std::isfinite(x2) || !std::isfinite(y2))
        return false;
    return !polygon_.segmentIntersects(x1, y1, x2, y2);
}
} // namespace ompl_glider
