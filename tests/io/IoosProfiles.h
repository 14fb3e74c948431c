#pragma once
// Writes glider DAC profile files in the IOOS layout (templates v2.0-v4.0) with NetCDF-C, for the tests: one file per
// profile, the scalars time_uv, lat_uv, lon_uv, u, v with their template attributes, profile_time/lat/lon, the
// *_qc flags, the platform variable and the trajectory name.
#include <netcdf.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace ioos_test
{
struct Profile
{
    double time;                // seconds since 1970
    double lon, lat;            // degrees
    double u, v;                // in velocityUnits (-999: fill)
    signed char qc{1};          // u_qc / v_qc
    std::string glider{"ru29"}; // platform:id
    // the DAC's time and position; NaN: 30 min before the profile, 0.001 degrees south-west of it
    double timeUv{std::nan("")}, lonUv{std::nan("")}, latUv{std::nan("")};
    std::string velocityUnits{"m s-1"}; // the units of u and v
};

inline void check(int status, const std::string &what)
{
    if (status != NC_NOERR)
        throw std::runtime_error(what + ": " + nc_strerror(status));
}

inline void writeProfile(const std::string &path, const Profile &p)
{
    int nc = 0;
    check(nc_create(path.c_str(), NC_CLOBBER | NC_NETCDF4, &nc), "create " + path);
    const auto text = [&](int var, const char *name, const std::string &value) {
        check(nc_put_att_text(nc, var, name, value.size(), value.c_str()), name);
    };
    text(NC_GLOBAL, "Conventions", "CF-1.6, Unidata Dataset Discovery v1.0");
    text(NC_GLOBAL, "format_version", "IOOS_Glider_NetCDF_v2.0.nc");
    text(NC_GLOBAL, "featureType", "trajectoryProfile");
    int dimTime = 0, dimStr = 0;
    check(nc_def_dim(nc, "time", 1, &dimTime), "dim time");
    check(nc_def_dim(nc, "traj_strlen", 20, &dimStr), "dim traj_strlen");
    int traj = 0;
    check(nc_def_var(nc, "trajectory", NC_CHAR, 1, &dimStr, &traj), "trajectory");
    text(traj, "cf_role", "trajectory_id");
    const auto scalar = [&](const char *name, const char *units, const char *standard, double value) {
        int id = 0;
        check(nc_def_var(nc, name, NC_DOUBLE, 0, nullptr, &id), name);
        const double fill = -999.0;
        check(nc_put_att_double(nc, id, "_FillValue", NC_DOUBLE, 1, &fill), name);
        text(id, "units", units);
        text(id, "standard_name", standard);
        return std::make_pair(id, value);
    };
    const std::pair<int, double> vars[] = {
        scalar("profile_time", "seconds since 1970-01-01T00:00:00Z", "time", p.time),
        scalar("profile_lat", "degrees_north", "latitude", p.lat),
        scalar("profile_lon", "degrees_east", "longitude", p.lon),
        scalar("time_uv", "seconds since 1970-01-01T00:00:00Z", "time",
               std::isnan(p.timeUv) ? p.time - 1800.0 : p.timeUv),
        scalar("lat_uv", "degrees_north", "latitude", std::isnan(p.latUv) ? p.lat - 0.001 : p.latUv),
        scalar("lon_uv", "degrees_east", "longitude", std::isnan(p.lonUv) ? p.lon - 0.001 : p.lonUv),
        scalar("u", p.velocityUnits.c_str(), "eastward_sea_water_velocity", p.u),
        scalar("v", p.velocityUnits.c_str(), "northward_sea_water_velocity", p.v)};
    int uqc = 0, vqc = 0, platform = 0;
    check(nc_def_var(nc, "u_qc", NC_BYTE, 0, nullptr, &uqc), "u_qc");
    check(nc_def_var(nc, "v_qc", NC_BYTE, 0, nullptr, &vqc), "v_qc");
    text(uqc, "flag_meanings",
         "no_qc_performed good_data probably_good_data bad_data_that_are_potentially_correctable "
         "bad_data value_changed not_used not_used interpolated_value missing_value");
    check(nc_def_var(nc, "platform", NC_INT, 0, nullptr, &platform), "platform");
    text(platform, "id", p.glider);
    text(platform, "type", "platform");
    check(nc_enddef(nc), "enddef");
    char name[20] = {0};
    const std::string id = (p.glider + "-20261115T0000").substr(0, sizeof name);
    std::memcpy(name, id.data(), id.size());
    check(nc_put_var_text(nc, traj, name), "trajectory");
    for (const auto &[id, value] : vars)
        check(nc_put_var_double(nc, id, &value), "value");
    check(nc_put_var_schar(nc, uqc, &p.qc), "u_qc");
    check(nc_put_var_schar(nc, vqc, &p.qc), "v_qc");
    check(nc_close(nc), "close");
}
} // namespace ioos_test
