// The nodes of 1-D longitude/latitude (or x/y) axes that cover the region: ascending or descending axes, 0..360
// or -180..180 longitudes, and global axes cut across their seam (the loaded longitudes are unwrapped); rows
// beyond +-kMaxGridLatitude are left out.
#include <algorithm>
#include <cmath>

#include "GriddedInternal.h"
#include "ompl_glider/ResourceLimits.h"
#include "ompl_glider/io/GeoBox.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
/// Reads the 1-D axis var after the memory check of both axes. @throws Error for fill values, non-finite numbers
/// or values that are not strictly monotonic (longitudes: also across one seam, returned unwrapped).
std::vector<double> readAxis(const GriddedDataset &f, int var, bool longitude)
{
    std::vector<double> raw = f.readAll1D(var);
    checkAxisValues(f, var, raw, "coordinate");
    unpackCoordinates(f, var, raw);
    const std::vector<double> values = longitude ? unwrapLongitudes(raw) : raw;
    checkStrictlyMonotonic(f, values, raw, "coordinate", f.varName(var));
    return values;
}

/// The x and y axes (the memory they need checked first: the value, a copy and an index each).
void readAxes(const GriddedDataset &f, const Layout &l, std::vector<double> &xs, std::vector<double> &ys)
{
    const int xv = l.coordVar[std::size_t(l.dimX)], yv = l.coordVar[std::size_t(l.dimY)];
    const std::size_t nx = f.dimLen(l.dims[std::size_t(l.dimX)]), ny = f.dimLen(l.dims[std::size_t(l.dimY)]);
    checkMemory(3.0 * 8.0 * (double(nx) + double(ny)),
                "NetCDF file '" + f.path() + "': the axes '" + l.xName + "' and '" + l.yName + "' (" +
                    std::to_string(nx) + " and " + std::to_string(ny) + " values)",
                "use a coarser file");
    ys = readAxis(f, yv, false);
    xs = readAxis(f, xv, l.geographic);
}

/// y: the range covering the region (all without region), stored ascending.
void subsetY(const GriddedDataset &f, const Layout &l, const RegionOfInterest &r, const std::vector<double> &ys,
             HorizontalSubset &h)
{
    std::size_t ya = 0, yb = ys.size() - 1;
    if (r.given)
    {
        auto range = indexRange(ys, r.latMin - r.margin, r.latMax + r.margin, r.marginNodes);
        if (!range)
            throw f.error("region " + std::string(l.geographic ? "latitude" : "y") + " [" + std::to_string(r.latMin) +
                              ", " + std::to_string(r.latMax) + "] is outside '" + l.yName + "' [" +
                              std::to_string(*std::min_element(ys.begin(), ys.end())) + ", " +
                              std::to_string(*std::max_element(ys.begin(), ys.end())) + "]",
                          "GriddedCurrentOptions::region");
        ya = range->first;
        yb = range->second;
    }
    const bool yDesc = ys.size() > 1 && ys[1] < ys[0];
    for (std::size_t k = 0; k <= yb - ya; ++k)
    {
        const std::size_t fi = yDesc ? yb - k : ya + k;
        if (l.geographic && std::abs(ys[fi]) > kMaxGridLatitude)
            continue; // a pole row (the grid degenerates there): never loaded, whatever the region's margin
        h.yIdx.push_back(fi);
        h.lat1D.push_back(ys[fi]);
    }
}

/// An x axis in ascending order: values xa[k] at file index xmap[k]; cyclic for a global longitude axis (whose
/// repeated seam column, 180 after -180 or 360 after 0, is left out).
struct AscendingX
{
    std::vector<double> xa;
    std::vector<std::size_t> xmap;
    double step{0.0};
    bool cyclic{false};
};

AscendingX ascendingX(const std::vector<double> &xs, bool geographic)
{
    AscendingX x;
    const bool xDesc = xs.size() > 1 && xs[1] < xs[0];
    x.xa = xs;
    x.xmap.resize(xs.size());
    for (std::size_t k = 0; k < xs.size(); ++k)
        x.xmap[k] = xDesc ? xs.size() - 1 - k : k;
    for (std::size_t k = 0; k < xs.size(); ++k)
        x.xa[k] = xs[x.xmap[k]];
    std::size_t n = x.xa.size();
    x.step = n > 1 ? (x.xa[n - 1] - x.xa[0]) / double(n - 1) : 360.0;
    // Rounding of float axes (a 1/12-degree axis in float32 is off by up to 3e-5) against a missing column.
    const double tol = 0.01 * std::abs(x.step);
    if (geographic && n > 3 && std::abs(x.xa[n - 1] - x.xa[0] - 360.0) <= tol)
    {
        // both seam columns (-180 and 180, or 0 and 360): one column a turn apart, left out so that the seam is
        // one cell like any other (not a cell of zero width)
        x.xa.pop_back();
        x.xmap.pop_back();
        --n;
        x.step = (x.xa[n - 1] - x.xa[0]) / double(n - 1);
    }
    const std::vector<double> &xa = x.xa;
    x.cyclic = geographic && n > 2 && (xa[n - 1] - xa[0] + x.step) >= 360.0 - tol && (xa[n - 1] - xa[0]) < 360.0;
    return x;
}

