// Forecast files as pilots get them: velocity units in any spelling UDUNITS-2 reads (converted with the exact
// factor), non-velocity units refused, the units override; u/v under the usual names of models without CF
// standard names (POP urot/vrot, winds UWND/VWND, u10/v10, UVEL/VVEL, ROMS u_eastward/v_northward) and the
// candidate list when none is found; steady fields (no time axis, one record, GriddedCurrentOptions::steadyRecord)
// and time axes without "since" (GriddedCurrentOptions::timeUnits).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "TestNetCdfUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"
#include "ompl_glider/io/UnitConversion.h"

using namespace ompl_glider;
using glider_test::linspace;
using glider_test::NcWriter;
using glider_test::TempDir;

namespace
{
std::string unitsErrorOf(const std::function<void()> &f)
{
    try
    {
        f();
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

/// A Cartesian file u(time, y, x) = uRaw, v(time, y, x) = vRaw in the given units (x, y in metres, 2 times 1 h
/// apart); no units attribute when `units` is "-".
void writeCartesian(const std::string &path, const std::string &units, double uRaw, double vRaw)
{
    NcWriter w(path);
    const int dt = w.dim("time", 2), dy = w.dim("y", 3), dx = w.dim("x", 4);
    const int vt = w.var("time", NC_DOUBLE, {dt}), vy = w.var("y", NC_DOUBLE, {dy}), vx = w.var("x", NC_DOUBLE, {dx});
    w.text(vt, "units", "seconds since 2026-01-01 00:00:00");
    w.text(vy, "units", "m");
    w.text(vx, "units", "m");
    const int u = w.var("u", NC_DOUBLE, {dt, dy, dx}), v = w.var("v", NC_DOUBLE, {dt, dy, dx});
    if (units != "-")
    {
        w.text(u, "units", units);
        w.text(v, "units", units);
    }
    w.enddef();
    w.put(vt, {0.0, 3600.0});
    w.put(vy, linspace(0.0, 1000.0, 3));
    w.put(vx, linspace(0.0, 1000.0, 4));
    w.put(u, std::vector<double>(24, uRaw));
    w.put(v, std::vector<double>(24, vRaw));
}

/// Geographic 3 x 3 grid without CF standard names: u/v under the given names and dimensions (time, lat, lon)
/// with `nt` times ("hours since 2026-03-01" unless timeUnits says otherwise; no time dimension when nt is 0);
/// u = uRecord[k] at time k (0.1 when not given), v = 0.
void writeGeographic(const std::string &path, const std::string &uName, const std::string &vName, std::size_t nt,
                     const std::string &timeUnits = "hours since 2026-03-01 00:00:00", std::vector<double> uRecord = {})
{
    if (uRecord.empty())
        uRecord.assign(std::max<std::size_t>(nt, 1), 0.1);
    NcWriter w(path);
    const int dy = w.dim("lat", 3), dx = w.dim("lon", 3);
    int dt = -1, vt = -1;
    if (nt > 0)
    {
        dt = w.dim("time", nt);
        vt = w.var("time", NC_DOUBLE, {dt});
        if (!timeUnits.empty())
            w.text(vt, "units", timeUnits);
    }
    const int vy = w.var("lat", NC_DOUBLE, {dy}), vx = w.var("lon", NC_DOUBLE, {dx});
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    const std::vector<int> dims = nt > 0 ? std::vector<int>{dt, dy, dx} : std::vector<int>{dy, dx};
    const int u = w.var(uName, NC_FLOAT, dims), v = w.var(vName, NC_FLOAT, dims);
    w.text(u, "units", "m/s");
    w.text(v, "units", "m/s");
    w.enddef();
    if (nt > 0)
        w.put(vt, linspace(0.0, 6.0, nt));
    w.put(vy, {47.0, 47.1, 47.2});
    w.put(vx, {-53.0, -52.9, -52.8});
    std::vector<double> pu;
    for (std::size_t k = 0; k < std::max<std::size_t>(nt, 1); ++k)
        for (int n = 0; n < 9; ++n)
            pu.push_back(uRecord[k]);
    w.put(u, pu);
    w.put(v, std::vector<double>(pu.size(), 0.0));
}

/// u at the centre node of a loaded geographic 3 x 3 file (eastward there: the projection's centre) at time t.
double centreU(const GriddedCurrents &nc, double t)
{
    const Point2 p = nc.toLocal({-52.9, 47.1});
    return nc.field->velocity(p.x, p.y, 0.0, t).u;
}
} // namespace

TEST(NetCdfUnits, SpellingsOfCmPerSecondKnotsAndOthersConvertWithTheExactFactor)
{
    TempDir tmp;
    struct Case
    {
        std::string units;
        double factor;
    };
    const double knot = 1852.0 / 3600.0;
    const std::vector<Case> cases = {
        {"m s-1", 1.0},
        {"m/s", 1.0},
        {"M/S", 1.0},
        {"meters per second", 1.0},
        {"mps", 1.0},
        {"ms-1", 1.0},
        {"cm/s", 0.01},
        {"cm s-1", 0.01},
        {"centimeter/s", 0.01},
        {"centimeters per second", 0.01},
        {"CM/S", 0.01},
        {"cm.s-1", 0.01},
        {"cms-1", 0.01},
        {"knots", knot},
        {"knot", knot},
        {"kt", knot},
        {"kts", knot},
        {"kn", knot},
        {"KT", knot},
        {"km/h", 1000.0 / 3600.0},
        {"mm/s", 0.001},
        {" mm s-1 ", 0.001},
        {"furlongs/fortnight", 660.0 * 1200.0 / 3937.0 / (14 * 86400.0)}}; // UDUNITS: 660 US survey feet
    const double uRaw = 37.0, vRaw = -12.5;
    int n = 0;
    for (const Case &c : cases)
    {
        const std::string path = tmp.file("units" + std::to_string(n++) + ".nc");
        writeCartesian(path, c.units, uRaw, vRaw);
        const GriddedCurrents nc = loadGriddedCurrents(path);
        const Velocity w = nc.field->velocity(1500.0, 700.0, 0.0, 1800.0);
        // float storage: 7 significant digits; a wrong factor (1, 0.1, 1/1.852) is far off
        EXPECT_NEAR(w.u, uRaw * c.factor, 1e-6 * std::abs(uRaw * c.factor)) << "'" << c.units << "'";
        EXPECT_NEAR(w.v, vRaw * c.factor, 1e-6 * std::abs(vRaw * c.factor)) << "'" << c.units << "'";
    }
    // the factors themselves, to the last bit where the closed form is one rounding away
    EXPECT_DOUBLE_EQ(velocityToMetresPerSecond("cm/s").factor, 0.01);
    EXPECT_DOUBLE_EQ(velocityToMetresPerSecond("centimeter/s").factor, 0.01);
    EXPECT_DOUBLE_EQ(velocityToMetresPerSecond("knots").factor, knot);
    EXPECT_DOUBLE_EQ(velocityToMetresPerSecond("kt").factor, knot);
    EXPECT_EQ(velocityToMetresPerSecond("m s-1").offset, 0.0);
    EXPECT_DOUBLE_EQ(lengthToMetres("km").factor, 1000.0);
    EXPECT_DOUBLE_EQ(lengthToMetres("centimeters").factor, 0.01);
    EXPECT_TRUE(isDimensionless("degrees_east"));
    EXPECT_TRUE(isDimensionless("1"));
    EXPECT_FALSE(isDimensionless("m"));
}

TEST(NetCdfUnits, ConversionsFromSeveralThreadsAgree)
{
    // UDUNITS-2's parser keeps global state: every call is serialised, the database read once
    const std::vector<std::pair<std::string, double>> spellings = {
        {"cm s-1", 0.01}, {"knots", 1852.0 / 3600.0}, {"km/h", 1000.0 / 3600.0}, {"m/s", 1.0}, {"mm/s", 0.001}};
    std::vector<int> wrong(4, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&, t] {
            for (int i = 0; i < 300; ++i)
            {
                const auto &[units, factor] = spellings[std::size_t(i + t) % spellings.size()];
                if (std::abs(velocityToMetresPerSecond(units).factor - factor) > 1e-15 * factor)
                    ++wrong[std::size_t(t)];
                try
                {
                    velocityToMetresPerSecond("degC");
                    ++wrong[std::size_t(t)];
                }
                catch (const Error &)
                {
                }
            }
        });
    for (std::thread &th : threads)
        th.join();
    EXPECT_EQ(wrong, std::vector<int>(4, 0));
}

TEST(NetCdfUnits, NonVelocityUnitsAreRefusedNamingFileVariableAndUnits)
{
    TempDir tmp;
    for (const std::string units : {"degC", "m", "m s-2", "Pa"})
    {
        const std::string path = tmp.file("bad.nc");
        writeCartesian(path, units, 1.0, 1.0);
        const std::string m = unitsErrorOf([&] { loadGriddedCurrents(path); });
        EXPECT_NE(m.find(path), std::string::npos) << m;
        EXPECT_NE(m.find("variable 'u'"), std::string::npos) << m;
        EXPECT_NE(m.find("'" + units + "'"), std::string::npos) << m;
        EXPECT_NE(m.find("not a velocity"), std::string::npos) << m;
        EXPECT_NE(m.find("velocityUnits"), std::string::npos) << m; // how to override them
    }
    const std::string path = tmp.file("gibberish.nc");
    writeCartesian(path, "parsecs per thingy", 1.0, 1.0);
    std::string m = unitsErrorOf([&] { loadGriddedCurrents(path); });
    EXPECT_NE(m.find("'parsecs per thingy'"), std::string::npos) << m;
    EXPECT_NE(m.find("not understood"), std::string::npos) << m;
    // the library function alone says what UDUNITS-2 made of them
    m = unitsErrorOf([] { velocityToMetresPerSecond("degC"); });
    EXPECT_NE(m.find("not a velocity"), std::string::npos) << m;
    EXPECT_NE(m.find("K @ 273.15"), std::string::npos) << m;
    m = unitsErrorOf([] { lengthToMetres("s"); });
    EXPECT_NE(m.find("not a length"), std::string::npos) << m;
}

TEST(NetCdfUnits, OverrideReplacesTheFilesUnitsAndIsChecked)
{
    TempDir tmp;
    const std::string path = tmp.file("wrong_units.nc");
    writeCartesian(path, "degC", 40.0, 10.0); // a file that says degC for velocities in cm/s
    GriddedCurrentOptions o;
    o.velocityUnits = "cm s-1";
    const GriddedCurrents nc = loadGriddedCurrents(path, o);
    const Velocity w = nc.field->velocity(1500.0, 700.0, 0.0, 0.0);
    EXPECT_NEAR(w.u, 0.4, 1e-7);
    EXPECT_NEAR(w.v, 0.1, 1e-7);
    o.velocityUnits = "knots";
    EXPECT_NEAR(loadGriddedCurrents(path, o).field->velocity(1500.0, 700.0, 0.0, 0.0).u, 40.0 * 1852.0 / 3600.0, 1e-5);
    // velocities without units in a geographic file: the override is the way through
    const std::string geo = tmp.file("geo.nc");
    {
        NcWriter w(geo);
        const int dy = w.dim("lat", 2), dx = w.dim("lon", 2);
        const int vy = w.var("lat", NC_DOUBLE, {dy}), vx = w.var("lon", NC_DOUBLE, {dx});
        w.text(vy, "units", "degrees_north");
        w.text(vx, "units", "degrees_east");
        const int u = w.var("u", NC_FLOAT, {dy, dx}), v = w.var("v", NC_FLOAT, {dy, dx});
        w.enddef();
        w.put(vy, {10.0, 10.1});
        w.put(vx, {20.0, 20.1});
        w.put(u, {50, 50, 50, 50});
        w.put(v, {0, 0, 0, 0});
    }
    std::string m = unitsErrorOf([&] { loadGriddedCurrents(geo); });
    EXPECT_NE(m.find("variable 'u' has no units"), std::string::npos) << m;
    EXPECT_NE(m.find("velocityUnits"), std::string::npos) << m;
    GriddedCurrentOptions g;
    g.velocityUnits = "cm/s";
    const Velocity gv = loadGriddedCurrents(geo, g).field->velocity(0.0, 0.0, 0.0, 0.0);
    EXPECT_NEAR(std::hypot(gv.u, gv.v), 0.5, 1e-6);
    // a bad override names the option and the units
    o.velocityUnits = "degC";
    m = unitsErrorOf([&] { loadGriddedCurrents(path, o); });
    EXPECT_NE(m.find("GriddedCurrentOptions::velocityUnits"), std::string::npos) << m;
    EXPECT_NE(m.find("'degC'"), std::string::npos) << m;
    EXPECT_NE(m.find("not a velocity"), std::string::npos) << m;
    o.velocityUnits = "furlongs per blink";
    m = unitsErrorOf([&] { loadGriddedCurrents(path, o); });
    EXPECT_NE(m.find("not understood"), std::string::npos) << m;
}

TEST(NetCdfUnits, CartesianAxesAndDepthInAnyLengthUnit)
{
    TempDir tmp;
    // POP: depth z_t in centimetres, x/y in km; a time axis unit that is not a length is refused on an axis
    const std::string path = tmp.file("pop_like.nc");
    {
        NcWriter w(path);
        const int dz = w.dim("z_t", 3), dy = w.dim("y", 2), dx = w.dim("x", 2);
        const int vz = w.var("z_t", NC_DOUBLE, {dz}), vy = w.var("y", NC_DOUBLE, {dy}),
                  vx = w.var("x", NC_DOUBLE, {dx});
        w.text(vz, "units", "centimeters");
        w.text(vz, "positive", "down");
        w.text(vy, "units", "km");
        w.text(vx, "units", "kilometre");
        const int u = w.var("UVEL", NC_FLOAT, {dz, dy, dx}), v = w.var("VVEL", NC_FLOAT, {dz, dy, dx});
        w.text(u, "units", "centimeter/s");
        w.text(v, "units", "centimeter/s");
        w.enddef();
        w.put(vz, {500.0, 1500.0, 2500.0}); // 5, 15, 25 m
        w.put(vy, {0.0, 2.0});
        w.put(vx, {0.0, 3.0});
        // u = 10 cm/s at 5 m, 20 at 15 m, 30 at 25 m
        std::vector<double> pu;
        for (double s : {10.0, 20.0, 30.0})
            for (int n = 0; n < 4; ++n)
                pu.push_back(s);
        w.put(u, pu);
        w.put(v, std::vector<double>(12, 0.0));
    }
    const GriddedCurrents nc = loadGriddedCurrents(path);
    EXPECT_EQ(nc.uVariable, "UVEL");
    EXPECT_EQ(nc.field->depthAxis().nodes(), (std::vector<double>{5.0, 15.0, 25.0}));
    EXPECT_NEAR(nc.field->velocity(1500.0, 1000.0, 10.0, 0.0).u, 0.15, 1e-7); // halfway 5 m .. 15 m
    const Region e = nc.field->extent();
    EXPECT_EQ(e.xMax, 3000.0);
    EXPECT_EQ(e.yMax, 2000.0);
}

TEST(NetCdfNames, VelocitiesFoundUnderUsualNamesInAnyCase)
{
    TempDir tmp;
    const std::vector<std::pair<std::string, std::string>> pairs = {{"urot", "vrot"}, {"UWND", "VWND"},
                                                                    {"uwnd", "vwnd"}, {"u10", "v10"},
                                                                    {"UVEL", "VVEL"}, {"u_eastward", "v_northward"},
                                                                    {"U10", "V10"}};
    int n = 0;
    for (const auto &[u, v] : pairs)
    {
        const std::string path = tmp.file("names" + std::to_string(n++) + ".nc");
        writeGeographic(path, u, v, 2);
        const GriddedCurrents nc = loadGriddedCurrents(path);
        EXPECT_EQ(nc.uVariable, u);
        EXPECT_EQ(nc.vVariable, v);
        EXPECT_NEAR(centreU(nc, 0.0), 0.1, 1e-6) << u;
    }
}

TEST(NetCdfNames, NoVelocityFoundListsTheCandidatesWithUnitsAndDimensions)
{
    TempDir tmp;
    const std::string path = tmp.file("pop_misc.nc");
    {
        NcWriter w(path);
        const int dt = w.dim("time", 1), dz = w.dim("z_t", 2), dj = w.dim("nlat", 2), di = w.dim("nlon", 2);
        const int dy = w.dim("lat", 2), dx = w.dim("lon", 2);
        const int vt = w.var("time", NC_DOUBLE, {dt});
        w.text(vt, "units", "days since 2026-01-01");
        const int vy = w.var("lat", NC_DOUBLE, {dy}), vx = w.var("lon", NC_DOUBLE, {dx});
        w.text(vy, "units", "degrees_north");
        w.text(vx, "units", "degrees_east");
        const int temp = w.var("temp", NC_FLOAT, {dt, dy, dx});
        w.text(temp, "units", "degC");
        const int uvel2 = w.var("UVEL2", NC_FLOAT, {dt, dz, dj, di});
        w.text(uvel2, "units", "cm/s");
        w.var("mask", NC_INT, {dj, di});
        w.enddef();
    }
    const std::string m = unitsErrorOf([&] { loadGriddedCurrents(path); });
    EXPECT_NE(m.find(path), std::string::npos) << m;
    EXPECT_NE(m.find("no eastward (u) velocity found"), std::string::npos) << m;
    EXPECT_NE(m.find("candidates: temp(time,lat,lon) [degC], UVEL2(time,z_t,nlat,nlon) [cm/s], "
                     "mask(nlat,nlon) [no units]"),
              std::string::npos)
        << m;
    EXPECT_EQ(m.find("lat(lat)"), std::string::npos) << m; // 1-D variables are no candidates
    EXPECT_NE(m.find("GriddedCurrentOptions::uName/vName"), std::string::npos) << m;
    // named, they load (UVEL2 has no v partner here: the v error lists the same candidates)
    GriddedCurrentOptions o;
    o.uName = "UVEL2";
    const std::string mv = unitsErrorOf([&] { loadGriddedCurrents(path, o); });
    EXPECT_NE(mv.find("no northward (v) velocity found"), std::string::npos) << mv;
    EXPECT_NE(mv.find("UVEL2(time,z_t,nlat,nlon) [cm/s]"), std::string::npos) << mv;
    o.uName = "uvel3";
    const std::string mg = unitsErrorOf([&] { loadGriddedCurrents(path, o); });
    EXPECT_NE(mg.find("no variable 'uvel3'"), std::string::npos) << mg;
    EXPECT_NE(mg.find("temp(time,lat,lon) [degC]"), std::string::npos) << mg;
}

TEST(NetCdfSteady, NoTimeAxisOrOneRecordIsASteadyFieldTakingAnyDeparture)
{
    TempDir tmp;
    const std::string none = tmp.file("no_time.nc");
    writeGeographic(none, "u", "v", 0);
    GriddedCurrentOptions o;
    GriddedCurrents nc = loadGriddedCurrents(none, o);
    EXPECT_TRUE(nc.steady);
    EXPECT_FALSE(nc.dated);
    EXPECT_EQ(nc.field->timeEnd(), std::numeric_limits<double>::infinity());
    o.departure = "86400";
    nc = loadGriddedCurrents(none, o);
    EXPECT_EQ(nc.departureTime, 86400.0);
    EXPECT_NEAR(centreU(nc, 1e7), 0.1, 1e-6);
    o.departure = "2026-03-01T00:00:00Z"; // a date needs dates in the file
    std::string m = unitsErrorOf([&] { loadGriddedCurrents(none, o); });
    EXPECT_NE(m.find("departure"), std::string::npos) << m;
    EXPECT_NE(m.find("no dated time axis"), std::string::npos) << m;
    const ForecastTimeAxis a = readForecastTimeAxis(none);
    EXPECT_TRUE(a.steady);
    EXPECT_FALSE(a.found);
    // the options for a time axis make no sense without one
    GriddedCurrentOptions t;
    t.timeUnits = "days since 2026-01-01";
    m = unitsErrorOf([&] { loadGriddedCurrents(none, t); });
    EXPECT_NE(m.find("GriddedCurrentOptions::timeUnits given, but variable 'u' has no time dimension"),
              std::string::npos)
        << m;
    t = {};
    t.steadyRecord = 0;
    m = unitsErrorOf([&] { readForecastTimeAxis(none, t); });
    EXPECT_NE(m.find("GriddedCurrentOptions::steadyRecord given"), std::string::npos) << m;

    // one record: steady, dated by it, any date accepted
    const std::string one = tmp.file("one_record.nc");
    writeGeographic(one, "u", "v", 1);
    o = {};
    o.departure = "2026-04-01T00:00:00Z";
    nc = loadGriddedCurrents(one, o);
    EXPECT_TRUE(nc.steady);
    EXPECT_TRUE(nc.dated);
    EXPECT_EQ(nc.isoTime(nc.departureTime), "2026-04-01T00:00:00Z");
    EXPECT_EQ(nc.departureTime, 31.0 * 86400);
    EXPECT_EQ(nc.field->timeEnd(), std::numeric_limits<double>::infinity());
    EXPECT_TRUE(readForecastTimeAxis(one).steady);
    // two records: not steady, the departure must lie in the forecast
    const std::string two = tmp.file("two_records.nc");
    writeGeographic(two, "u", "v", 2);
    EXPECT_FALSE(loadGriddedCurrents(two).steady);
    m = unitsErrorOf([&] { loadGriddedCurrents(two, o); });
    EXPECT_NE(m.find("outside the forecast"), std::string::npos) << m;
}

TEST(NetCdfTime, AxisWithoutSinceNamesBothOptionsAndEachGetsThrough)
{
    TempDir tmp;
    // a climatology-like axis in "month": records 0, 6, 12 with u = 0.1, 0.2, 0.3
    const std::string path = tmp.file("months.nc");
    writeGeographic(path, "uo", "vo", 3, "month", {0.1, 0.2, 0.3});
    std::string m = unitsErrorOf([&] { loadGriddedCurrents(path); });
    EXPECT_NE(m.find(path), std::string::npos) << m;
    EXPECT_NE(m.find("time variable 'time': units 'month'"), std::string::npos) << m;
    EXPECT_NE(m.find("GriddedCurrentOptions::timeUnits"), std::string::npos) << m;
    EXPECT_NE(m.find("GriddedCurrentOptions::steadyRecord"), std::string::npos) << m;
    // the same without units attribute, and in hours without a date
    for (const std::string units : {"", "hours"})
    {
        const std::string p = tmp.file("undated.nc");
        writeGeographic(p, "uo", "vo", 3, units);
        m = unitsErrorOf([&] { loadGriddedCurrents(p); });
        EXPECT_NE(m.find("GriddedCurrentOptions::timeUnits"), std::string::npos) << "'" << units << "': " << m;
    }

    // timeUnits: the values (0, 6, 12) are days since 2026-01-15
    GriddedCurrentOptions o;
    o.timeUnits = "days since 2026-01-15";
    GriddedCurrents nc = loadGriddedCurrents(path, o);
    EXPECT_TRUE(nc.dated);
    EXPECT_FALSE(nc.steady);
    EXPECT_EQ(nc.isoTime(0.0), "2026-01-15T00:00:00Z");
    EXPECT_EQ(nc.forecastEnd, 12.0 * 86400);
    EXPECT_NEAR(centreU(nc, 3.0 * 86400), 0.15, 1e-6); // halfway between the first two records
    EXPECT_EQ(readForecastTimeAxis(path, o).originSeconds, nc.originSeconds);
    EXPECT_EQ(readForecastTimeAxis(path, o).span, 12.0 * 86400);
    // checked: a units text without "since", or one the calendar parser refuses
    o.timeUnits = "days";
    m = unitsErrorOf([&] { loadGriddedCurrents(path, o); });
    EXPECT_NE(m.find("GriddedCurrentOptions::timeUnits 'days'"), std::string::npos) << m;
    o.timeUnits = "fortnights since 2026-01-15";
    m = unitsErrorOf([&] { loadGriddedCurrents(path, o); });
    EXPECT_NE(m.find("GriddedCurrentOptions::timeUnits 'fortnights since 2026-01-15'"), std::string::npos) << m;

    // steadyRecord: only that record, a steady field (undated here: the axis has no dates)
    for (std::size_t k : {0u, 2u})
    {
        GriddedCurrentOptions s;
        s.steadyRecord = k;
        nc = loadGriddedCurrents(path, s);
        EXPECT_TRUE(nc.steady);
        EXPECT_FALSE(nc.dated);
        EXPECT_EQ(nc.loadedShape[0], 1u);
        EXPECT_EQ(nc.field->timeEnd(), std::numeric_limits<double>::infinity());
        EXPECT_NEAR(centreU(nc, 0.0), 0.1 * double(k + 1), 1e-6);
        EXPECT_NEAR(centreU(nc, 5e6), 0.1 * double(k + 1), 1e-6);
        EXPECT_TRUE(readForecastTimeAxis(path, s).steady);
    }
    // with dates (timeUnits) the record dates the steady field
    GriddedCurrentOptions s;
    s.steadyRecord = 1;
    s.timeUnits = "days since 2026-01-15";
    nc = loadGriddedCurrents(path, s);
    EXPECT_TRUE(nc.steady);
    EXPECT_TRUE(nc.dated);
    EXPECT_EQ(nc.isoTime(0.0), "2026-01-21T00:00:00Z");
    EXPECT_EQ(readForecastTimeAxis(path, s).originSeconds, nc.originSeconds);
    // out of range
    s = {};
    s.steadyRecord = 3;
    m = unitsErrorOf([&] { loadGriddedCurrents(path, s); });
    EXPECT_NE(m.find("GriddedCurrentOptions::steadyRecord 3 is out of range: time variable 'time' has 3 records "
                     "(0 to 2)"),
              std::string::npos)
        << m;
}
