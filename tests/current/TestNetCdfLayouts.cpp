// NetCDF loading in the layouts forecasts come in: packed HYCOM-like (time, depth, lat, lon; short with
// scale/offset; 0..360 longitudes), CMEMS-like (float, standard_name, descending latitude, m s-1), a global grid
// cut across the antimeridian, a NEMO-like curvilinear grid with land and a noleap calendar, a Cartesian file,
// and the errors for missing or wrong pieces. Values are checked at grid nodes and between them.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "TestNetCdfUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"

using namespace ompl_glider;
using glider_test::inPlane;
using glider_test::linspace;
using glider_test::NcWriter;
using glider_test::TempDir;

namespace
{

// HYCOM-like: u = 0.1 + 0.01 i + 0.015 j - 0.001 depth + 0.01 hour (exact multiples of the 0.001 packing step)
const std::vector<double> kHyLon = linspace(280.0, 0.5, 10); // 280 .. 284.5 = -80 .. -75.5
const std::vector<double> kHyLat = linspace(30.0, 0.5, 8);
const std::vector<double> kHyDepth{0, 10, 30, 100, 300, 1000};
const std::vector<double> kHyHours = linspace(0.0, 3.0, 12);
double hyU(double lon, double lat, double depth, double hour)
{
    return 0.1 + 0.02 * (lon - 280.0) + 0.03 * (lat - 30.0) - 0.001 * depth + 0.01 * hour / 3.0;
}
double hyV(double lon, double lat, double, double hour)
{
    return -0.2 + 0.01 * (lon - 280.0) - 0.002 * hour / 3.0 + 0.0 * lat;
}

void writeHycom(const std::string &path, bool withLand)
{
    NcWriter w(path);
    const int dt = w.dim("time", kHyHours.size()), dz = w.dim("depth", kHyDepth.size());
    const int dy = w.dim("lat", kHyLat.size()), dx = w.dim("lon", kHyLon.size());
    const int vt = w.var("time", NC_DOUBLE, {dt}), vz = w.var("depth", NC_DOUBLE, {dz});
    const int vy = w.var("lat", NC_DOUBLE, {dy}), vx = w.var("lon", NC_DOUBLE, {dx});
    w.text(vt, "units", "hours since 2000-01-01 00:00:00");
    w.text(vt, "calendar", "gregorian");
    w.text(vz, "units", "m");
    w.text(vz, "positive", "down");
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    const int u = w.var("water_u", NC_SHORT, {dt, dz, dy, dx}), v = w.var("water_v", NC_SHORT, {dt, dz, dy, dx});
    for (int var : {u, v})
    {
        w.text(var, "units", "m/s");
        w.num(var, "scale_factor", NC_FLOAT, {0.001});
        w.num(var, "add_offset", NC_FLOAT, {0.0});
        w.fill(var, NC_SHORT, -30000);
    }
    w.text(u, "standard_name", "eastward_sea_water_velocity");
    w.text(v, "standard_name", "northward_sea_water_velocity");
    w.enddef();
    w.put(vt, kHyHours);
    w.put(vz, kHyDepth);
    w.put(vy, kHyLat);
    w.put(vx, kHyLon);
    std::vector<double> pu, pv;
    for (double h : kHyHours)
        for (double z : kHyDepth)
            for (double la : kHyLat)
                for (double lo : kHyLon)
                {
                    // packed = value / scale; the 300 m and deeper layers are land east of 283 (a shelf) when asked
                    const bool land = withLand && z >= 300 && lo >= 283.0;
                    pu.push_back(land ? -30000 : std::round(hyU(lo, la, z, h) / 0.001));
                    pv.push_back(land ? -30000 : std::round(hyV(lo, la, z, h) / 0.001));
                }
    w.put(u, pu);
    w.put(v, pv);
}
} // namespace

