// Real-sized global forecasts (0.5 and 0.25 degrees, float32, Copernicus-Marine layout; GlobalForecast.h) read across
// their seams: a -180..180 grid across the antimeridian, a 0..360 grid across Greenwich, a regional 0..360 extract
// written across Greenwich (359.75 then 0), a global grid with both seam columns, and the pole rows. The field
// must equal the file at its nodes (rotated into the plane), in any longitude convention.
#include <gtest/gtest.h>

#include <cmath>

#include "GlobalForecast.h"
#include "TestNetCdfUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"

using namespace ompl_glider;
using glider_test::GlobalForecastSpec;
using glider_test::regionOptions;
using glider_test::TempDir;

namespace
{

/// The loaded field at the node (lon, lat) against the file's value there (the analytic field in float32),
/// eastward/northward rotated into the plane with the projection's east and north directions at the node.
void expectNodeSpeed(const GriddedCurrents &nc, double lon, double lat)
{
    const Point2 p = nc.toLocal({lon, lat});
    const Velocity c = nc.field->velocity(p.x, p.y, 0.0, 0.0);
    double u, v;
    glider_test::globalCurrent(lon, lat, u, v);
    const Velocity e = glider_test::inPlane(nc, lon, lat, double(float(u)), double(float(v)));
    EXPECT_NEAR(c.u, e.u, 1e-7) << lon << "," << lat;
    EXPECT_NEAR(c.v, e.v, 1e-7) << lon << "," << lat;
    EXPECT_TRUE(nc.field->inWater(p.x, p.y, 0.0)) << lon << "," << lat;
}
} // namespace

TEST(NetCdfGlobal, AntimeridianOfAMinus180To180Grid)
{
    TempDir tmp;
    const std::string path = tmp.file("global180.nc");
    glider_test::writeGlobalForecast(path, GlobalForecastSpec{}); // -180..179.5, -90..90, 0.5 degrees
    // the region across the antimeridian in three spellings: the same nodes, the same plane
    const GriddedCurrents a = loadGriddedCurrents(path, regionOptions(170, -170, 20, 40));
    const GriddedCurrents b = loadGriddedCurrents(path, regionOptions(170, 190, 20, 40));
    const GriddedCurrents c = loadGriddedCurrents(path, regionOptions(-190, -170, 20, 40));
    for (const GriddedCurrents *nc : {&a, &b, &c})
    {
        EXPECT_EQ(nc->loadedShape[3], 41u + 4u); // 170..190 plus 2 margin nodes each side, not 720
        EXPECT_EQ(nc->lonMin, 169.0);
        EXPECT_EQ(nc->lonMax, 191.0);
        EXPECT_EQ(nc->latMin, 19.0);
        EXPECT_EQ(nc->latMax, 41.0);
    }
    for (double lon : {175.0, 179.5, 180.0, -180.0, -179.5, 185.0, -175.0})
        for (double lat : {25.0, 30.5})
            expectNodeSpeed(a, lon, lat);
    const Point2 p = a.toLocal({185.0, 30.0}), q = b.toLocal({-175.0, 30.0});
    EXPECT_EQ(p.x, q.x);
    EXPECT_EQ(p.y, q.y);
    const LonLat g = a.toGeographic(p); // out always in -180..180
    EXPECT_NEAR(g.lon, -175.0, 1e-9);
    EXPECT_NEAR(g.lat, 30.0, 1e-9);
}

TEST(NetCdfGlobal, GreenwichOfA0To360Grid)
{
    TempDir tmp;
    const std::string path = tmp.file("global360.nc");
    GlobalForecastSpec s;
    s.lon0 = 0.0;
    glider_test::writeGlobalForecast(path, s); // 0..359.5
    const GriddedCurrents a = loadGriddedCurrents(path, regionOptions(-10, 10, 45, 55));
    const GriddedCurrents b = loadGriddedCurrents(path, regionOptions(350, 10, 45, 55));
    for (const GriddedCurrents *nc : {&a, &b})
    {
        EXPECT_EQ(nc->loadedShape[3], 41u + 4u);
        EXPECT_EQ(nc->lonMin, -11.0);
        EXPECT_EQ(nc->lonMax, 11.0);
    }
    for (double lon : {-5.0, -0.5, 0.0, 359.5, 0.5, 5.0, 355.0})
        expectNodeSpeed(a, lon, 50.0);
    const LonLat g = a.toGeographic(a.toLocal({355.0, 50.0}));
    EXPECT_NEAR(g.lon, -5.0, 1e-9);
}

