// The probability of reach over an ensemble's members (mission/ReachProbability.h): against one level-set solve per
// member made here (the equal members' p is that solve's reachable set; the drawn members' goal quantiles are the
// weighted quantile of their own solves), the weighted quantile itself, reachability.nc read back with NetCDF-C, the
// GeoJSON and summary.json, and the section's bad values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <string>

#include <netcdf.h>
#include <nlohmann/json.hpp>

#include "ompl_glider/Exception.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Observations.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/mission/ReachProbability.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/output/OutputWriter.h"
#include "ompl_glider/output/ReachabilityFiles.h"
#include "ompl_glider/output/SummaryJson.h"
#include "ompl_glider/reachability/LevelSet.h"

using namespace ompl_glider;

namespace
{
constexpr double kInfinity = std::numeric_limits<double>::infinity();

const std::string kJet = "{type: meandering_jet, parameters: {B0: 1.2, epsilon: 0.3, omega: 0.4, theta: "
                         "1.5707963267948966, k: 0.84, c: 0.12}}";

/// The jet mission at a coarse cell (0.25: 41 x 33 nodes), with @p current and @p extra sections.
MissionSpec jetMission(const std::string &current, const std::string &extra)
{
    return parseMission("name: reach\ncurrent: " + current + R"(
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1.0, y: -3.0}
goal: {x: 8.0, y: 3.0}
departure: {time: 0}
vehicle: {speed: 1.0}
)" + extra,
                        "reach.yaml");
}

/// One member's own level-set solve: its problem alone, the cell @p cell, one thread, run on to @p tEnd.
Reachability ownSolve(const MissionProblem &member, double cell, double tEnd, bool stopAtGoal)
{
    std::shared_ptr<GliderContext> ctx;
    makeSimpleSetup(member.gliderProblem(0.0, member.getSpec().vehicle.speed), &ctx);
    LevelSetParams p;
    p.cellSize = cell;
    p.threads = 1;
    const LevelSetSolver solver(ctx, p);
    return solver.solve(member.getStart().x, member.getStart().y, 0.0, tEnd, member.getGoal(), stopAtGoal);
}

std::size_t nodesOf(const ReachProbability &r)
{
    return static_cast<std::size_t>(r.nx) * static_cast<std::size_t>(r.ny);
}
} // namespace

// The weighted quantile: the smallest value whose values at or below it weigh at least q; +inf where the finite
// values do not attain q; ties count together; equal weights give the ceil(q M)-th smallest.
TEST(ReachProbability, WeightedQuantileWithUnequalWeightsAndAQuantileNotReached)
{
    const std::vector<double> v{3.0, 1.0, 2.0, kInfinity}, w{0.1, 0.2, 0.3, 0.4}; // cumulative 0.2, 0.5, 0.6, 1
    EXPECT_EQ(weightedQuantile(v, w, 0.1), 1.0);
    EXPECT_EQ(weightedQuantile(v, w, 0.2), 1.0);
    EXPECT_EQ(weightedQuantile(v, w, 0.25), 2.0);
    EXPECT_EQ(weightedQuantile(v, w, 0.5), 2.0);
    EXPECT_EQ(weightedQuantile(v, w, 0.55), 3.0);
    EXPECT_EQ(weightedQuantile(v, w, 0.6), 3.0);
    EXPECT_EQ(weightedQuantile(v, w, 0.61), kInfinity); // the member that never arrives holds the rest
    EXPECT_EQ(weightedQuantile({1.0, 1.0, 2.0}, {0.3, 0.3, 0.4}, 0.5), 1.0); // a tie weighs 0.6 at 1
    EXPECT_EQ(weightedQuantile({1.0, 1.0, 2.0}, {0.3, 0.3, 0.4}, 0.61), 2.0);
    const std::vector<double> e{5.0, 2.0, 4.0, 1.0, 3.0}, ew(5, 0.2);
    for (const double q : {0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.99})
        EXPECT_EQ(weightedQuantile(e, ew, q), std::ceil(q * 5 - 1e-9)) << q; // values 1..5: the k-th is k
    EXPECT_THROW(weightedQuantile({1.0}, {0.5, 0.5}, 0.5), Error);
}

