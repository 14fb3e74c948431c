// Land in forecast files as models write it: velocities stored as exact zeros (POP), mask variables (ROMS mask_rho,
// CF flag_meanings, ERA5's land fraction lsm, POP's KMT level count), masks on dimensions of their own, and a
// seasonal mask that closes a region only in winter. Each file is written here with NetCDF-C.
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
// a 0.25-degree grid, lon -72..-67, lat 38..42 (21 x 17 nodes), 4 daily records
constexpr std::size_t kNx = 21, kNy = 17, kNt = 4;
const std::vector<double> kLon = linspace(-72.0, 0.25, kNx);
const std::vector<double> kLat = linspace(38.0, 0.25, kNy);

/// True for the nodes of the "island" block: lon -70.5..-69.5, lat 39.5..40.5 (5 x 5 nodes).
bool inBlock(std::size_t i, std::size_t j)
{
    return i >= 6 && i <= 10 && j >= 6 && j <= 10;
}

struct Extra
{
    std::string name;
    std::vector<std::string>
        dims; ///< names among time, depth, lat, lon (or own names, created with the grid's lengths)
    nc_type type{NC_BYTE};
    std::function<double(std::size_t t, std::size_t k, std::size_t j, std::size_t i)> value;
    std::vector<std::pair<std::string, std::string>> textAtts;
    std::vector<std::pair<std::string, std::vector<double>>> numAtts;
};

/// u(time, [depth,] lat, lon) = uv(t, k, j, i) with v = 0.1 where uv is not zero; extra variables as given.
void writeFile(const std::string &path, std::size_t nz,
               const std::function<double(std::size_t, std::size_t, std::size_t, std::size_t)> &uv,
               const std::vector<Extra> &extras = {})
{
    NcWriter w(path);
    const int dt = w.dim("time", kNt), dy = w.dim("lat", kNy), dx = w.dim("lon", kNx);
    const int dz = nz > 0 ? w.dim("depth", nz) : -1;
    const int vt = w.var("time", NC_DOUBLE, {dt}), vy = w.var("lat", NC_DOUBLE, {dy}),
              vx = w.var("lon", NC_DOUBLE, {dx});
    w.text(vt, "units", "days since 2026-01-01 00:00:00");
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    int vz = -1;
    std::vector<int> dims{dt};
    if (nz > 0)
    {
        vz = w.var("depth", NC_DOUBLE, {dz});
        w.text(vz, "units", "m");
        w.text(vz, "positive", "down");
        dims.push_back(dz);
    }
    dims.push_back(dy);
    dims.push_back(dx);
    const int vu = w.var("u", NC_FLOAT, dims), vv = w.var("v", NC_FLOAT, dims);
    w.text(vu, "units", "m/s");
    w.text(vv, "units", "m/s");
    w.fill(vu, NC_FLOAT, -999.0);
    w.fill(vv, NC_FLOAT, -999.0);
    std::vector<int> extraVars;
    for (const Extra &e : extras)
    {
        std::vector<int> ed;
        for (const std::string &d : e.dims)
        {
            if (d == "time")
                ed.push_back(dt);
            else if (d == "depth")
                ed.push_back(dz);
            else if (d == "lat")
                ed.push_back(dy);
            else if (d == "lon")
                ed.push_back(dx);
            else // a dimension of the mask's own: "eta_rho:17"
            {
                const auto colon = d.find(':');
                int id;
                if (nc_inq_dimid(w.id(), d.substr(0, colon).c_str(), &id) != NC_NOERR)
                    id = w.dim(d.substr(0, colon), std::stoul(d.substr(colon + 1)));
                ed.push_back(id);
            }
        }
        const int v = w.var(e.name, e.type, ed);
        for (const auto &[k, val] : e.textAtts)
            w.text(v, k, val);
        for (const auto &[k, vals] : e.numAtts)
            w.num(v, k, e.type, vals);
        extraVars.push_back(v);
    }
    w.enddef();
    std::vector<double> t(kNt);
    for (std::size_t i = 0; i < kNt; ++i)
        t[i] = double(i) * 30.0; // monthly: Jan 1, Jan 31, Mar 2, Apr 1
    w.put(vt, t);
    w.put(vy, kLat);
    w.put(vx, kLon);
    const std::size_t nzz = std::max<std::size_t>(nz, 1);
    if (nz > 0)
        w.put(vz, linspace(0.0, 50.0, nz));
    std::vector<double> u, v;
    for (std::size_t it = 0; it < kNt; ++it)
        for (std::size_t k = 0; k < nzz; ++k)
            for (std::size_t j = 0; j < kNy; ++j)
                for (std::size_t i = 0; i < kNx; ++i)
                {
                    const double s = uv(it, k, j, i);
                    u.push_back(s);
                    v.push_back(s == 0.0 || s == -999.0 ? s : 0.1);
                }
    w.put(vu, u);
    w.put(vv, v);
    for (std::size_t q = 0; q < extras.size(); ++q)
    {
        const Extra &e = extras[q];
        const bool hasT = std::find(e.dims.begin(), e.dims.end(), "time") != e.dims.end();
        const bool hasZ = std::find(e.dims.begin(), e.dims.end(), "depth") != e.dims.end();
        std::vector<double> vals;
        for (std::size_t it = 0; it < (hasT ? kNt : 1); ++it)
            for (std::size_t k = 0; k < (hasZ ? nzz : 1); ++k)
                for (std::size_t j = 0; j < kNy; ++j)
                    for (std::size_t i = 0; i < kNx; ++i)
                        vals.push_back(e.value(it, k, j, i));
        w.put(extraVars[q], vals);
    }
}

