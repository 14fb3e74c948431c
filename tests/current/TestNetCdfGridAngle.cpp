// The grid angle of a rotated curvilinear grid without an `angle` variable, derived from the nodes' longitudes and
// latitudes (deriveGridAngle(), an internal of the reader): equal to the true angle at every node of ROMS-like grids
// at several rotations; the loaded velocities of a ROMS-like C grid without `angle` equal those with it; an
// unrotated grid is left alone; a grid whose directions are ambiguous (left-handed, or an i direction that kinks) is
// refused with a message naming the node and what to give instead. Files written here with NetCDF-C.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "ModelGrids.h"
#include "TestNetCdfUtil.h"
#include "gridded/GriddedInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"

using namespace ompl_glider;
using glider_test::inPlane;
using glider_test::kDeg;
using glider_test::NcWriter;
using glider_test::RomsGrid;
using glider_test::TempDir;

namespace
{
/// lon/lat of every rho point of the grid.
void rhoNodes(const RomsGrid &g, std::vector<double> &lon, std::vector<double> &lat)
{
    lon.clear();
    lat.clear();
    for (std::size_t j = 0; j < RomsGrid::kEta; ++j)
        for (std::size_t i = 0; i < RomsGrid::kXi; ++i)
        {
            const LonLat p = g.geo(double(j), double(i));
            lon.push_back(p.lon);
            lat.push_back(p.lat);
        }
}

/// A curvilinear file with u/v along the grid (no standard_name, no angle) on nodes lon/lat(j, i) of nj x ni, the
/// grid components of a uniform eastward current of 0.3 m/s turned by angle(j, i).
void writeGridRelative(const std::string &path, std::size_t nj, std::size_t ni,
                       const std::function<LonLat(std::size_t, std::size_t)> &node,
                       const std::function<double(std::size_t, std::size_t)> &angle)
{
    NcWriter w(path);
    const int dt = w.dim("time", 1), dj = w.dim("eta_rho", nj), di = w.dim("xi_rho", ni);
    const int vt = w.var("time", NC_DOUBLE, {dt});
    w.text(vt, "units", "days since 2026-04-01");
    const int lo = w.var("lon_rho", NC_DOUBLE, {dj, di}), la = w.var("lat_rho", NC_DOUBLE, {dj, di});
    w.text(lo, "units", "degree_east");
    w.text(la, "units", "degree_north");
    const int u = w.var("u", NC_FLOAT, {dt, dj, di}), v = w.var("v", NC_FLOAT, {dt, dj, di});
    w.text(u, "units", "m/s");
    w.text(v, "units", "m/s");
    w.enddef();
    w.put(vt, {0.0});
    std::vector<double> lon, lat, pu, pv;
    for (std::size_t j = 0; j < nj; ++j)
        for (std::size_t i = 0; i < ni; ++i)
        {
            const LonLat g = node(j, i);
            lon.push_back(g.lon);
            lat.push_back(g.lat);
            const double a = angle(j, i);
            pu.push_back(0.3 * std::cos(a));
            pv.push_back(-0.3 * std::sin(a));
        }
    w.put(lo, lon);
    w.put(la, lat);
    w.put(u, pu);
    w.put(v, pv);
}
} // namespace