// An ensemble of one flow listed three times: p is 0 or 1 at every node and frame and is, node by node, the reachable
// set {T <= t} of one level-set solve of that flow on the same cell; every member's goal time is that solve's.
TEST(ReachProbability, EqualMembersGiveTheSingleLevelSetsReachableSet)
{
    MissionSpec m = jetMission("{ensemble: [" + kJet + ", " + kJet + ", " + kJet + "]}",
                               "reachability: {horizon: 9, interval: 1.5, resolution: 0.25}\n");
    const MissionProblem problem(m);
    ASSERT_EQ(problem.getMembers().size(), 3u);
    const ReachProbability r = computeReachProbability(problem, PlannedPath(), 0.0);
    EXPECT_EQ(r.members, 3u);
    EXPECT_FALSE(r.weighed);
    EXPECT_FALSE(r.stopped);
    ASSERT_EQ(r.times.size(), 6u); // 1.5, 3, ..., 9
    EXPECT_DOUBLE_EQ(r.times.back(), 9.0);
    EXPECT_DOUBLE_EQ(r.resolution, 0.25);
    const Reachability one = ownSolve(problem.withMember(0), 0.25, 9.0, false);
    ASSERT_EQ(one.nx, r.nx);
    ASSERT_EQ(one.ny, r.ny);
    ASSERT_EQ(one.arrival.size(), nodesOf(r));
    std::size_t reached = 0, unreached = 0;
    for (std::size_t f = 0; f < r.times.size(); ++f)
        for (std::size_t n = 0; n < nodesOf(r); ++n)
        {
            const float p = r.probability[f][n];
            ASSERT_TRUE(p == 0.0f || p == 1.0f) << "frame " << f << " node " << n << ": " << p;
            ASSERT_EQ(p == 1.0f, one.arrival[n] <= r.times[f]) << "frame " << f << " node " << n;
            (p == 1.0f ? reached : unreached) += 1;
        }
    EXPECT_GT(reached, 1000u); // the fronts grew over the frames, and left part of the region unreached
    EXPECT_GT(unreached, 1000u);
    ASSERT_TRUE(one.goalReached);
    for (const double t : r.goalTimes)
        EXPECT_EQ(t, one.goalTime);
    EXPECT_EQ(r.goalProbability, 1.0);
    for (const ReachQuantile &q : r.quantiles)
        EXPECT_EQ(q.arrival, one.goalTime);
    // the contours of p = level are the single solve's isochrones, point for point
    ASSERT_EQ(r.contours.size(), r.times.size() * r.levels.size());
    std::size_t drawn = 0;
    for (const ReachContour &c : r.contours)
    {
        const std::vector<std::vector<Point2>> lines = one.isochrone(c.time);
        ASSERT_EQ(c.lines.size(), lines.size()) << c.time;
        for (std::size_t k = 0; k < lines.size(); ++k)
        {
            ASSERT_EQ(c.lines[k].size(), lines[k].size());
            for (std::size_t i = 0; i < lines[k].size(); ++i)
            {
                ASSERT_EQ(c.lines[k][i].x, lines[k][i].x);
                ASSERT_EQ(c.lines[k][i].y, lines[k][i].y);
            }
            drawn += lines[k].size();
        }
    }
    EXPECT_GT(drawn, 100u);
}

