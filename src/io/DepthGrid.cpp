// A seafloor-depth grid for the depth limit (see DepthGrid.h), read through GriddedDataset: every NetCDF-C call
// checked, every error naming the file and the variable.
#include "ompl_glider/io/DepthGrid.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>

#include "GriddedDataset.h"
#include "ompl_glider/Exception.h"
#include "NumberText.h"

namespace ompl_glider
{
namespace
{
using gridded_detail::GriddedDataset;

std::string lowerCase(std::string s)
{
    for (char &c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

/// A word's number in @p table (a sign, an axis), 0 for a word it does not hold.
int numberOfWord(const std::map<std::string, int> &table, const std::string &word)
{
    const auto it = table.find(word);
    return it == table.end() ? 0 : it->second;
}

/// +1: positive down (a depth), -1: positive up (an elevation), 0: the text does not say.
int signOfStandardName(const std::string &sn)
{
    static const std::map<std::string, int> signs = {{"depth", 1},
                                                     {"model_sea_floor_depth_below_sea_level", 1},
                                                     {"altitude", -1},
                                                     {"surface_altitude", -1},
                                                     {"bedrock_altitude", -1}};
    if (sn.rfind("sea_floor_depth", 0) == 0)
        return 1;
    if (sn.rfind("height", 0) == 0)
        return -1;
    return numberOfWord(signs, sn);
}
int signOfName(const std::string &name)
{
    static const std::map<std::string, int> signs = {{"depth", 1},  {"h", 1},      {"bathymetry", 1}, {"bathy", 1},
                                                     {"deptho", 1}, {"hraw", 1},   {"elevation", -1}, {"z", -1},
                                                     {"topo", -1},  {"rose", -1},  {"altitude", -1},  {"height", -1},
                                                     {"elev", -1},  {"btdata", -1}};
    return numberOfWord(signs, lowerCase(name));
}
int signOfLongName(const std::string &longName)
{
    const std::string n = lowerCase(longName);
    if (n.find("elevation") != std::string::npos || n.find("height") != std::string::npos ||
        n.find("altitude") != std::string::npos || n.find("relief") != std::string::npos)
        return -1;
    if (n.find("depth") != std::string::npos || n.find("bathymetry") != std::string::npos)
        return 1;
    return 0;
}

/// The sign that turns the variable's values into depths (positive down) and why; 0 when nothing settles it.
int depthSign(const GriddedDataset &f, int var, std::string &why)
{
    static const std::map<std::string, int> positive = {{"up", -1}, {"down", 1}};
    if (const int s = numberOfWord(positive, lowerCase(f.attText(var, "positive").value_or(""))))
    {
        why = s < 0 ? "elevation, positive up (attribute positive)" : "depth, positive down (attribute positive)";
        return s;
    }
    const std::string sn = f.attText(var, "standard_name").value_or("");
    if (const int s = signOfStandardName(sn))
    {
        why = std::string(s > 0 ? "depth, positive down" : "elevation, positive up") + " (standard_name " + sn + ")";
        return s;
    }
    if (const int s = signOfName(f.varName(var)))
    {
        why = std::string(s > 0 ? "depth, positive down" : "elevation, positive up") + " (by its name)";
        return s;
    }
    const std::string ln = f.attText(var, "long_name").value_or("");
    if (const int s = signOfLongName(ln))
    {
        why = std::string(s > 0 ? "depth, positive down" : "elevation, positive up") + " (long_name '" + ln + "')";
        return s;
    }
    return 0;
}

/// The depth variable: the one named, else the first 2-D variable whose standard_name or name is a depth's.
int findDepthVariable(const GriddedDataset &f, const std::string &variable)
{
    if (!variable.empty())
    {
        const std::optional<int> v = f.findVar(variable);
        if (!v)
            throw f.error("no variable '" + variable + "' (the seafloor depth)");
        return *v;
    }
    for (int pass = 0; pass < 2; ++pass)
        for (int v = 0; v < f.nvars(); ++v)
        {
            if (f.varDims(v).size() != 2)
                continue;
            const int s =
                pass == 0 ? signOfStandardName(f.attText(v, "standard_name").value_or("")) : signOfName(f.varName(v));
            if (s != 0)
                return v;
        }
    throw f.error("no seafloor depth or elevation variable (a 2-D variable with standard_name sea_floor_depth*, "
                  "height_above_* or altitude, or named depth, h, bathymetry, elevation, z, topo); name it with "
                  "bathymetry_variable");
}

/// The 1-D coordinate variable of dimension @p dim, or nullopt.
std::optional<std::vector<double>> axisOf(const GriddedDataset &f, int dim)
{
    const std::optional<int> v = f.findVar(f.dimName(dim));
    if (!v || f.varDims(*v) != std::vector<int>{dim})
        return std::nullopt;
    return f.readAll1D(*v);
}

/// 2-D lon/lat of the variable: its `coordinates` attribute, else lon_rho/lat_rho. Empty when there are none.
bool coordinates2D(const GriddedDataset &f, int var, std::vector<double> &lon, std::vector<double> &lat)
{
    std::vector<std::string> names;
    const std::string c = f.attText(var, "coordinates").value_or("");
    for (std::size_t p = 0; p < c.size();)
    {
        const std::size_t q = c.find(' ', p);
        const std::string w = c.substr(p, q == std::string::npos ? std::string::npos : q - p);
        if (!w.empty())
            names.push_back(w);
        p = q == std::string::npos ? c.size() : q + 1;
    }
    names.push_back("lon_rho");
    names.push_back("lat_rho");
    std::optional<int> lo, la;
    for (const std::string &n : names)
    {
        const std::optional<int> v = f.findVar(n);
        if (!v || f.varDims(*v) != f.varDims(var))
            continue;
        static const std::map<std::string, int> axisOfUnits = {
            {"degrees_east", 1}, {"degree_east", 1}, {"degrees_north", -1}, {"degree_north", -1}};
        const std::string l = lowerCase(n);
        const int axis = numberOfWord(axisOfUnits, lowerCase(f.attText(*v, "units").value_or("")));
        if (!lo && (l.rfind("lon", 0) == 0 || axis > 0))
            lo = v;
        else if (!la && (l.rfind("lat", 0) == 0 || axis < 0))
            la = v;
    }
    if (!lo || !la)
        return false;
    lon = f.readAll1D(*lo);
    lat = f.readAll1D(*la);
    return true;
}

/// Which horizontal axis dimension @p dim is, by its coordinate variable: +1 x (longitude), -1 y (latitude), 0 when
/// nothing says (its units, standard_name, axis attribute, then its name).
int axisKind(const GriddedDataset &f, int dim)
{
    static const std::map<std::string, int> byUnits = {{"degrees_east", 1}, {"degree_east", 1},    {"degrees_e", 1},
                                                       {"degree_e", 1},     {"degrees_north", -1}, {"degree_north", -1},
                                                       {"degrees_n", -1},   {"degree_n", -1}};
    static const std::map<std::string, int> byStandardName = {
        {"longitude", 1}, {"grid_longitude", 1}, {"projection_x_coordinate", 1},
        {"latitude", -1}, {"grid_latitude", -1}, {"projection_y_coordinate", -1}};
    static const std::map<std::string, int> byAxis = {{"x", 1}, {"y", -1}};
    static const std::map<std::string, int> byName = {{"x", 1}, {"easting", 1}, {"y", -1}, {"northing", -1}};
    const std::string name = lowerCase(f.dimName(dim));
    if (const std::optional<int> v = f.findVar(f.dimName(dim)))
        for (const auto &[attribute, table] :
             {std::make_pair("units", &byUnits), std::make_pair("standard_name", &byStandardName),
              std::make_pair("axis", &byAxis)})
            if (const int kind = numberOfWord(*table, lowerCase(f.attText(*v, attribute).value_or(""))))
                return kind;
    if (name.rfind("lon", 0) == 0 || name.rfind("x_", 0) == 0)
        return 1;
    if (name.rfind("lat", 0) == 0 || name.rfind("y_", 0) == 0)
        return -1;
    return numberOfWord(byName, name);
}

/// Indices of a 1-D axis within [lo, hi] plus one node beyond each side, in ascending order of their values.
std::vector<std::size_t> cut(const std::vector<double> &v, double lo, double hi)
{
    std::vector<std::size_t> idx(v.size());
    std::iota(idx.begin(), idx.end(), std::size_t{0});
    std::sort(idx.begin(), idx.end(), [&](std::size_t p, std::size_t q) { return v[p] < v[q]; });
    std::size_t a = 0, b = idx.size();
    while (a < idx.size() && v[idx[a]] < lo)
        ++a;
    while (b > a && v[idx[b - 1]] > hi)
        --b;
    a = a > 0 ? a - 1 : a;
    b = b < idx.size() ? b + 1 : b;
    return {idx.begin() + static_cast<long>(a), idx.begin() + static_cast<long>(b)};
}
/// Refuses a grid that has no water over the region: only fill values, or land everywhere (a depth read with the
/// wrong sign), naming the convention it was read with and what to set if the values mean the other.
void checkHasWater(const GriddedDataset &f, const DepthGrid &g)
{
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (double d : g.depth)
        if (!std::isnan(d))
        {
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    if (lo > hi)
        throw f.error("variable '" + g.variable +
                      "' holds only fill values over the mission's region: no seafloor "
                      "depth there");
    if (hi > 0.0)
        return;
    const bool up = g.convention.rfind("elevation", 0) == 0;
    const double vLo = up ? -hi : lo, vHi = up ? -lo : hi; // the file's values
    throw f.error("variable '" + g.variable + "' read as " + g.convention +
                  " makes every node over the mission's "
                  "region land (values " +
                  text::number(vLo) + ".." + text::number(vHi) +
                  " m in the file); expected "
                  "a seafloor below the trip: if its values are " +
                  (up ? "depths, positive down" : "elevations, positive up") + ", mark the variable positive = \"" +
                  (up ? "down" : "up") + "\" (ncatted -a positive," + g.variable + ",o,c," + (up ? "down" : "up") +
                  " FILE)");
}
} // namespace

DepthGrid readDepthGrid(const std::string &path, const std::string &variable, const GeoBox &region)
{
    const GriddedDataset f(path);
    const int var = findDepthVariable(f, variable);
    DepthGrid g;
    g.variable = f.varName(var);
    const std::vector<int> dims = f.varDims(var);
    if (dims.size() != 2)
        throw f.error("variable '" + g.variable +
                      "' (the seafloor depth) must have 2 dimensions (lat/y, lon/x), it has " +
                      std::to_string(dims.size()));
    const int sign = depthSign(f, var, g.convention);
    if (sign == 0)
        throw f.error("variable '" + g.variable +
                      "': cannot tell a depth (positive down) from an elevation (positive up): "
                      "it has no attribute 'positive', no standard_name and no long_name that says which");
    const std::size_t n0 = f.dimLen(dims[0]), n1 = f.dimLen(dims[1]);
    if (n0 < 2 || n1 < 2)
        throw f.error("variable '" + g.variable + "' needs at least 2 x 2 nodes, it has " + std::to_string(n0) + " x " +
                      std::to_string(n1));
    const std::vector<double> raw = f.readAll1D(var);
    const std::vector<double> fills = f.attDoubles(var, "_FillValue"), missing = f.attDoubles(var, "missing_value");
    const std::vector<double> scale = f.attDoubles(var, "scale_factor"), offset = f.attDoubles(var, "add_offset");
    auto value = [&](std::size_t n) {
        const double v = raw[n];
        if (!std::isfinite(v) || std::abs(v) >= 9.9e36 || (!fills.empty() && v == fills[0]) ||
            (!missing.empty() && v == missing[0]))
            return std::nan("");
        return sign * (v * (scale.empty() ? 1.0 : scale[0]) + (offset.empty() ? 0.0 : offset[0]));
    };
    std::vector<double> lon2, lat2;
    if (axisOf(f, dims[0]) && axisOf(f, dims[1]))
    {
        // the dimension order (lat, lon) or (lon, lat), told by the axes themselves, never by their ranges
        const int k0 = axisKind(f, dims[0]), k1 = axisKind(f, dims[1]);
        const std::string d0 = f.dimName(dims[0]), d1 = f.dimName(dims[1]);
        if (k0 == k1)
            throw f.error("variable '" + g.variable + "' on dimensions (" + d0 + ", " + d1 + "): " +
                          (k0 == 0 ? "cannot tell which is longitude/x and which latitude/y"
                                   : std::string("both axes say they are ") + (k0 > 0 ? "longitude/x" : "latitude/y")) +
                          "; give the coordinate variables units degrees_east and degrees_north (or standard_name, "
                          "or axis X and Y), or name the dimensions lon and lat (x and y)");
        const bool transposed = k0 > 0 || k1 < 0;
        const int dx = transposed ? dims[0] : dims[1], dy = transposed ? dims[1] : dims[0];
        const auto ax = axisOf(f, dx), ay = axisOf(f, dy);
        const std::string xn = lowerCase(f.dimName(dx));
        const std::string units = lowerCase(f.attText(*f.findVar(f.dimName(dx)), "units").value_or(""));
        g.geographic = units.find("degree") != std::string::npos || xn.find("lon") != std::string::npos;
        g.rectilinear = true;
        std::vector<double> xs = *ax;
        std::vector<std::size_t> ci, rj;
        if (g.geographic)
        {
            // longitudes shifted by whole turns next to the region's middle (a global axis cut across its seam)
            const double mid = 0.5 * (region.lonMin + region.lonMax);
            for (double &x : xs)
                x = mid + std::remainder(x - mid, 360.0);
            ci = cut(xs, region.lonMin, region.lonMax);
            rj = cut(*ay, region.latMin, region.latMax);
        }
        else
        {
            ci = cut(xs, -HUGE_VAL, HUGE_VAL);
            rj = cut(*ay, -HUGE_VAL, HUGE_VAL);
        }
        if (ci.size() < 2 || rj.size() < 2)
            throw f.error("variable '" + g.variable + "' has fewer than 2 x 2 nodes over the mission's region");
        const auto strict = [&](const std::vector<std::size_t> &idx, const std::vector<double> &values, int dim) {
            for (std::size_t k = 1; k < idx.size(); ++k)
                if (!(values[idx[k]] > values[idx[k - 1]]))
                    throw f.error("axis '" + f.dimName(dim) + "' of the bathymetry '" + g.variable +
                                  "' is not strictly monotonic (" + text::number(values[idx[k]]) + " twice)");
        };
        strict(ci, xs, dx);
        strict(rj, *ay, dy);
        g.nx = ci.size();
        g.ny = rj.size();
        for (std::size_t j = 0; j < g.ny; ++j)
            for (std::size_t i = 0; i < g.nx; ++i)
            {
                g.a.push_back(xs[ci[i]]);
                g.b.push_back((*ay)[rj[j]]);
                g.depth.push_back(value(transposed ? ci[i] * n1 + rj[j] : rj[j] * n1 + ci[i]));
            }
        checkHasWater(f, g);
        return g;
    }
    if (!coordinates2D(f, var, lon2, lat2))
        throw f.error("variable '" + g.variable + "' has neither coordinate variables of its dimensions '" +
                      f.dimName(dims[0]) + "', '" + f.dimName(dims[1]) + "' nor 2-D lon/lat coordinates");
    g.nx = n1;
    g.ny = n0;
    const double mid = 0.5 * (region.lonMin + region.lonMax);
    for (std::size_t n = 0; n < n0 * n1; ++n)
    {
        g.a.push_back(mid + std::remainder(lon2[n] - mid, 360.0));
        g.b.push_back(lat2[n]);
        g.depth.push_back(value(n));
    }
    checkHasWater(f, g);
    return g;
}
} // namespace ompl_glider
