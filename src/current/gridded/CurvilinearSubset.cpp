// The nodes of a 2-D curvilinear grid that cover the region: the index box of the nodes inside (scanned in row
// blocks, longitudes wrapped about the region's centre), widened by the margin nodes, and their coordinates.
#include <algorithm>
#include <cmath>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
/// Rows j0..j1 (inclusive) and the columns of a curvilinear grid, in order (across the wrap of a periodic grid:
/// ..., P - 1, 0, 1, ...).
struct IndexBox
{
    std::size_t j0{0}, j1{0};
    std::vector<std::size_t> cols;
};

/// @throws Error when a value of the 2-D coordinate var read as rows rows[] and columns cols[] (row-major) is a
/// fill value or not finite.
void checkNodeValues(const GriddedDataset &f, int var, const std::vector<double> &v,
                     const std::vector<std::size_t> &rows, const std::vector<std::size_t> &cols)
{
    const std::size_t k = firstFillOrNonFinite(f, var, v);
    if (k < v.size())
        throw f.error("coordinate '" + f.varName(var) + "' holds fill values or non-finite numbers (" +
                      text::number(v[k]) + " at (j, i) = (" + std::to_string(rows[k / cols.size()]) + ", " +
                      std::to_string(cols[k % cols.size()]) + ")); expected finite coordinates");
}

std::vector<std::size_t> range(std::size_t a, std::size_t b)
{
    std::vector<std::size_t> r;
    for (std::size_t k = a; k <= b; ++k)
        r.push_back(k);
    return r;
}

/// Reads the 2-D coordinate var at rows x cols (any order, row-major) and checks its values.
std::vector<double> readNodes(const GriddedDataset &f, int var, const std::vector<std::size_t> &rows,
                              const std::vector<std::size_t> &cols)
{
    std::vector<double> out(rows.size() * cols.size());
    readScatter(f, var, {makeDimRead(rows), makeDimRead(cols)}, {cols.size(), 1}, out);
    checkNodeValues(f, var, out, rows, cols);
    unpackCoordinates(f, var, out);
    return out;
}

/// Distance in degrees between two nodes on the sphere's chart (longitude difference wrapped and scaled by the
/// cosine of the mean latitude): good enough to compare neighbour spacings.
double nodeDistance(double lon1, double lat1, double lon2, double lat2)
{
    const double dlon = std::abs(wrapTo(lon2, lon1) - lon1) * std::cos(0.5 * (lat1 + lat2) * M_PI / 180.0);
    return std::hypot(dlon, lat2 - lat1);
}

/// The period P of the columns of a geographic curvilinear grid of nx columns: column P - 1 neighbours column 0
/// as column 0 neighbours column 1 (a global grid whose i-index wraps, e.g. a displaced-pole grid's seam), with
/// the columns from P on repeating columns 0, 1, ... (P = nx - 1: one repeated column; nx - 2: NEMO's two halo
/// columns); 0 when the index does not wrap. Decided on the rows where the grid is regular enough to tell (at
/// least half of them must agree: the rows of a north fold need not).
std::size_t columnPeriod(const GriddedDataset &f, const Layout &l, std::size_t nx, std::size_t ny)
{
    if (!l.geographic || nx < 4)
        return 0;
    const std::vector<std::size_t> rows = range(0, ny - 1), cols = {0, 1, nx - 2, nx - 1};
    const std::vector<double> lo = readNodes(f, l.lon2D, rows, cols), la = readNodes(f, l.lat2D, rows, cols);
    const double same = 1e-6;
    for (std::size_t p : {nx - 1, nx - 2, nx})
    {
        std::size_t agree = 0, rowsSeen = 0;
        for (std::size_t j = 0; j < ny; ++j)
        {
            auto at = [&](std::size_t c, double &x, double &y) {
                x = lo[j * 4 + c];
                y = la[j * 4 + c];
            };
            double x0, y0, x1, y1, xa, ya, xb, yb;
            at(0, x0, y0);
            at(1, x1, y1);
            at(2, xa, ya);
            at(3, xb, yb);
            const double step = nodeDistance(x0, y0, x1, y1);
            if (!(step > same) || std::abs(y0) > 89.0)
                continue;
            ++rowsSeen;
            bool ok = false;
            if (p == nx - 1) // column nx - 1 is column 0 again
                ok = nodeDistance(xb, yb, x0, y0) < same && nodeDistance(xa, ya, x0, y0) < 2.0 * step;
            else if (p == nx - 2) // columns nx - 2, nx - 1 are columns 0, 1 again
                ok = nodeDistance(xa, ya, x0, y0) < same && nodeDistance(xb, yb, x1, y1) < same;
            else // column nx - 1 is the neighbour of column 0
                ok = nodeDistance(xb, yb, x0, y0) < 2.0 * step && nodeDistance(xb, yb, x0, y0) > same;
            agree += ok;
        }
        if (rowsSeen > 0 && 2 * agree > rowsSeen)
            return p;
    }
    return 0;
}

/// Grows the rows [j0, j1] and marks in `used` the columns (below used.size()) of the nodes of rows
/// [r0, r0 + rows) that lie in the region (+ margin).
void scanRows(const GriddedDataset &f, const Layout &l, const RegionOfInterest &r, std::size_t r0, std::size_t rows,
              std::size_t nx, IndexBox &box, std::vector<char> &used)
{
    const double cLon = 0.5 * (r.lon0 + r.lon1), m = r.margin;
    const std::vector<std::size_t> rr = range(r0, r0 + rows - 1), cc = range(0, nx - 1);
    const std::vector<double> la = readNodes(f, l.lat2D, rr, cc), lo = readNodes(f, l.lon2D, rr, cc);
    for (std::size_t k = 0; k < rows; ++k)
        for (std::size_t i = 0; i < used.size(); ++i)
        {
            const double y = la[k * nx + i];
            double x = lo[k * nx + i];
            if (l.geographic)
                x = wrapTo(x, cLon);
            if (y >= r.latMin - m && y <= r.latMax + m && x >= r.lon0 - m && x <= r.lon1 + m)
            {
                box.j0 = std::min(box.j0, r0 + k);
                box.j1 = std::max(box.j1, r0 + k);
                used[i] = 1;
            }
        }
}