// Five drawn jet members: each member's goal time is its own solve's, the quantiles are the weighted quantile of
// them (the ceil(q M)-th smallest), and with a horizon between the third and the fourth arrival, p at the goal is
// 3/5, the 0.5 quantile the third arrival and the 0.9 quantile not reached.
TEST(ReachProbability, GoalQuantilesAreTheMembersOwnSolvesQuantiles)
{
    const std::string drawn = "{type: meandering_jet, parameters: {B0: 1.2, epsilon: 0.3, omega: 0.4, theta: "
                              "1.5707963267948966, k: 0.84, c: 0.12}, members: 5, spread: {B0: 0.25, k: 0.25, c: "
                              "0.25}, seed: 7}";
    MissionSpec m = jetMission(drawn, "reachability: {horizon: 20, resolution: 0.25}\n");
    const MissionProblem problem(m);
    ASSERT_EQ(problem.getMembers().size(), 5u);
    const ReachProbability r = computeReachProbability(problem, PlannedPath(), 0.0);
    ASSERT_EQ(r.goalTimes.size(), 5u);
    std::vector<double> own;
    for (std::size_t k = 0; k < 5; ++k)
    {
        const Reachability s = ownSolve(problem.withMember(k), 0.25, 20.0, true);
        ASSERT_TRUE(s.goalReached) << k;
        EXPECT_EQ(r.goalTimes[k], s.goalTime) << "member " << k; // running on past the goal changes nothing
        own.push_back(s.goalTime);
    }
    std::vector<double> sorted = own;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_LT(sorted.front(), sorted.back() - 0.05); // the members differ
    ASSERT_EQ(r.quantiles.size(), 3u);
    for (const ReachQuantile &q : r.quantiles)
    {
        const double expected = sorted[static_cast<std::size_t>(std::ceil(q.q * 5 - 1e-9)) - 1];
        EXPECT_TRUE(q.reached) << q.q;
        EXPECT_EQ(q.arrival, expected) << q.q;
        EXPECT_EQ(q.travelTime, expected) << q.q;
    }
    EXPECT_EQ(r.goalProbability, 1.0);

    // a horizon between the third and the fourth arrival
    m.reachability.horizon = 0.5 * (sorted[2] + sorted[3]);
    m.reachability.quantiles = {0.5, 0.9};
    const ReachProbability h = computeReachProbability(MissionProblem(m), PlannedPath(), 0.0);
    EXPECT_NEAR(h.goalProbability, 0.6, 1e-12);
    ASSERT_EQ(h.quantiles.size(), 2u);
    EXPECT_TRUE(h.quantiles[0].reached);
    EXPECT_EQ(h.quantiles[0].arrival, sorted[2]);
    EXPECT_FALSE(h.quantiles[1].reached);
    EXPECT_EQ(h.quantiles[1].arrival, kInfinity);
    // p at the last frame is the share of members whose own front came, node by node
    for (std::size_t n = 0; n < nodesOf(h); n += 7)
    {
        int count = 0;
        for (std::size_t k = 0; k < 5; ++k)
            count += h.memberArrival[k][n] <= h.times.back();
        ASSERT_FLOAT_EQ(h.probability.back()[n], count / 5.0f) << n;
    }
}