/// Is the centre of the block (lon -70, lat 40) in water, and a point away from it (-68, 41)?
struct Probe
{
    bool block, away;
};
Probe probe(const GriddedCurrents &nc, double depth = 0.0)
{
    const Point2 b = nc.toLocal({-70.0, 40.0}), a = nc.toLocal({-68.0, 41.0});
    return {nc.field->inWater(b.x, b.y, depth), nc.field->inWater(a.x, a.y, depth)};
}

double open(std::size_t, std::size_t, std::size_t, std::size_t)
{
    return 0.3;
}
} // namespace

TEST(NetCdfLand, VelocitiesExactlyZeroAtEveryTimeAreLandByDefault)
{
    TempDir dir;
    const std::string path = dir.file("pop_like.nc");
    // the block is 0 at every time; one node outside it is 0 only in the first record (a calm moment, not land)
    writeFile(path, 0, [](std::size_t t, std::size_t, std::size_t j, std::size_t i) {
        if (inBlock(i, j))
            return 0.0;
        if (i == 15 && j == 12 && t == 0)
            return 0.0;
        return 0.3;
    });
    const GriddedCurrents nc = loadGriddedCurrents(path);
    EXPECT_EQ(nc.zeroLandNodes, 25u);
    EXPECT_EQ(nc.fillLandNodes, 0u);
    EXPECT_EQ(nc.landNodes, 25u);
    const Probe p = probe(nc);
    EXPECT_FALSE(p.block);
    EXPECT_TRUE(p.away);
    const Point2 calm = nc.toLocal({kLon[15], kLat[12]});
    EXPECT_TRUE(nc.field->inWater(calm.x, calm.y, 0.0));
    // a leg across the block is refused, one beside it accepted
    const Point2 w = nc.toLocal({-71.5, 40.0}), e = nc.toLocal({-68.5, 40.0}), n1 = nc.toLocal({-71.5, 41.5}),
                 n2 = nc.toLocal({-68.5, 41.5});
    EXPECT_FALSE(nc.field->segmentInWater(w.x, w.y, e.x, e.y, 0.0));
    EXPECT_TRUE(nc.field->segmentInWater(n1.x, n1.y, n2.x, n2.y, 0.0));

    // a still field (zero at every node and time) is water, not all land
    const std::string stillFile = dir.file("still.nc");
    writeFile(stillFile, 0, [](std::size_t, std::size_t, std::size_t, std::size_t) { return 0.0; });
    EXPECT_EQ(loadGriddedCurrents(stillFile).landNodes, 0u);

    GriddedCurrentOptions off;
    off.zeroVelocityLand = false;
    const GriddedCurrents still = loadGriddedCurrents(path, off);
    EXPECT_EQ(still.landNodes, 0u);
    EXPECT_TRUE(probe(still).block);
}

