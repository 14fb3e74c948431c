#pragma once
// A global (or regional) surface-current forecast as Copernicus Marine writes it, written with NetCDF-C: dimensions
// (time, depth, latitude, longitude), float32 uo/vo in m s-1 with CF standard names and a NaN _FillValue (land),
// float32 coordinate axes, hours since 1950-01-01. The current is a smooth analytic field, periodic in longitude,
// so that a 0..360 file and a -180..180 file hold the same field.
#include <netcdf.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace glider_test
{
/// The analytic current (m/s) at (lon, lat) in degrees: a zonal band structure plus a weak meridional wave,
/// |c| <= 0.16 m/s, the same at lon and lon + 360 (up to rounding).
inline void globalCurrent(double lon, double lat, double &u, double &v)
{
    const double a = lon * M_PI / 180.0, b = lat * M_PI / 180.0;
    u = 0.1 * std::cos(b) * std::cos(3.0 * b) + 0.03 * std::sin(a) * std::cos(b);
    v = 0.05 * std::sin(2.0 * a) * std::cos(b);
}

/// What to write.
struct GlobalForecastSpec
{
    double lon0{-180.0}, dlon{0.5};
    std::size_t nlon{720};
    bool wrapTo360{false}; ///< longitudes written modulo 360 (a 0..360 extract across Greenwich: 359.75, 0, 0.25)
    double lat0{-90.0}, dlat{0.5};
    std::size_t nlat{361};
    std::vector<double> hours{0.0, 24.0 * 366.0}; ///< forecast times (a year: long trips fit)
    /// land: nodes with lon in [landLon0, landLon1] (degrees east, either convention; landLon1 < landLon0 across
    /// the antimeridian) and lat in [landLat0, landLat1] are fill values. Empty box (landLat1 < landLat0): no land.
    double landLon0{0.0}, landLon1{0.0}, landLat0{1.0}, landLat1{0.0};
};

/// True when the node (lon, lat) lies in the spec's land box.
inline bool globalForecastLand(const GlobalForecastSpec &s, double lon, double lat)
{
    if (!(lat >= s.landLat0 && lat <= s.landLat1))
        return false;
    auto east = [](double from, double to) { return std::fmod(std::fmod(to - from, 360.0) + 360.0, 360.0); };
    return east(s.landLon0, lon) <= east(s.landLon0, s.landLon1) + 1e-9;
}

#define GF_CHECK(expr)                                                                                                 \
    do                                                                                                                 \
    {                                                                                                                  \
        const int st_ = (expr);                                                                                        \
        if (st_ != NC_NOERR)                                                                                           \
            throw std::runtime_error(std::string(#expr) + ": " + nc_strerror(st_));                                    \
    } while (0)

/// Writes the forecast (netCDF-4). @throws std::runtime_error when NetCDF-C fails.
inline void writeGlobalForecast(const std::string &path, const GlobalForecastSpec &s)
{
    int nc, dt, dz, dy, dx, vt, vz, vy, vx, vu, vv;
    GF_CHECK(nc_create(path.c_str(), NC_CLOBBER | NC_NETCDF4, &nc));
    GF_CHECK(nc_def_dim(nc, "time", s.hours.size(), &dt));
    GF_CHECK(nc_def_dim(nc, "depth", 1, &dz));
    GF_CHECK(nc_def_dim(nc, "latitude", s.nlat, &dy));
    GF_CHECK(nc_def_dim(nc, "longitude", s.nlon, &dx));
    GF_CHECK(nc_def_var(nc, "time", NC_DOUBLE, 1, &dt, &vt));
    GF_CHECK(nc_def_var(nc, "depth", NC_FLOAT, 1, &dz, &vz));
    GF_CHECK(nc_def_var(nc, "latitude", NC_FLOAT, 1, &dy, &vy));
    GF_CHECK(nc_def_var(nc, "longitude", NC_FLOAT, 1, &dx, &vx));
    auto text = [&](int var, const char *name, const std::string &value) {
        GF_CHECK(nc_put_att_text(nc, var, name, value.size(), value.c_str()));
    };
    text(vt, "units", "hours since 1950-01-01");
    text(vt, "standard_name", "time");
    text(vt, "calendar", "gregorian");
    text(vz, "units", "m");
    text(vz, "positive", "down");
    text(vz, "standard_name", "depth");
    text(vy, "units", "degrees_north");
    text(vy, "standard_name", "latitude");
    text(vx, "units", "degrees_east");
    text(vx, "standard_name", "longitude");
    const int dims[4] = {dt, dz, dy, dx};
    GF_CHECK(nc_def_var(nc, "uo", NC_FLOAT, 4, dims, &vu));
    GF_CHECK(nc_def_var(nc, "vo", NC_FLOAT, 4, dims, &vv));
    const float fill = std::numeric_limits<float>::quiet_NaN();
    for (const auto &[var, name] : {std::pair<int, const char *>{vu, "eastward"}, {vv, "northward"}})
    {
        text(var, "units", "m s-1");
        text(var, "standard_name", std::string(name) + "_sea_water_velocity");
        GF_CHECK(nc_def_var_fill(nc, var, 0, &fill));
    }
    GF_CHECK(nc_enddef(nc));
    const double hours0 = 76.0 * 365.25 * 24.0; // about 2026
    std::vector<double> t(s.hours.size());
    for (std::size_t k = 0; k < t.size(); ++k)
        t[k] = hours0 + s.hours[k];
    const float depth = 0.494f;
    std::vector<float> lat(s.nlat), lon(s.nlon);
    for (std::size_t j = 0; j < s.nlat; ++j)
        lat[j] = static_cast<float>(s.lat0 + s.dlat * double(j));
    for (std::size_t i = 0; i < s.nlon; ++i)
    {
        const double l = s.lon0 + s.dlon * double(i);
        lon[i] = static_cast<float>(s.wrapTo360 ? std::fmod(std::fmod(l, 360.0) + 360.0, 360.0) : l);
    }
    GF_CHECK(nc_put_var_double(nc, vt, t.data()));
    GF_CHECK(nc_put_var_float(nc, vz, &depth));
    GF_CHECK(nc_put_var_float(nc, vy, lat.data()));
    GF_CHECK(nc_put_var_float(nc, vx, lon.data()));
    std::vector<float> u(s.nlat * s.nlon), v(s.nlat * s.nlon);
    for (std::size_t j = 0; j < s.nlat; ++j)
        for (std::size_t i = 0; i < s.nlon; ++i)
        {
            double a, b;
            globalCurrent(lon[i], lat[j], a, b);
            const bool land = globalForecastLand(s, lon[i], lat[j]);
            u[j * s.nlon + i] = land ? fill : static_cast<float>(a);
            v[j * s.nlon + i] = land ? fill : static_cast<float>(b);
        }
    for (std::size_t k = 0; k < s.hours.size(); ++k) // a steady field at every forecast time
    {
        const std::size_t start[4] = {k, 0, 0, 0}, count[4] = {1, 1, s.nlat, s.nlon};
        GF_CHECK(nc_put_vara_float(nc, vu, start, count, u.data()));
        GF_CHECK(nc_put_vara_float(nc, vv, start, count, v.data()));
    }
    GF_CHECK(nc_close(nc));
}
#undef GF_CHECK
} // namespace glider_test