TEST(NetCdfLayouts, PackedHycomLikeValuesAtNodesAndBetween)
{
    TempDir tmp;
    const std::string path = tmp.file("hycom.nc");
    writeHycom(path, true);
    GriddedCurrentOptions o; // everything automatic; whole file
    const GriddedCurrents nc = loadGriddedCurrents(path, o);
    ASSERT_TRUE(nc.geographic);
    ASSERT_TRUE(nc.dated);
    EXPECT_EQ(nc.uVariable, "water_u");
    EXPECT_EQ(nc.isoTime(0.0), "2000-01-01T00:00:00Z");
    EXPECT_EQ(nc.loadedShape, (std::vector<std::size_t>{12, 6, 8, 10}));
    const GriddedCurrentField &f = *nc.field;
    EXPECT_EQ(f.timeEnd(), 33.0 * 3600); // Refuse by default
    // at nodes: exact (float storage)
    for (double lon : {280.0, 281.5, 284.5})
        for (double lat : {30.0, 31.5, 33.5})
            for (double z : {0.0, 30.0, 100.0})
                for (double hour : {0.0, 9.0, 33.0})
                {
                    const Point2 p = nc.toLocal({lon, lat});
                    const Velocity e = inPlane(nc, lon, lat, hyU(lon, lat, z, hour), hyV(lon, lat, z, hour));
                    const Velocity c = f.velocity(p.x, p.y, z, hour * 3600);
                    EXPECT_NEAR(c.u, e.u, 1e-6) << lon << " " << lat << " " << z << " " << hour;
                    EXPECT_NEAR(c.v, e.v, 1e-6);
                }
    // between nodes in space, depth and time: linear in all four, reproduced by bilinear/linear
    for (double lon : {280.2, 281.37, 283.9})
        for (double lat : {30.1, 32.26})
            for (double z : {5.0, 64.0})
                for (double hour : {1.0, 20.5})
                {
                    const Point2 p = nc.toLocal({lon, lat});
                    const Velocity e = inPlane(nc, lon, lat, hyU(lon, lat, z, hour), hyV(lon, lat, z, hour));
                    const Velocity c = f.velocity(p.x, p.y, z, hour * 3600);
                    EXPECT_NEAR(c.u, e.u, 2e-4) << lon << " " << lat << " " << z << " " << hour;
                    EXPECT_NEAR(c.v, e.v, 2e-4);
                }
    // the shelf: wet at the surface, dry at 300 m east of 283 E, wet at 300 m west of it
    Point2 p = nc.toLocal({-76.5, 32.0});
    EXPECT_TRUE(f.inWater(p.x, p.y, 0));
    EXPECT_FALSE(f.inWater(p.x, p.y, 300));
    p = nc.toLocal({-79.0, 32.0});
    EXPECT_TRUE(f.inWater(p.x, p.y, 300));
    // outside the grid
    p = nc.toLocal({-70.0, 32.0});
    EXPECT_FALSE(f.inWater(p.x, p.y, 0));
    // round trip of coordinates for output
    const LonLat g = nc.toGeographic(nc.toLocal({-78.25, 31.75}));
    EXPECT_NEAR(g.lon, -78.25, 1e-9);
    EXPECT_NEAR(g.lat, 31.75, 1e-9);
}

