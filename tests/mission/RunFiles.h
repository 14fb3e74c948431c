#pragma once
// Forecast runs written as a model writes them, for the tests of forecast runs: daily runs of a swirl whose centre
// and strength depend on the run (runs differ where they overlap), each run 3-hourly over 3 days from its
// reference time 2026-03-(1 + r) 00:00Z; one file per run (writeRun()) or all runs in one file of several runs as a
// THREDDS FMRC serves them (writeFmrc(): a run dimension, a 2-D time).
#include <cmath>
#include <string>
#include <vector>

#include "../current/TestNetCdfUtil.h"
#include "ompl_glider/mission/ForecastMission.h"

namespace glider_test
{
/// How a run file states its reference time.
enum class RunReference
{
    Variable,  ///< a scalar forecast_reference_time variable, hours since 1970
    Attribute, ///< a global attribute holding the date
    None       ///< nothing: the first time is taken
};

constexpr std::size_t kRunTimes = 25, kRunNy = 9, kRunNx = 9;

inline std::vector<double> runLats()
{
    return linspace(47.0, 0.125, kRunNy);
}
inline std::vector<double> runLons()
{
    return linspace(-53.0, 0.125, kRunNx);
}

/// Run r's u and v at its first @p nt records (hours 0, 3, ... after its reference time), order (t, lat, lon).
inline void runFlow(int r, std::size_t nt, std::vector<double> &u, std::vector<double> &v)
{
    u.clear();
    v.clear();
    const double cx = -52.5 + 0.05 * r, cy = 47.5 - 0.03 * r, s = 0.3 + 0.04 * r;
    for (double h : linspace(0.0, 3.0, nt))
        for (double la : runLats())
            for (double lo : runLons())
            {
                const double a = 2.0 * M_PI * (h + 24.0 * r) / 40.0;
                u.push_back(-s * (la - cy) + 0.05 * std::cos(a));
                v.push_back(0.7 * s * (lo - cx) + 0.05 * std::sin(a));
            }
}

/// The CF attributes of a run file's lat (@p vy), lon (@p vx) and velocity (@p vu, @p vv) variables.
inline void describeLatLonVelocity(NcWriter &w, int vy, int vx, int vu, int vv, const std::string &units = "m s-1")
{
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    w.text(vu, "standard_name", "eastward_sea_water_velocity");
    w.text(vv, "standard_name", "northward_sea_water_velocity");
    for (int v : {vu, vv})
        w.text(v, "units", units);
}

/// The command line's problem on the runs (glider_plan --currents FILES --runs): across the swirl at 0.5 m/s, its
/// last field held past a run's end, departing at @p departure; the runs or file are the caller's.
inline ompl_glider::ForecastInput runsInput(const std::string &departure)
{
    ompl_glider::ForecastInput in;
    in.start = {-52.85, 47.15};
    in.goal = {-52.1, 47.85};
    in.speed = 0.5;
    in.current.horizonPolicy = ompl_glider::BeyondForecast::HoldLast;
    in.departure = departure;
    return in;
}

/// Run r in a file of its own: its first @p nt records, "hours since" its reference time.
inline void writeRun(const std::string &path, int r, RunReference ref, std::size_t nt = kRunTimes)
{
    NcWriter w(path, NC_CLOBBER);
    const int dt = w.dim("time", nt), dy = w.dim("lat", kRunNy), dx = w.dim("lon", kRunNx);
    const int vt = w.var("time", NC_DOUBLE, {dt}), vy = w.var("lat", NC_DOUBLE, {dy}),
              vx = w.var("lon", NC_DOUBLE, {dx});
    const int vu = w.var("uo", NC_FLOAT, {dt, dy, dx}), vv = w.var("vo", NC_FLOAT, {dt, dy, dx});
    const std::string day = "2026-03-0" + std::to_string(1 + r);
    w.text(vt, "units", "hours since " + day + " 00:00:00");
    w.text(vt, "standard_name", "time");
    describeLatLonVelocity(w, vy, vx, vu, vv);
    int vr = -1;
    if (ref == RunReference::Variable)
    {
        vr = w.var("forecast_reference_time", NC_DOUBLE, {});
        w.text(vr, "standard_name", "forecast_reference_time");
        w.text(vr, "units", "hours since 1970-01-01 00:00:00");
    }
    if (ref == RunReference::Attribute)
        w.text(NC_GLOBAL, "forecast_reference_time", day + "T00:00:00Z");
    w.enddef();
    std::vector<double> u, v;
    runFlow(r, nt, u, v);
    w.put(vt, linspace(0.0, 3.0, nt));
    w.put(vy, runLats());
    w.put(vx, runLons());
    w.put(vu, u);
    w.put(vv, v);
    if (vr >= 0)
    {
        const double since1970 = (56.0 * 365.0 + 14.0 + 59.0 + r) * 24.0; // 2026-03-01 + r, in hours since 1970
        w.put(vr, {since1970});
    }
}

/// How a file of several runs names its run and time coordinates (THREDDS: `run`/`time` in an NcML FMRC,
/// `reftime`/`time1` in a feature collection's TwoD dataset) and whether the velocities have a depth.
struct FmrcLayout
{
    std::string run{"run"}, time{"time"};
    bool depth{false};
};

/// Runs 0 .. lengths.size() - 1 in one file of several runs: u(run, time, [depth,] lat, lon), run(run) the reference
/// times in hours since 2026-03-01 (standard_name forecast_reference_time), time(run, time) the valid times; run r
/// has its first lengths[r] records, the rest of its row of time and its velocities fill values (NaN).
inline void writeFmrc(const std::string &path, const std::vector<std::size_t> &lengths, const FmrcLayout &l = {})
{
    NcWriter w(path, NC_CLOBBER);
    const std::size_t nr = lengths.size(), nz = l.depth ? 2 : 1;
    const int dr = w.dim(l.run, nr), dt = w.dim(l.time, kRunTimes), dy = w.dim("lat", kRunNy),
              dx = w.dim("lon", kRunNx);
    std::vector<int> vdims{dr, dt, dy, dx};
    int dz = -1, vz = -1;
    if (l.depth)
    {
        dz = w.dim("depth", nz);
        vdims = {dr, dt, dz, dy, dx};
        vz = w.var("depth", NC_DOUBLE, {dz});
        w.text(vz, "units", "m");
        w.text(vz, "positive", "down");
    }
    const int vr = w.var(l.run, NC_DOUBLE, {dr}), vt = w.var(l.time, NC_DOUBLE, {dr, dt}),
              vy = w.var("lat", NC_DOUBLE, {dy}), vx = w.var("lon", NC_DOUBLE, {dx});
    const int vu = w.var("uo", NC_FLOAT, vdims), vv = w.var("vo", NC_FLOAT, vdims);
    w.text(vr, "units", "hours since 2026-03-01T00:00:00Z");
    w.text(vr, "standard_name", "forecast_reference_time");
    w.text(vr, "_CoordinateAxisType", "RunTime");
    w.text(vt, "units", "hours since 2026-03-01T00:00:00Z");
    w.text(vt, "standard_name", "time");
    w.num(vt, "_FillValue", NC_DOUBLE, {NAN});
    describeLatLonVelocity(w, vy, vx, vu, vv);
    for (int v : {vu, vv})
        w.num(v, "_FillValue", NC_FLOAT, {NAN});
    w.enddef();
    std::vector<double> runs, times, u, v, ur, vr2;
    const std::size_t nh = kRunNy * kRunNx;
    for (std::size_t r = 0; r < nr; ++r)
    {
        runs.push_back(24.0 * double(r));
        runFlow(int(r), kRunTimes, ur, vr2);
        for (std::size_t k = 0; k < kRunTimes; ++k)
        {
            const bool has = k < lengths[r];
            times.push_back(has ? 24.0 * double(r) + 3.0 * double(k) : NAN);
            for (std::size_t z = 0; z < nz; ++z)
                for (std::size_t q = 0; q < nh; ++q)
                {
                    u.push_back(has ? ur[k * nh + q] : NAN);
                    v.push_back(has ? vr2[k * nh + q] : NAN);
                }
        }
    }
    w.put(vr, runs);
    w.put(vt, times);
    w.put(vy, runLats());
    w.put(vx, runLons());
    if (vz >= 0)
        w.put(vz, {0.0, 50.0});
    w.put(vu, u);
    w.put(vv, v);
}
} // namespace glider_test
