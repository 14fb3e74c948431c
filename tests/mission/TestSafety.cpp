// Safety margins through the one pipeline: the keep-off distance from land (islands, a forecast's land cells) kept by
// every planner family, the closest approach in the result, and the depth limit from a GEBCO-like bathymetry file.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../current/TestNetCdfUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/environment/KeepOffZone.h"
#include "ompl_glider/io/DepthGrid.h"
#include "ompl_glider/io/GriddedBathymetry.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;
using namespace glider_test;

namespace
{
/// A still sea with a square island [4, 6] x [-1, 1] right on the line from start to goal.
std::string islandMission(const std::string &planner, const std::string &safety)
{
    return "name: rock\ncurrent: {type: uniform, parameters: {u: 0.05, v: 0.0}}\n"
           "region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\nstart: {x: 1, y: 0.3}\ngoal: {x: 9, y: 0.3}\n"
           "vehicle: {speed: 0.5}\n"
           "forbidden:\n  obstacles:\n    - {name: Rock, kind: island, points: [[4, -1], [6, -1], [6, 1], [4, 1]]}\n"
           "planner: {name: \"" +
           planner + "\", grid_size: 0.25, time_limit: 20}\n" + safety;
}

/// Smallest distance of the route (track of a heading route, else the legs) to the island's sides, sampled densely:
/// independent of the keep-off zone's own geometry.
double sampledClearance(const PlannedPath &p)
{
    const std::vector<TimedPoint> &r = p.track.size() > 1 ? p.track : p.path;
    double best = HUGE_VAL;
    for (std::size_t k = 0; k + 1 < r.size(); ++k)
        for (int q = 0; q <= 400; ++q)
        {
            const double s = q / 400.0, x = r[k].x + s * (r[k + 1].x - r[k].x), y = r[k].y + s * (r[k + 1].y - r[k].y);
            const double dx = std::max({4.0 - x, 0.0, x - 6.0}), dy = std::max({-1.0 - y, 0.0, y - 1.0});
            best = std::min(best, std::hypot(dx, dy));
        }
    return best;
}
} // namespace

TEST(Safety, EveryPlannerFamilyKeepsTheKeepOffDistance)
{
    for (const std::string planner : {"ZA*TVE", "LevelSet", "Isochrone"})
    {
        SCOPED_TRACE(planner);
        const MissionProblem problem(parseMission(islandMission(planner, "safety: {keep_off: 0.6}\n"), "rock.yaml"));
        ASSERT_TRUE(problem.getLand());
        const MissionResult r = runMission(problem);
        ASSERT_TRUE(r.plan.solved) << r.plan.status << ": " << r.plan.reason;
        EXPECT_GE(r.closestLand.distance, 0.6 * (1.0 - 1e-9));
        EXPECT_GE(sampledClearance(r.plan), 0.6 * (1.0 - 1e-9));
        EXPECT_NEAR(r.closestLand.distance, sampledClearance(r.plan), 1e-3);
    }
    // without a keep-off distance the fastest route grazes the island: the check above bites
    const MissionProblem open(parseMission(islandMission("ZA*TVE", ""), "rock.yaml"));
    const MissionResult r = runMission(open);
    ASSERT_TRUE(r.plan.solved);
    EXPECT_LT(r.closestLand.distance, 0.3);
    EXPECT_NEAR(r.closestLand.distance, sampledClearance(r.plan), 1e-3);
}

TEST(Safety, KeepOffLengthsAndTheirUnits)
{
    // a dimensionless mission takes planning units, or metres with units.length_m
    const MissionSpec a = parseMission(islandMission("ZA*TVE", "safety: {keep_off: 0.4}\n"), "a.yaml");
    EXPECT_DOUBLE_EQ(a.safety.keepOff, 0.4);
    const MissionSpec b = parseMission(
        "units: {length_m: 20000, time_s: 43200}\n" + islandMission("ZA*TVE", "safety: {keep_off: 2km}\n"), "b.yaml");
    EXPECT_DOUBLE_EQ(b.safety.keepOff, 0.1);
    for (const std::string bad :
         {"safety: {keep_off: 2km}\n", "safety: {keep_off: -1}\n", "safety: {keep_off: 2 parsecs}\n"})
    {
        try
        {
            parseMission(islandMission("ZA*TVE", bad), "c.yaml");
            ADD_FAILURE() << bad << " accepted";
        }
        catch (const Error &e)
        {
            EXPECT_NE(std::string(e.what()).find("safety.keep_off"), std::string::npos) << e.what();
        }
    }
    // a start within the keep-off distance is refused, naming it
    const MissionProblem near(parseMission(islandMission("ZA*TVE", "safety: {keep_off: 3.5}\n"), "d.yaml"));
    const MissionResult r = runMission(near);
    EXPECT_FALSE(r.plan.solved);
    EXPECT_NE(r.plan.reason.find("keep-off"), std::string::npos) << r.plan.reason;
}

