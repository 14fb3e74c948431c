// The depth axis: metres, positive down (positive = "up" negated; any length unit converted with UDUNITS-2), sorted
// ascending, and the layers down to the deepest depth the glider reaches.
#include <algorithm>
#include <cmath>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
/// Depth values of zv in metres, positive down, in file order. @throws Error for an unknown positive attribute or
/// units, fill values or non-finite numbers.
std::vector<double> readDepthMetres(const GriddedDataset &f, int zv)
{
    const std::string zn = f.varName(zv);
    std::vector<double> zs = f.readAll1D(zv);
    checkAxisValues(f, zv, zs, "depth");
    unpackCoordinates(f, zv, zs);
    const std::string pos = lower(f.attText(zv, "positive").value_or("down"));
    if (pos != "down" && pos != "up")
        throw f.error("depth '" + zn + "': attribute positive = '" + pos + "', expected 'down' or 'up'");
    // any length unit (UDUNITS-2: m, cm as POP writes, km, ...); none, "1" or "level": metres
    const std::string zu = trim(unitsOf(f, zv));
    LinearConversion toMetres;
    if (!(zu.empty() || zu == "1" || lower(zu) == "level"))
    {
        try
        {
            toMetres = lengthToMetres(zu);
        }
        catch (const Error &e)
        {
            throw f.error("depth '" + zn + "': " + e.what());
        }
    }
    for (double &z : zs)
        z = (pos == "up" ? -1.0 : 1.0) * toMetres(z);
    return zs;
}
} // namespace

AxisSelection selectDepths(const GriddedDataset &f, const Layout &l, double maxDepth)
{
    AxisSelection s;
    if (l.dimZ < 0)
        return s;
    const int zv = l.coordVar[std::size_t(l.dimZ)];
    if (isSigmaCoordinate(f, zv))
    {
        // every s-level: which of them reach a depth differs from node to node (remapSigmaToDepths())
        s.values = f.readAll1D(zv);
        checkAxisValues(f, zv, s.values, "depth");
        s.idx.clear();
        for (std::size_t k = 0; k < s.values.size(); ++k)
            s.idx.push_back(k);
        s.sigma = true;
        return s;
    }
    const std::vector<double> zs = readDepthMetres(f, l.coordVar[std::size_t(l.dimZ)]);
    std::vector<std::size_t> order(zs.size());
    for (std::size_t k = 0; k < zs.size(); ++k)
        order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return zs[a] < zs[b]; });
    for (std::size_t k = 1; k < order.size(); ++k)
        if (zs[order[k]] == zs[order[k - 1]])
            throw f.error("depth '" + f.varName(l.coordVar[std::size_t(l.dimZ)]) + "' has the depth " +
                          text::number(zs[order[k]]) + " m twice (indices " + std::to_string(order[k - 1]) + " and " +
                          std::to_string(order[k]) + "); expected distinct depths");
    std::size_t last = order.size() - 1;
    if (std::isfinite(maxDepth))
    {
        // down to the first layer at or below maxDepth, plus 2 for cubic/Akima stencils
        last = 0;
        while (last + 1 < order.size() && zs[order[last]] < maxDepth)
            ++last;
        last = std::min(order.size() - 1, last + 2);
    }
    s.idx.clear();
    s.values.clear();
    for (std::size_t k = 0; k <= last; ++k)
    {
        s.idx.push_back(order[k]);
        s.values.push_back(zs[order[k]]);
    }
    return s;
}
} // namespace gridded_detail
} // namespace ompl_glider
