// Model grids as ocean models write them: a global curvilinear grid whose i-index wraps (a displaced-pole
// grid's seam in the ocean), with and without a repeated seam column; a ROMS-like Arakawa C grid (u and v on their
// own points, rotated by `angle`, masks mask_rho/mask_u/mask_v); a POP-like B grid (UVEL/VVEL along the grid in cm/s
// on ULONG/ULAT, ANGLE, KMU). Every file is written here with NetCDF-C; the loaded field is compared at nodes with
// the analytic eastward/northward current the file was made from.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "ModelGrids.h"
#include "TestNetCdfUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/current/GriddedCurrents.h"

using namespace ompl_glider;
using glider_test::inPlane;
using glider_test::kDeg;
using glider_test::NcWriter;
using glider_test::regionOptions;
using glider_test::RomsGrid;
using glider_test::TempDir;
using glider_test::wrapCurrent;
using glider_test::WrapGrid;

namespace
{

void expectWrapNodes(const GriddedCurrents &nc, const WrapGrid &g, std::size_t j, const std::vector<std::size_t> &cols)
{
    for (std::size_t i : cols)
    {
        const double lon = g.lon(j, i), lat = g.lat(j, i);
        double ue, vn;
        wrapCurrent(lon, lat, ue, vn);
        const Velocity e = inPlane(nc, lon, lat, double(float(ue)), double(float(vn)));
        const Point2 p = nc.toLocal({lon, lat});
        const Velocity c = nc.field->velocity(p.x, p.y, 0.0, 0.0);
        EXPECT_NEAR(c.u, e.u, 1e-6) << "node (" << j << ", " << i << ") at " << lon << ", " << lat;
        EXPECT_NEAR(c.v, e.v, 1e-6) << "node (" << j << ", " << i << ") at " << lon << ", " << lat;
        EXPECT_TRUE(nc.field->inWater(p.x, p.y, 0.0));
    }
}

} // namespace

TEST(NetCdfModelGrids, CurvilinearGridWhoseIndexWrapsIsSubsetAcrossItsSeam)
{
    TempDir tmp;
    for (bool repeat : {false, true})
    {
        WrapGrid g;
        g.repeat = repeat;
        const std::string path = tmp.file(repeat ? "repeat.nc" : "wrap.nc");
        g.write(path);
        // a region across the index seam (43W | 40W): the columns on both sides of it, not the whole band
        const GriddedCurrents nc = loadGriddedCurrents(path, regionOptions(-52, -28, 10, 30));
        ASSERT_TRUE(nc.field->curvilinear());
        EXPECT_LE(nc.loadedShape[3], 16u) << "columns loaded (repeat " << repeat << ")";
        EXPECT_GE(nc.loadedShape[3], 9u);
        EXPECT_LE(nc.loadedShape[2], 16u);
        EXPECT_LT(nc.lonMin, -52.0);
        EXPECT_GT(nc.lonMax, -28.0);
        expectWrapNodes(nc, g, 30, {116, 117, 118, 119, 0, 1, 2, 3});
        expectWrapNodes(nc, g, 35, {117, 119, 0, 2});
        // between nodes across the seam: the cell between columns 119 and 0 is water and interpolates the two
        const LonLat mid{0.5 * (g.lon(30, 119) + g.lon(30, 0)), 0.5 * (g.lat(30, 119) + g.lat(30, 0))};
        const Point2 p = nc.toLocal(mid);
        EXPECT_TRUE(nc.field->inWater(p.x, p.y, 0.0));
        double ue, vn;
        wrapCurrent(mid.lon, mid.lat, ue, vn);
        const Velocity e = inPlane(nc, mid.lon, mid.lat, ue, vn), c = nc.field->velocity(p.x, p.y, 0.0, 0.0);
        EXPECT_NEAR(c.u, e.u, 2e-4);
        EXPECT_NEAR(c.v, e.v, 2e-4);
        // a region away from the seam, and one across the value seam (180) near column 73
        const GriddedCurrents east = loadGriddedCurrents(path, regionOptions(10, 30, -10, 10));
        EXPECT_LE(east.loadedShape[3], 14u);
        expectWrapNodes(east, g, 20, {17, 18, 19, 20});
        const GriddedCurrents pacific = loadGriddedCurrents(path, regionOptions(170, -170, 0, 20));
        EXPECT_LE(pacific.loadedShape[3], 14u);
        expectWrapNodes(pacific, g, 25, {70, 71, 72, 73});
    }
}