TEST(NetCdfLayouts, LoadsOnlyTheRegionDepthsAndTimesTheMissionNeeds)
{
    TempDir tmp;
    const std::string path = tmp.file("hycom.nc");
    writeHycom(path, false);
    GriddedCurrentOptions o;
    o.lonMin = -79.0; // the file is 0..360
    o.lonMax = -78.0;
    o.latMin = 31.0;
    o.latMax = 32.0;
    o.marginNodes = 1;
    o.maxDepth = 20.0;                    // layers 0, 10, 30 (first at or below 20) + 2 = 5
    o.departure = "2000-01-01T06:00:00Z"; // hour 6 = index 2
    o.horizon = 3 * 3600.0;               // to hour 9 = index 3: indices 0 .. 6 with the margin of 2
    o.field.beyond = BeyondForecast::HoldLast;
    const GriddedCurrents nc = loadGriddedCurrents(path, o);
    // lon -79 .. -78 = 281 .. 282: nodes 2..4 + 1 = 1..5 (5); lat 31..32: nodes 2..4 + 1 = 1..5 (5)
    EXPECT_EQ(nc.loadedShape, (std::vector<std::size_t>{7, 5, 5, 5}));
    EXPECT_LT(nc.loadedValues * 6, nc.fileValues);
    EXPECT_NEAR(nc.departureTime, 6 * 3600.0, 1e-9);
    EXPECT_TRUE(std::isinf(nc.field->timeEnd()));
    EXPECT_NEAR(nc.projection->lon0(), -78.5, 1e-12);
    EXPECT_NEAR(nc.projection->lat0(), 31.5, 1e-12);
    // the subset gives the same values as the whole file
    const GriddedCurrents all = loadGriddedCurrents(path, GriddedCurrentOptions{});
    for (double lon : {-78.9, -78.3})
        for (double lat : {31.2, 31.8})
            for (double z : {0.0, 15.0})
            {
                const Point2 p = nc.toLocal({lon, lat});
                const Velocity a = nc.field->velocity(p.x, p.y, z, 8 * 3600.0);
                const Velocity e = inPlane(nc, lon, lat, hyU(lon + 360, lat, z, 8), hyV(lon + 360, lat, z, 8));
                EXPECT_NEAR(a.u, e.u, 2e-4);
                EXPECT_NEAR(a.v, e.v, 2e-4);
                const Point2 q = all.toLocal({lon, lat});
                const Velocity b = all.field->velocity(q.x, q.y, z, 8 * 3600.0);
                EXPECT_NEAR(std::hypot(a.u, a.v), std::hypot(b.u, b.v), 2e-4);
            }
    // departure outside the forecast: a clear error
    o.departure = "2000-01-03T00:00:00Z";
    try
    {
        loadGriddedCurrents(path, o);
        FAIL();
    }
    catch (const Error &e)
    {
        const std::string m = e.what();
        EXPECT_NE(m.find("outside the forecast"), std::string::npos) << m;
        EXPECT_NE(m.find(path), std::string::npos) << m;
        EXPECT_NE(m.find("2000-01-02T09:00:00Z"), std::string::npos) << m; // the last forecast time
    }
    o.departure = "1999-12-31T23:00:00Z";
    EXPECT_THROW(loadGriddedCurrents(path, o), Error);
    o.departure = "7200"; // seconds after the first forecast time
    EXPECT_NEAR(loadGriddedCurrents(path, o).departureTime, 7200.0, 1e-9);
}

TEST(NetCdfLayouts, CmemsLikeFloatDescendingLatitudeWithFill)
{
    TempDir tmp;
    const std::string path = tmp.file("cmems.nc");
    const std::vector<double> lat = linspace(34.0, -0.5, 5); // descending
    const std::vector<double> lon = linspace(-10.0, 0.5, 6);
    const std::vector<double> time{946684800.0, 946684800.0 + 86400}; // seconds since 1970: 2000-01-01, -02
    {
        NcWriter w(path);
        const int dt = w.dim("time", 2), dz = w.dim("depth", 1), dy = w.dim("latitude", 5), dx = w.dim("longitude", 6);
        const int vt = w.var("time", NC_DOUBLE, {dt}), vz = w.var("depth", NC_FLOAT, {dz});
        const int vy = w.var("latitude", NC_FLOAT, {dy}), vx = w.var("longitude", NC_FLOAT, {dx});
        w.text(vt, "units", "seconds since 1970-01-01 00:00:00");
        w.text(vt, "calendar", "proleptic_gregorian");
        w.text(vz, "units", "m");
        w.text(vy, "standard_name", "latitude");
        w.text(vx, "standard_name", "longitude");
        w.text(vy, "units", "degrees_north");
        w.text(vx, "units", "degrees_east");
        const int u = w.var("uo", NC_FLOAT, {dt, dz, dy, dx}), v = w.var("vo", NC_FLOAT, {dt, dz, dy, dx});
        w.text(u, "standard_name", "eastward_sea_water_velocity");
        w.text(v, "standard_name", "northward_sea_water_velocity");
        w.text(u, "units", "m s-1");
        w.text(v, "units", "m s-1");
        w.fill(u, NC_FLOAT, 1e20);
        w.fill(v, NC_FLOAT, 1e20);
        w.enddef();
        w.put(vt, time);
        w.put(vz, {0.494});
        w.put(vy, lat);
        w.put(vx, lon);
        std::vector<double> pu, pv;
        for (int t = 0; t < 2; ++t)
            for (double la : lat)
                for (double lo : lon)
                {
                    const bool land = la == 34.0 && lo == -10.0; // north-west corner node
                    pu.push_back(land ? 1e20 : 0.25 + 0.1 * (la - 32.0) + 0.05 * t);
                    pv.push_back(land ? 1e20 : 0.05 * (lo + 10.0));
                }
        w.put(u, pu);
        w.put(v, pv);
    }
    const GriddedCurrents nc = loadGriddedCurrents(path);
    EXPECT_EQ(nc.isoTime(0), "2000-01-01T00:00:00Z");
    EXPECT_EQ(nc.isoTime(86400), "2000-01-02T00:00:00Z");
    EXPECT_NEAR(nc.fieldTime("2000-01-01T12:00:00Z"), 43200.0, 1e-9);
    const GriddedCurrentField &f = *nc.field;
    // (points on the outer rows are avoided: a parallel bulges out of the straight cell edge in the plane)
    for (double la : {32.1, 32.75, 33.4})
        for (double lo : {-9.5, -8.2, -7.6})
        {
            const Point2 p = nc.toLocal({lo, la});
            const Velocity e = inPlane(nc, lo, la, 0.25 + 0.1 * (la - 32.0) + 0.025, 0.05 * (lo + 10.0));
            const Velocity c = f.velocity(p.x, p.y, 0.494, 43200.0);
            EXPECT_NEAR(c.u, e.u, 1e-4) << la << " " << lo;
            EXPECT_NEAR(c.v, e.v, 1e-4);
            EXPECT_TRUE(f.inWater(p.x, p.y, 0.494));
        }
    // the land corner: dry cell, zero current at the node, no 1e20 anywhere
    Point2 p = nc.toLocal({-9.75, 33.75});
    EXPECT_FALSE(f.inWater(p.x, p.y, 0.494));
    p = nc.toLocal({-10.0, 34.0});
    const Velocity c = f.velocity(p.x, p.y, 0.494, 0);
    EXPECT_NEAR(std::hypot(c.u, c.v), 0.0, 1e-5);
    EXPECT_LT(f.maxSpeed(Region{}), 1.0);
}

