// The region of interest of the options and the index range of an axis that covers it.
#include <algorithm>
#include <cmath>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{
RegionOfInterest regionOfInterest(const GriddedCurrentOptions &opt, bool geographic)
{
    RegionOfInterest r;
    r.given = std::isfinite(opt.lonMin) && std::isfinite(opt.lonMax) && std::isfinite(opt.latMin) &&
              std::isfinite(opt.latMax);
    if (!r.given && (std::isfinite(opt.lonMin) || std::isfinite(opt.lonMax) || std::isfinite(opt.latMin) ||
                     std::isfinite(opt.latMax)))
        throw Error("GriddedCurrentOptions: give all four of lonMin, lonMax, latMin, latMax, or none");
    if (r.given && opt.latMin > opt.latMax)
        throw Error("GriddedCurrentOptions: latMin > latMax");
    r.lonMin = r.lon0 = opt.lonMin;
    r.lonMax = r.lon1 = opt.lonMax;
    if (r.given && geographic && r.lon1 < r.lon0)
        r.lon1 += 360.0; // across the antimeridian
    if (r.given && !geographic && r.lon1 < r.lon0)
        throw Error("GriddedCurrentOptions: lonMin (x) > lonMax (x) in Cartesian mode");
    r.latMin = opt.latMin;
    r.latMax = opt.latMax;
    r.margin = opt.margin;
    r.marginNodes = opt.marginNodes;
    return r;
}

std::optional<std::pair<std::size_t, std::size_t>> indexRange(const std::vector<double> &ax, double lo, double hi,
                                                              int extra)
{
    std::size_t a = ax.size(), b = 0;
    for (std::size_t i = 0; i < ax.size(); ++i)
        if (ax[i] >= lo && ax[i] <= hi)
        {
            a = std::min(a, i);
            b = std::max(b, i);
        }
    if (a == ax.size())
    {
        // region between two nodes: take the bracketing pair
        for (std::size_t i = 0; i + 1 < ax.size(); ++i)
        {
            const double mn = std::min(ax[i], ax[i + 1]), mx = std::max(ax[i], ax[i + 1]);
            if (mn <= hi && mx >= lo)
            {
                a = i;
                b = i + 1;
                break;
            }
        }
        if (a == ax.size())
            return std::nullopt;
    }
    const std::size_t e = static_cast<std::size_t>(std::max(0, extra));
    a = a >= e ? a - e : 0;
    b = std::min(ax.size() - 1, b + e);
    return std::make_pair(a, b);
}

double wrapTo(double lon, double centre)
{
    double d = std::fmod(lon - centre + 180.0, 360.0);
    if (d < 0)
        d += 360.0;
    return centre + d - 180.0;
}
} // namespace gridded_detail
} // namespace ompl_glider