TEST(NetCdfModelGrids, RomsCGridIsReadAtItsOwnPointsRotatedAndMasked)
{
    TempDir tmp;
    const RomsGrid grid;
    const std::string path = tmp.file("roms.nc");
    grid.write(path);
    const GriddedCurrents nc = loadGriddedCurrents(path);
    ASSERT_TRUE(nc.field->curvilinear());
    EXPECT_EQ(nc.maskVariable, "mask_rho");
    // the interior rho points: 12 x 16
    EXPECT_EQ(nc.loadedShape[2], RomsGrid::kEta - 2);
    EXPECT_EQ(nc.loadedShape[3], RomsGrid::kXi - 2);
    std::size_t checked = 0;
    for (std::size_t j = 1; j + 1 < RomsGrid::kEta; ++j)
        for (std::size_t i = 1; i + 1 < RomsGrid::kXi; ++i)
        {
            const LonLat g = grid.geo(double(j), double(i));
            const Point2 p = nc.toLocal(g);
            // land rho points are dry (a point is water where the cell holding it has no land corner)
            bool nearLand = false;
            for (std::size_t a = j - 1; a <= j + 1; ++a)
                for (std::size_t b = i - 1; b <= i + 1; ++b)
                    nearLand = nearLand || RomsGrid::land(a, b);
            if (RomsGrid::land(j, i))
            {
                EXPECT_FALSE(nc.field->inWater(p.x, p.y, 0.0)) << j << " " << i;
                continue;
            }
            if (nearLand)
                continue;
            EXPECT_TRUE(nc.field->inWater(p.x, p.y, 0.0)) << j << " " << i;
            double ue, vn;
            RomsGrid::current(grid.at(double(j), double(i)), ue, vn);
            const Velocity e = inPlane(nc, g.lon, g.lat, ue, vn), c = nc.field->velocity(p.x, p.y, 0.0, 0.0);
            EXPECT_NEAR(c.u, e.u, 2e-6) << j << " " << i;
            EXPECT_NEAR(c.v, e.v, 2e-6) << j << " " << i;
            ++checked;
        }
    EXPECT_GT(checked, 120u);
    // the coast face counts as zero flow: at the rho point west of the land block, u is the mean of its west face
    // and 0
    {
        const std::size_t j = 10, i = 10;
        const LonLat g = grid.geo(double(j), double(i));
        const Point2 p = nc.toLocal(g);
        double ue, vn;
        RomsGrid::current(grid.at(double(j), double(i) - 0.5), ue, vn);
        const double west = ue * std::cos(grid.theta) + vn * std::sin(grid.theta);
        RomsGrid::current(grid.at(double(j) - 0.5, double(i)), ue, vn);
        const double south = -ue * std::sin(grid.theta) + vn * std::cos(grid.theta);
        RomsGrid::current(grid.at(double(j) + 0.5, double(i)), ue, vn);
        const double north = -ue * std::sin(grid.theta) + vn * std::cos(grid.theta);
        const double ug = 0.5 * west, vg = 0.5 * (south + north);
        const Velocity e = inPlane(nc, g.lon, g.lat, ug * std::cos(grid.theta) - vg * std::sin(grid.theta),
                                   ug * std::sin(grid.theta) + vg * std::cos(grid.theta));
        const Velocity c = nc.field->velocity(p.x, p.y, 0.0, 0.0);
        EXPECT_NEAR(c.u, e.u, 2e-6);
        EXPECT_NEAR(c.v, e.v, 2e-6);
    }
    // without the angle the components stay along the grid: 30 degrees off
    GriddedCurrentOptions none;
    none.angleName = "none";
    const GriddedCurrents raw = loadGriddedCurrents(path, none);
    const LonLat g = grid.geo(4, 4);
    double ue, vn;
    RomsGrid::current(grid.at(4, 4), ue, vn);
    const Point2 p = raw.toLocal(g);
    const Velocity e = inPlane(raw, g.lon, g.lat, ue, vn), c = raw.field->velocity(p.x, p.y, 0.0, 0.0);
    EXPECT_GT(std::hypot(c.u - e.u, c.v - e.v), 0.1);
    // a region: fewer rho points, the same values
    const LonLat lo = grid.geo(3, 3), hi = grid.geo(7, 8);
    const GriddedCurrents sub =
        loadGriddedCurrents(path, regionOptions(std::min(lo.lon, hi.lon), std::max(lo.lon, hi.lon),
                                                std::min(lo.lat, hi.lat), std::max(lo.lat, hi.lat)));
    EXPECT_LT(sub.loadedValues, nc.loadedValues);
    const LonLat m = grid.geo(5, 5);
    RomsGrid::current(grid.at(5, 5), ue, vn);
    const Point2 q = sub.toLocal(m);
    const Velocity es = inPlane(sub, m.lon, m.lat, ue, vn), cs = sub.field->velocity(q.x, q.y, 0.0, 0.0);
    EXPECT_NEAR(cs.u, es.u, 2e-6);
    EXPECT_NEAR(cs.v, es.v, 2e-6);
}