TEST(NetCdfLayouts, GlobalGridCutAcrossTheAntimeridian)
{
    TempDir tmp;
    const std::string path = tmp.file("global.nc");
    const std::vector<double> lon = linspace(-180.0, 1.0, 360), lat{-1.0, 0.0, 1.0, 2.0};
    {
        NcWriter w(path);
        const int dy = w.dim("lat", 4), dx = w.dim("lon", 360);
        const int vy = w.var("lat", NC_DOUBLE, {dy}), vx = w.var("lon", NC_DOUBLE, {dx});
        w.text(vy, "units", "degrees_north");
        w.text(vx, "units", "degrees_east");
        const int u = w.var("u", NC_FLOAT, {dy, dx}), v = w.var("v", NC_FLOAT, {dy, dx});
        w.text(u, "units", "cm/s");
        w.text(v, "units", "cm/s");
        w.enddef();
        w.put(vy, lat);
        w.put(vx, lon);
        std::vector<double> pu, pv;
        for (std::size_t j = 0; j < 4; ++j)
            for (double lo : lon)
            {
                pu.push_back(0.1 * std::fmod(lo + 360.0, 360.0)); // cm/s, continuous across 180
                pv.push_back(0.0);
            }
        w.put(u, pu);
        w.put(v, pv);
    }
    GriddedCurrentOptions o;
    o.lonMin = 178.0;
    o.lonMax = -178.0; // across the antimeridian
    o.latMin = 0.0;
    o.latMax = 1.0;
    const GriddedCurrents nc = loadGriddedCurrents(path, o);
    EXPECT_LE(nc.loadedShape[3], 10u);            // 176 .. 184 (9 nodes), not 360
    EXPECT_TRUE(std::isinf(nc.field->timeEnd())); // steady
    for (double lo : {178.0, 179.5, -180.0, -179.25, -178.0})
    {
        const Point2 p = nc.toLocal({lo, 0.5});
        const double expectMs = 0.001 * std::fmod(lo + 360.0, 360.0); // cm/s -> m/s
        const Velocity c = nc.field->velocity(p.x, p.y, 0, 0);
        EXPECT_NEAR(std::hypot(c.u, c.v), expectMs, 1e-6) << lo;
        EXPECT_TRUE(nc.field->inWater(p.x, p.y, 0));
    }
}

