// Node coordinates of the loaded grid: geographic nodes projected with LocalProjection (curvilinear grid of
// projected nodes) and their eastward/northward velocities rotated into x/y; Cartesian axes scaled to metres.
#include <cmath>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
/// Projects every node and rotates its velocities (all loaded times and depths) from east/north into x/y.
void projectNodes(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, const LocalProjection &proj,
                  GriddedData &g)
{
    const std::size_t nx = g.nx, ny = g.ny, nh = nx * ny, nz = g.depth.size(), nt = g.time.size();
    g.nodeX.resize(nh);
    g.nodeY.resize(nh);
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
        {
            const std::size_t n = j * nx + i;
            const double lon = l.curvilinear ? h.nodeLon[n] : h.lon1D[i];
            const double lat = l.curvilinear ? h.nodeLat[n] : h.lat1D[j];
            if (std::abs(lat) > 89.9)
                throw f.error("grid node at latitude " + std::to_string(lat) +
                              " is too close to a pole for a local projection; restrict the region");
            const Point2 p = proj.forward(lon, lat);
            g.nodeX[n] = p.x;
            g.nodeY[n] = p.y;
            double ex, ey, nx_, ny_;
            proj.eastDirection(lon, lat, ex, ey);
            proj.northDirection(lon, lat, nx_, ny_);
            for (std::size_t it = 0; it < nt; ++it)
                for (std::size_t k = 0; k < nz; ++k)
                {
                    const std::size_t idx = (it * nz + k) * nh + n;
                    const double ue = g.u[idx], vn = g.v[idx];
                    g.u[idx] = static_cast<float>(ue * ex + vn * nx_);
                    g.v[idx] = static_cast<float>(ue * ey + vn * ny_);
                }
        }
}

/// Cartesian x/y (any length unit -> metres; dimensionless as they are): 1-D axes or curvilinear nodes.
void cartesianNodes(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, GriddedData &g)
{
    if (l.curvilinear)
    {
        const LinearConversion cx = axisConversion(f, l.lon2D), cy = axisConversion(f, l.lat2D);
        const std::size_t nh = g.nx * g.ny;
        g.nodeX.resize(nh);
        g.nodeY.resize(nh);
        for (std::size_t n = 0; n < nh; ++n)
        {
            g.nodeX[n] = cx(h.nodeLon[n]);
            g.nodeY[n] = cy(h.nodeLat[n]);
        }
        return;
    }
    const LinearConversion cx = axisConversion(f, l.coordVar[std::size_t(l.dimX)]);
    const LinearConversion cy = axisConversion(f, l.coordVar[std::size_t(l.dimY)]);
    for (double v : h.lon1D)
        g.x.push_back(cx(v));
    for (double v : h.lat1D)
        g.y.push_back(cy(v));
}
} // namespace

std::shared_ptr<const LocalProjection> setNodeCoordinates(const GriddedDataset &f, const Layout &l,
                                                          const HorizontalSubset &h, const RegionOfInterest &r,
                                                          const GriddedCurrentOptions &opt, GriddedData &g)
{
    if (!l.geographic)
    {
        cartesianNodes(f, l, h, g);
        return nullptr;
    }
    const double refLon = std::isfinite(opt.refLon) ? opt.refLon : (r.given ? 0.5 * (r.lon0 + r.lon1) : h.centreLon);
    const double refLat =
        std::isfinite(opt.refLat) ? opt.refLat : (r.given ? 0.5 * (r.latMin + r.latMax) : h.centreLat);
    auto proj = std::make_shared<LocalProjection>(refLon, refLat);
    projectNodes(f, l, h, *proj, g);
    return proj;
}
} // namespace gridded_detail
} // namespace ompl_glider
