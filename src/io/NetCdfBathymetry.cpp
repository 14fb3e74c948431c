// Seafloor depth from a NetCDF grid (see NetCdfBathymetry.h), read through NcFile: every NetCDF-C call checked,
// every error naming the file and the variable.
#include "ompl_glider/io/NetCdfBathymetry.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "NcFile.h"
#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
using netcdf_detail::NcFile;

/// A coordinate axis of the bathymetry as written in the file.
struct Axis
{
    std::string name;            ///< the dimension and its coordinate variable
    std::vector<double> values;  ///< file order
    std::string units;           ///< the units attribute ("" when absent)
};

/// The coordinate variable of dimension `dim` of the depth variable `variable`: the variable named like the
/// dimension, 1-D on it. @throws Error naming the file, the variable and the dimension.
Axis readAxis(const NcFile &f, int dim, const std::string &variable)
{
    Axis a;
    a.name = f.dimName(dim);
    const std::optional<int> var = f.findVar(a.name);
    if (!var)
        throw f.error("no coordinate variable '" + a.name + "' for the dimension '" + a.name + "' of the bathymetry '" +
                      variable + "'");
    const std::vector<int> dims = f.varDims(*var);
    if (dims.size() != 1 || dims[0] != dim)
        throw f.error("coordinate variable '" + a.name + "' of the bathymetry '" + variable +
                      "' must be 1-D on its dimension '" + a.name + "'");
    a.values = f.readAll1D(*var);
    a.units = f.attText(*var, "units").value_or("");
    return a;
}

/// True when the axis is descending (it is then stored reversed). @throws Error naming the file, the axis and the
/// depth variable `variable` unless the axis is strictly monotonic.
bool isDescending(const NcFile &f, const Axis &a, const std::string &variable)
{
    const std::vector<double> &v = a.values;
    const bool flip = v.size() > 1 && v[1] < v[0];
    for (std::size_t i = 1; i < v.size(); ++i)
        if ((v[i] - v[i - 1]) * (flip ? -1 : 1) <= 0)
            throw f.error("axis '" + a.name + "' of the bathymetry '" + variable + "' is not monotonic");
    return flip;
}

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
}  // namespace

NetCdfBathymetry::NetCdfBathymetry(const std::string &path, const std::string &variable,
                                   std::function<LonLat(double, double)> toGeographic)
  : toGeographic_(std::move(toGeographic))
{
    const NcFile f(path);
    const std::optional<int> var = f.findVar(variable);
    if (!var)
        throw f.error("no variable '" + variable + "' (the seafloor depth)");
    const std::vector<int> dims = f.varDims(*var);
    if (dims.size() != 2)
        throw f.error("variable '" + variable + "' must have 2 dimensions (y/lat, x/lon), it has " +
                      std::to_string(dims.size()));
    const Axis ax = readAxis(f, dims[1], variable);
    const Axis ay = readAxis(f, dims[0], variable);
    const std::size_t nx = ax.values.size(), ny = ay.values.size();
    if (nx == 0 || ny == 0)
        throw f.error("variable '" + variable + "' has no values (its axes '" + ay.name + "', '" + ax.name +
                      "' are empty)");
    geographic_ = ax.units.find("degree") != std::string::npos || ax.name.find("lon") != std::string::npos;
    const std::vector<double> raw = f.readAll1D(*var);
    // the netCDF default fill values (9.97e36) are caught by the magnitude test below
    const std::vector<double> fills = f.attDoubles(*var, "_FillValue");
    const bool hasFill = !fills.empty();
    const double fill = hasFill ? fills.front() : 0.0;
    const double sign = f.attText(*var, "positive").value_or("") == "up" ? -1.0 : 1.0;
    // Ascending axes.
    const bool flipX = isDescending(f, ax, variable), flipY = isDescending(f, ay, variable);
    ax_.resize(nx);
    ay_.resize(ny);
    depth_.resize(nx * ny);
    for (std::size_t i = 0; i < nx; ++i)
        ax_[i] = ax.values[flipX ? nx - 1 - i : i];
    for (std::size_t j = 0; j < ny; ++j)
        ay_[j] = ay.values[flipY ? ny - 1 - j : j];
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
        {
            const double v = raw[(flipY ? ny - 1 - j : j) * nx + (flipX ? nx - 1 - i : i)];
            const bool isFill = !std::isfinite(v) || (hasFill && v == fill) || std::abs(v) >= 9.9e36;
            depth_[j * nx + i] = isFill ? 0.0 : std::max(0.0, sign * v);
        }
    if (geographic_ && !toGeographic_)
        throw f.error("the bathymetry '" + variable + "' is on longitude/latitude: the mission needs a projection");
}

double NetCdfBathymetry::atAxes(double a, double b) const
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

double NetCdfBathymetry::seafloorDepth(double x, double y) const
{
    if (!geographic_)
        return atAxes(x, y);
    const LonLat g = toGeographic_(x, y);  // longitude in -180..180: shifted into the axis's own convention
    const double mid = 0.5 * (ax_.front() + ax_.back());
    return atAxes(mid + std::remainder(g.lon - mid, 360.0), g.lat);
}
}  // namespace ompl_glider