TEST(NetCdfLand, MaskVariablesOfEachKindAreReadByTheirMeaning)
{
    TempDir dir;
    struct Case
    {
        const char *what;
        Extra mask;
    };
    auto block01 = [](double inside, double outside) {
        return [=](std::size_t, std::size_t, std::size_t j, std::size_t i) { return inBlock(i, j) ? inside : outside; };
    };
    const std::vector<Case> cases = {
        {"ROMS mask_rho, 1 = water",
         {"mask_rho", {"lat", "lon"}, NC_DOUBLE, block01(0, 1), {{"long_name", "mask on RHO-points"}}, {}}},
        {"CF flag_meanings",
         {"lsmask",
          {"lat", "lon"},
          NC_BYTE,
          block01(2, 1),
          {{"flag_meanings", "sea land sea_ice"}},
          {{"flag_values", {1, 2, 3}}}}},
        {"flag_meanings, ice is not water",
         {"surface_type",
          {"lat", "lon"},
          NC_BYTE,
          block01(3, 1),
          {{"flag_meanings", "sea land sea_ice_shelf"}, {"long_name", "type"}},
          {{"flag_values", {1, 2, 3}}}}},
        {"ERA5 land fraction", {"lsm", {"lat", "lon"}, NC_FLOAT, block01(0.7, 0.3), {}, {}}},
        {"land_binary_mask",
         {"land_flag", {"lat", "lon"}, NC_BYTE, block01(1, 0), {{"standard_name", "land_binary_mask"}}, {}}},
        {"on its own dimensions", {"mask", {"eta_rho:17", "xi_rho:21"}, NC_BYTE, block01(0, 1), {}, {}}},
        {"with a time axis", {"tmask", {"time", "lat", "lon"}, NC_BYTE, block01(0, 1), {}, {}}},
    };
    for (const Case &c : cases)
    {
        const std::string path = dir.file(std::string(c.mask.name) + ".nc");
        writeFile(path, 0, open, {c.mask});
        const GriddedCurrents nc = loadGriddedCurrents(path);
        EXPECT_EQ(nc.maskVariable, c.mask.name) << c.what;
        EXPECT_EQ(nc.maskLandNodes, 25u) << c.what;
        const Probe p = probe(nc);
        EXPECT_FALSE(p.block) << c.what;
        EXPECT_TRUE(p.away) << c.what;
        // "none" turns the mask off
        GriddedCurrentOptions none;
        none.maskName = "none";
        const GriddedCurrents nm = loadGriddedCurrents(path, none);
        EXPECT_TRUE(nm.maskVariable.empty()) << c.what;
        EXPECT_TRUE(probe(nm).block) << c.what;
    }
    // a fill value in the mask is land
    const std::string filled = dir.file("filled.nc");
    Extra m{"mask", {"lat", "lon"}, NC_FLOAT, block01(-1e20, 1), {}, {{"_FillValue", {-1e20}}}};
    writeFile(filled, 0, open, {m});
    EXPECT_FALSE(probe(loadGriddedCurrents(filled)).block);
}

TEST(NetCdfLand, LevelCountMaskClosesTheDeepLayersOnly)
{
    // POP's KMT: 3 depth layers (0, 50, 100 m); in the block KMT = 2 (the 100 m layer is rock); at one node KMT = 0
    TempDir dir;
    const std::string path = dir.file("kmt.nc");
    Extra kmt{"KMT",
              {"lat", "lon"},
              NC_INT,
              [](std::size_t, std::size_t, std::size_t j, std::size_t i) {
                  return i == 18 && j == 3 ? 0.0 : inBlock(i, j) ? 2.0 : 3.0;
              },
              {},
              {}};
    writeFile(path, 3, open, {kmt});
    const GriddedCurrents nc = loadGriddedCurrents(path);
    EXPECT_EQ(nc.maskVariable, "KMT");
    EXPECT_TRUE(probe(nc, 0.0).block);
    EXPECT_TRUE(probe(nc, 40.0).block);
    EXPECT_FALSE(probe(nc, 100.0).block);
    EXPECT_FALSE(probe(nc, 75.0).block); // between 50 and 100 m the deep layer carries weight
    EXPECT_TRUE(probe(nc, 100.0).away);
    const Point2 dry = nc.toLocal({kLon[18], kLat[3]});
    EXPECT_FALSE(nc.field->inWater(dry.x, dry.y, 0.0));
}

TEST(NetCdfLand, SeasonalMaskClosesOnlyTheRecordsOfTheTrip)
{
    // the block is ice (mask 0) in the first two records (Jan 1, Jan 31) and open water from Mar 2
    TempDir dir;
    const std::string path = dir.file("seasonal.nc");
    Extra m{"tmask",
            {"time", "lat", "lon"},
            NC_BYTE,
            [](std::size_t t, std::size_t, std::size_t j, std::size_t i) {
                return inBlock(i, j) && t < 2 ? 0.0 : 1.0; },
            {},
            {}};
    writeFile(path, 0, open, {m});
    GriddedCurrentOptions january;
    january.departure = "2026-01-01T00:00:00Z";
    january.horizon = 10 * 86400.0;
    EXPECT_FALSE(probe(loadGriddedCurrents(path, january)).block);
    GriddedCurrentOptions spring;
    spring.departure = "2026-03-15T00:00:00Z";
    spring.horizon = 10 * 86400.0;
    const GriddedCurrents nc = loadGriddedCurrents(path, spring);
    EXPECT_TRUE(probe(nc).block);
    // Jan 1 and Jan 31 are loaded (the stencil margin of cubic time schemes) but are not records of the trip
    EXPECT_EQ(nc.loadedShape[0], 4u);
}

