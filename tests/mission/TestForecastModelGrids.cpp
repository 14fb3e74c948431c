// Routes on model grids: across the index seam of a global curvilinear grid round an island that sits on
// the seam, and across a ROMS-like C grid round a masked island. Land clearance is checked independently of the
// planner: every leg is sampled every ~200 m (cells are 5 km and 300 km) and no sample may lie inside a cell with
// a land corner, found from the sample's lon/lat through the grid's own formulas.
#include <gtest/gtest.h>

#include <cmath>

#include "../current/ModelGrids.h"
#include "../current/TestNetCdfUtil.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;
using namespace glider_test;

namespace
{
/// Samples every leg of the route every `step` metres, calls bad(lon, lat) and fails on the first true.
template <typename Bad>
void expectClearOfLand(const MissionProblem &problem, const std::vector<TimedPoint> &path, double step, Bad bad)
{
    std::size_t samples = 0;
    for (std::size_t k = 0; k + 1 < path.size(); ++k)
    {
        const TimedPoint &a = path[k], &b = path[k + 1];
        const int n = std::max(2, int(std::hypot(b.x - a.x, b.y - a.y) / step));
        for (int q = 0; q <= n; ++q, ++samples)
        {
            const double s = double(q) / n;
            const LonLat g = problem.toGeographic({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)});
            ASSERT_GE(g.lon, -180.0);
            ASSERT_LE(g.lon, 180.0);
            ASSERT_FALSE(bad(g.lon, g.lat)) << "leg " << k << " at " << g.lon << ", " << g.lat;
        }
    }
    EXPECT_GT(samples, 100u);
}

/// True when the point at fractional grid indices (fi, fj) lies inside a cell with a land corner (land(j, i) of its
/// four corners, column i + 1 taken modulo `columns` for a grid whose index wraps), at least `margin` of a cell
/// from the cell's edges: the planner's cells have straight projected edges, the grid's follow its own formula.
template <typename Land>
bool inModelLandCell(double fi, double fj, Land land, std::size_t columns, double margin = 0.01)
{
    const std::size_t i = std::size_t(std::floor(fi)), j = std::size_t(std::floor(fj)), i1 = (i + 1) % columns;
    const bool corner = land(j, i) || land(j + 1, i) || land(j, i1) || land(j + 1, i1);
    const double a = fi - std::floor(fi), b = fj - std::floor(fj);
    return corner && a > margin && a < 1 - margin && b > margin && b < 1 - margin;
}
} // namespace

TEST(ForecastModelGrids, RouteAcrossTheIndexSeamOfAWrappingCurvilinearGridGoesRoundAnIslandOnIt)
{
    TempDir dir;
    WrapGrid grid;
    // at 20N (row 30) the nodes lie at -34 + 3i: the index seam runs between column 119 (37W) and column 0 (34W);
    // the island covers rows 29..31 of columns 119 and 0
    grid.landRows[0] = 29;
    grid.landRows[1] = 31;
    grid.landCols[0] = 119;
    grid.landCols[1] = 0;
    const std::string file = dir.file("wrap.nc");
    grid.write(file);
    ForecastInput in;
    in.current.file = file;
    in.start = {-44.0, 20.0};
    in.goal = {-27.0, 20.5};
    in.speed = 1.0;
    const MissionSpec spec = forecastMission(in);
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.status << " " << r.plan.reason;
    EXPECT_TRUE(std::isinf(r.plan.straightLineTime)) << "the straight leg crosses the island";
    // cell (j, i) from lon/lat: lat = -40 + 2j, lon = -40 + 3i + 0.2j (mod 360) is affine in (i, j)
    auto bad = [&](double lon, double lat) {
        const double fj = (lat + 40.0) / 2.0;
        double fi = std::fmod(lon + 40.0 - 0.2 * fj, 360.0) / 3.0;
        if (fi < 0)
            fi += 120.0;
        return inModelLandCell(
            fi, fj, [&](std::size_t j, std::size_t i) { return grid.land(j, i); }, 120);
    };
    expectClearOfLand(problem, r.plan.path, 200.0, bad);
    // the route went round the island: north of row 31 or south of row 29 somewhere
    double north = -90, south = 90;
    for (const TimedPoint &w : r.plan.path)
    {
        const LonLat g = problem.toGeographic({w.x, w.y});
        north = std::max(north, g.lat);
        south = std::min(south, g.lat);
    }
    EXPECT_TRUE(north > grid.lat(31, 0) || south < grid.lat(29, 0)) << north << " " << south;
    const LonLat end = problem.toGeographic({r.plan.path.back().x, r.plan.path.back().y});
    EXPECT_NEAR(end.lon, -27.0, 1e-6);
    EXPECT_NEAR(end.lat, 20.5, 1e-6);
}