TEST(NetCdfLayouts, CurvilinearNemoLikeGridWithLandAndNoleapCalendar)
{
    TempDir tmp;
    const std::string path = tmp.file("nemo.nc");
    const std::size_t ni = 12, nj = 9;
    const double th = 0.35;
    auto nodeLon = [&](double i, double j) {
        return -50.0 + 0.1 * (i * std::cos(th) - j * std::sin(th)) / std::cos(45.0 * M_PI / 180);
    };
    auto nodeLat = [&](double i, double j) { return 45.0 + 0.1 * (i * std::sin(th) + j * std::cos(th)); };
    auto uf = [](double i, double j, double day) { return 0.1 + 0.01 * i + 0.02 * j + 0.04 * day; };
    auto vf = [](double, double j, double) { return -0.05 + 0.01 * j; };
    auto land = [&](std::size_t i, std::size_t j) { return i >= 9 && j >= 6; };
    {
        NcWriter w(path);
        const int dt = w.dim("time_counter", 2), dz = w.dim("deptht", 1), dy = w.dim("y", nj), dx = w.dim("x", ni);
        const int vt = w.var("time_counter", NC_DOUBLE, {dt}), vz = w.var("deptht", NC_FLOAT, {dz});
        const int la = w.var("nav_lat", NC_FLOAT, {dy, dx}), lo = w.var("nav_lon", NC_FLOAT, {dy, dx});
        w.text(vt, "units", "days since 1950-01-01 00:00:00");
        w.text(vt, "calendar", "noleap");
        w.text(vz, "units", "m");
        w.text(vz, "positive", "down");
        w.text(la, "units", "degrees_north");
        w.text(lo, "units", "degrees_east");
        const int u = w.var("vozocrtx", NC_DOUBLE, {dt, dz, dy, dx}),
                  v = w.var("vomecrty", NC_DOUBLE, {dt, dz, dy, dx});
        for (int var : {u, v})
        {
            w.text(var, "units", "m/s");
            w.text(var, "coordinates", "nav_lon nav_lat");
            w.num(var, "missing_value", NC_DOUBLE, {-999.0});
        }
        // eastward/northward as written (without, the rotated grid's velocities would be read as along the grid)
        w.text(u, "standard_name", "eastward_sea_water_velocity");
        w.text(v, "standard_name", "northward_sea_water_velocity");
        w.enddef();
        w.put(vt, {25550.0, 25550.25}); // 2020-01-01 00:00 and 06:00 in the noleap calendar
        w.put(vz, {0.5});
        std::vector<double> pla, plo, pu, pv;
        for (std::size_t j = 0; j < nj; ++j)
            for (std::size_t i = 0; i < ni; ++i)
            {
                pla.push_back(nodeLat(i, j));
                plo.push_back(nodeLon(i, j));
            }
        for (double day : {0.0, 0.25})
            for (std::size_t j = 0; j < nj; ++j)
                for (std::size_t i = 0; i < ni; ++i)
                {
                    pu.push_back(land(i, j) ? -999.0 : uf(i, j, day));
                    pv.push_back(land(i, j) ? -999.0 : vf(i, j, day));
                }
        w.put(la, pla);
        w.put(lo, plo);
        w.put(u, pu);
        w.put(v, pv);
    }
    GriddedCurrentOptions o;
    o.uName = "vozocrtx";
    o.vName = "vomecrty";
    const GriddedCurrents nc = loadGriddedCurrents(path, o);
    ASSERT_TRUE(nc.field->curvilinear());
    EXPECT_EQ(nc.calendar, Calendar::NoLeap);
    EXPECT_EQ(nc.isoTime(0), "2020-01-01T00:00:00Z");
    EXPECT_NEAR(nc.fieldTime("2020-01-01T06:00:00Z"), 21600.0, 1e-9);
    EXPECT_EQ(nc.field->timeEnd(), 21600.0);
    const GriddedCurrentField &f = *nc.field;
    // nav_lat/nav_lon are float: compare at the stored node positions and at index-space midpoints
    for (double i : {0.5, 2.0, 3.5, 7.25})
        for (double j : {0.25, 1.5, 4.0, 7.75})
        {
            const double lon = nodeLon(i, j), lat = nodeLat(i, j);
            const Point2 p = nc.toLocal({lon, lat});
            EXPECT_TRUE(f.inWater(p.x, p.y, 0.5)) << i << " " << j;
            const Velocity e = inPlane(nc, lon, lat, uf(i, j, 0.125), vf(i, j, 0.125));
            const Velocity c = f.velocity(p.x, p.y, 0.5, 10800.0);
            EXPECT_NEAR(c.u, e.u, 2e-4) << i << " " << j;
            EXPECT_NEAR(c.v, e.v, 2e-4) << i << " " << j;
        }
    // land corner (i >= 9, j >= 6): dry, and no -999 read as a current
    Point2 p = nc.toLocal({nodeLon(10.5, 7.5), nodeLat(10.5, 7.5)});
    EXPECT_FALSE(f.inWater(p.x, p.y, 0.5));
    const Velocity c = f.velocity(p.x, p.y, 0.5, 0);
    EXPECT_LT(std::hypot(c.u, c.v), 1.0);
    p = nc.toLocal({nodeLon(8.5, 5.5), nodeLat(8.5, 5.5)}); // cell with the land corner (9, 6)
    EXPECT_FALSE(f.inWater(p.x, p.y, 0.5));
    p = nc.toLocal({nodeLon(7.5, 5.5), nodeLat(7.5, 5.5)});
    EXPECT_TRUE(f.inWater(p.x, p.y, 0.5));
    // region subset of a curvilinear grid
    o.lonMin = nodeLon(2, 2);
    o.lonMax = nodeLon(4, 2);
    o.latMin = nodeLat(2, 2);
    o.latMax = nodeLat(2, 4);
    o.marginNodes = 1;
    const GriddedCurrents sub = loadGriddedCurrents(path, o);
    EXPECT_LT(sub.loadedValues, nc.loadedValues);
    p = sub.toLocal({nodeLon(3, 3), nodeLat(3, 3)});
    const Velocity e = inPlane(sub, nodeLon(3, 3), nodeLat(3, 3), uf(3, 3, 0), vf(3, 3, 0));
    EXPECT_NEAR(sub.field->velocity(p.x, p.y, 0.5, 0).u, e.u, 2e-4);
}