// The files of a geographic, dated mission through runMission() and the output layer: reachability.nc read back with
// NetCDF-C (dimensions, CF attributes, p in [0, 1], non-decreasing in time at every node, equal to the result), the
// GeoJSON's features and summary.json's `reachability`.
TEST(ReachProbability, NetCdfGeoJsonAndSummaryOfAGeographicMission)
{
    const std::string drawn = "{type: meandering_jet, parameters: {B0: 1.2, epsilon: 0.3, omega: 0.4, theta: "
                              "1.5707963267948966, k: 0.84, c: 0.12}, members: 3, spread: {B0: 0.25}, seed: 7}";
    const std::string dir = (std::filesystem::temp_directory_path() / "ompl_glider_reach_files").string();
    std::filesystem::remove_all(dir);
    MissionSpec m = parseMission("name: reach\nunits: {length_m: 50000, time_s: 86400}\nepoch: "
                                 "\"2026-06-01T00:00:00Z\"\nprojection: {lon0: -70.0, lat0: 36.0}\ncurrent: " +
                                     drawn + R"(
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1.0, y: -3.0}
goal: {x: 8.0, y: 3.0}
departure: {time: 0}
vehicle: {speed: 1.0}
planner: {name: zastartve, grid_size: 0.8, sectors: 2, global_check: false}
reachability: {horizon: 6 d, interval: 2 d, resolution: 0.25, levels: [0.5, 0.9], member_arrival: true}
outputs: {files: [summary, reachability]}
)",
                                 "reach.yaml");
    m.outputs.directory = dir;
    const MissionProblem problem(m);
    const MissionResult result = runMission(problem);
    ASSERT_TRUE(result.reachability);
    const ReachProbability &r = *result.reachability;
    writeOutputs(result, problem);

    int nc = -1;
    ASSERT_EQ(nc_open((dir + "/reachability.nc").c_str(), NC_NOWRITE, &nc), NC_NOERR);
    const auto dimLen = [&](const char *name) {
        int d = -1;
        std::size_t len = 0;
        EXPECT_EQ(nc_inq_dimid(nc, name, &d), NC_NOERR) << name;
        EXPECT_EQ(nc_inq_dimlen(nc, d, &len), NC_NOERR) << name;
        return len;
    };
    const auto text = [&](int var, const char *name) {
        std::size_t len = 0;
        if (nc_inq_attlen(nc, var, name, &len) != NC_NOERR)
            return std::string("(none)");
        std::string s(len, '\0');
        EXPECT_EQ(nc_get_att_text(nc, var, name, s.data()), NC_NOERR);
        return s;
    };
    const auto varId = [&](const char *name) {
        int v = -1;
        EXPECT_EQ(nc_inq_varid(nc, name, &v), NC_NOERR) << name;
        return v;
    };
    const std::size_t nt = dimLen("time"), ny = dimLen("y"), nx = dimLen("x");
    EXPECT_EQ(nt, 3u); // days 2, 4, 6
    EXPECT_EQ(nx, static_cast<std::size_t>(r.nx));
    EXPECT_EQ(ny, static_cast<std::size_t>(r.ny));
    EXPECT_EQ(dimLen("member"), 3u);
    EXPECT_EQ(text(NC_GLOBAL, "Conventions"), "CF-1.8");
    EXPECT_NE(text(NC_GLOBAL, "title"), "(none)");
    EXPECT_NE(text(NC_GLOBAL, "source"), "(none)");
    EXPECT_NE(text(NC_GLOBAL, "history"), "(none)");
    const int vTime = varId("time");
    EXPECT_EQ(text(vTime, "units"), "days since 2026-06-01 00:00:00");
    EXPECT_EQ(text(vTime, "calendar"), "standard");
    std::vector<double> days(nt);
    ASSERT_EQ(nc_get_var_double(nc, vTime, days.data()), NC_NOERR);
    EXPECT_NEAR(days[0], 2.0, 1e-9);
    EXPECT_NEAR(days[2], 6.0, 1e-9);
    EXPECT_EQ(text(varId("lon"), "units"), "degrees_east");
    EXPECT_EQ(text(varId("lat"), "units"), "degrees_north");
    const int vP = varId("probability");
    EXPECT_EQ(text(vP, "units"), "1");
    EXPECT_NE(text(vP, "long_name"), "(none)");
    EXPECT_EQ(text(vP, "coordinates"), "lon lat");
    float range[2] = {-1, -1};
    ASSERT_EQ(nc_get_att_float(nc, vP, "valid_range", range), NC_NOERR);
    EXPECT_EQ(range[0], 0.0f);
    EXPECT_EQ(range[1], 1.0f);
    nc_type type = NC_NAT;
    ASSERT_EQ(nc_inq_vartype(nc, vP, &type), NC_NOERR);
    EXPECT_EQ(type, NC_FLOAT);
    std::vector<float> p(nt * ny * nx);
    ASSERT_EQ(nc_get_var_float(nc, vP, p.data()), NC_NOERR);
    std::size_t between = 0;
    for (std::size_t f = 0; f < nt; ++f)
        for (std::size_t n = 0; n < ny * nx; ++n)
        {
            const float v = p[f * ny * nx + n];
            ASSERT_GE(v, 0.0f);
            ASSERT_LE(v, 1.0f);
            ASSERT_EQ(v, r.probability[f][n]) << f << " " << n;
            if (f > 0)
            {
                ASSERT_GE(v, p[(f - 1) * ny * nx + n]) << "reach is monotone: frame " << f << " node " << n;
            }
            between += v > 0.0f && v < 1.0f;
        }
    EXPECT_GT(between, 0u); // the members disagree somewhere
    std::vector<double> arrival(3 * ny * nx);
    ASSERT_EQ(nc_get_var_double(nc, varId("arrival"), arrival.data()), NC_NOERR);
    for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t n = 0; n < ny * nx; n += 5)
        {
            if (std::isfinite(r.memberArrival[k][n]))
            {
                ASSERT_NEAR(arrival[k * ny * nx + n], r.memberArrival[k][n], 1e-9); // days since the departure
            }
            else
            {
                ASSERT_EQ(arrival[k * ny * nx + n], NC_FILL_DOUBLE);
            }
        }
    EXPECT_EQ(nc_close(nc), NC_NOERR);

    std::ifstream gj(dir + "/reachability.geojson");
    const nlohmann::json g = nlohmann::json::parse(gj);
    EXPECT_EQ(g["type"], "FeatureCollection");
    ASSERT_EQ(g["features"].size(), 3u * 2u);
    for (const auto &f : g["features"])
    {
        EXPECT_EQ(f["geometry"]["type"], "MultiLineString");
        for (const char *key : {"time", "time_iso", "since_departure", "level"})
            EXPECT_TRUE(f["properties"].contains(key)) << key;
        for (const auto &line : f["geometry"]["coordinates"])
            for (const auto &pt : line)
            {
                EXPECT_NEAR(pt[0].get<double>(), -70.0, 6.0); // lon/lat about the projection's centre
                EXPECT_NEAR(pt[1].get<double>(), 36.0, 4.0);
            }
    }
    EXPECT_EQ(g["features"][0]["properties"]["time_iso"], "2026-06-03T00:00:00Z");

    std::ifstream sj(dir + "/summary.json");
    const nlohmann::json s = nlohmann::json::parse(sj);
    ASSERT_TRUE(s.contains("reachability"));
    const auto &j = s["reachability"];
    EXPECT_EQ(j["members"], 3);
    EXPECT_EQ(j["weights"].size(), 3u);
    EXPECT_DOUBLE_EQ(j["horizon"].get<double>(), 6.0);
    EXPECT_EQ(j["times"].size(), 3u);
    EXPECT_EQ(j["goal"]["member_arrivals"].size(), 3u);
    EXPECT_DOUBLE_EQ(j["goal"]["probability"].get<double>(), r.goalProbability);
    ASSERT_EQ(j["goal"]["quantiles"].size(), 3u);
    for (std::size_t k = 0; k < 3; ++k)
    {
        const auto &q = j["goal"]["quantiles"][k];
        for (const char *key : {"q", "travel_time", "arrival", "arrival_iso"})
            EXPECT_TRUE(q.contains(key)) << key;
        EXPECT_EQ(q["arrival"].is_null(), !r.quantiles[k].reached);
    }
    EXPECT_TRUE(j.contains("wall_seconds"));
    std::filesystem::remove_all(dir);
}