TEST(NetCdfModelGrids, RomsCGridWithoutMasksTakesLandFromFillValues)
{
    TempDir tmp;
    const RomsGrid grid;
    const std::string path = tmp.file("roms_nomask.nc");
    grid.write(path, false);
    const GriddedCurrents nc = loadGriddedCurrents(path);
    EXPECT_EQ(nc.maskVariable, "");
    // inside the land block (both faces of u fill values): land; two points off it: water with the true current
    for (auto [j, i] : {std::pair<std::size_t, std::size_t>{10, 12}, {10, 13}})
    {
        const Point2 p = nc.toLocal(grid.geo(double(j), double(i)));
        EXPECT_FALSE(nc.field->inWater(p.x, p.y, 0.0)) << j << " " << i;
    }
    const LonLat g = grid.geo(4, 6);
    double ue, vn;
    RomsGrid::current(grid.at(4, 6), ue, vn);
    const Point2 p = nc.toLocal(g);
    EXPECT_TRUE(nc.field->inWater(p.x, p.y, 0.0));
    const Velocity e = inPlane(nc, g.lon, g.lat, ue, vn), c = nc.field->velocity(p.x, p.y, 0.0, 0.0);
    EXPECT_NEAR(c.u, e.u, 2e-6);
    EXPECT_NEAR(c.v, e.v, 2e-6);
}