TEST(NetCdfGridAngle, DerivedAngleEqualsTheTrueAngleAtEveryNode)
{
    for (const double deg : {30.0, -45.0, 75.0, 150.0})
    {
        RomsGrid g;
        g.theta = deg * kDeg;
        std::vector<double> lon, lat;
        rhoNodes(g, lon, lat);
        const gridded_detail::DerivedGridAngle a =
            gridded_detail::deriveGridAngle(lon, lat, RomsGrid::kXi, RomsGrid::kEta, true);
        ASSERT_TRUE(a.fault.empty()) << a.fault;
        ASSERT_TRUE(a.rotated);
        ASSERT_EQ(a.radians.size(), RomsGrid::kEta * RomsGrid::kXi);
        double worst = 0.0;
        for (std::size_t j = 0; j < RomsGrid::kEta; ++j)
            for (std::size_t i = 0; i < RomsGrid::kXi; ++i)
            {
                // the true angle: the grid's xi direction in the plane (theta) less the direction of local east there
                const std::size_t n = j * RomsGrid::kXi + i;
                double ex, ey;
                g.proj.eastDirection(lon[n], lat[n], ex, ey);
                double diff = a.radians[n] - (g.theta - std::atan2(ey, ex));
                diff = std::remainder(diff, 2.0 * M_PI);
                worst = std::max(worst, std::abs(diff) / kDeg);
                EXPECT_NEAR(diff / kDeg, 0.0, 0.002) << "theta " << deg << " node (" << j << ", " << i << ")";
            }
        // (the true angle varies over the grid by the meridians' convergence; the derived one follows it)
        EXPECT_LT(worst, 0.002) << deg;
    }
    // Cartesian coordinates (metres): the angle is the plane's
    RomsGrid g;
    std::vector<double> x, y;
    for (std::size_t j = 0; j < RomsGrid::kEta; ++j)
        for (std::size_t i = 0; i < RomsGrid::kXi; ++i)
            x.push_back(g.at(double(j), double(i)).x), y.push_back(g.at(double(j), double(i)).y);
    const auto c = gridded_detail::deriveGridAngle(x, y, RomsGrid::kXi, RomsGrid::kEta, false);
    for (double r : c.radians)
        ASSERT_NEAR(r, g.theta, 1e-12);
}

TEST(NetCdfGridAngle, RomsGridWithoutAngleVariableLoadsAsWithIt)
{
    TempDir tmp;
    RomsGrid with, without;
    without.writeAngle = false;
    const std::string a = tmp.file("with.nc"), b = tmp.file("without.nc");
    with.write(a);
    without.write(b);
    const GriddedCurrents na = loadGriddedCurrents(a), nb = loadGriddedCurrents(b);
    EXPECT_EQ(na.gridAngle, "variable 'angle'");
    EXPECT_EQ(nb.gridAngle.rfind("derived from 'lon_rho'/'lat_rho': the grid's i direction 29.", 0), 0u)
        << nb.gridAngle;
    std::size_t checked = 0;
    for (std::size_t j = 1; j + 1 < RomsGrid::kEta; ++j)
        for (std::size_t i = 1; i + 1 < RomsGrid::kXi; ++i)
        {
            const LonLat g = with.geo(double(j), double(i));
            const Point2 p = nb.toLocal(g);
            if (!nb.field->inWater(p.x, p.y, 0.0))
                continue;
            const Velocity va = na.field->velocity(p.x, p.y, 0.0, 0.0), vb = nb.field->velocity(p.x, p.y, 0.0, 0.0);
            // the file's angle is 30 degrees everywhere; the true one differs by the meridians' convergence
            // (up to 0.6 degree here), so the derived rotation is the more exact: the two within 0.02 * |c|
            EXPECT_NEAR(vb.u, va.u, 5e-3) << j << " " << i;
            EXPECT_NEAR(vb.v, va.v, 5e-3) << j << " " << i;
            bool nearLand = false;
            for (std::size_t s = j - 1; s <= j + 1; ++s)
                for (std::size_t t = i - 1; t <= i + 1; ++t)
                    nearLand = nearLand || RomsGrid::land(s, t);
            if (nearLand)
                continue;
            // the true current: the vector (cx, cy) of the grid's plane, split there into east and north, then put
            // in the loaded field's plane
            double cx, cy, ex, ey, nx, ny;
            RomsGrid::current(with.at(double(j), double(i)), cx, cy);
            with.proj.eastDirection(g.lon, g.lat, ex, ey);
            with.proj.northDirection(g.lon, g.lat, nx, ny);
            const double det = ex * ny - ey * nx;
            const double east = (cx * ny - cy * nx) / det, north = (ex * cy - ey * cx) / det;
            const Velocity e = inPlane(nb, g.lon, g.lat, east, north);
            EXPECT_NEAR(vb.u, e.u, 2e-5) << j << " " << i;
            EXPECT_NEAR(vb.v, e.v, 2e-5) << j << " " << i;
            ++checked;
        }
    EXPECT_GT(checked, 120u);
}