// The section's bad values: exit 2's errors name the file, the line and the field.
TEST(ReachProbability, BadSectionValuesNameFileLineAndField)
{
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"reachability: {horizon: -1}", "reach.yaml:8: field 'reachability.horizon'"},
        {"reachability: {interval: 0 d}", "reach.yaml:8: field 'reachability.interval'"},
        {"reachability: {resolution: 0}", "reach.yaml:8: field 'reachability.resolution'"},
        {"reachability: {levels: [0.5, 1.0]}", "reach.yaml:8: field 'reachability.levels[1]'"},
        {"reachability: {levels: []}", "reach.yaml:8: field 'reachability.levels'"},
        {"reachability: {quantiles: [0]}", "reach.yaml:8: field 'reachability.quantiles[0]'"},
        {"reachability: {member_arrival: maybe}", "reach.yaml:8: field 'reachability.member_arrival'"},
        {"reachability: {horizon: 10 parsecs}", "reach.yaml:8: field 'reachability.horizon'"},
        {"reachability: {steps: 3}", "reach.yaml:8: unknown field 'reachability.steps'"},
    };
    for (const auto &[yaml, expected] : cases)
    {
        try
        {
            jetMission(kJet, yaml + "\n");
            ADD_FAILURE() << "accepted: " << yaml;
        }
        catch (const Error &e)
        {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << yaml << "\n" << e.what();
        }
    }
}

// A cell too fine for the memory limit is refused before any front, naming the mission's field.
TEST(ReachProbability, ACellBeyondTheMemoryLimitNamesTheResolution)
{
    MissionSpec m = jetMission(kJet, "reachability: {horizon: 5, resolution: 0.002}\n");
    const MissionProblem problem(m);
    ASSERT_EQ(setenv("OMPL_GLIDER_MEMORY_LIMIT", "64M", 1), 0);
    try
    {
        computeReachProbability(problem, PlannedPath(), 0.0);
        ADD_FAILURE() << "a cell of 0.002 (2e7 nodes) passed a memory limit of 64 MB";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("reach.yaml:8: field 'reachability.resolution'"), std::string::npos)
            << e.what();
    }
    unsetenv("OMPL_GLIDER_MEMORY_LIMIT");
}

