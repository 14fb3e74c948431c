// Land from a tracer: where a model's temperature or salinity holds its missing value, the model has no ocean. On a
// B grid (POP, MOM) the velocity points are the corners of the tracer cells, and a velocity point is land when any
// of the four tracer cells around it is: the model itself holds the velocity there at zero. The rules are
// documented at applyTracerLand() (GriddedInternal.h) and loadGriddedCurrents() (GriddedCurrents.h).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
const char *const kTracerStandardNames[] = {"sea_water_potential_temperature",    "sea_water_temperature",
                                            "sea_water_conservative_temperature", "sea_water_salinity",
                                            "sea_water_practical_salinity",       "sea_water_absolute_salinity"};
const char *const kTracerNames[] = {"temp", "t",        "salt",     "theta",      "thetao",
                                    "so",   "votemper", "vosaline", "water_temp", "salinity"};

/// The tracer variable: the given one (which must fit), else the first candidate that fits; -1 for none.
int findTracer(const GriddedDataset &f, const Layout &l, const GriddedCurrentOptions &opt, const HorizontalSubset &h,
               const AxisSelection &z, const AxisSelection &t, std::optional<GridFit> &fit)
{
    std::string why;
    if (lower(opt.tracerName) == "none")
        return -1;
    if (!opt.tracerName.empty())
    {
        const auto v = f.findVar(opt.tracerName);
        if (!v)
            throw f.error("no tracer variable '" + opt.tracerName +
                          "' (given as the tracer whose missing values mark land: GriddedCurrentOptions::tracerName)");
        fit = fitToGrid(f, l, *v, h, z, t, why);
        if (!fit)
            throw f.error("tracer variable '" + opt.tracerName +
                          "' (GriddedCurrentOptions::tracerName) does not fit the velocities: " + why);
        return *v;
    }
    std::vector<int> order;
    for (const char *sn : kTracerStandardNames)
        for (int var = 0; var < f.nvars(); ++var)
            if (stdName(f, var) == sn)
                order.push_back(var);
    for (const char *name : kTracerNames)
        for (int var = 0; var < f.nvars(); ++var)
            if (lower(f.varName(var)) == name)
                order.push_back(var);
    for (int var : order)
        if (var != l.uVar && var != l.vVar && (fit = fitToGrid(f, l, var, h, z, t, why)))
            return var;
    return -1;
}

/// The longitude/latitude (x/y) variables of the velocities' grid.
std::pair<int, int> velocityCoordinates(const Layout &l)
{
    if (l.curvilinear)
        return {l.lon2D, l.lat2D};
    return {l.coordVar[std::size_t(l.dimX)], l.coordVar[std::size_t(l.dimY)]};
}

/// The tracer's own longitude/latitude (x/y) variables: from its `coordinates` attribute (variables on its
/// horizontal dimensions), else the 1-D coordinate variables of its horizontal dimensions; -1 where none.
std::pair<int, int> tracerCoordinates(const GriddedDataset &f, const Layout &l, int var, const GridFit &fit)
{
    const std::vector<int> dims = f.varDims(var);
    std::vector<int> horizontal;
    for (std::size_t d = 0; d < dims.size(); ++d)
        if (fit.role[d] == Role::X || fit.role[d] == Role::Y)
            horizontal.push_back(dims[d]);
    auto onGrid = [&](int c) {
        const std::vector<int> cd = f.varDims(c);
        return !cd.empty() && std::all_of(cd.begin(), cd.end(), [&](int d) {
            return std::find(horizontal.begin(), horizontal.end(), d) != horizontal.end();
        });
    };
    const bool geo = l.geographic;
    int lon = -1, lat = -1;
    if (const auto text = f.attText(var, "coordinates"))
    {
        std::istringstream is(*text);
        std::string name;
        while (is >> name)
            if (const auto c = f.findVar(name); c && onGrid(*c))
            {
                if (lon < 0 && (geo ? isLonVar(f, *c) : isXVar(f, *c)))
                    lon = *c;
                else if (lat < 0 && (geo ? isLatVar(f, *c) : isYVar(f, *c)))
                    lat = *c;
            }
    }
    if (lon < 0 || lat < 0)
        for (std::size_t d = 0; d < dims.size(); ++d)
        {
            const auto c = f.findVar(f.dimName(dims[d]));
            if (!c || f.varDims(*c) != std::vector<int>{dims[d]})
                continue;
            if (fit.role[d] == Role::X && lon < 0)
                lon = *c;
            if (fit.role[d] == Role::Y && lat < 0)
                lat = *c;
        }
    return {lon, lat};
}

