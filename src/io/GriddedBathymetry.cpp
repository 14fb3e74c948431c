// Seafloor depth from a NetCDF grid (see GriddedBathymetry.h), read by readDepthGrid (DepthGrid.h).
#include "ompl_glider/io/GriddedBathymetry.h"

#include <algorithm>
#include <cmath>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
/// Index k with a[k] <= q <= a[k+1] (clamped) and the fraction.
void locate(const std::vector<double> &a, double q, std::size_t &k, double &f)
{
    if (a.size() == 1)
    {
        k = 0;
        f = 0;
        return;
    }
    q = std::clamp(q, a.front(), a.back());
    k = static_cast<std::size_t>(std::upper_bound(a.begin(), a.end(), q) - a.begin());
    k = k == 0 ? 0 : std::min(k - 1, a.size() - 2);
    f = (q - a[k]) / (a[k + 1] - a[k]);
}
} // namespace

GriddedBathymetry::GriddedBathymetry(const std::string &path, const std::string &variable,
                                     std::function<LonLat(double, double)> toGeographic, const GeoBox &region)
    : toGeographic_(std::move(toGeographic))
{
    // the one reader of seafloor depths (its sign rule, axis order and checks are the depth limit's too)
    const DepthGrid g = readDepthGrid(path, variable, region);
    if (!g.rectilinear)
        throw Error("NetCDF file '" + path + "': the bathymetry '" + g.variable +
                    "' is on 2-D longitude/latitude: dive profiles read a grid on 1-D axes");
    geographic_ = g.geographic;
    variable_ = g.variable;
    convention_ = g.convention;
    ax_.assign(g.a.begin(), g.a.begin() + static_cast<long>(g.nx));
    for (std::size_t j = 0; j < g.ny; ++j)
        ay_.push_back(g.b[j * g.nx]);
    depth_.resize(g.depth.size());
    for (std::size_t n = 0; n < g.depth.size(); ++n)
        depth_[n] = std::isnan(g.depth[n]) ? 0.0 : std::max(0.0, g.depth[n]); // fill values and land: depth 0
    if (geographic_ && !toGeographic_)
        throw Error("NetCDF file '" + path + "': the bathymetry '" + g.variable +
                    "' is on longitude/latitude: the mission needs a projection");
}

double GriddedBathymetry::atAxes(double a, double b) const
{
    std::size_t i, j;
    double fx, fy;
    locate(ax_, a, i, fx);
    locate(ay_, b, j, fy);
    const std::size_t nx = ax_.size();
    const std::size_t i1 = std::min(i + 1, nx - 1), j1 = std::min(j + 1, ay_.size() - 1);
    const double d00 = depth_[j * nx + i], d10 = depth_[j * nx + i1], d01 = depth_[j1 * nx + i],
                 d11 = depth_[j1 * nx + i1];
    return (1 - fy) * ((1 - fx) * d00 + fx * d10) + fy * ((1 - fx) * d01 + fx * d11);
}

double GriddedBathymetry::seafloorDepth(double x, double y) const
{
    if (!geographic_)
        return atAxes(x, y);
    const LonLat g = toGeographic_(x, y); // longitude in -180..180: shifted into the axis's own convention
    const double mid = 0.5 * (ax_.front() + ax_.back());
    return atAxes(mid + std::remainder(g.lon - mid, 360.0), g.lat);
}
std::shared_ptr<const Bathymetry> readBathymetry(const std::string &path, const std::string &variable,
                                                 std::function<LonLat(double x, double y)> toGeographic,
                                                 const GeoBox &region)
{
    return std::make_shared<GriddedBathymetry>(path, variable, std::move(toGeographic), region);
}
} // namespace ompl_glider
