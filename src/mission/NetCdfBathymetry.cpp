#include "ompl_glider/mission/NetCdfBathymetry.h"

#include <netcdf.h>

#include <algorithm>
#include <cmath>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
std::string textAttribute(int nc, int var, const char *name)
{
    std::size_t len = 0;
    if (nc_inq_attlen(nc, var, name, &len) != NC_NOERR)
        return "";
    std::string v(len, '\0');
    if (nc_get_att_text(nc, var, name, v.data()) != NC_NOERR)
        return "";
    while (!v.empty() && v.back() == '\0')
        v.pop_back();
    return v;
}

std::vector<double> readAxis(int nc, const std::string &path, const std::string &dimName, std::size_t n,
                             std::string &units)
{
    int var;
    if (nc_inq_varid(nc, dimName.c_str(), &var) != NC_NOERR)
        throw Error(path + ": no coordinate variable '" + dimName + "' for the bathymetry's dimension");
    std::vector<double> v(n);
    if (nc_get_var_double(nc, var, v.data()) != NC_NOERR)
        throw Error(path + ": cannot read coordinate variable '" + dimName + "'");
    units = textAttribute(nc, var, "units");
    return v;
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
    int nc;
    if (nc_open(path.c_str(), NC_NOWRITE, &nc) != NC_NOERR)
        throw Error("cannot open bathymetry file '" + path + "'");
    struct Closer
    {
        int id;
        ~Closer()
        {
            nc_close(id);
        }
    } closer{nc};
    int var, ndims;
    if (nc_inq_varid(nc, variable.c_str(), &var) != NC_NOERR)
        throw Error(path + ": no variable '" + variable + "' (the seafloor depth)");
    nc_inq_varndims(nc, var, &ndims);
    if (ndims != 2)
        throw Error(path + ": variable '" + variable + "' must have 2 dimensions (y/lat, x/lon), it has " +
                    std::to_string(ndims));
    int dims[2];
    nc_inq_vardimid(nc, var, dims);
    char nameY[NC_MAX_NAME + 1], nameX[NC_MAX_NAME + 1];
    std::size_t ny, nx;
    nc_inq_dim(nc, dims[0], nameY, &ny);
    nc_inq_dim(nc, dims[1], nameX, &nx);
    std::string ux, uy;
    std::vector<double> ax = readAxis(nc, path, nameX, nx, ux);
    std::vector<double> ay = readAxis(nc, path, nameY, ny, uy);
    geographic_ = ux.find("degree") != std::string::npos || std::string(nameX).find("lon") != std::string::npos;
    std::vector<double> raw(nx * ny);
    if (nc_get_var_double(nc, var, raw.data()) != NC_NOERR)
        throw Error(path + ": cannot read variable '" + variable + "'");
    double fill = NC_FILL_DOUBLE;
    bool hasFill = nc_get_att_double(nc, var, "_FillValue", &fill) == NC_NOERR;
    if (!hasFill)
    {
        float ff;
        nc_type type;
        nc_inq_vartype(nc, var, &type);
        if (type == NC_FLOAT)
            fill = nc_get_att_float(nc, var, "_FillValue", &ff) == NC_NOERR ? ff : NC_FILL_FLOAT;
    }
    const double sign = textAttribute(nc, var, "positive") == "up" ? -1.0 : 1.0;
    // Ascending axes.
    const bool flipX = nx > 1 && ax[1] < ax[0], flipY = ny > 1 && ay[1] < ay[0];
    for (std::size_t i = 1; i < nx; ++i)
        if ((ax[i] - ax[i - 1]) * (flipX ? -1 : 1) <= 0)
            throw Error(path + ": axis '" + std::string(nameX) + "' is not monotonic");
    for (std::size_t j = 1; j < ny; ++j)
        if ((ay[j] - ay[j - 1]) * (flipY ? -1 : 1) <= 0)
            throw Error(path + ": axis '" + std::string(nameY) + "' is not monotonic");
    ax_.resize(nx);
    ay_.resize(ny);
    depth_.resize(nx * ny);
    for (std::size_t i = 0; i < nx; ++i)
        ax_[i] = ax[flipX ? nx - 1 - i : i];
    for (std::size_t j = 0; j < ny; ++j)
        ay_[j] = ay[flipY ? ny - 1 - j : j];
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
        {
            const double v = raw[(flipY ? ny - 1 - j : j) * nx + (flipX ? nx - 1 - i : i)];
            const bool isFill = !std::isfinite(v) || (hasFill && v == fill) || std::abs(v) >= 9.9e36;
            depth_[j * nx + i] = isFill ? 0.0 : std::max(0.0, sign * v);
        }
    if (geographic_ && !toGeographic_)
        throw Error(path + ": the bathymetry is on longitude/latitude: the mission needs a projection");
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