/// Value of coordinate variable c (1-D on the tracer's y or x dimension, or 2-D on both) at file row j, column i.
double coordinateAt(const GriddedDataset &f, int c, int yDim, std::size_t j, std::size_t i)
{
    const std::vector<int> cd = f.varDims(c);
    std::vector<double> v(1);
    std::vector<DimRead> reads;
    for (int d : cd)
        reads.push_back(makeDimRead({d == yDim ? j : i}));
    readScatter(f, c, reads, std::vector<std::size_t>(cd.size(), 0), v);
    const Packing p = packingOf(f, c);
    return v[0] * p.scale + p.offset;
}

enum class Corner
{
    Same,      ///< the tracer at the velocity point's own index
    NorthEast, ///< velocity point (j, i) at the north-east corner of tracer cell (j, i) (POP, MOM)
    SouthWest  ///< velocity point (j, i) at the south-west corner of tracer cell (j, i)
};

/// Where velocity point (j, i) lies relative to the tracer points, from their coordinates at up to 9 loaded nodes:
/// the offset (a, b) of the velocity point from tracer point (j, i) in steps of the tracer grid's i and j; NorthEast
/// when every node gives (1/2, 1/2), SouthWest for (-1/2, -1/2), else Same.
Corner measuredCorner(const GriddedDataset &f, const Layout &l, int var, const GridFit &fit, const HorizontalSubset &h,
                      int tLon, int tLat)
{
    const std::vector<int> dims = f.varDims(var);
    int yDim = -1;
    for (std::size_t d = 0; d < dims.size(); ++d)
        if (fit.role[d] == Role::Y)
            yDim = dims[d];
    const std::size_t nx = h.xIdx.size(), ny = h.yIdx.size();
    const std::size_t fx = f.dimLen(l.dims[std::size_t(l.dimX)]), fy = f.dimLen(l.dims[std::size_t(l.dimY)]);
    int ne = 0, sw = 0, other = 0;
    for (std::size_t qj = 1; qj <= 3; ++qj)
        for (std::size_t qi = 1; qi <= 3; ++qi)
        {
            const std::size_t jj = std::min(ny - 1, qj * ny / 4), ii = std::min(nx - 1, qi * nx / 4);
            const std::size_t j = h.yIdx[jj], i = h.xIdx[ii];
            if (j + 1 >= fy || i + 1 >= fx)
                continue;
            const double uLon = l.curvilinear ? h.nodeLon[jj * nx + ii] : h.lon1D[ii];
            const double uLat = l.curvilinear ? h.nodeLat[jj * nx + ii] : h.lat1D[jj];
            const double scale = l.geographic ? std::cos(uLat * M_PI / 180.0) : 1.0;
            auto local = [&](std::size_t a, std::size_t b, double &x, double &y) {
                const double lon = coordinateAt(f, tLon, yDim, a, b), lat = coordinateAt(f, tLat, yDim, a, b);
                x = (l.geographic ? wrapTo(lon, uLon) - uLon : lon - uLon) * scale;
                y = lat - uLat;
            };
            double x0, y0, x1, y1, x2, y2;
            local(j, i, x0, y0);
            local(j, i + 1, x1, y1);
            local(j + 1, i, x2, y2);
            const double ex = x1 - x0, ey = y1 - y0, fxv = x2 - x0, fyv = y2 - y0, dx = -x0, dy = -y0;
            const double det = ex * fyv - ey * fxv;
            if (!(std::abs(det) > 0.0) || !std::isfinite(det))
                continue;
            const double a = (dx * fyv - dy * fxv) / det, b = (ex * dy - ey * dx) / det;
            if (std::abs(a - 0.5) < 0.25 && std::abs(b - 0.5) < 0.25)
                ++ne;
            else if (std::abs(a + 0.5) < 0.25 && std::abs(b + 0.5) < 0.25)
                ++sw;
            else
                ++other;
        }
    if (ne > 0 && sw == 0 && other == 0)
        return Corner::NorthEast;
    if (sw > 0 && ne == 0 && other == 0)
        return Corner::SouthWest;
    return Corner::Same;
}

/// File index k + d along a dimension of n indices: across the seam of a periodic grid (period p > 0), else the
/// index itself where k + d lies outside the file (no cell there).
std::size_t neighbour(std::size_t k, int d, std::size_t n, std::size_t p)
{
    const long q = long(k) + d;
    if (q >= 0 && q < long(n))
        return std::size_t(q);
    if (p > 0)
        return std::size_t(((q % long(p)) + long(p)) % long(p));
    return k;
}
} // namespace