namespace
{
/// A uniform current (u, 0) over lon -53..-51, lat 47.5..48.5 and 5 days from 2026-03-15, hourly, as a CF file.
std::string uniformMember(const std::string &name, double u)
{
    const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "reach_members";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    int nc = 0, dt = 0, dy = 0, dx = 0, vt = 0, vy = 0, vx = 0, vu = 0, vv = 0;
    EXPECT_EQ(nc_create(path.c_str(), NC_CLOBBER, &nc), NC_NOERR);
    const int nt = 121, ny = 21, nx = 41;
    nc_def_dim(nc, "time", nt, &dt);
    nc_def_dim(nc, "lat", ny, &dy);
    nc_def_dim(nc, "lon", nx, &dx);
    nc_def_var(nc, "time", NC_DOUBLE, 1, &dt, &vt);
    nc_def_var(nc, "lat", NC_DOUBLE, 1, &dy, &vy);
    nc_def_var(nc, "lon", NC_DOUBLE, 1, &dx, &vx);
    const int dims[] = {dt, dy, dx};
    nc_def_var(nc, "u", NC_FLOAT, 3, dims, &vu);
    nc_def_var(nc, "v", NC_FLOAT, 3, dims, &vv);
    const auto text = [&](int var, const char *k, const std::string &v) {
        nc_put_att_text(nc, var, k, v.size(), v.c_str());
    };
    text(vt, "units", "hours since 2026-03-15 00:00:00");
    text(vt, "standard_name", "time");
    text(vy, "units", "degrees_north");
    text(vx, "units", "degrees_east");
    text(vu, "units", "m/s");
    text(vu, "standard_name", "eastward_sea_water_velocity");
    text(vv, "units", "m/s");
    text(vv, "standard_name", "northward_sea_water_velocity");
    nc_enddef(nc);
    std::vector<double> t(nt), y(ny), x(nx);
    for (int i = 0; i < nt; ++i)
        t[i] = i;
    for (int j = 0; j < ny; ++j)
        y[j] = 47.5 + 0.05 * j;
    for (int i = 0; i < nx; ++i)
        x[i] = -53.0 + 0.05 * i;
    nc_put_var_double(nc, vt, t.data());
    nc_put_var_double(nc, vy, y.data());
    nc_put_var_double(nc, vx, x.data());
    const std::vector<float> U(static_cast<std::size_t>(nt) * ny * nx, static_cast<float>(u)), V(U.size(), 0.0f);
    nc_put_var_float(nc, vu, U.data());
    nc_put_var_float(nc, vv, V.data());
    nc_close(nc);
    return path;
}
} // namespace

// A stop request (Python's Ctrl-C) ends the fronts: the result says it was stopped, and the files are still written.
TEST(ReachProbability, AStopRequestEndsTheFrontsAndSaysSo)
{
    const MissionProblem problem(
        jetMission("{ensemble: [" + kJet + ", " + kJet + "]}", "reachability: {horizon: 9, resolution: 0.25}\n"));
    requestStop();
    const ReachProbability r = computeReachProbability(problem, PlannedPath(), 0.0);
    clearStop();
    EXPECT_TRUE(r.stopped);
    EXPECT_EQ(r.goalProbability, 0.0);
    MissionResult result;
    result.spec = problem.getSpec();
    result.reachability = r;
    const nlohmann::json g = nlohmann::json::parse(reachabilityGeoJson(result));
    EXPECT_TRUE(g["features"].empty());
    const std::string nc = (std::filesystem::temp_directory_path() / "ompl_glider_reach_stopped.nc").string();
    writeReachabilityNetCdf(nc, result, problem); // what was computed: nothing, with its frames and members
    int id = -1, dim = -1;
    std::size_t frames = 0;
    ASSERT_EQ(nc_open(nc.c_str(), NC_NOWRITE, &id), NC_NOERR);
    EXPECT_EQ(nc_inq_dimid(id, "time", &dim), NC_NOERR);
    EXPECT_EQ(nc_inq_dimlen(id, dim, &frames), NC_NOERR);
    EXPECT_EQ(frames, r.times.size());
    nc_close(id);
    std::filesystem::remove(nc);
    const ReachProbability again = computeReachProbability(problem, PlannedPath(), 0.0);
    EXPECT_FALSE(again.stopped);
    EXPECT_EQ(again.goalProbability, 1.0);
}

