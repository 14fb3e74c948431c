// Land from every signal a model file gives (issue "land is at least what the model says"): POP's B grid with
// velocities that are fill values inside land and exact zeros at the coast (a velocity point touching a land tracer
// cell), a tracer masked on land, TLAT/TLONG against ULAT/ULONG, a ROMS C grid with mask_rho/mask_u and a tracer,
// and an A grid whose calm exact-zero water must stay water while its coastal zeros are land. Each file is written
// here with NetCDF-C in the layout of the model.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "TestNetCdfUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"

using namespace ompl_glider;
using namespace glider_test;

namespace
{
// ---- POP's B grid, as NCL's pop.nc: urot/vrot (cm/s) and t on (nlat, nlon), lat2d/lon2d the u-grid ----

constexpr std::size_t kNj = 12, kNi = 14;
constexpr double kPopFill = 9.96921e36;

double uLon(std::size_t i)
{
    return -80.0 + 0.5 * double(i);
}
double uLat(std::size_t j)
{
    return 20.0 + 0.5 * double(j);
}

/// Land tracer cells: a continent at the south-west corner (rows 0..2, columns 0..3) and a one-cell island (7, 9).
bool landT(std::size_t j, std::size_t i)
{
    return (j <= 2 && i <= 3) || (j == 7 && i == 9);
}
/// Velocity point (j, i) is the north-east corner of tracer cell (j, i): the cells around it.
bool anyT(std::size_t j, std::size_t i)
{
    return landT(j, i) || landT(j, i + 1) || landT(j + 1, i) || landT(j + 1, i + 1);
}
bool allT(std::size_t j, std::size_t i)
{
    return landT(j, i) && landT(j, i + 1) && landT(j + 1, i) && landT(j + 1, i + 1);
}

struct PopFile
{
    bool uGridLabel{true}; ///< lat2d/lon2d say "u-grid" (as pop.nc)
    bool tracer{true};     ///< write t
    bool tracerAllFill{false};
    /// POP history layout instead: ULONG/ULAT for the velocities, TLONG/TLAT (tOffset cells from them) for TEMP
    bool history{false};
    double tOffset{-0.5};
};

void writePop(const std::string &path, const PopFile &p)
{
    NcWriter w(path, NC_CLOBBER);
    const int dj = w.dim("nlat", kNj), di = w.dim("nlon", kNi);
    const int la = w.var(p.history ? "ULAT" : "lat2d", NC_FLOAT, {dj, di});
    const int lo = w.var(p.history ? "ULONG" : "lon2d", NC_FLOAT, {dj, di});
    w.text(la, "units", "degrees_north");
    w.text(lo, "units", "degrees_east");
    if (p.uGridLabel && !p.history)
    {
        w.text(la, "long_name", "array of u-grid latitudes");
        w.text(lo, "long_name", "array of u-grid longitudes");
    }
    int tla = -1, tlo = -1;
    if (p.history)
    {
        tla = w.var("TLAT", NC_FLOAT, {dj, di});
        tlo = w.var("TLONG", NC_FLOAT, {dj, di});
        w.text(tla, "units", "degrees_north");
        w.text(tlo, "units", "degrees_east");
    }
    const std::string coords = p.history ? "ULONG ULAT" : "lat2d lon2d";
    const int u = w.var(p.history ? "UVEL" : "urot", NC_FLOAT, {dj, di});
    const int v = w.var(p.history ? "VVEL" : "vrot", NC_FLOAT, {dj, di});
    for (int var : {u, v})
    {
        w.num(var, "missing_value", NC_FLOAT, {kPopFill});
        w.fill(var, NC_FLOAT, kPopFill);
        w.text(var, "units", "centimeter/s");
        w.text(var, "coordinates", coords);
    }
    int t = -1;
    if (p.tracer)
    {
        t = w.var(p.history ? "TEMP" : "t", NC_FLOAT, {dj, di});
        w.text(t, "long_name", "Potential Temperature");
        w.text(t, "units", "degC");
        w.text(t, "coordinates", p.history ? "TLONG TLAT" : "lat2d lon2d");
        w.fill(t, NC_FLOAT, kPopFill);
        w.num(t, "missing_value", NC_FLOAT, {kPopFill});
    }
    w.enddef();
    std::vector<double> lat, lon, tlat, tlon, uu, vv, tt;
    for (std::size_t j = 0; j < kNj; ++j)
        for (std::size_t i = 0; i < kNi; ++i)
        {
            lat.push_back(uLat(j));
            lon.push_back(uLon(i));
            tlat.push_back(uLat(j) + 0.5 * p.tOffset);
            tlon.push_back(uLon(i) + 0.5 * p.tOffset);
            // land inside (all 4 cells land): fill values; at the coast (some land): exactly 0; water: a current
            const double s = allT(j, i) ? kPopFill : anyT(j, i) ? 0.0 : 20.0 + double(i);
            uu.push_back(s);
            vv.push_back(s == kPopFill ? s : s == 0.0 ? 0.0 : 5.0);
            tt.push_back(p.tracerAllFill || landT(j, i) ? kPopFill : 12.0 + 0.1 * double(j));
        }
    w.put(la, lat);
    w.put(lo, lon);
    if (p.history)
    {
        w.put(tla, tlat);
        w.put(tlo, tlon);
    }
    w.put(u, uu);
    w.put(v, vv);
    if (p.tracer)
        w.put(t, tt);
}

/// inWater() at the centre of every cell of velocity points (j..j+1, i..i+1) against `land` of its corners.
void expectCells(const GriddedCurrents &nc, const std::function<bool(std::size_t, std::size_t)> &land,
                 const std::string &what)
{
    for (std::size_t j = 0; j + 1 < kNj; ++j)
        for (std::size_t i = 0; i + 1 < kNi; ++i)
        {
            const bool water = !land(j, i) && !land(j, i + 1) && !land(j + 1, i) && !land(j + 1, i + 1);
            const Point2 c = nc.toLocal({uLon(i) + 0.25, uLat(j) + 0.25});
            EXPECT_EQ(nc.field->inWater(c.x, c.y, 0.0), water) << what << ": cell (" << j << ", " << i << ")";
        }
}

std::size_t countNodes(const std::function<bool(std::size_t, std::size_t)> &pred)
{
    std::size_t n = 0;
    for (std::size_t j = 0; j < kNj; ++j)
        for (std::size_t i = 0; i < kNi; ++i)
            n += pred(j, i);
    return n;
}

bool has(const std::string &s, const std::string &part)
{
    return s.find(part) != std::string::npos;
}
} // namespace