TEST(NetCdfGlobal, RegionalExtractWrittenAcrossGreenwich)
{
    TempDir tmp;
    const std::string path = tmp.file("extract.nc");
    GlobalForecastSpec s;
    s.lon0 = 340.0; // 340, ..., 359.75, 0, ..., 20 (0.25 degrees, 0..360 convention)
    s.dlon = 0.25;
    s.nlon = 161;
    s.wrapTo360 = true;
    s.lat0 = 30.0;
    s.dlat = 0.25;
    s.nlat = 81;
    glider_test::writeGlobalForecast(path, s);
    // the whole extract: 40 degrees, not a 20-degree strip on either side of the jump
    const GriddedCurrents all = loadGriddedCurrents(path);
    EXPECT_EQ(all.loadedShape[3], 161u);
    EXPECT_EQ(all.lonMin, -20.0);
    EXPECT_EQ(all.lonMax, 20.0);
    // a region across the jump, in either convention
    for (const auto &o : {regionOptions(-5, 5, 35, 40), regionOptions(355, 5, 35, 40), regionOptions(355, 365, 35, 40)})
    {
        const GriddedCurrents nc = loadGriddedCurrents(path, o);
        EXPECT_EQ(nc.loadedShape[3], 41u + 4u);
        EXPECT_EQ(nc.lonMin, -5.5);
        EXPECT_EQ(nc.lonMax, 5.5);
        for (double lon : {-5.0, -0.25, 359.75, 0.0, 0.25, 5.0})
            expectNodeSpeed(nc, lon, 37.5);
    }
    // beyond the extract: refused, naming the axis
    EXPECT_THROW(loadGriddedCurrents(path, regionOptions(100, 110, 35, 40)), Error);
}

TEST(NetCdfGlobal, BothSeamColumnsAreReadAsOne)
{
    TempDir tmp;
    for (double lon0 : {-180.0, 0.0})
    {
        const std::string path = tmp.file("dup" + std::to_string(int(lon0)) + ".nc");
        GlobalForecastSpec s;
        s.lon0 = lon0;
        s.nlon = 721; // -180..180 or 0..360: the seam column twice
        glider_test::writeGlobalForecast(path, s);
        // not refused as non-monotonic; the repeated column is left out of the whole grid
        const GriddedCurrents all = loadGriddedCurrents(path);
        EXPECT_EQ(all.loadedShape[3], 720u);
        // across the seam: one run of nodes half a degree apart, no cell of zero width
        const double seam = lon0 == 0.0 ? 0.0 : 180.0;
        const GriddedCurrents nc = loadGriddedCurrents(path, regionOptions(seam - 10, seam + 10, 20, 40));
        EXPECT_EQ(nc.loadedShape[3], 41u + 4u);
        EXPECT_EQ(nc.lonMax - nc.lonMin, 22.0);
        EXPECT_GT(nc.field->minCellSize(), 0.5 * 0.5 * 111e3 * std::cos(41.0 * M_PI / 180.0));
        for (double d : {-0.5, 0.0, 0.5})
            expectNodeSpeed(nc, seam + d, 30.0);
    }
}

TEST(NetCdfGlobal, PoleRowsAreLeftOutNotRefused)
{
    TempDir tmp;
    const std::string path = tmp.file("poles.nc");
    glider_test::writeGlobalForecast(path, GlobalForecastSpec{}); // rows at -90 and 90
    // the whole file, and a polar cap all round: loaded without the rows at +-90 (a grid cannot be projected there)
    const GriddedCurrents all = loadGriddedCurrents(path);
    EXPECT_EQ(all.loadedShape[2], 359u);
    EXPECT_EQ(all.latMin, -89.5);
    EXPECT_EQ(all.latMax, 89.5);
    const GriddedCurrents cap = loadGriddedCurrents(path, regionOptions(-180, 180 - 1e-9, 80, 90));
    EXPECT_EQ(cap.latMax, 89.5);
    EXPECT_EQ(cap.latMin, 79.0);
    expectNodeSpeed(cap, 10.0, 85.0);
    expectNodeSpeed(cap, -170.0, 89.5);
}