// A horizon beyond the level set's limits (ResourceLimits.h) is refused before any front, naming the field.
TEST(ReachProbability, AHorizonBeyondTheLevelSetsLimitsNamesTheHorizon)
{
    const MissionProblem problem(jetMission(kJet, "reachability: {horizon: 1e7, resolution: 0.25}\n"));
    try
    {
        computeReachProbability(problem, PlannedPath(), 0.0);
        ADD_FAILURE() << "a horizon of 1e7 passed";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("reach.yaml:8: field 'reachability.horizon': the fronts of 1 member(s)"),
                  std::string::npos)
            << e.what();
    }
}

// Members weighed by the glider's DAC (MissionProblem::observations()->members): the weights are theirs, not equal,
// and p is the weight of the members whose front came, node by node; the goal's quantiles are the weighted ones.
TEST(ReachProbability, MembersWeighedByTheObservationsWeighTheProbability)
{
    const std::string a = uniformMember("slow.nc", 0.05), b = uniformMember("middle.nc", 0.2),
                      c = uniformMember("fast.nc", 0.35);
    const std::filesystem::path dac = std::filesystem::path(::testing::TempDir()) / "reach_members" / "dac.csv";
    {
        std::ofstream f(dac);
        f << "time,lon,lat,u,v\n"; // eight DAC of the middle member's (0.2, 0) in the 12 h before the last fix
        const double end = parseIsoTime("2026-03-16T00:00:00Z");
        for (int k = 0; k < 8; ++k)
            f << formatIsoTime(end - 1.5 * 3600.0 * (8 - k)) << "," << -52.30 + 0.03 * k << ",48.0,0.2,0\n";
        f << formatIsoTime(end) << ",-52.09,48.0,,\n";
    }
    const MissionSpec m =
        parseMission("name: weighed\ncurrent: {ensemble: [{type: netcdf, file: '" + a + "'}, {type: netcdf, file: '" +
                         b + "'}, {type: netcdf, file: '" + c +
                         "'}]}\ngoal: {lon: -51.8, lat: 48.05}\nvehicle: {speed: 0.3}\n"
                         "observations: '" +
                         dac.string() + "'\nreachability: {horizon: 12 h, interval: 3 h, resolution: 1 km}\n",
                     "weighed.yaml");
    const MissionProblem problem(m);
    ASSERT_TRUE(problem.observations());
    ASSERT_EQ(problem.observations()->members.size(), 3u);
    const ReachProbability r = computeReachProbability(problem, PlannedPath(), problem.getSpec().departure.time);
    ASSERT_TRUE(problem.getMembers().empty()); // the plan is made on the forecast the members make
    ASSERT_EQ(problem.weighedMembers().size(), 3u);
    ASSERT_TRUE(r.weighed);
    EXPECT_EQ(r.members, 3u);
    double sum = 0.0;
    for (const MemberScore &s : problem.observations()->members)
        sum += s.weight;
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(r.weights[k], problem.observations()->members[k].weight / sum, 1e-12);
    EXPECT_GT(r.weights[1], r.weights[0] + 0.05); // the DAC are the middle member's
    EXPECT_GT(r.weights[1], r.weights[2] + 0.05);
    std::size_t unequal = 0;
    for (std::size_t f = 0; f < r.times.size(); ++f)
        for (std::size_t n = 0; n < nodesOf(r); ++n)
        {
            double p = 0.0;
            for (std::size_t k = 0; k < 3; ++k)
                p += r.memberArrival[k][n] <= r.times[f] ? r.weights[k] : 0.0;
            ASSERT_NEAR(r.probability[f][n], p, 1e-6) << f << " " << n;
            const double third = 3.0 * p;
            unequal += std::abs(third - std::round(third)) > 0.01; // not a share of equal weights
        }
    EXPECT_GT(unequal, 100u);
    // the goal's quantiles: the smallest goal time whose members weigh at least q, by hand
    std::vector<std::size_t> order{0, 1, 2};
    std::sort(order.begin(), order.end(),
              [&](std::size_t i, std::size_t j) { return r.goalTimes[i] < r.goalTimes[j]; });
    for (const ReachQuantile &q : r.quantiles)
    {
        double cumulative = 0.0, expected = kInfinity;
        for (const std::size_t k : order)
            if (std::isfinite(r.goalTimes[k]) && (cumulative += r.weights[k]) >= q.q - 1e-12)
            {
                expected = r.goalTimes[k];
                break;
            }
        EXPECT_EQ(q.arrival, expected) << q.q;
        EXPECT_EQ(q.reached, std::isfinite(expected)) << q.q;
    }
}