TEST(NetCdfModelGrids, PopBGridAlongTheGridInCmPerSecondWithAngleAndKmu)
{
    TempDir tmp;
    const std::string path = tmp.file("pop.nc");
    // a rotated grid as in RomsGrid (angle 30 degrees given in degrees here), u and v together on the U points,
    // two depth levels (z_t in cm), KMU = 1 (one ocean level) on a block, 0 (land) on another
    const RomsGrid grid;
    const std::size_t nj = RomsGrid::kEta, ni = RomsGrid::kXi;
    auto kmu = [](std::size_t j, std::size_t i) { return RomsGrid::land(j, i) ? 0.0 : (i <= 4 && j <= 4 ? 1.0 : 2.0); };
    {
        NcWriter w(path, NC_CLOBBER);
        const int dt = w.dim("time", 1), dz = w.dim("z_t", 2), dj = w.dim("nlat", nj), di = w.dim("nlon", ni);
        const int vt = w.var("time", NC_DOUBLE, {dt}), vz = w.var("z_t", NC_FLOAT, {dz});
        w.text(vt, "units", "days since 0001-01-01 00:00:00");
        w.text(vt, "calendar", "noleap");
        w.text(vz, "units", "centimeters");
        w.text(vz, "positive", "down");
        const int ul = w.var("ULONG", NC_DOUBLE, {dj, di}), ua = w.var("ULAT", NC_DOUBLE, {dj, di});
        const int tl = w.var("TLONG", NC_DOUBLE, {dj, di}), ta = w.var("TLAT", NC_DOUBLE, {dj, di});
        for (int var : {ul, tl})
            w.text(var, "units", "degrees_east");
        for (int var : {ua, ta})
            w.text(var, "units", "degrees_north");
        const int an = w.var("ANGLE", NC_DOUBLE, {dj, di});
        w.text(an, "units", "degrees");
        const int km = w.var("KMU", NC_INT, {dj, di});
        const int u = w.var("UVEL", NC_FLOAT, {dt, dz, dj, di}), v = w.var("VVEL", NC_FLOAT, {dt, dz, dj, di});
        for (int var : {u, v})
        {
            w.text(var, "units", "centimeter/s");
            w.text(var, "coordinates", "ULONG ULAT z_t time");
        }
        w.enddef();
        w.put(vt, {730000.0});
        w.put(vz, {500.0, 5000.0}); // 5 m and 50 m
        std::vector<double> lon, lat, tlon, tlat, m, pu, pv;
        for (std::size_t j = 0; j < nj; ++j)
            for (std::size_t i = 0; i < ni; ++i)
            {
                const LonLat g = grid.geo(double(j), double(i)), h = grid.geo(double(j) - 0.5, double(i) - 0.5);
                lon.push_back(g.lon);
                lat.push_back(g.lat);
                tlon.push_back(h.lon);
                tlat.push_back(h.lat);
                m.push_back(kmu(j, i));
            }
        for (int k = 0; k < 2; ++k)
            for (std::size_t j = 0; j < nj; ++j)
                for (std::size_t i = 0; i < ni; ++i)
                {
                    double ue, vn;
                    RomsGrid::current(grid.at(double(j), double(i)), ue, vn);
                    const double s = k == 0 ? 100.0 : 50.0; // cm/s; half the speed at 50 m
                    pu.push_back(kmu(j, i) > k ? s * (ue * std::cos(grid.theta) + vn * std::sin(grid.theta)) : 0.0);
                    pv.push_back(kmu(j, i) > k ? s * (-ue * std::sin(grid.theta) + vn * std::cos(grid.theta)) : 0.0);
                }
        w.put(ul, lon);
        w.put(ua, lat);
        w.put(tl, tlon);
        w.put(ta, tlat);
        w.put(an, std::vector<double>(nj * ni, 30.0));
        w.put(km, m);
        w.put(u, pu);
        w.put(v, pv);
    }
    GriddedCurrentOptions o;
    o.uName = "UVEL";
    o.vName = "VVEL";
    const GriddedCurrents nc = loadGriddedCurrents(path, o);
    EXPECT_EQ(nc.maskVariable, "KMU");
    EXPECT_EQ(nc.loadedShape[3], ni); // the U points themselves
    for (auto [j, i] : {std::pair<std::size_t, std::size_t>{2, 2}, {6, 7}, {12, 16}})
        for (double depth : {5.0, 50.0})
        {
            const LonLat g = grid.geo(double(j), double(i));
            const Point2 p = nc.toLocal(g);
            double ue, vn;
            RomsGrid::current(grid.at(double(j), double(i)), ue, vn);
            const double s = depth == 5.0 ? 1.0 : 0.5;
            const bool water = kmu(j, i) > (depth == 5.0 ? 0 : 1);
            EXPECT_EQ(nc.field->inWater(p.x, p.y, depth), water) << j << " " << i << " " << depth;
            if (!water)
                continue;
            const Velocity e = inPlane(nc, g.lon, g.lat, s * ue, s * vn), c = nc.field->velocity(p.x, p.y, depth, 0.0);
            EXPECT_NEAR(c.u, e.u, 2e-6) << j << " " << i << " " << depth;
            EXPECT_NEAR(c.v, e.v, 2e-6) << j << " " << i << " " << depth;
        }
    const Point2 p = nc.toLocal(grid.geo(10, 12));
    EXPECT_FALSE(nc.field->inWater(p.x, p.y, 5.0));
}