TEST(NetCdfLayouts, DepthPositiveUpAndCartesianFiles)
{
    TempDir tmp;
    const std::string path = tmp.file("cart.nc");
    {
        NcWriter w(path);
        const int dz = w.dim("z", 3), dy = w.dim("y", 3), dx = w.dim("x", 4);
        const int vz = w.var("z", NC_DOUBLE, {dz}), vy = w.var("y", NC_DOUBLE, {dy}), vx = w.var("x", NC_DOUBLE, {dx});
        w.text(vz, "units", "m");
        w.text(vz, "positive", "up");
        w.text(vx, "units", "km");
        w.text(vy, "units", "km");
        const int u = w.var("u", NC_FLOAT, {dz, dy, dx}), v = w.var("v", NC_FLOAT, {dz, dy, dx});
        w.text(u, "units", "cm s-1");
        w.text(v, "units", "cm s-1");
        w.enddef();
        w.put(vz, {-100.0, -50.0, 0.0}); // positive up: 100 m deep first
        w.put(vy, {0, 1, 2});
        w.put(vx, {0, 1, 2, 3});
        std::vector<double> pu, pv;
        for (double z : {100.0, 50.0, 0.0})
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 4; ++i)
                {
                    pu.push_back(10.0 + 0.1 * z + i); // cm/s
                    pv.push_back(-5.0 + j);
                }
        w.put(u, pu);
        w.put(v, pv);
    }
    const GriddedCurrents nc = loadGriddedCurrents(path);
    EXPECT_FALSE(nc.geographic);
    EXPECT_EQ(nc.projection, nullptr);
    const Velocity c = nc.field->velocity(1500.0, 500.0, 75.0, 0.0); // km axes -> metres
    EXPECT_NEAR(c.u, 0.01 * (10.0 + 7.5 + 1.5), 1e-7);
    EXPECT_NEAR(c.v, 0.01 * (-5.0 + 0.5), 1e-7);
    EXPECT_EQ(nc.field->depthAxis().front(), 0.0);
    EXPECT_EQ(nc.field->depthAxis().back(), 100.0);
    GriddedCurrentOptions o;
    o.maxDepth = 10.0; // layers 0, 50 + 2 -> all 3 here
    EXPECT_EQ(loadGriddedCurrents(path, o).loadedShape[1], 3u);
    // the same with every name given: still Cartesian (the names do not make it geographic)
    o.uName = "u";
    o.vName = "v";
    o.lonName = "x";
    o.latName = "y";
    o.depthName = "z";
    const GriddedCurrents named = loadGriddedCurrents(path, o);
    EXPECT_FALSE(named.geographic);
    EXPECT_NEAR(named.field->velocity(1500.0, 500.0, 75.0, 0.0).u, c.u, 1e-9);
    // asking for geographic coordinates of a Cartesian file is an error naming what was expected
    o.coordinates = CoordinateMode::Geographic;
    EXPECT_THROW(loadGriddedCurrents(path, o), Error);
}

