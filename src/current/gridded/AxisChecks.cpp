// Coordinate values the grid can be built on: no NaN, infinities or fill values (a coordinate variable never
// written reads as its fill value), 1-D axes strictly monotonic (longitudes possibly across one seam, as in
// 170, 180, -170 or 350, 0, 10), and 2-D curvilinear grids without coinciding neighbours or folded cells.
#include <cmath>
#include <sstream>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{

std::size_t firstFillOrNonFinite(const GriddedDataset &f, int var, const std::vector<double> &values)
{
    const Packing p = packingOf(f, var);
    for (std::size_t k = 0; k < values.size(); ++k)
        if (!std::isfinite(values[k]) || p.isFill(values[k]))
            return k;
    return values.size();
}

void checkAxisValues(const GriddedDataset &f, int var, const std::vector<double> &values, const std::string &kind)
{
    const std::size_t k = firstFillOrNonFinite(f, var, values);
    if (k < values.size())
        throw f.error(kind + " '" + f.varName(var) + "' holds fill values or non-finite numbers (" +
                      text::number(values[k]) + " at index " + std::to_string(k) + "); expected finite coordinates");
}

std::size_t monotonicBreak(const std::vector<double> &values)
{
    if (values.size() < 2)
        return values.size();
    const bool up = values[1] > values[0];
    for (std::size_t k = 1; k < values.size(); ++k)
        if (up ? !(values[k] > values[k - 1]) : !(values[k] < values[k - 1]))
            return k;
    return values.size();
}

void checkStrictlyMonotonic(const GriddedDataset &f, const std::vector<double> &values,
                            const std::vector<double> &shown, const std::string &kind, const std::string &name)
{
    const std::size_t k = monotonicBreak(values);
    if (k < values.size())
        throw f.error(kind + " '" + name + "' is not strictly monotonic: " + text::number(shown[k - 1]) + " at index " +
                      std::to_string(k - 1) + ", then " + text::number(shown[k]) + " at index " + std::to_string(k));
}

std::vector<double> unwrapLongitudes(const std::vector<double> &lon)
{
    if (monotonicBreak(lon) == lon.size())
        return lon;
    std::vector<double> out = lon;
    double shift = 0.0;
    for (std::size_t k = 1; k < lon.size(); ++k)
    {
        const double d = lon[k] - lon[k - 1];
        if (d < -180.0)
            shift += 360.0;
        else if (d > 180.0)
            shift -= 360.0;
        out[k] = lon[k] + shift;
    }
    if (monotonicBreak(out) < out.size() || std::abs(out.back() - out.front()) >= 360.0)
        return lon; // not one turn across a seam: left for checkStrictlyMonotonic to refuse
    return out;
}

namespace
{
/// Node n relative to node ref in a local plane: the longitude difference (wrapped, times cos(latitude)) and the
/// latitude difference when geographic, else the coordinate differences.
void planar(bool geographic, const HorizontalSubset &h, std::size_t ref, std::size_t n, double &x, double &y)
{
    x = h.nodeLon[n] - h.nodeLon[ref];
    y = h.nodeLat[n] - h.nodeLat[ref];
    if (geographic)
        x = (wrapTo(h.nodeLon[n], h.nodeLon[ref]) - h.nodeLon[ref]) * std::cos(h.nodeLat[ref] * M_PI / 180.0);
}

/// Orientation of the cell with lower corner n: the sign of (node n+1 - node n) x (node n+nx - node n).
int cellSign(bool geographic, const HorizontalSubset &h, std::size_t n, std::size_t nx)
{
    double ex, ey, gx, gy;
    planar(geographic, h, n, n + 1, ex, ey);
    planar(geographic, h, n, n + nx, gx, gy);
    const double c = ex * gy - ey * gx;
    return c > 0.0 ? 1 : (c < 0.0 ? -1 : 0);
}

/// "(j, i)" of node n of the box, file indices.
std::string nodeText(const HorizontalSubset &h, std::size_t n)
{
    const std::size_t nx = h.xIdx.size();
    return "(" + std::to_string(h.yIdx[n / nx]) + ", " + std::to_string(h.xIdx[n % nx]) + ")";
}
} // namespace

void checkCurvilinearNodes(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h)
{
    const std::size_t nx = h.xIdx.size(), ny = h.yIdx.size();
    const std::string who = "curvilinear coordinates '" + l.xName + "'/'" + l.yName + "' are not strictly monotonic: ";
    for (std::size_t n = 0; n < nx * ny; ++n)
        for (std::size_t m : {n + 1, n + nx})
        {
            if ((m == n + 1 && m % nx == 0) || m >= nx * ny)
                continue;
            double x, y;
            planar(l.geographic, h, n, m, x, y);
            if (x == 0.0 && y == 0.0)
                throw f.error(who + "the nodes at (j, i) = " + nodeText(h, n) + " and " + nodeText(h, m) + " coincide");
        }
    int first = 0;
    for (std::size_t j = 0; j + 1 < ny; ++j)
        for (std::size_t i = 0; i + 1 < nx; ++i)
        {
            const int s = cellSign(l.geographic, h, j * nx + i, nx);
            first = first == 0 ? s : first;
            if (s == 0 || s != first)
                throw f.error(who + "the grid cell at (j, i) = " + nodeText(h, j * nx + i) +
                              " is folded or degenerate (its orientation differs from the first cell's)");
        }
}
} // namespace gridded_detail
} // namespace ompl_glider