TEST(NetCdfModelGrids, StaggeredAndAngleErrorsNameTheVariables)
{
    TempDir tmp;
    const RomsGrid grid;
    const std::string path = tmp.file("roms.nc");
    grid.write(path);
    GriddedCurrentOptions o;
    o.angleName = "grid_angle";
    try
    {
        loadGriddedCurrents(path, o);
        FAIL() << "a missing angle variable must be refused";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("no grid angle variable 'grid_angle'"), std::string::npos) << e.what();
    }
    o.angleName = "mask_u"; // not on the grid of the rho points
    try
    {
        loadGriddedCurrents(path, o);
        FAIL() << "an angle off the grid must be refused";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("is not on the grid"), std::string::npos) << e.what();
    }
    // u and v on different grids that are not a ROMS C grid
    const std::string odd = tmp.file("odd.nc");
    {
        NcWriter w(odd);
        const int a = w.dim("y", 4), b = w.dim("x", 5), c = w.dim("y2", 4), d = w.dim("x2", 6);
        const int la = w.var("lat", NC_DOUBLE, {a, b}), lo = w.var("lon", NC_DOUBLE, {a, b});
        w.text(la, "units", "degrees_north");
        w.text(lo, "units", "degrees_east");
        const int u = w.var("u", NC_FLOAT, {a, b}), v = w.var("v", NC_FLOAT, {c, d});
        w.text(u, "units", "m/s");
        w.text(v, "units", "m/s");
        w.enddef();
        std::vector<double> lat, lon;
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 5; ++i)
                lat.push_back(40 + 0.1 * j), lon.push_back(-70 + 0.1 * i);
        w.put(la, lat);
        w.put(lo, lon);
        w.put(u, std::vector<double>(20, 0.1));
        w.put(v, std::vector<double>(24, 0.1));
    }
    try
    {
        loadGriddedCurrents(odd);
        FAIL() << "velocities on unrelated grids must be refused";
    }
    catch (const Error &e)
    {
        const std::string m = e.what();
        EXPECT_NE(m.find("'u' (y = 4, x = 5) and 'v' (y2 = 4, x2 = 6) are on different grids"), std::string::npos) << m;
    }
}

TEST(NetCdfModelGrids, RomsSCoordinateLevelsBecomeDepthsPerColumn)
{
    TempDir tmp;
    RomsGrid grid;
    grid.sLevels = 8;
    const std::string path = tmp.file("roms_s.nc");
    grid.write(path);
    GriddedCurrentOptions o;
    o.maxDepth = 100.0;
    const GriddedCurrents nc = loadGriddedCurrents(path, o);
    const GriddedCurrentField &f = *nc.field;
    // depth levels in metres: the standard ones down to 100 m and 2 more
    const Axis &levels = f.depthAxis();
    ASSERT_GE(levels.size(), 3u);
    EXPECT_EQ(levels[0], 0.0);
    EXPECT_EQ(levels[levels.size() - 3], 100.0);
    const double zTop = grid.levelZ(grid.sLevels - 1, 200.0); // the top s-level where the bottom is 200 m
    std::size_t checked = 0;
    for (auto [j, i] : {std::pair<std::size_t, std::size_t>{6, 4}, {7, 8}, {10, 4}, {4, 8}})
        for (double depth : {0.0, 10.0, 50.0, 100.0})
        {
            const LonLat g = grid.geo(double(j), double(i));
            const Point2 p = nc.toLocal(g);
            double ue, vn;
            RomsGrid::current(grid.at(double(j), double(i)), ue, vn);
            // linear in depth between s-levels (the factor is linear in z); above the top level, its value
            const double s = RomsGrid::depthFactor(std::min(-depth, zTop));
            ASSERT_TRUE(f.inWater(p.x, p.y, depth)) << j << " " << i << " " << depth;
            const Velocity e = inPlane(nc, g.lon, g.lat, s * ue, s * vn), c = f.velocity(p.x, p.y, depth, 0.0);
            EXPECT_NEAR(c.u, e.u, 2e-6) << j << " " << i << " " << depth;
            EXPECT_NEAR(c.v, e.v, 2e-6) << j << " " << i << " " << depth;
            ++checked;
        }
    EXPECT_EQ(checked, 16u);
    // the shallow bank (30 m): water at 10 m, land at 50 m
    const Point2 bank = nc.toLocal(grid.geo(3, 13.5));
    EXPECT_TRUE(f.inWater(bank.x, bank.y, 10.0));
    EXPECT_FALSE(f.inWater(bank.x, bank.y, 50.0));
    // a depth average over 0..40 m of the same file: one layer
    o.depthAverage = std::make_pair(0.0, 40.0);
    const GriddedCurrents avg = loadGriddedCurrents(path, o);
    EXPECT_EQ(avg.field->depthAxis().size(), 1u);
}