TEST(NetCdfLand, AGivenMaskMustExistAndFitTheGrid)
{
    TempDir dir;
    const std::string path = dir.file("staggered_mask.nc");
    // a mask on a staggered grid (one column fewer): ignored when looking automatically, an error when named
    Extra m{"mask_u", {"eta_u:17", "xi_u:20"},
            NC_BYTE,  [](std::size_t, std::size_t, std::size_t, std::size_t) {
                return 0.0; },
            {},       {}};
    writeFile(path, 0, open, {m});
    EXPECT_TRUE(loadGriddedCurrents(path).maskVariable.empty());
    GriddedCurrentOptions given;
    given.maskName = "mask_u";
    try
    {
        loadGriddedCurrents(path, given);
        FAIL() << "expected an Error";
    }
    catch (const Error &e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("mask variable 'mask_u'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("does not fit"), std::string::npos) << msg;
        EXPECT_NE(msg.find("GriddedCurrentOptions::maskName"), std::string::npos) << msg;
        EXPECT_NE(msg.find("xi_u = 20"), std::string::npos) << msg;
        EXPECT_NE(msg.find("staggered_mask.nc"), std::string::npos) << msg;
    }
    given.maskName = "landsea";
    EXPECT_THROW(loadGriddedCurrents(path, given), Error);
}

TEST(NetCdfLand, DepthAverageOfALinearProfileIsExactAndKeepsTheLandOfItsLayers)
{
    // 5 layers at 0, 50, 100, 150, 200 m; u = 0.1 + 0.001 z (linear: the trapezoid rule is exact), v = 0.1; the
    // block is rock at 150 m only (fill values)
    TempDir dir;
    const std::string path = dir.file("layers.nc");
    writeFile(path, 5, [](std::size_t, std::size_t k, std::size_t j, std::size_t i) {
        if (k == 3 && inBlock(i, j))
            return -999.0;
        return 0.1 + 0.001 * 50.0 * double(k);
    });
    auto averaged = [&](double top, double bottom) {
        GriddedCurrentOptions o;
        o.depthAverage = std::make_pair(top, bottom);
        return loadGriddedCurrents(path, o);
    };
    // u is linear in z, so its average over a range is its value at the range's mean depth: compare with the 3-D
    // field read at that depth (the same rotation into the local frame, the same interpolation)
    const GriddedCurrents full = loadGriddedCurrents(path);
    auto at = [](const GriddedCurrents &nc, double z) {
        const Point2 p = nc.toLocal({-68.0, 41.0});
        return nc.field->velocity(p.x, p.y, z, 0.0);
    };
    const GriddedCurrents deep = averaged(20.0, 170.0);
    EXPECT_EQ(deep.field->nz(), 1u);
    EXPECT_NEAR(at(deep, 0.0).u, at(full, 95.0).u, 1e-7);
    EXPECT_NEAR(at(deep, 0.0).v, at(full, 95.0).v, 1e-7);
    EXPECT_NEAR(std::hypot(at(deep, 0.0).u, at(deep, 0.0).v), std::hypot(0.195, 0.1), 1e-4);
    EXPECT_FALSE(probe(deep).block); // rock at 150 m lies within 20..170 m
    const GriddedCurrents shallow = averaged(0.0, 90.0);
    EXPECT_NEAR(at(shallow, 0.0).u, at(full, 45.0).u, 1e-7);
    EXPECT_TRUE(probe(shallow).block); // the 150 m layer carries no weight over 0..90 m
    // beyond the deepest layer the profile is constant: 0..300 m averages 200 m of the profile and 100 m of 0.3,
    // (200 * 0.2 + 100 * 0.3) / 300 = 0.2333..., the profile's value at 133.33 m
    const GriddedCurrents beyond = averaged(0.0, 300.0);
    EXPECT_NEAR(at(beyond, 0.0).u, at(full, 400.0 / 3.0).u, 1e-7);
    GriddedCurrentOptions bad;
    bad.depthAverage = std::make_pair(100.0, 50.0);
    EXPECT_THROW(loadGriddedCurrents(path, bad), Error);
}