bool cornerVelocities(const GriddedDataset &f, const Layout &l)
{
    if (l.staggered)
        return false;
    const auto [lon, lat] = velocityCoordinates(l);
    for (int c : {lon, lat})
    {
        if (c < 0)
            continue;
        const std::string name = lower(f.varName(c));
        const std::string longName = lower(f.attText(c, "long_name").value_or(""));
        if (inList(name, {"ulat", "ulong", "ulon", "xu_ocean", "yu_ocean"}) ||
            longName.find("u-grid") != std::string::npos || longName.find("u grid") != std::string::npos)
            return true;
    }
    return false;
}

void applyTracerLand(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, const AxisSelection &z,
                     const AxisSelection &t, const GriddedCurrentOptions &opt, GriddedData &g, GriddedCurrents &out)
{
    out.cornerGrid = cornerVelocities(f, l);
    std::optional<GridFit> fit;
    const int var = findTracer(f, l, opt, h, z, t, fit);
    if (var < 0)
        return;
    // where the tracer cells lie: the same points, or (B grid) the velocity points at their corners
    Corner corner = Corner::Same;
    std::string how;
    if (!l.staggered)
    {
        const auto [uLon, uLat] = velocityCoordinates(l);
        const auto [tLon, tLat] = tracerCoordinates(f, l, var, *fit);
        if (tLon < 0 || tLat < 0 || (tLon == uLon && tLat == uLat))
        {
            // the tracer has the velocities' coordinates: a B grid when those say they are the velocity points
            corner = out.cornerGrid ? Corner::NorthEast : Corner::Same;
            if (out.cornerGrid)
                how = " ('" + f.varName(uLon) + "'/'" + f.varName(uLat) + "' are the velocity points)";
        }
        else
        {
            corner = measuredCorner(f, l, var, *fit, h, tLon, tLat);
            how = " (from '" + f.varName(tLon) + "'/'" + f.varName(tLat) + "' against '" + f.varName(uLon) + "'/'" +
                  f.varName(uLat) + "')";
        }
    }
    using Offset = std::pair<int, int>; // (row, column)
    std::vector<Offset> offsets{{0, 0}};
    if (corner == Corner::NorthEast)
        offsets = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
    else if (corner == Corner::SouthWest)
        offsets = {{0, 0}, {0, -1}, {-1, 0}, {-1, -1}};
    // land per loaded node (and layer, for a tracer with depth) from the tracer cells around it
    const std::size_t nh = g.nx * g.ny, nzLoaded = g.depth.size();
    const std::size_t nt = fit->hasTime ? t.idx.size() : 1, nz = fit->hasDepth ? nzLoaded : 1;
    const std::size_t fx = f.dimLen(l.dims[std::size_t(l.dimX)]), fy = f.dimLen(l.dims[std::size_t(l.dimY)]);
    const Packing p = packingOf(f, var);
    std::vector<std::uint8_t> land(nz * nh, 0);
    std::size_t valid = 0;
    std::vector<double> raw(nt * nz * nh);
    for (const auto &[dj, di] : offsets)
    {
        std::vector<std::size_t> ys(h.yIdx.size()), xs(h.xIdx.size());
        for (std::size_t k = 0; k < ys.size(); ++k)
            ys[k] = neighbour(h.yIdx[k], dj, fy, 0);
        for (std::size_t k = 0; k < xs.size(); ++k)
            xs[k] = neighbour(h.xIdx[k], di, fx, h.xPeriod);
        fit->setHorizontal(ys, xs);
        readScatter(f, var, fit->reads, fit->stride, raw);
        for (std::size_t it = 0; it < nt; ++it)
        {
            if (fit->hasTime && !t.inTrip(it))
                continue;
            for (std::size_t q = 0; q < nz * nh; ++q)
            {
                const bool missing = p.isFill(raw[it * nz * nh + q]);
                land[q] = land[q] || missing;
                valid += !missing;
            }
        }
    }
    if (valid == 0)
        return; // no value in the region: a variable never written, not a map of land
    out.tracerVariable = f.varName(var);
    out.tracerPlacement = corner == Corner::Same ? "same points"
                                                 : std::string("B grid: velocity points at the ") +
                                                       (corner == Corner::NorthEast ? "north-east" : "south-west") +
                                                       " corners of the tracer cells" + how;
    out.cornerGrid = out.cornerGrid || corner != Corner::Same;
    for (std::size_t k = 0; k < nzLoaded; ++k)
        for (std::size_t n = 0; n < nh; ++n)
        {
            std::uint8_t &w = g.water[k * nh + n];
            if (w && land[(fit->hasDepth ? k : 0) * nh + n])
            {
                w = 0;
                ++out.tracerLandNodes;
            }
        }
    out.landNodes = static_cast<std::size_t>(std::count(g.water.begin(), g.water.end(), 0));
}
} // namespace gridded_detail
} // namespace ompl_glider
