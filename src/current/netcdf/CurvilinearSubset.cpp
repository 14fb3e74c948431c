// The nodes of a 2-D curvilinear grid that cover the region: the index box of the nodes inside (scanned in row
// blocks, longitudes wrapped about the region's centre), widened by the margin nodes, and their coordinates.
#include <algorithm>
#include <cmath>

#include "NetCdfInternal.h"

namespace ompl_glider
{
namespace netcdf_detail
{
namespace
{
/// Rows j0..j1 and columns i0..i1 (inclusive) of a curvilinear grid.
struct IndexBox
{
    std::size_t j0{0}, j1{0}, i0{0}, i1{0};
};

/// @throws Error when a value of the 2-D coordinate var read as rows from j0 and columns from i0 (nx per row) is a
/// fill value or not finite.
void checkNodeValues(const NcFile &f, int var, const std::vector<double> &v, std::size_t nx, std::size_t j0,
                     std::size_t i0)
{
    const std::size_t k = firstFillOrNonFinite(f, var, v);
    if (k < v.size())
        throw f.error("coordinate '" + f.varName(var) + "' holds fill values or non-finite numbers (" +
                      numText(v[k]) + " at (j, i) = (" + std::to_string(j0 + k / nx) + ", " +
                      std::to_string(i0 + k % nx) + ")); expected finite coordinates");
}

/// Grows box to the nodes of rows [r0, r0 + rows) (values la/lo) that lie in the region (+ margin).
void scanRows(const NcFile &f, const Layout &l, const RegionOfInterest &r, std::size_t r0, std::size_t rows,
              std::size_t nx, IndexBox &box)
{
    const double cLon = 0.5 * (r.lon0 + r.lon1), m = r.margin;
    std::vector<double> la(rows * nx), lo(rows * nx);
    std::size_t st[2] = {r0, 0}, ct[2] = {rows, nx};
    f.check(nc_get_vara_double(f.id(), l.lat2D, st, ct, la.data()), "read '" + l.yName + "'");
    f.check(nc_get_vara_double(f.id(), l.lon2D, st, ct, lo.data()), "read '" + l.xName + "'");
    checkNodeValues(f, l.lat2D, la, nx, r0, 0);
    checkNodeValues(f, l.lon2D, lo, nx, r0, 0);
    for (std::size_t k = 0; k < rows; ++k)
        for (std::size_t i = 0; i < nx; ++i)
        {
            const double y = la[k * nx + i];
            double x = lo[k * nx + i];
            if (l.geographic)
                x = wrapTo(x, cLon);
            if (y >= r.latMin - m && y <= r.latMax + m && x >= r.lon0 - m && x <= r.lon1 + m)
            {
                box.j0 = std::min(box.j0, r0 + k);
                box.j1 = std::max(box.j1, r0 + k);
                box.i0 = std::min(box.i0, i);
                box.i1 = std::max(box.i1, i);
            }
        }
}

/// The index box of the nodes in the region, widened by the margin nodes; the whole grid without region.
IndexBox regionBox(const NcFile &f, const Layout &l, const RegionOfInterest &r)
{
    const std::size_t nx = f.dimLen(l.dims[std::size_t(l.dimX)]), ny = f.dimLen(l.dims[std::size_t(l.dimY)]);
    if (!r.given)
        return {0, ny - 1, 0, nx - 1};
    IndexBox box{ny, 0, nx, 0};
    const std::size_t block = std::max<std::size_t>(1, 1000000 / std::max<std::size_t>(1, nx));
    for (std::size_t r0 = 0; r0 < ny; r0 += block)
        scanRows(f, l, r, r0, std::min(block, ny - r0), nx, box);
    if (box.j0 == ny)
        throw f.error("no node of the curvilinear grid ('" + l.xName + "', '" + l.yName + "') lies in the region [" +
                      std::to_string(r.lonMin) + ", " + std::to_string(r.lonMax) + "] x [" +
                      std::to_string(r.latMin) + ", " + std::to_string(r.latMax) + "]");
    const std::size_t e = std::size_t(std::max(0, r.marginNodes));
    box.j0 = box.j0 >= e ? box.j0 - e : 0;
    box.i0 = box.i0 >= e ? box.i0 - e : 0;
    box.j1 = std::min(ny - 1, box.j1 + e);
    box.i1 = std::min(nx - 1, box.i1 + e);
    return box;
}

/// Bounds and centre of the bounding box of the loaded nodes (longitudes wrapped about ref when geographic).
void setCentre(bool geographic, double ref, HorizontalSubset &h)
{
    double a = kInf, b = -kInf, c = kInf, d = -kInf;
    for (std::size_t k = 0; k < h.nodeLat.size(); ++k)
    {
        const double x = geographic ? wrapTo(h.nodeLon[k], ref) : h.nodeLon[k];
        a = std::min(a, x);
        b = std::max(b, x);
        c = std::min(c, h.nodeLat[k]);
        d = std::max(d, h.nodeLat[k]);
    }
    h.lonLo = a;
    h.lonHi = b;
    h.latLo = c;
    h.latHi = d;
    h.centreLon = 0.5 * (a + b);
    h.centreLat = 0.5 * (c + d);
}
}  // namespace

HorizontalSubset curvilinearSubset(const NcFile &f, const Layout &l, const RegionOfInterest &r, const AxisSelection &z,
                                   const AxisSelection &t)
{
    HorizontalSubset h;
    const IndexBox box = regionBox(f, l, r);
    if (box.i1 - box.i0 < 1 || box.j1 - box.j0 < 1)
        throw f.error("the region covers fewer than 2 grid nodes along a dimension of '" + l.xName + "'");
    checkTripMemory(f, box.i1 - box.i0 + 1, box.j1 - box.j0 + 1, t.idx.size(), z.idx.size());
    for (std::size_t j = box.j0; j <= box.j1; ++j)
        h.yIdx.push_back(j);
    for (std::size_t i = box.i0; i <= box.i1; ++i)
        h.xIdx.push_back(i);
    std::size_t st[2] = {box.j0, box.i0}, ct[2] = {h.yIdx.size(), h.xIdx.size()};
    h.nodeLat.resize(ct[0] * ct[1]);
    h.nodeLon.resize(ct[0] * ct[1]);
    f.check(nc_get_vara_double(f.id(), l.lat2D, st, ct, h.nodeLat.data()), "read '" + l.yName + "'");
    f.check(nc_get_vara_double(f.id(), l.lon2D, st, ct, h.nodeLon.data()), "read '" + l.xName + "'");
    checkNodeValues(f, l.lat2D, h.nodeLat, ct[1], box.j0, box.i0);
    checkNodeValues(f, l.lon2D, h.nodeLon, ct[1], box.j0, box.i0);
    checkCurvilinearNodes(f, l, h);
    const std::size_t mid = (ct[0] / 2) * ct[1] + ct[1] / 2;
    const double ref = r.given ? 0.5 * (r.lon0 + r.lon1) : h.nodeLon[mid];
    setCentre(l.geographic, ref, h);
    return h;
}
}  // namespace netcdf_detail
}  // namespace ompl_glider