namespace
{
// 0.2-degree grid, lon -80..-76, lat 25..28; a land block (i 9..11, j 0..6) attached to the south edge
constexpr std::size_t kSafetyNx = 21, kNy = 16;
bool land(std::size_t i, std::size_t j)
{
    return i >= 9 && i <= 11 && j <= 6;
}

void writeForecast(const std::string &path)
{
    NcWriter w(path, NC_CLOBBER);
    const int dy = w.dim("lat", kNy), dx = w.dim("lon", kSafetyNx);
    const int vy = w.var("lat", NC_DOUBLE, {dy}), vx = w.var("lon", NC_DOUBLE, {dx});
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    const int vu = w.var("u", NC_FLOAT, {dy, dx}), vv = w.var("v", NC_FLOAT, {dy, dx});
    for (int v : {vu, vv})
        w.text(v, "units", "m/s");
    w.text(vu, "standard_name", "eastward_sea_water_velocity");
    w.text(vv, "standard_name", "northward_sea_water_velocity");
    w.enddef();
    std::vector<double> lat(kNy), lon(kSafetyNx), u, v;
    for (std::size_t j = 0; j < kNy; ++j)
        lat[j] = 25.0 + 0.2 * double(j);
    for (std::size_t i = 0; i < kSafetyNx; ++i)
        lon[i] = -80.0 + 0.2 * double(i);
    for (std::size_t j = 0; j < kNy; ++j)
        for (std::size_t i = 0; i < kSafetyNx; ++i)
        {
            u.push_back(land(i, j) ? 0.0 : 0.05);
            v.push_back(0.0);
        }
    w.put(vy, lat);
    w.put(vx, lon);
    w.put(vu, u);
    w.put(vv, v);
}

/// GEBCO-like elevation (positive up, by its standard_name) on a 0.05-degree grid: 500 m deep, a 20 m bank over
/// lon -78.5..-77.5, lat 26.0..26.8 north of the land block, and land (+10 m) on the block.
double bankDepth(double lon, double lat)
{
    if (lon >= -78.5 && lon <= -77.5 && lat >= 26.0 && lat <= 26.8)
        return 20.0;
    return 500.0;
}
/// Written as GEBCO does, elevation(lat, lon); @p transposed: elevation(lon, lat), as some tools write it.
void writeGebco(const std::string &path, bool transposed = false)
{
    NcWriter w(path, NC_CLOBBER);
    const std::size_t nx = 101, ny = 81; // lon -80..-75, lat 24..28
    const int dy = w.dim("lat", ny), dx = w.dim("lon", nx);
    const int vy = w.var("lat", NC_DOUBLE, {dy}), vx = w.var("lon", NC_DOUBLE, {dx});
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    const int ve = w.var("elevation", NC_FLOAT, transposed ? std::vector<int>{dx, dy} : std::vector<int>{dy, dx});
    w.text(ve, "standard_name", "height_above_mean_sea_level");
    w.text(ve, "units", "m");
    w.enddef();
    std::vector<double> lat(ny), lon(nx), e;
    for (std::size_t j = 0; j < ny; ++j)
        lat[j] = 24.0 + 0.05 * double(j);
    for (std::size_t i = 0; i < nx; ++i)
        lon[i] = -80.0 + 0.05 * double(i);
    for (std::size_t p = 0; p < (transposed ? nx : ny); ++p)
        for (std::size_t q = 0; q < (transposed ? ny : nx); ++q)
            e.push_back(transposed ? -bankDepth(lon[p], lat[q]) : -bankDepth(lon[q], lat[p]));
    w.put(vy, lat);
    w.put(vx, lon);
    w.put(ve, e);
}
} // namespace

TEST(Safety, KeepOffFromAForecastsLandCells)
{
    TempDir dir;
    const std::string file = dir.file("coast.nc");
    writeForecast(file);
    ForecastInput in;
    in.current.file = file;
    in.start = {-79.4, 25.5};
    in.goal = {-76.6, 25.5}; // the land block lies between them
    in.speed = 0.5;
    MissionSpec spec = forecastMission(in);
    const MissionResult open = runMission(MissionProblem(spec));
    ASSERT_TRUE(open.plan.solved) << open.plan.reason;
    EXPECT_LT(open.closestLand.distance, 10000.0); // round the block's corner closely
    spec.safety.keepOff = 15000.0;
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    EXPECT_GE(r.closestLand.distance, 15000.0 * (1.0 - 1e-9));
    ASSERT_TRUE(r.closestLandLonLat);
    // brute force over every edge of the land boundary, sampled along the route: the same bound
    const auto edges = problem.getField()->landBoundary(0.0);
    ASSERT_FALSE(edges.empty());
    const KeepOffZone plain(edges, 0.0);
    for (std::size_t k = 0; k + 1 < r.plan.path.size(); ++k)
        for (int q = 0; q <= 50; ++q)
        {
            const TimedPoint &a = r.plan.path[k], &b = r.plan.path[k + 1];
            const double s = q / 50.0;
            EXPECT_GE(plain.distanceTo(a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)), 15000.0 * (1.0 - 1e-9));
        }
    EXPECT_GT(r.plan.travelTime, open.plan.travelTime);
}