TEST(NetCdfTracerLand, PopBGridCoastalZerosAndTheTracerAreLand)
{
    TempDir dir;
    const std::string path = dir.file("pop.nc");
    writePop(path, {});
    const std::size_t fill = countNodes(allT), coast = countNodes(anyT) - fill;
    ASSERT_EQ(fill, 6u);
    ASSERT_EQ(coast, 10u); // the continent's ring of 6 and the island's 4 corners
    GriddedCurrentOptions o;
    o.uName = "urot";
    o.vName = "vrot";
    // every signal: the fill values, then the tracer's cells around each velocity point (the zeros are its land)
    const GriddedCurrents nc = loadGriddedCurrents(path, o);
    EXPECT_EQ(nc.tracerVariable, "t");
    EXPECT_TRUE(nc.cornerGrid);
    EXPECT_TRUE(has(nc.tracerPlacement, "north-east corners")) << nc.tracerPlacement;
    EXPECT_TRUE(has(nc.tracerPlacement, "'lon2d'/'lat2d'")) << nc.tracerPlacement;
    EXPECT_EQ(nc.fillLandNodes, fill);
    EXPECT_EQ(nc.tracerLandNodes, coast);
    EXPECT_EQ(nc.zeroLandNodes, 0u);
    EXPECT_EQ(nc.maskLandNodes, 0u);
    EXPECT_EQ(nc.landNodes, fill + coast);
    expectCells(nc, anyT, "tracer");

    // without the tracer: the B grid's zeros are land, the island's too (its zeros touch no fill value)
    GriddedCurrentOptions noTracer = o;
    noTracer.tracerName = "none";
    const GriddedCurrents zeros = loadGriddedCurrents(path, noTracer);
    EXPECT_TRUE(zeros.tracerVariable.empty());
    EXPECT_TRUE(zeros.cornerGrid); // from the u-grid coordinates
    EXPECT_EQ(zeros.fillLandNodes, fill);
    EXPECT_EQ(zeros.zeroLandNodes, coast);
    expectCells(zeros, anyT, "zeros");

    // the old answer, fill values alone: the coastal ring and the island are water
    noTracer.zeroVelocityLand = false;
    const GriddedCurrents fillOnly = loadGriddedCurrents(path, noTracer);
    EXPECT_EQ(fillOnly.landNodes, fill);
    expectCells(fillOnly, allT, "fill values only");
}