TEST(NetCdfLayouts, ErrorsNameTheFileTheVariableAndWhatWasExpected)
{
    TempDir tmp;
    const std::string path = tmp.file("hycom.nc");
    writeHycom(path, false);
    auto message = [&](const std::string &p, const GriddedCurrentOptions &o) -> std::string {
        try
        {
            loadGriddedCurrents(p, o);
        }
        catch (const Error &e)
        {
            return e.what();
        }
        return "";
    };
    GriddedCurrentOptions o;
    o.uName = "nope";
    std::string m = message(path, o);
    EXPECT_NE(m.find(path), std::string::npos) << m;
    EXPECT_NE(m.find("'nope'"), std::string::npos) << m;
    EXPECT_NE(m.find("uName"), std::string::npos) << m;

    m = message(tmp.file("missing.nc"), {});
    EXPECT_NE(m.find("missing.nc"), std::string::npos) << m;

    // a file without velocities
    const std::string empty = tmp.file("temp.nc");
    {
        NcWriter w(empty);
        const int dx = w.dim("lon", 3);
        const int t = w.var("temperature", NC_FLOAT, {dx});
        w.text(t, "units", "K");
        w.enddef();
        w.put(t, {1, 2, 3});
    }
    m = message(empty, {});
    EXPECT_NE(m.find("eastward_sea_water_velocity"), std::string::npos) << m;
    EXPECT_NE(m.find("temp.nc"), std::string::npos) << m;

    // wrong units, bad time units, unknown dimension
    auto variant = [&](const std::string &name, const std::string &uunits, const std::string &tunits, bool extraDim) {
        const std::string p = tmp.file(name);
        NcWriter w(p);
        const int dt = w.dim("time", 2), de = w.dim("member", 3), dy = w.dim("lat", 2), dx = w.dim("lon", 2);
        const int vt = w.var("time", NC_DOUBLE, {dt}), vy = w.var("lat", NC_DOUBLE, {dy}),
                  vx = w.var("lon", NC_DOUBLE, {dx});
        w.text(vt, "units", tunits);
        w.text(vy, "units", "degrees_north");
        w.text(vx, "units", "degrees_east");
        std::vector<int> dims = extraDim ? std::vector<int>{dt, de, dy, dx} : std::vector<int>{dt, dy, dx};
        const int u = w.var("uo", NC_FLOAT, dims), v = w.var("vo", NC_FLOAT, dims);
        w.text(u, "units", uunits);
        w.text(v, "units", "m/s");
        w.enddef();
        w.put(vt, {0, 1});
        w.put(vy, {10, 11});
        w.put(vx, {20, 21});
        const std::vector<double> z(extraDim ? 24 : 8, 0.1);
        w.put(u, z);
        w.put(v, z);
        return p;
    };
    // (furlongs/fortnight is a velocity UDUNITS-2 converts: TestNetCdfUnitsAndNames.cpp)
    m = message(variant("units.nc", "furlongs per blink", "hours since 2000-01-01", false), {});
    EXPECT_NE(m.find("'uo'"), std::string::npos) << m;
    EXPECT_NE(m.find("furlongs per blink"), std::string::npos) << m;
    EXPECT_NE(m.find("m/s"), std::string::npos) << m;
    m = message(variant("tunits.nc", "m/s", "hours after 2000-01-01", false), {});
    EXPECT_NE(m.find("'time'"), std::string::npos) << m;
    EXPECT_NE(m.find("since"), std::string::npos) << m;
    m = message(variant("dims.nc", "m/s", "hours since 2000-01-01", true), {});
    EXPECT_NE(m.find("'member'"), std::string::npos) << m;
    // region outside the file
    GriddedCurrentOptions r;
    r.lonMin = 0;
    r.lonMax = 1;
    r.latMin = -60;
    r.latMax = -59;
    m = message(path, r);
    EXPECT_NE(m.find("latitude"), std::string::npos) << m;
    EXPECT_NE(m.find("'lat'"), std::string::npos) << m;
}
