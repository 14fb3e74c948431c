// A route on a model file whose land is stored as zero velocities (as POP writes it): a peninsula between start and
// goal with a strong current through it would make the straight route attractive; the route must go around it.
// Checked independently of the planner's own land test: every leg is sampled every ~50 m (a cell is ~20 km) and no
// sample may lie inside a cell with a land corner, computed from lon/lat and the land node list.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "../current/TestNetCdfUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;
using namespace glider_test;

namespace
{
// 0.2-degree grid, lon -80..-76, lat 25..28 (21 x 16 nodes); the peninsula: lon -78.6..-77.4 (i = 7..13), lat
// 25..27.2 (j = 0..11), attached to the southern edge; open water north of it
constexpr std::size_t kNx = 21, kNy = 16;
bool peninsula(std::size_t i, std::size_t j)
{
    return i >= 7 && i <= 13 && j <= 11;
}
double lonOf(std::size_t i)
{
    return -80.0 + 0.2 * double(i);
}
double latOf(std::size_t j)
{
    return 25.0 + 0.2 * double(j);
}

void writePopLike(const std::string &path)
{
    NcWriter w(path, NC_CLOBBER); // classic format, as many model archives are
    const int dt = w.dim("time", 2), dy = w.dim("lat", kNy), dx = w.dim("lon", kNx);
    const int vt = w.var("time", NC_DOUBLE, {dt}), vy = w.var("lat", NC_DOUBLE, {dy}),
              vx = w.var("lon", NC_DOUBLE, {dx});
    w.text(vt, "units", "hours since 2026-05-01 00:00:00");
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    const int vu = w.var("UVEL", NC_FLOAT, {dt, dy, dx}), vv = w.var("VVEL", NC_FLOAT, {dt, dy, dx});
    for (int v : {vu, vv})
        w.text(v, "units", "m/s");
    w.text(vu, "standard_name", "eastward_sea_water_velocity");
    w.text(vv, "standard_name", "northward_sea_water_velocity");
    w.enddef();
    w.put(vt, {0.0, 720.0});
    std::vector<double> lat(kNy), lon(kNx);
    for (std::size_t j = 0; j < kNy; ++j)
        lat[j] = latOf(j);
    for (std::size_t i = 0; i < kNx; ++i)
        lon[i] = lonOf(i);
    w.put(vy, lat);
    w.put(vx, lon);
    std::vector<double> u, v;
    for (int t = 0; t < 2; ++t)
        for (std::size_t j = 0; j < kNy; ++j)
            for (std::size_t i = 0; i < kNx; ++i)
            {
                // land: exactly zero; water: an eastward current of 0.4 m/s in the south (where it would carry
                // a glider straight across the peninsula), weaker to the north
                u.push_back(peninsula(i, j) ? 0.0 : 0.4 - 0.02 * double(j));
                v.push_back(peninsula(i, j) ? 0.0 : 0.02);
            }
    w.put(vu, u);
    w.put(vv, v);
}

/// True when (lon, lat) lies inside a grid cell with a land corner, shrunk by `margin` degrees on each side.
bool inLandCell(double lon, double lat, double margin)
{
    const double fi = (lon + 80.0) / 0.2, fj = (lat - 25.0) / 0.2;
    if (fi < 0 || fj < 0 || fi >= kNx - 1 || fj >= kNy - 1)
        return false;
    const std::size_t i = std::size_t(fi), j = std::size_t(fj);
    const bool land = peninsula(i, j) || peninsula(i + 1, j) || peninsula(i, j + 1) || peninsula(i + 1, j + 1);
    const double m = margin / 0.2;
    return land && fi - double(i) > m && double(i + 1) - fi > m && fj - double(j) > m && double(j + 1) - fj > m;
}
} // namespace