TEST(NetCdfTracerLand, WithoutBGridLabelsTheTracerIsReadAtTheSameIndex)
{
    TempDir dir;
    PopFile p;
    p.uGridLabel = false;
    const std::string path = dir.file("unlabelled.nc");
    writePop(path, p);
    GriddedCurrentOptions o;
    o.uName = "urot";
    o.vName = "vrot";
    const GriddedCurrents nc = loadGriddedCurrents(path, o);
    EXPECT_EQ(nc.tracerPlacement, "same points");
    EXPECT_FALSE(nc.cornerGrid);
    // the tracer at the same index marks the cells' own corner; the coastal zeros touching land are land too
    const std::size_t fill = countNodes(allT);
    EXPECT_EQ(nc.fillLandNodes, fill);
    EXPECT_EQ(nc.tracerLandNodes, countNodes([](std::size_t j, std::size_t i) { return landT(j, i) && !allT(j, i); }));
    EXPECT_EQ(nc.landNodes, countNodes(anyT));
    expectCells(nc, anyT, "same index");
    // without tracer and labels: zeros touching land are land; the island's block of zeros, touching none, is taken
    // for calm water (nothing in such a file tells an island's zeros from a calm sea's)
    GriddedCurrentOptions noTracer = o;
    noTracer.tracerName = "none";
    const GriddedCurrents zeros = loadGriddedCurrents(path, noTracer);
    EXPECT_EQ(zeros.zeroLandNodes, 6u);
    expectCells(
        zeros, [](std::size_t j, std::size_t i) { return anyT(j, i) && j < 5; }, "zeros next to land");
}

TEST(NetCdfTracerLand, TracerCoordinatesPlaceTheCellsOfAPopHistoryFile)
{
    TempDir dir;
    // TLAT/TLONG half a cell south-west of ULAT/ULONG: the velocity points are the cells' north-east corners
    PopFile p;
    p.history = true;
    const std::string path = dir.file("history.nc");
    writePop(path, p);
    const GriddedCurrents nc = loadGriddedCurrents(path);
    EXPECT_EQ(nc.tracerVariable, "TEMP");
    EXPECT_TRUE(has(nc.tracerPlacement, "north-east corners")) << nc.tracerPlacement;
    EXPECT_TRUE(has(nc.tracerPlacement, "'TLONG'/'TLAT' against 'ULONG'/'ULAT'")) << nc.tracerPlacement;
    EXPECT_EQ(nc.landNodes, countNodes(anyT));
    expectCells(nc, anyT, "history");
    // the tracer half a cell north-east: the velocity points are the south-west corners
    p.tOffset = 0.5;
    const std::string ne = dir.file("northeast.nc");
    writePop(ne, p);
    const GriddedCurrents sw = loadGriddedCurrents(ne);
    EXPECT_TRUE(has(sw.tracerPlacement, "south-west corners")) << sw.tracerPlacement;
    auto around = [](std::size_t j, std::size_t i) {
        return landT(j, i) || (i > 0 && landT(j, i - 1)) || (j > 0 && landT(j - 1, i)) ||
               (i > 0 && j > 0 && landT(j - 1, i - 1));
    };
    // (land is the union: the velocities' zeros and fills mark their own north-east cells too)
    expectCells(
        sw, [&](std::size_t j, std::size_t i) { return around(j, i) || anyT(j, i); }, "south-west");
    // the tracer on the velocities' own points: the same index
    p.tOffset = 0.0;
    const std::string same = dir.file("same.nc");
    writePop(same, p);
    EXPECT_EQ(loadGriddedCurrents(same).tracerPlacement, "same points");
}

