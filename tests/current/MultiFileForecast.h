#pragma once
// A forecast written by the tests twice: as one file, and split into daily files with different time units and
// origins (one day overlapping the next by a record that holds other values: the later file's must win).
#include <cmath>
#include <string>
#include <vector>

#include "TestNetCdfUtil.h"

namespace glider_test
{
/// 3-hourly records from 2026-03-01T00:00Z over 4 days (32 records); lon -53..-52, lat 47..48 in 0.2 degrees.
constexpr int kMfRecords = 32;
constexpr double kMfStepHours = 3.0;

inline double mfU(double lon, double lat, double hours)
{
    return 0.25 * std::sin(2.0 * M_PI * hours / 26.0 + 3.0 * lon) + 0.05 * (lat - 47.5);
}
inline double mfV(double lon, double lat, double hours)
{
    return 0.15 * std::cos(4.0 * lat + hours / 9.0) - 0.03 * (lon + 52.5);
}

struct MfFile
{
    std::string units;         ///< units of the time variable
    std::vector<double> raw;   ///< time values as written
    std::vector<double> hours; ///< the same times, hours since 2026-03-01T00:00Z (what u/v are computed at)
    std::vector<double> bias;  ///< added to u per record (0: the true forecast)
    std::string calendar{"standard"};
    double lonShift{0.0};    ///< moves the grid (a mismatched file)
    double landHour{30.0};   ///< at this hour node (i 2, j 3) is a fill value (land in this record only)
    double stillUntil{24.0}; ///< node (i 3, j 2) is u = v = 0 before this hour (all of day 0's file)
    bool land{true};         ///< the fill-value land nodes above are written (false: no fill values at all)
};

inline void writeMfFile(const std::string &path, const MfFile &m)
{
    NcWriter w(path, NC_CLOBBER);
    const std::size_t nt = m.raw.size(), ny = 6, nx = 6;
    const int dt = w.dim("time", nt), dy = w.dim("lat", ny), dx = w.dim("lon", nx);
    const int vt = w.var("time", NC_DOUBLE, {dt}), vy = w.var("lat", NC_DOUBLE, {dy}),
              vx = w.var("lon", NC_DOUBLE, {dx});
    const int vu = w.var("u", NC_FLOAT, {dt, dy, dx}), vv = w.var("v", NC_FLOAT, {dt, dy, dx});
    w.text(vt, "units", m.units);
    w.text(vt, "calendar", m.calendar);
    w.text(vt, "standard_name", "time");
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    for (int v : {vu, vv})
        w.text(v, "units", "m s-1");
    w.text(vu, "standard_name", "eastward_sea_water_velocity");
    w.text(vv, "standard_name", "northward_sea_water_velocity");
    w.fill(vu, NC_FLOAT, -999.0);
    w.fill(vv, NC_FLOAT, -999.0);
    w.enddef();
    const std::vector<double> lat = linspace(47.0, 0.2, ny), lon = linspace(-53.0 + m.lonShift, 0.2, nx);
    std::vector<double> u, v;
    for (std::size_t k = 0; k < nt; ++k)
        for (std::size_t j = 0; j < ny; ++j)
            for (std::size_t i = 0; i < nx; ++i)
            {
                // one land node (fill value) in every record, one node that is still in every record
                const bool land = m.land && ((i == 5 && j == 0) || (i == 2 && j == 3 && m.hours[k] == m.landHour));
                const bool still = (i == 0 && j == 5) || (i == 3 && j == 2 && m.hours[k] < m.stillUntil);
                u.push_back(land ? -999.0 : still ? 0.0 : mfU(lon[i], lat[j], m.hours[k]) + m.bias.at(k));
                v.push_back(land ? -999.0 : still ? 0.0 : mfV(lon[i], lat[j], m.hours[k]));
            }
    w.put(vt, m.raw);
    w.put(vy, lat);
    w.put(vx, lon);
    w.put(vu, u);
    w.put(vv, v);
}

/// Hours h0, h0 + 3, ... (n values).
inline std::vector<double> mfHours(double h0, int n)
{
    return linspace(h0, kMfStepHours, std::size_t(n));
}

/// The whole forecast in one file, "hours since 2026-03-01 00:00:00".
inline MfFile mfCombined()
{
    MfFile m;
    m.units = "hours since 2026-03-01 00:00:00";
    m.hours = mfHours(0.0, kMfRecords);
    m.raw = m.hours;
    m.bias.assign(m.hours.size(), 0.0);
    return m;
}

/// Day d (0..3) as its own file: day 0 in hours since 2026-03-01, day 1 in days since 2026-03-02 with one more
/// record (2026-03-03T00:00, biased: day 2's file must replace it), day 2 in seconds since 2026-03-02 12:00,
/// day 3 in minutes since 2026-02-28 00:00.
inline MfFile mfDay(int d)
{
    MfFile m;
    m.hours = mfHours(24.0 * d, 8);
    if (d == 1)
        m.hours.push_back(48.0);
    m.bias.assign(m.hours.size(), 0.0);
    if (d == 1)
        m.bias.back() = 0.5;
    for (double h : m.hours)
    {
        if (d == 0)
            m.raw.push_back(h);
        else if (d == 1)
            m.raw.push_back((h - 24.0) / 24.0);
        else if (d == 2)
            m.raw.push_back((h - 36.0) * 3600.0);
        else
            m.raw.push_back((h + 24.0) * 60.0);
    }
    m.units = d == 0   ? "hours since 2026-03-01 00:00:00"
              : d == 1 ? "days since 2026-03-02"
              : d == 2 ? "seconds since 2026-03-02 12:00:00"
                       : "minutes since 2026-02-28";
    return m;
}
/// The forecast written as one file (combined.nc) and as the 4 daily files named by dayName(d), in a fresh
/// directory.
struct MfFiles
{
    TempDir dir;
    std::string combined = dir.file("combined.nc");
    std::vector<std::string> days;
    template <typename DayName> explicit MfFiles(DayName dayName, bool land = true)
    {
        MfFile c = mfCombined();
        c.land = land;
        writeMfFile(combined, c);
        for (int d = 0; d < 4; ++d)
        {
            days.push_back(dir.file(dayName(d)));
            MfFile f = mfDay(d);
            f.land = land;
            writeMfFile(days.back(), f);
        }
    }
};
} // namespace glider_test