/// x of a non-cyclic axis: the range covering the region, the region shifted by whole turns into the axis's
/// convention (0..360 or -180..180) when geographic.
void subsetXLinear(const GriddedDataset &f, const Layout &l, const RegionOfInterest &r, const AscendingX &x,
                   HorizontalSubset &h)
{
    const std::vector<double> &xa = x.xa;
    double lo = r.lon0 - r.margin, hi = r.lon1 + r.margin;
    if (l.geographic)
    {
        const double mid = 0.5 * (xa.front() + xa.back());
        const double c = 0.5 * (lo + hi);
        const double k = std::round((mid - c) / 360.0);
        lo += 360.0 * k;
        hi += 360.0 * k;
    }
    auto range = indexRange(xa, lo, hi, r.marginNodes);
    if (!range)
        throw f.error("region " + std::string(l.geographic ? "longitude" : "x") + " [" + std::to_string(r.lonMin) +
                          ", " + std::to_string(r.lonMax) + "] is outside '" + l.xName + "' [" +
                          std::to_string(xa.front()) + ", " + std::to_string(xa.back()) + "]",
                      "GriddedCurrentOptions::region");
    for (std::size_t k = range->first; k <= range->second; ++k)
    {
        h.xIdx.push_back(x.xmap[k]);
        h.lon1D.push_back(xa[k]);
    }
}

/// x of a cyclic (global) longitude axis: virtual index v, file position v mod n, value xa[v mod n] + 360
/// floor(v / n), so that a region across the seam is one increasing run.
void subsetXCyclic(const GriddedDataset &f, const Layout &l, const RegionOfInterest &r, const AscendingX &x,
                   HorizontalSubset &h)
{
    const std::vector<double> &xa = x.xa;
    const double lo = r.lon0 - r.margin, hi = r.lon1 + r.margin;
    const double lo0 = xa[0] + std::fmod(std::fmod(lo - xa[0], 360.0) + 360.0, 360.0); // in [xa0, xa0+360)
    const double hiV = lo0 + (hi - lo);
    const long ln = long(xa.size());
    long vs = long(std::floor((lo0 - xa[0]) / x.step)) - r.marginNodes;
    long ve = long(std::ceil((hiV - xa[0]) / x.step)) + r.marginNodes;
    if (ve - vs + 1 > ln)
        ve = vs + ln - 1;
    for (long v = vs; v <= ve; ++v)
    {
        const long q = ((v % ln) + ln) % ln;
        const long wraps = (v - q) / ln;
        h.xIdx.push_back(x.xmap[std::size_t(q)]);
        h.lon1D.push_back(xa[std::size_t(q)] + 360.0 * double(wraps));
    }
    // strictly increasing unless the axis is irregular at the seam
    for (std::size_t k = 1; k < h.lon1D.size(); ++k)
        if (!(h.lon1D[k] > h.lon1D[k - 1]))
            throw f.error("longitude axis '" + l.xName + "' is not increasing across its seam");
}
} // namespace

HorizontalSubset rectilinearSubset(const GriddedDataset &f, const Layout &l, const RegionOfInterest &r,
                                   const AxisSelection &z, const AxisSelection &t)
{
    HorizontalSubset h;
    std::vector<double> xs, ys;
    readAxes(f, l, xs, ys);
    subsetY(f, l, r, ys, h);
    const AscendingX x = ascendingX(xs, l.geographic);
    if (!r.given)
    {
        for (std::size_t k = 0; k < x.xa.size(); ++k)
        {
            h.xIdx.push_back(x.xmap[k]);
            h.lon1D.push_back(x.xa[k]);
        }
    }
    else if (!l.geographic || !x.cyclic)
        subsetXLinear(f, l, r, x, h);
    else
        subsetXCyclic(f, l, r, x, h);
    if (h.xIdx.size() < 2 || h.yIdx.size() < 2)
        throw f.error("the region covers fewer than 2 grid nodes along '" + l.xName + "' or '" + l.yName + "'");
    checkTripMemory(f, h.xIdx.size(), h.yIdx.size(), t.idx.size(), z.idx.size());
    h.lonLo = h.lon1D.front();
    h.lonHi = h.lon1D.back();
    h.latLo = h.lat1D.front();
    h.latHi = h.lat1D.back();
    h.centreLon = 0.5 * (h.lonLo + h.lonHi);
    h.centreLat = 0.5 * (h.latLo + h.latHi);
    return h;
}
} // namespace gridded_detail
} // namespace ompl_glider