TEST(NetCdfTracerLand, TracerChoiceNoneAndUnwrittenTracers)
{
    TempDir dir;
    PopFile p;
    p.tracerAllFill = true; // a variable defined but never written: its fill values are not a map of land
    const std::string path = dir.file("empty_tracer.nc");
    writePop(path, p);
    GriddedCurrentOptions o;
    o.uName = "urot";
    o.vName = "vrot";
    const GriddedCurrents nc = loadGriddedCurrents(path, o);
    EXPECT_TRUE(nc.tracerVariable.empty());
    EXPECT_EQ(nc.tracerLandNodes, 0u);
    EXPECT_EQ(nc.landNodes, countNodes(anyT)); // the B grid's zeros still are
    // a given tracer must exist and fit the velocities
    o.tracerName = "salt";
    try
    {
        loadGriddedCurrents(path, o);
        FAIL() << "a missing tracer must be refused";
    }
    catch (const Error &e)
    {
        EXPECT_TRUE(has(e.what(), "no tracer variable 'salt'")) << e.what();
        EXPECT_TRUE(has(e.what(), "empty_tracer.nc")) << e.what();
    }
}

// ---- an A grid: 1-D axes, land as fill values, coastal zeros and calm water ----

namespace
{
constexpr std::size_t kAj = 12, kAi = 14, kAt = 3;
bool fillBlock(std::size_t j, std::size_t i)
{
    return (j <= 2 && i <= 3) || (j >= 10 && i >= 12); // a continent and a corner of land in the north-east
}
bool ring(std::size_t j, std::size_t i)
{
    return !fillBlock(j, i) && j <= 3 && i <= 4; // zeros along the continent's coast
}
bool calm(std::size_t j, std::size_t i)
{
    return j >= 6 && j <= 7 && i >= 8 && i <= 9; // a calm patch in open water, exactly 0 in every record
}

void writeAGrid(const std::string &path, bool tracer)
{
    NcWriter w(path);
    const int dt = w.dim("time", kAt), dy = w.dim("lat", kAj), dx = w.dim("lon", kAi);
    const int vt = w.var("time", NC_DOUBLE, {dt}), vy = w.var("lat", NC_DOUBLE, {dy});
    const int vx = w.var("lon", NC_DOUBLE, {dx});
    w.text(vt, "units", "hours since 2026-06-01 00:00:00");
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    const int u = w.var("uo", NC_FLOAT, {dt, dy, dx}), v = w.var("vo", NC_FLOAT, {dt, dy, dx});
    for (int var : {u, v})
    {
        w.text(var, "units", "m s-1");
        w.fill(var, NC_FLOAT, 1e20);
    }
    int tv = -1;
    if (tracer)
    {
        tv = w.var("thetao", NC_FLOAT, {dt, dy, dx});
        w.text(tv, "standard_name", "sea_water_potential_temperature");
        w.fill(tv, NC_FLOAT, 1e20);
    }
    w.enddef();
    w.put(vt, {0.0, 24.0, 48.0});
    std::vector<double> lat, lon;
    for (std::size_t j = 0; j < kAj; ++j)
        lat.push_back(uLat(j));
    for (std::size_t i = 0; i < kAi; ++i)
        lon.push_back(uLon(i));
    w.put(vy, lat);
    w.put(vx, lon);
    std::vector<double> uu, vv, tt;
    for (std::size_t k = 0; k < kAt; ++k)
        for (std::size_t j = 0; j < kAj; ++j)
            for (std::size_t i = 0; i < kAi; ++i)
            {
                const bool land = fillBlock(j, i), still = ring(j, i) || calm(j, i);
                uu.push_back(land ? 1e20 : still ? 0.0 : 0.2 + 0.01 * double(k));
                vv.push_back(land ? 1e20 : still ? 0.0 : 0.05);
                // the tracer: missing on the land and at one node the velocities call water (a dry cell)
                tt.push_back(land || (j == 5 && i == 4) ? 1e20 : 14.0);
            }
    w.put(u, uu);
    w.put(v, vv);
    if (tracer)
        w.put(tv, tt);
}

bool waterAt(const GriddedCurrents &nc, double lon, double lat)
{
    const Point2 p = nc.toLocal({lon, lat});
    return nc.field->inWater(p.x, p.y, 0.0);
}
} // namespace