TEST(ForecastModelGrids, RouteOnARomsCGridGoesRoundItsMaskedIsland)
{
    TempDir dir;
    const RomsGrid grid;
    const std::string file = dir.file("roms.nc");
    grid.write(file);
    ForecastInput in;
    in.current.file = file;
    const LonLat s = grid.geo(10, 3), g = grid.geo(10.2, 16); // the straight line crosses the island (eta 9..11)
    in.start = {s.lon, s.lat};
    in.goal = {g.lon, g.lat};
    in.speed = 0.5;
    const MissionSpec spec = forecastMission(in);
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.status << " " << r.plan.reason;
    EXPECT_TRUE(std::isinf(r.plan.straightLineTime)) << "the straight leg crosses the island";
    // (eta, xi) of a position: the grid's own plane, rotation undone
    auto bad = [&](double lon, double lat) {
        const Point2 p = grid.proj.forward(lon, lat);
        const double a = (p.x * std::cos(grid.theta) + p.y * std::sin(grid.theta)) / grid.d + 0.5 * RomsGrid::kXi;
        const double b = (-p.x * std::sin(grid.theta) + p.y * std::cos(grid.theta)) / grid.d + 0.5 * RomsGrid::kEta;
        return inModelLandCell(a, b, RomsGrid::land, RomsGrid::kXi);
    };
    expectClearOfLand(problem, r.plan.path, 200.0, bad);
}

TEST(ForecastModelGrids, RomsGridWithoutAngleGivesTheSameRouteAsWithIt)
{
    // the rotated (30 degrees) C grid with its `angle`, and the same file without: the angle is then derived from
    // lon_rho/lat_rho and the route is the same; read as east/north (angle none), it is not
    TempDir dir;
    RomsGrid with, without;
    without.writeAngle = false;
    const std::string a = dir.file("with.nc"), b = dir.file("without.nc");
    with.write(a);
    without.write(b);
    const LonLat s = with.geo(3, 2), g = with.geo(8, 15);
    auto plan = [&](const std::string &file, const std::string &angle) {
        ForecastInput in;
        in.current.file = file;
        if (!angle.empty())
            in.current.variables["angle"] = angle;
        in.start = {s.lon, s.lat};
        in.goal = {g.lon, g.lat};
        in.speed = 0.5;
        const MissionProblem problem(forecastMission(in));
        return runMission(problem);
    };
    const MissionResult ra = plan(a, ""), rb = plan(b, ""), rn = plan(a, "none");
    ASSERT_TRUE(ra.plan.solved && rb.plan.solved && rn.plan.solved)
        << ra.plan.reason << rb.plan.reason << rn.plan.reason;
    EXPECT_NEAR(rb.plan.travelTime / ra.plan.travelTime, 1.0, 1e-3) << ra.plan.travelTime << " " << rb.plan.travelTime;
    EXPECT_GT(std::abs(rn.plan.travelTime / ra.plan.travelTime - 1.0), 0.01) << rn.plan.travelTime;
    // the report and summary say how the angle was found
    EXPECT_NE(rb.forecastNotes.front().find("grid angle derived from 'lon_rho'/'lat_rho'"), std::string::npos);
    EXPECT_NE(ra.forecastNotes.front().find("grid angle from the variable 'angle'"), std::string::npos);
}