/// The columns of the nodes in the region, widened by e columns each side: from the first to the last used one;
/// across the wrap of a periodic grid (period = used.size() < nx), the shortest run of columns that holds them
/// all (the complement of the longest run of unused columns), never the same column twice.
std::vector<std::size_t> usedColumns(const std::vector<char> &used, std::size_t nx, std::size_t e, bool periodic)
{
    const std::size_t p = used.size();
    std::size_t first = p, last = 0;
    for (std::size_t i = 0; i < p; ++i)
        if (used[i])
        {
            first = std::min(first, i);
            last = i;
        }
    if (!periodic)
        return range(first >= e ? first - e : 0, std::min(nx - 1, last + e));
    // the longest cyclic run of unused columns
    std::size_t bestLen = 0, bestEnd = 0, run = 0;
    for (std::size_t k = 0; k < 2 * p; ++k)
    {
        run = used[k % p] ? 0 : run + 1;
        if (run > bestLen)
        {
            bestLen = std::min(run, p);
            bestEnd = k % p; // the last unused column of the run
        }
    }
    const std::size_t start = (bestEnd + 1) % p, width = p - bestLen;
    const std::size_t widened = std::min(p, width + 2 * e);
    const std::size_t from = widened == p ? start : (start + p - e) % p;
    std::vector<std::size_t> cols;
    for (std::size_t k = 0; k < widened; ++k)
        cols.push_back((from + k) % p);
    return cols;
}

/// The index box of the nodes in the region, widened by the margin nodes; the whole grid without region. period:
/// columnPeriod() of the grid (0 for a staggered one).
IndexBox regionBox(const GriddedDataset &f, const Layout &l, const RegionOfInterest &r, std::size_t period)
{
    const std::size_t nx = f.dimLen(l.dims[std::size_t(l.dimX)]), ny = f.dimLen(l.dims[std::size_t(l.dimY)]);
    if (!r.given)
        return {0, ny - 1, range(0, nx - 1)};
    IndexBox box{ny, 0, {}};
    std::vector<char> used(period > 0 ? period : nx, 0);
    const std::size_t block = std::max<std::size_t>(1, 1000000 / std::max<std::size_t>(1, nx));
    for (std::size_t r0 = 0; r0 < ny; r0 += block)
        scanRows(f, l, r, r0, std::min(block, ny - r0), nx, box, used);
    if (box.j0 == ny)
        throw f.error("no node of the curvilinear grid ('" + l.xName + "', '" + l.yName + "') lies in the region [" +
                      std::to_string(r.lonMin) + ", " + std::to_string(r.lonMax) + "] x [" + std::to_string(r.latMin) +
                      ", " + std::to_string(r.latMax) + "]");
    const std::size_t e = std::size_t(std::max(0, r.marginNodes));
    box.j0 = box.j0 >= e ? box.j0 - e : 0;
    box.j1 = std::min(ny - 1, box.j1 + e);
    box.cols = usedColumns(used, nx, e, period > 0);
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
} // namespace

HorizontalSubset curvilinearSubset(const GriddedDataset &f, const Layout &l, const RegionOfInterest &r,
                                   const AxisSelection &z, const AxisSelection &t)
{
    HorizontalSubset h;
    const std::size_t period =
        l.staggered ? 0
                    : columnPeriod(f, l, f.dimLen(l.dims[std::size_t(l.dimX)]), f.dimLen(l.dims[std::size_t(l.dimY)]));
    IndexBox box = regionBox(f, l, r, period);
    h.xPeriod = period;
    if (l.staggered)
    {
        // a C grid's u and v surround its interior cell centres only: rows and columns 1 .. n - 2
        const std::size_t nx = f.dimLen(l.dims[std::size_t(l.dimX)]), ny = f.dimLen(l.dims[std::size_t(l.dimY)]);
        box.j0 = std::max<std::size_t>(box.j0, 1);
        box.j1 = std::min(box.j1, ny >= 2 ? ny - 2 : 0);
        std::vector<std::size_t> inner;
        for (std::size_t i : box.cols)
            if (i >= 1 && i + 2 <= nx)
                inner.push_back(i);
        box.cols = inner;
        if (box.j1 < box.j0)
            box.j1 = box.j0;
    }
    if (box.cols.size() < 2 || box.j1 - box.j0 < 1)
        throw f.error("the region covers fewer than 2 grid nodes along a dimension of '" + l.xName + "'");
    checkTripMemory(f, box.cols.size(), box.j1 - box.j0 + 1, t.idx.size(), z.idx.size());
    h.yIdx = range(box.j0, box.j1);
    h.xIdx = box.cols;
    h.nodeLat = readNodes(f, l.lat2D, h.yIdx, h.xIdx);
    h.nodeLon = readNodes(f, l.lon2D, h.yIdx, h.xIdx);
    const std::size_t ct[2] = {h.yIdx.size(), h.xIdx.size()};
    checkCurvilinearNodes(f, l, h);
    const std::size_t mid = (ct[0] / 2) * ct[1] + ct[1] / 2;
    const double ref = r.given ? 0.5 * (r.lon0 + r.lon1) : h.nodeLon[mid];
    setCentre(l.geographic, ref, h);
    return h;
}
} // namespace gridded_detail
} // namespace ompl_glider