TEST(ForecastLand, RouteGoesAroundAPeninsulaStoredAsZeroVelocity)
{
    TempDir dir;
    const std::string file = dir.file("pop_like.nc");
    writePopLike(file);
    ForecastInput in;
    in.current.file = file;
    in.start = {-79.5, 25.6}; // south-west of the peninsula
    in.goal = {-76.5, 26.4};  // east of it: the straight line crosses it
    in.speed = 0.5;
    const MissionSpec spec = forecastMission(in);
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.status << " " << r.plan.reason;
    EXPECT_TRUE(std::isinf(r.plan.straightLineTime)) << "the straight leg must be refused";
    // the route passes north of the peninsula
    double northmost = -90.0;
    for (const TimedPoint &w : r.plan.path)
        northmost = std::max(northmost, problem.toGeographic({w.x, w.y}).lat);
    EXPECT_GT(northmost, latOf(11));
    // independent land clearance: every ~50 m along every leg
    for (std::size_t k = 0; k + 1 < r.plan.path.size(); ++k)
    {
        const TimedPoint &a = r.plan.path[k], &b = r.plan.path[k + 1];
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        const int n = std::max(2, int(len / 50.0));
        for (int q = 0; q <= n; ++q)
        {
            const double s = double(q) / n;
            const LonLat g = problem.toGeographic({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)});
            // 0.001 degree (~100 m) margin: the planner's cells have straight projected edges, the check's cells
            // follow meridians and parallels; they differ by far less than that over a 0.2-degree cell
            ASSERT_FALSE(inLandCell(g.lon, g.lat, 0.001)) << "leg " << k << " at " << g.lon << ", " << g.lat;
        }
    }
    // the same file with zero velocities taken as water would let the route cross (the old, unsafe answer)
    ForecastInput water = in;
    water.current.zeroVelocityLand = false;
    const MissionProblem open(forecastMission(water));
    const MissionResult ro = runMission(open);
    ASSERT_TRUE(ro.plan.solved);
    EXPECT_TRUE(std::isfinite(ro.plan.straightLineTime));
}

TEST(ForecastLand, StartOnLandNamesTheNearestWaterAndSnapsToItOnRequest)
{
    TempDir dir;
    const std::string file = dir.file("pop_like.nc");
    writePopLike(file);
    ForecastInput in;
    in.current.file = file;
    in.start = {-78.4, 25.6}; // on the peninsula, 0.4 degree east of its western shore (cells with a land corner
                              // end at the nodes of lon -78.8)
    in.goal = {-76.5, 26.4};
    in.speed = 0.5;
    try
    {
        forecastMission(in);
        FAIL() << "a start on land must be refused";
    }
    catch (const Error &e)
    {
        const std::string m = e.what();
        EXPECT_NE(m.find("start -78.4,25.6 (lon,lat) is on land"), std::string::npos) << m;
        EXPECT_NE(m.find("the nearest water is -78.80"), std::string::npos) << m;
        EXPECT_NE(m.find(",25.6"), std::string::npos) << m;
        EXPECT_NE(m.find("km away (safety.snap_to_water: true uses it)"), std::string::npos) << m;
    }
    in.snapToWater = true;
    MissionSpec spec = forecastMission(in);
    EXPECT_TRUE(spec.safety.snapToWater);
    const MissionProblem problem(spec);
    const LonLat s = problem.toGeographic(problem.getStart());
    EXPECT_NEAR(s.lon, -78.8, 0.01);
    EXPECT_NEAR(s.lat, 25.6, 0.01);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    ASSERT_FALSE(r.forecastNotes.empty());
    EXPECT_EQ(r.forecastNotes.back().rfind("start lon,lat -78.4,25.6 is on land: moved to the nearest water lon,lat "
                                           "-78.80",
                                           0),
              0u)
        << r.forecastNotes.back();
    // the same problem without snapping (as a mission file gives it): refused, naming the field and the water
    spec.safety.snapToWater = false;
    try
    {
        const MissionProblem refused(spec);
        FAIL() << "a start on land must be refused";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("the nearest water is lon,lat -78.80"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("safety.snap_to_water: true"), std::string::npos) << e.what();
    }
}