TEST(NetCdfTracerLand, CoastalZerosAreLandAndCalmWaterAwayFromLandIsWater)
{
    TempDir dir;
    const std::string path = dir.file("agrid.nc");
    writeAGrid(path, false);
    const GriddedCurrents nc = loadGriddedCurrents(path);
    EXPECT_FALSE(nc.cornerGrid);
    EXPECT_EQ(nc.fillLandNodes, countNodes(fillBlock));
    // the continent's coastal zeros touch its fill values: land; the calm patch touches no land: water
    EXPECT_EQ(nc.zeroLandNodes, countNodes(ring));
    EXPECT_EQ(nc.landNodes, countNodes(fillBlock) + countNodes(ring));
    EXPECT_TRUE(waterAt(nc, uLon(8) + 0.25, uLat(6) + 0.25));  // inside the calm patch
    EXPECT_FALSE(waterAt(nc, uLon(4) + 0.25, uLat(3) + 0.25)); // on the coastal ring's outer corner cell
    EXPECT_TRUE(waterAt(nc, uLon(5) + 0.25, uLat(4) + 0.25));

    // a region that cuts the calm patch at its west edge: the file goes on beyond it, where land may lie, so the
    // patch is land (as a coastal ring cut by the region would be)
    GriddedCurrentOptions cut = regionOptions(uLon(8), uLon(13), uLat(0), uLat(11));
    cut.marginNodes = 0;
    const GriddedCurrents part = loadGriddedCurrents(path, cut);
    EXPECT_GT(part.fillLandNodes, 0u); // the north-east corner of land is in the region
    EXPECT_EQ(part.zeroLandNodes, countNodes(calm));
    EXPECT_FALSE(waterAt(part, uLon(8) + 0.25, uLat(6) + 0.25));

    // the tracer adds its dry node (at the same index on an A grid); the rest is unchanged
    const std::string withTracer = dir.file("agrid_thetao.nc");
    writeAGrid(withTracer, true);
    const GriddedCurrents t = loadGriddedCurrents(withTracer);
    EXPECT_EQ(t.tracerVariable, "thetao");
    EXPECT_EQ(t.tracerPlacement, "same points");
    EXPECT_EQ(t.tracerLandNodes, 1u);
    EXPECT_EQ(t.zeroLandNodes, countNodes(ring));
    EXPECT_FALSE(waterAt(t, uLon(4) + 0.25, uLat(5) + 0.25));
    EXPECT_TRUE(waterAt(t, uLon(8) + 0.25, uLat(6) + 0.25));
}

// ---- ROMS: an Arakawa C grid with mask_rho, mask_u/mask_v and a tracer on the rho points ----

