// The seam of gridded sources (ForecastSource.h): the request's names, a forecast's extent, frame and clock.
#include "ompl_glider/current/ForecastSource.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "../io/NumberText.h"
#include "../io/TextUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/LocalProjection.h"

namespace ompl_glider
{
std::string ForecastRequest::variable(const std::string &role) const
{
    const auto it = variables.find(role);
    return it == variables.end() ? std::string() : it->second;
}

std::string ForecastRequest::optionName(ForecastOption option, const std::string &fallback) const
{
    const auto it = optionNames.find(option);
    return it == optionNames.end() || it->second.empty() ? fallback : it->second;
}

bool ForecastExtent::contains(double a, double b) const
{
    if (!(b >= latMin && b <= latMax))
        return false;
    if (!geographic)
        return a >= lonMin && a <= lonMax;
    // the longitude the shorter way from the centre of the bounds
    const double centre = 0.5 * (lonMin + lonMax);
    double d = std::fmod(a - centre + 180.0, 360.0);
    if (d < 0)
        d += 360.0;
    const double lon = centre + d - 180.0;
    return allLongitudes || (lon >= lonMin - 1e-9 && lon <= lonMax + 1e-9);
}

std::string ForecastExtent::text() const
{
    using ompl_glider::text::number;
    if (!geographic)
        return xName + " " + number(lonMin) + ".." + number(lonMax) + ", " + yName + " " + number(latMin) + ".." +
               number(latMax);
    return (allLongitudes ? std::string("lon all") : "lon " + number(lonMin) + ".." + number(lonMax)) + ", lat " +
           number(latMin) + ".." + number(latMax);
}

double ForecastFrame::fieldTime(const std::string &text) const
{
    const std::string s = text::trim(text);
    char *end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (!s.empty() && end && *end == '\0' && std::isfinite(v))
        return v;
    if (!dated)
        throw Error("time '" + text + "': the forecast has no dated time axis; give a number (field time units)");
    return secondsSinceCalendarEpoch(s, calendar) - originSeconds;
}

std::string ForecastFrame::isoTime(double t) const
{
    if (!dated)
    {
        std::ostringstream os;
        os << t;
        return os.str();
    }
    return formatDateTime(dateFromCalendarEpoch(originSeconds + t, calendar));
}

LonLat ForecastFrame::toGeographic(Point2 p) const
{
    if (projection)
        return projection->inverse(p.x, p.y);
    return {p.x / xyMetres, p.y / xyMetres}; // the file's own x/y units
}

Point2 ForecastFrame::toLocal(LonLat g) const
{
    if (projection)
        return projection->forward(g.lon, g.lat);
    return {g.lon * xyMetres, g.lat * xyMetres};
}
} // namespace ompl_glider