TEST(NetCdfGridAngle, UnrotatedCurvilinearGridIsLeftAlone)
{
    TempDir tmp;
    const std::string path = tmp.file("plain.nc");
    writeGridRelative(
        path, 8, 10,
        [](std::size_t j, std::size_t i) {
            return LonLat{-60.0 + 0.1 * double(i), 30.0 + 0.1 * double(j)};
        },
        [](std::size_t, std::size_t) { return 0.0; });
    const GriddedCurrents nc = loadGriddedCurrents(path);
    EXPECT_EQ(nc.gridAngle, "");
    const Point2 p = nc.toLocal({-59.55, 30.35});
    const Velocity c = nc.field->velocity(p.x, p.y, 0.0, 0.0), e = inPlane(nc, -59.55, 30.35, 0.3, 0.0);
    EXPECT_NEAR(c.u, e.u, 1e-6);
    EXPECT_NEAR(c.v, e.v, 1e-6);
}

TEST(NetCdfGridAngle, AmbiguousGridsAreRefused)
{
    TempDir tmp;
    // a left-handed rotated grid: eta runs clockwise of xi, so grid-relative v could point either way
    RomsGrid g;
    const std::string left = tmp.file("left.nc");
    writeGridRelative(
        left, 10, 12, [&](std::size_t j, std::size_t i) { return g.geo(-double(j), double(i)); },
        [&](std::size_t, std::size_t) { return g.theta; });
    try
    {
        loadGriddedCurrents(left);
        FAIL() << "a left-handed rotated grid without angle must be refused";
    }
    catch (const Error &e)
    {
        const std::string m = e.what();
        EXPECT_NE(m.find("left.nc"), std::string::npos) << m;
        EXPECT_NE(m.find("no grid angle variable"), std::string::npos) << m;
        EXPECT_NE(m.find("'lon_rho'/'lat_rho' gives no clear angle: at (j, i) = (0, 0)"), std::string::npos) << m;
        EXPECT_NE(m.find("j direction lies -"), std::string::npos) << m;
        EXPECT_NE(m.find("GriddedCurrentOptions::angleName 'none'"), std::string::npos) << m;
    }
    // the way out the message names: the velocities declared eastward/northward
    GriddedCurrentOptions none;
    none.angleName = "none";
    EXPECT_EQ(loadGriddedCurrents(left, none).gridAngle, "");
    // an i direction that kinks by 80 degrees at column 5 (j stays perpendicular to the first part)
    std::vector<double> x, y;
    for (std::size_t j = 0; j < 6; ++j)
        for (std::size_t i = 0; i < 10; ++i)
        {
            const double a = (i <= 5 ? 20.0 : 100.0) * kDeg, s = i <= 5 ? double(i) : 5.0;
            const double t = i <= 5 ? 0.0 : double(i) - 5.0;
            x.push_back(s * std::cos(20.0 * kDeg) + t * std::cos(a) - double(j) * std::sin(20.0 * kDeg));
            y.push_back(s * std::sin(20.0 * kDeg) + t * std::sin(a) + double(j) * std::cos(20.0 * kDeg));
        }
    const auto k = gridded_detail::deriveGridAngle(x, y, 10, 6, false);
    EXPECT_NE(k.fault.find("i direction turns by"), std::string::npos) << k.fault;
    EXPECT_EQ(k.faultI, 4u);
}