TEST(NetCdfModelGrids, RomsEastwardVelocitiesOnRhoPointsAreNotTurnedByTheAngle)
{
    // ROMS' u_eastward/v_northward (already east/north, on the rho points, no standard_name) beside the grid's angle
    TempDir tmp;
    const RomsGrid grid;
    const std::string path = tmp.file("roms_avg.nc");
    const std::size_t nj = RomsGrid::kEta, ni = RomsGrid::kXi;
    {
        NcWriter w(path, NC_CLOBBER);
        const int dt = w.dim("ocean_time", 1), dj = w.dim("eta_rho", nj), di = w.dim("xi_rho", ni);
        const int vt = w.var("ocean_time", NC_DOUBLE, {dt});
        w.text(vt, "units", "seconds since 2026-04-01 00:00:00");
        const int lo = w.var("lon_rho", NC_DOUBLE, {dj, di}), la = w.var("lat_rho", NC_DOUBLE, {dj, di});
        w.text(lo, "units", "degree_east");
        w.text(la, "units", "degree_north");
        const int an = w.var("angle", NC_DOUBLE, {dj, di});
        w.text(an, "units", "radians");
        const int u = w.var("u_eastward", NC_FLOAT, {dt, dj, di}), v = w.var("v_northward", NC_FLOAT, {dt, dj, di});
        w.text(u, "units", "meter second-1");
        w.text(v, "units", "meter second-1");
        w.enddef();
        w.put(vt, {0.0});
        std::vector<double> lon, lat, pu, pv;
        for (std::size_t j = 0; j < nj; ++j)
            for (std::size_t i = 0; i < ni; ++i)
            {
                const LonLat g = grid.geo(double(j), double(i));
                lon.push_back(g.lon);
                lat.push_back(g.lat);
                double ue, vn;
                RomsGrid::current(grid.at(double(j), double(i)), ue, vn);
                pu.push_back(ue);
                pv.push_back(vn);
            }
        w.put(lo, lon);
        w.put(la, lat);
        w.put(an, std::vector<double>(nj * ni, grid.theta));
        w.put(u, pu);
        w.put(v, pv);
    }
    const GriddedCurrents nc = loadGriddedCurrents(path);
    EXPECT_EQ(nc.uVariable, "u_eastward");
    const LonLat g = grid.geo(6, 7);
    double ue, vn;
    RomsGrid::current(grid.at(6, 7), ue, vn);
    const Point2 p = nc.toLocal(g);
    const Velocity e = inPlane(nc, g.lon, g.lat, ue, vn), c = nc.field->velocity(p.x, p.y, 0.0, 0.0);
    EXPECT_NEAR(c.u, e.u, 2e-6);
    EXPECT_NEAR(c.v, e.v, 2e-6);
}