TEST(NetCdfTracerLand, RomsMasksAndTracerOnTheRhoPoints)
{
    TempDir dir;
    const std::string path = dir.file("roms.nc");
    constexpr std::size_t ne = 10, nxi = 12;
    auto landRho = [](std::size_t j, std::size_t i) { return j >= 3 && j <= 5 && i >= 4 && i <= 7; };
    auto dry = [](std::size_t j, std::size_t i) { return j == 7 && i == 2; }; // tracer missing, mask says water
    {
        NcWriter w(path, NC_CLOBBER);
        const int dt = w.dim("ocean_time", 2), er = w.dim("eta_rho", ne), xr = w.dim("xi_rho", nxi);
        const int eu = w.dim("eta_u", ne), xu = w.dim("xi_u", nxi - 1), ev = w.dim("eta_v", ne - 1),
                  xv = w.dim("xi_v", nxi);
        const int vt = w.var("ocean_time", NC_DOUBLE, {dt});
        w.text(vt, "units", "seconds since 2026-04-01 00:00:00");
        const int lon = w.var("lon_rho", NC_DOUBLE, {er, xr}), lat = w.var("lat_rho", NC_DOUBLE, {er, xr});
        w.text(lon, "units", "degree_east");
        w.text(lat, "units", "degree_north");
        const int mr = w.var("mask_rho", NC_DOUBLE, {er, xr}), mu = w.var("mask_u", NC_DOUBLE, {eu, xu}),
                  mv = w.var("mask_v", NC_DOUBLE, {ev, xv});
        const int u = w.var("u", NC_FLOAT, {dt, eu, xu}), v = w.var("v", NC_FLOAT, {dt, ev, xv});
        for (int var : {u, v})
            w.text(var, "units", "meter second-1");
        const int temp = w.var("temp", NC_FLOAT, {dt, er, xr});
        w.text(temp, "units", "Celsius");
        w.fill(temp, NC_FLOAT, 1e37);
        w.enddef();
        w.put(vt, {0.0, 86400.0});
        std::vector<double> a, b, m;
        for (std::size_t j = 0; j < ne; ++j)
            for (std::size_t i = 0; i < nxi; ++i)
            {
                a.push_back(-70.0 + 0.05 * double(i));
                b.push_back(40.0 + 0.05 * double(j));
                m.push_back(landRho(j, i) ? 0.0 : 1.0);
            }
        w.put(lon, a);
        w.put(lat, b);
        w.put(mr, m);
        // faces: land where either rho point beside them is (ROMS writes 0 there, no fill value)
        std::vector<double> fu, fv, uu, vv, tt;
        for (std::size_t j = 0; j < ne; ++j)
            for (std::size_t i = 0; i + 1 < nxi; ++i)
                fu.push_back(landRho(j, i) || landRho(j, i + 1) ? 0.0 : 1.0);
        for (std::size_t j = 0; j + 1 < ne; ++j)
            for (std::size_t i = 0; i < nxi; ++i)
                fv.push_back(landRho(j, i) || landRho(j + 1, i) ? 0.0 : 1.0);
        w.put(mu, fu);
        w.put(mv, fv);
        for (int k = 0; k < 2; ++k)
        {
            for (double f : fu)
                uu.push_back(f * (0.3 + 0.01 * k));
            for (double f : fv)
                vv.push_back(f * 0.1);
            for (std::size_t j = 0; j < ne; ++j)
                for (std::size_t i = 0; i < nxi; ++i)
                    tt.push_back(landRho(j, i) || dry(j, i) ? 1e37 : 11.0);
        }
        w.put(u, uu);
        w.put(v, vv);
        w.put(temp, tt);
    }
    const GriddedCurrents nc = loadGriddedCurrents(path);
    EXPECT_EQ(nc.maskVariable, "mask_rho");
    EXPECT_EQ(nc.tracerVariable, "temp");
    EXPECT_EQ(nc.tracerPlacement, "same points");
    EXPECT_FALSE(nc.cornerGrid);
    EXPECT_EQ(nc.maskLandNodes, 12u);  // the block (the loaded interior rho points hold all of it)
    EXPECT_EQ(nc.tracerLandNodes, 1u); // the dry cell the mask calls water
    EXPECT_EQ(nc.zeroLandNodes, 0u);
    EXPECT_EQ(nc.fillLandNodes, 0u);
    auto water = [&](double i, double j) {
        const Point2 p = nc.toLocal({-70.0 + 0.05 * i, 40.0 + 0.05 * j});
        return nc.field->inWater(p.x, p.y, 0.0);
    };
    EXPECT_FALSE(water(5.5, 4.5)); // in the block
    EXPECT_FALSE(water(2.5, 7.5)); // beside the dry cell
    EXPECT_TRUE(water(9.5, 7.5));  // open water
    // "none" leaves the tracer out
    GriddedCurrentOptions none;
    none.tracerName = "none";
    EXPECT_EQ(loadGriddedCurrents(path, none).landNodes, 12u);
}