TEST(Safety, DepthLimitFromAGebcoLikeFileInEitherDimensionOrder)
{
    for (bool transposed : {false, true})
    {
        SCOPED_TRACE(transposed ? "elevation(lon, lat)" : "elevation(lat, lon)");
        TempDir dir;
        const std::string file = dir.file("coast.nc"), gebco = dir.file("gebco.nc");
        writeForecast(file);
        writeGebco(gebco, transposed);
        ForecastInput in;
        in.current.file = file;
        in.start = {-79.4, 26.4};
        in.goal = {-76.6, 26.4}; // the bank lies between them, north of the land
        in.speed = 0.5;
        MissionSpec spec = forecastMission(in);
        spec.safety.bathymetry = gebco;
        spec.safety.minDepth = 10.0; // the bank is deep enough
        const MissionProblem shallowOk(spec);
        const MissionResult a = runMission(shallowOk);
        ASSERT_TRUE(a.plan.solved) << a.plan.reason;
        double minDepth = HUGE_VAL;
        for (std::size_t k = 0; k + 1 < a.plan.path.size(); ++k)
            for (int q = 0; q <= 200; ++q)
            {
                const TimedPoint &p = a.plan.path[k], &b = a.plan.path[k + 1];
                const double s = q / 200.0;
                const LonLat g = shallowOk.toGeographic({p.x + s * (b.x - p.x), p.y + s * (b.y - p.y)});
                minDepth = std::min(minDepth, bankDepth(g.lon, g.lat));
            }
        EXPECT_EQ(minDepth, 20.0) << "the direct route crosses the bank";
        spec.safety.minDepth = 50.0;
        const MissionProblem problem(spec);
        EXPECT_NE(problem.safetyNote().find("height_above_mean_sea_level"), std::string::npos) << problem.safetyNote();
        const MissionResult r = runMission(problem);
        ASSERT_TRUE(r.plan.solved) << r.plan.reason;
        for (std::size_t k = 0; k + 1 < r.plan.path.size(); ++k)
            for (int q = 0; q <= 200; ++q)
            {
                const TimedPoint &p = r.plan.path[k], &b = r.plan.path[k + 1];
                const double s = q / 200.0;
                const LonLat g = problem.toGeographic({p.x + s * (b.x - p.x), p.y + s * (b.y - p.y)});
                // a margin of 0.002 degree (cells reach 0.05 degree beyond the bank's nodes) for the projected cell
                // edges against the file's meridians and parallels
                const bool onBank =
                    g.lon >= -78.5 - 0.048 && g.lon <= -77.5 + 0.048 && g.lat >= 26.0 - 0.048 && g.lat <= 26.8 + 0.048;
                ASSERT_FALSE(onBank) << "leg " << k << " at " << g.lon << ", " << g.lat;
            }
        EXPECT_GT(r.plan.travelTime, a.plan.travelTime);
    }
}

TEST(Safety, BathymetryAxesThatDoNotSayWhichIsLongitudeAreRefusedNamingThem)
{
    // axes with the same numeric range and nothing that says which is longitude: never guessed
    TempDir dir;
    const std::string path = dir.file("anonymous.nc");
    {
        NcWriter w(path, NC_CLOBBER);
        const int d0 = w.dim("p", 5), d1 = w.dim("q", 5);
        const int v0 = w.var("p", NC_DOUBLE, {d0}), v1 = w.var("q", NC_DOUBLE, {d1});
        const int ve = w.var("depth", NC_FLOAT, {d0, d1});
        w.text(ve, "positive", "down");
        w.enddef();
        w.put(v0, std::vector<double>{10, 11, 12, 13, 14});
        w.put(v1, std::vector<double>{10, 11, 12, 13, 14});
        w.put(ve, std::vector<double>(25, 100.0));
    }
    try
    {
        readDepthGrid(path, "", GeoBox::world());
        ADD_FAILURE() << "an axis order was guessed";
    }
    catch (const Error &e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(path), std::string::npos) << msg;
        EXPECT_NE(msg.find("dimensions (p, q): cannot tell which is longitude/x"), std::string::npos) << msg;
    }
    // the dive profiles' reader is the same reader: the same refusal
    EXPECT_THROW(GriddedBathymetry(path, "depth", [](double x, double y) { return LonLat{x, y}; }), Error);
}

TEST(Safety, DiveProfilesAndTheDepthLimitReadOneFileAlike)
{
    // the same transposed GEBCO-like file through the dive profiles' reader: the bank's depths at its nodes
    TempDir dir;
    const std::string gebco = dir.file("gebco_t.nc");
    writeGebco(gebco, true);
    const GriddedBathymetry b(gebco, "", [](double x, double y) { return LonLat{x, y}; });
    EXPECT_EQ(b.variable(), "elevation");
    EXPECT_NE(b.convention().find("elevation, positive up"), std::string::npos) << b.convention();
    for (double lon : {-79.5, -78.0, -77.75, -76.0})
        for (double lat : {24.5, 26.4, 27.5})
            EXPECT_NEAR(b.seafloorDepth(lon, lat), bankDepth(lon, lat), 1e-3) << lon << " " << lat;
}
