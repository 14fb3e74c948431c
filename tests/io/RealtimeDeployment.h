#pragma once
// One small glider deployment written in every form readGliderObservations() reads, for the tests of its real-time
// sources: IOOS profile NetCDF files, an ERDDAP tabledap answer (.csvp, .csv, .ncCF in a contiguous ragged and in a
// flat layout) built from it and filtered by the query's `time>=` constraint, and Slocum dba files.
//
// Positions lie on a 1/64 degree lattice, so that the dba files' [-]DDMM.MMMM text (minutes multiples of 0.9375)
// gives back the very same doubles; u and v are written with 17 digits; times are whole seconds.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "IoosProfiles.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/output/SlocumGoto.h"

namespace realtime_test
{
/// One surfacing: the DAC of the dive it ends (its time and position: the surfacing's GPS fix), and the profile's fix.
struct Surfacing
{
    enum Kind
    {
        Good,
        Fill, ///< u and v -999 / NaN / empty (the real-time DAC not yet computed)
        Qc4   ///< u_qc, v_qc 4
    };
    double timeUv, lonUv, latUv, u, v;
    double time, lon, lat;
    Kind kind;
    int id; // profile_id
};

/// A new folder of @p name for the running case (ctest runs the cases at once: each its own folders).
inline std::filesystem::path freshDir(const std::string &name)
{
    const std::filesystem::path d =
        std::filesystem::path(::testing::TempDir()) /
        (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" + name);
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

inline double t0()
{
    return ompl_glider::parseIsoTime("2026-03-15T06:00:00Z");
}

/// The `time>=` constraint of the tests' URLs: it leaves out the first surfacing (the evening before).
inline const char *kSince = "2026-03-15T00:00:00Z";

/// An early surfacing (before kSince), then six every 2 h from t0(): the fourth's DAC a fill value, the fifth's
/// flagged 4. The last fix: the sixth's profile, at t0() + 10.5 h, (-52.375, 48.046875).
inline std::vector<Surfacing> deployment()
{
    const double d = 1.0 / 64.0;
    std::vector<Surfacing> out;
    out.push_back(
        {t0() - 43200.0, -52.75, 47.8125, 0.04, 0.01, t0() - 41400.0, -52.75 + d, 47.8125 + d, Surfacing::Good, 1});
    for (int k = 0; k < 6; ++k)
    {
        Surfacing s{t0() + 7200.0 * k,
                    -52.625 + 3 * k * d,
                    47.875 + 2 * k * d,
                    0.05 + 0.03 * k,
                    -0.02 + 0.01 * k,
                    0.0,
                    0.0,
                    0.0,
                    Surfacing::Good,
                    k + 2};
        s.time = s.timeUv + 1800.0;
        s.lon = s.lonUv + d;
        s.lat = s.latUv + d;
        s.kind = k == 3 ? Surfacing::Fill : k == 4 ? Surfacing::Qc4 : Surfacing::Good;
        if (s.kind == Surfacing::Fill)
            s.u = s.v = -999.0;
        out.push_back(s);
    }
    return out;
}

inline std::string iso(double t)
{
    const std::time_t s = static_cast<std::time_t>(t);
    std::tm tm{};
    gmtime_r(&s, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

inline std::string g17(double x)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

/// The surfacings at or after @p since (profile time), as ERDDAP's `time>=` constraint selects them.
inline std::vector<Surfacing> since(const std::vector<Surfacing> &d, double since)
{
    std::vector<Surfacing> out;
    for (const Surfacing &s : d)
        if (s.time >= since)
            out.push_back(s);
    return out;
}

/// The deployment as IOOS profile files in @p dir (one per surfacing).
inline void writeIoos(const std::filesystem::path &dir, const std::vector<Surfacing> &d)
{
    for (const Surfacing &s : d)
    {
        ioos_test::Profile p{s.time, s.lon, s.lat, s.u, s.v};
        p.qc = s.kind == Surfacing::Qc4 ? 4 : 1;
        p.timeUv = s.timeUv;
        p.lonUv = s.lonUv;
        p.latUv = s.latUv;
        ioos_test::writeProfile((dir / ("ru29_" + std::to_string(s.id) + ".nc")).string(), p);
    }
}

/// ERDDAP's .csvp answer (names with units in parentheses) or .csv answer (names, then a line of units; without
/// profile_id here): three rows per profile repeating its DAC, as ERDDAP gives a profile's rows.
inline std::string csvAnswer(const std::vector<Surfacing> &d, bool csvp)
{
    std::string out = csvp ? "time (UTC),latitude (degrees_north),longitude (degrees_east),profile_id,time_uv (UTC),"
                             "lat_uv (degrees_north),lon_uv (degrees_east),u (m s-1),v (m s-1),u_qc,v_qc\n"
                           : "time,latitude,longitude,time_uv,lat_uv,lon_uv,u,v,u_qc,v_qc\n"
                             "UTC,degrees_north,degrees_east,UTC,degrees_north,degrees_east,m s-1,m s-1,,\n";
    for (const Surfacing &s : d)
        for (int row = 0; row < 3; ++row)
        {
            std::string u = g17(s.u), v = g17(s.v);
            if (s.kind == Surfacing::Fill)
                u = csvp ? "-999" : "", v = csvp ? "NaN" : "";
            const std::string qc = s.kind == Surfacing::Qc4 ? "4" : "1";
            out += iso(s.time) + "," + g17(s.lat) + "," + g17(s.lon) + "," +
                   (csvp ? std::to_string(s.id) + "," : std::string()) + iso(s.timeUv) + "," + g17(s.latUv) + "," +
                   g17(s.lonUv) + "," + u + "," + v + "," + qc + "," + qc + "\n";
        }
    return out;
}

inline void nc(int status, const std::string &what)
{
    if (status != NC_NOERR)
        throw std::runtime_error(what + ": " + nc_strerror(status));
}

/// ERDDAP's .ncCF answer: @p flat false: a contiguous ragged trajectoryProfile (the profiles' variables on `profile`,
/// `rowSize` counting each profile's observations on `obs`); true: every variable on `row`, three rows a profile,
/// profile_id as text. Its bytes (a classic NetCDF file).
inline std::string ncCfAnswer(const std::vector<Surfacing> &d, bool flat, const std::filesystem::path &scratch,
                              const std::vector<std::string> &leaveOut = {})
{
    const std::string path = scratch.string();
    int id = 0;
    nc(nc_create(path.c_str(), NC_CLOBBER | NC_64BIT_OFFSET, &id), "create");
    const std::size_t rows = flat ? 3 * d.size() : d.size();
    int dim = 0, obs = 0, strlen = 0;
    nc(nc_def_dim(id, flat ? "row" : "profile", rows, &dim), "dim");
    nc(nc_def_dim(id, "obs", 3 * d.size(), &obs), "obs");
    nc(nc_def_dim(id, "profile_id_strlen", 8, &strlen), "strlen");
    const auto text = [&](int var, const char *name, const std::string &value) {
        nc(nc_put_att_text(id, var, name, value.size(), value.c_str()), name);
    };
    text(NC_GLOBAL, "featureType", flat ? "Point" : "TrajectoryProfile");
    text(NC_GLOBAL, "cdm_data_type", flat ? "Point" : "TrajectoryProfile");
    const auto left = [&](const char *name) {
        return std::find(leaveOut.begin(), leaveOut.end(), name) != leaveOut.end();
    };
    struct Var
    {
        const char *name;
        int var;
        std::vector<double> values;
    };
    std::vector<Var> vars;
    const auto def = [&](const char *name, nc_type type, const char *units, double fill) {
        if (left(name))
            return;
        int var = 0;
        nc(nc_def_var(id, name, type, 1, &dim, &var), name);
        if (*units)
            text(var, "units", units);
        if (type == NC_DOUBLE)
            nc(nc_put_att_double(id, var, "_FillValue", NC_DOUBLE, 1, &fill), name);
        else
        {
            const signed char f = -127;
            nc(nc_put_att_schar(id, var, "_FillValue", NC_BYTE, 1, &f), name);
        }
        vars.push_back({name, var, {}});
    };
    const char *seconds = "seconds since 1970-01-01T00:00:00Z";
    def("time", NC_DOUBLE, seconds, NAN);
    def("latitude", NC_DOUBLE, "degrees_north", NAN);
    def("longitude", NC_DOUBLE, "degrees_east", NAN);
    def("time_uv", NC_DOUBLE, seconds, NAN);
    def("lat_uv", NC_DOUBLE, "degrees_north", NAN);
    def("lon_uv", NC_DOUBLE, "degrees_east", NAN);
    // the flat answer declares -999 its fill value; the ragged one NaN (and holds -999 as a value, as in real time)
    def("u", NC_DOUBLE, "m s-1", flat ? -999.0 : NAN);
    def("v", NC_DOUBLE, "m s-1", flat ? -999.0 : NAN);
    def("u_qc", NC_BYTE, "", 0.0);
    def("v_qc", NC_BYTE, "", 0.0);
    int profile = 0, rowSize = 0, depth = 0;
    if (flat)
    {
        const int dims[2] = {dim, strlen};
        nc(nc_def_var(id, "profile_id", NC_CHAR, 2, dims, &profile), "profile_id");
    }
    else
    {
        nc(nc_def_var(id, "profile_id", NC_INT, 1, &dim, &profile), "profile_id");
        nc(nc_def_var(id, "rowSize", NC_INT, 1, &dim, &rowSize), "rowSize");
        text(rowSize, "sample_dimension", "obs");
        nc(nc_def_var(id, "depth", NC_FLOAT, 1, &obs, &depth), "depth");
    }
    nc(nc_enddef(id), "enddef");
    std::string ids;
    std::vector<int> intIds, sizes;
    for (const Surfacing &s : d)
        for (int r = 0; r < (flat ? 3 : 1); ++r)
        {
            const bool fill = s.kind == Surfacing::Fill;
            const double qc = s.kind == Surfacing::Qc4 ? 4 : 1;
            const double values[] = {
                s.time, s.lat, s.lon, s.timeUv, s.latUv, s.lonUv, fill ? -999.0 : s.u, fill ? -999.0 : s.v, qc, qc};
            for (Var &v : vars)
            {
                static const char *const order[] = {"time",   "latitude", "longitude", "time_uv", "lat_uv",
                                                    "lon_uv", "u",        "v",         "u_qc",    "v_qc"};
                const auto k = std::find_if(std::begin(order), std::end(order),
                                            [&](const char *n) { return std::string(n) == v.name; }) -
                               std::begin(order);
                v.values.push_back(values[k]);
            }
            std::string pid = "p" + std::to_string(s.id);
            pid.resize(8, '\0');
            ids += pid;
            intIds.push_back(s.id);
            sizes.push_back(3);
        }
    for (const Var &v : vars)
        nc(nc_put_var_double(id, v.var, v.values.data()), v.name);
    if (flat)
        nc(nc_put_var_text(id, profile, ids.data()), "profile_id");
    else
    {
        nc(nc_put_var_int(id, profile, intIds.data()), "profile_id");
        nc(nc_put_var_int(id, rowSize, sizes.data()), "rowSize");
        const std::vector<float> depths(3 * d.size(), 10.0f);
        nc(nc_put_var_float(id, depth, depths.data()), "depth");
    }
    nc(nc_close(id), "close");
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The sensors of the tests' dba files, their units and sizes.
inline const char *kSensors = "m_present_time m_gps_lat m_gps_lon m_gps_status m_water_vx m_water_vy m_depth";
inline const char *kUnits = "timestamp lat lon enum m/s m/s m";
inline const char *kSizes = "8 8 8 1 4 4 4";

/// A dba file's header (14 lines) for the Slocum file @p name ("ru29-2026-074-0-0"), then the label lines.
inline std::string dbaHeader(const std::string &name, const std::string &sensors = kSensors,
                             const std::string &units = kUnits, const std::string &sizes = kSizes)
{
    int count = 0;
    for (std::size_t i = 0; i < sensors.size(); ++i)
        count += sensors[i] != ' ' && (i == 0 || sensors[i - 1] == ' ');
    return "dbd_label: DBD_ASC(dinkum_binary_data_ascii)file\n"
           "encoding_ver: 2\n"
           "num_ascii_tags: 14\n"
           "all_sensors: 0\n"
           "filename: " +
           name +
           "\n"
           "the8x3_filename: 01230000\n"
           "filename_extension: sbd\n"
           "filename_label: " +
           name +
           "-sbd(01230000)\n"
           "mission_name: MICRO.MI\n"
           "fileopen_time: Sun_Mar_15_06:00:00_2026\n"
           "sensors_per_cycle: " +
           std::to_string(count) +
           "\n"
           "num_label_lines: 3\n"
           "num_segments: 1\n"
           "segment_filename_0: " +
           name + "\n" + sensors + "\n" + units + "\n" + sizes + "\n";
}

/// One dba row: time, lat and lon as [-]DDMM.MMMM (NaN: none), status, vx, vy (NaN: none), depth.
inline std::string dbaRow(double time, double lat, double lon, double status, double vx, double vy, double depth)
{
    const auto degMin = [](double x) {
        return std::isnan(x) ? std::string("NaN") : x == 69696969.0 ? "69696969" : ompl_glider::formatDegMin(x);
    };
    const auto num = [](double x) { return std::isnan(x) ? std::string("NaN") : g17(x); };
    return num(time) + " " + degMin(lat) + " " + degMin(lon) + " " + num(status) + " " + num(vx) + " " + num(vy) + " " +
           num(depth) + "\n";
}

/// One row of a Slocum file: time, lat, lon (degrees; NaN: none; 69696969: the placeholder), m_gps_status, m_water_vx,
/// m_water_vy (NaN: none), m_depth; the columns of kSensors.
struct SlocumRow
{
    double time, lat, lon, status, vx, vy, depth;
};

/// The fix before the dive of @p s (the previous surfacing's last fix): 30 min before its DAC's time, 1/64 degree
/// south-west of its DAC's position, so that the DAC is at the segment's mean time and position; the fix after the
/// dive is the profile's (30 min after, 1/64 degree north-east).
inline SlocumRow fixBeforeDive(const Surfacing &s)
{
    const double d = 1.0 / 64.0;
    return {s.timeUv - 1800.0, s.latUv - d, s.lonUv - d, 0.0, NAN, NAN, 0.25};
}

/// The deepest depth of the dive of the surfacing @p k (m).
inline double diveDepth(std::size_t k)
{
    return 60.0 + 10.0 * static_cast<double>(k);
}

/// The deployment as a Slocum's rows in two files (the cycles of its dba or binary files): per surfacing the fix
/// before the dive (a surface row before it), the dive (one row at diveDepth()), the fix after it (the placeholder
/// 69696969 for the fill surfacing, m_gps_status 2 for the flagged one), for a good surfacing a second fix 15 s later
/// (the DAC's fix is the surfacing's first), the DAC 30 s after the first fix (m_water_vx NaN for the fill
/// surfacing). The third surfacing's fix ends the first file, its DAC begins the second.
inline std::array<std::vector<SlocumRow>, 2> slocumRows(const std::vector<Surfacing> &d)
{
    std::array<std::vector<SlocumRow>, 2> files;
    for (std::size_t k = 0; k < d.size(); ++k)
    {
        const Surfacing &s = d[k];
        const bool fill = s.kind == Surfacing::Fill, qc = s.kind == Surfacing::Qc4;
        std::vector<SlocumRow> &before = files[k < 3 ? 0 : 1];
        std::vector<SlocumRow> &after = files[k < 2 ? 0 : 1];
        const SlocumRow start = fixBeforeDive(s);
        before.push_back({start.time - 60.0, NAN, NAN, NAN, NAN, NAN, 0.5}); // depths a float holds exactly
        before.push_back(start);
        before.push_back({s.timeUv, NAN, NAN, NAN, NAN, NAN, diveDepth(k)});
        before.push_back(
            {s.time, fill ? 69696969.0 : s.lat, fill ? 69696969.0 : s.lon, qc ? 2.0 : NAN, NAN, NAN, 0.125});
        if (s.kind == Surfacing::Good && k + 1 < d.size()) // the last surfacing's first fix is the last fix
            before.push_back({s.time + 15.0, s.lat + 1.0 / 64.0, s.lon, NAN, NAN, NAN, 0.125});
        after.push_back({s.time + 30.0, NAN, NAN, NAN, fill ? NAN : s.u, fill ? 0.1 : s.v, 0.25});
    }
    return files;
}

/// The names of the two files of slocumRows().
inline const char *kSlocumFiles[2] = {"ru29-2026-074-0-0", "ru29-2026-074-0-1"};

/// The deployment as a Slocum's dba files in @p dir (slocumRows()).
inline void writeDba(const std::filesystem::path &dir, const std::vector<Surfacing> &d)
{
    const auto rows = slocumRows(d);
    for (int f = 0; f < 2; ++f)
    {
        std::string text = dbaHeader(kSlocumFiles[f]);
        for (const SlocumRow &r : rows[f])
            text += dbaRow(r.time, r.lat, r.lon, r.status, r.vx, r.vy, r.depth);
        std::ofstream(dir / (std::string(kSlocumFiles[f]) + ".dba")) << text;
    }
}
} // namespace realtime_test
