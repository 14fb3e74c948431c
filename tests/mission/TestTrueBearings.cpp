// Every written heading is a TRUE bearing: flown as one (held constant clockwise from true north) by an integrator of
// this file's own in longitude and latitude on the WGS84 ellipsoid (its radii of curvature), with the current given
// in east and north components at each lon/lat, each segment of waypoints.csv ends within 10 m of the segment's end.
// The region is examples/jet_stations_execution.yaml's, whose projection is centred at the region's western edge:
// there the projection's grid north is 1-3 degrees off true north, and the planner's own (grid) headings flown as
// true bearings miss by hundreds of metres.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/RouteFiles.h"

using namespace ompl_glider;

// (a named namespace: the files of one test executable are compiled in unity batches)
namespace true_bearings_test
{
constexpr double kA = 6378137.0, kE2 = 6.69437999014e-3, kDeg = M_PI / 180.0;

/// WGS84's meridional (M) and prime-vertical (N) radii of curvature at latitude @p lat (degrees).
void radii(double lat, double &M, double &N)
{
    const double s = std::sin(lat * kDeg), w = 1.0 - kE2 * s * s;
    M = kA * (1.0 - kE2) / (w * std::sqrt(w));
    N = kA / std::sqrt(w);
}

/// The forecast's current at (lon, lat) in m/s east and north: the mission's field (defined in its plane) sampled at
/// the point, its plane vector split on the plane's images of one metre east and one metre north there.
void currentEastNorth(const MissionProblem &p, LonLat g, double t, double &east, double &north)
{
    const MissionSpec &m = p.getSpec();
    const Point2 at = p.toLocal(g);
    const Velocity c = p.getField()->velocity(at.x, at.y, m.vehicle.depth, t);
    double M, N;
    radii(g.lat, M, N);
    const double d = 1e-5;
    const Point2 e1 = p.toLocal({g.lon + d, g.lat}), e0 = p.toLocal({g.lon - d, g.lat});
    const Point2 n1 = p.toLocal({g.lon, g.lat + d}), n0 = p.toLocal({g.lon, g.lat - d});
    const double me = 2 * d * kDeg * N * std::cos(g.lat * kDeg), mn = 2 * d * kDeg * M; // metres of the steps
    const Point2 ae{(e1.x - e0.x) / me, (e1.y - e0.y) / me}, an{(n1.x - n0.x) / mn, (n1.y - n0.y) / mn};
    // c = east ae + north an: east and north in metres per field time unit (ae, an: plane units per metre)
    const double det = ae.x * an.y - ae.y * an.x;
    east = (c.u * an.y - c.v * an.x) / det / m.timeUnitSeconds;
    north = (ae.x * c.v - ae.y * c.u) / det / m.timeUnitSeconds;
}

/// Holds the TRUE bearing @p psi (degrees) from @p g for @p duration (field time units) from @p t: RK4 in lon/lat.
LonLat flyTrue(const MissionProblem &p, LonLat g, double t, double duration, double psi)
{
    const MissionSpec &m = p.getSpec();
    const double V = m.vehicle.speed * m.metresPerUnit() / m.timeUnitSeconds; // m/s
    const double tu = m.timeUnitSeconds;
    const auto rate = [&](LonLat q, double tq) {
        double M, N, ue, vn;
        radii(q.lat, M, N);
        currentEastNorth(p, q, tq, ue, vn);
        // degrees per field time unit
        return LonLat{(V * std::sin(psi * kDeg) + ue) / (N * std::cos(q.lat * kDeg)) / kDeg * tu,
                      (V * std::cos(psi * kDeg) + vn) / M / kDeg * tu};
    };
    const int n = std::max(50, static_cast<int>(std::ceil(duration * tu / 30.0))); // 30 s steps
    const double h = duration / n;
    for (int i = 0; i < n; ++i)
    {
        const LonLat k1 = rate(g, t);
        const LonLat k2 = rate({g.lon + 0.5 * h * k1.lon, g.lat + 0.5 * h * k1.lat}, t + 0.5 * h);
        const LonLat k3 = rate({g.lon + 0.5 * h * k2.lon, g.lat + 0.5 * h * k2.lat}, t + 0.5 * h);
        const LonLat k4 = rate({g.lon + h * k3.lon, g.lat + h * k3.lat}, t + h);
        g.lon += h / 6.0 * (k1.lon + 2 * k2.lon + 2 * k3.lon + k4.lon);
        g.lat += h / 6.0 * (k1.lat + 2 * k2.lat + 2 * k3.lat + k4.lat);
        t += h;
    }
    return g;
}

/// Metres between two nearby points (the ellipsoid's local radii).
double metres(LonLat a, LonLat b)
{
    double M, N;
    radii(0.5 * (a.lat + b.lat), M, N);
    return std::hypot((b.lon - a.lon) * kDeg * N * std::cos(0.5 * (a.lat + b.lat) * kDeg), (b.lat - a.lat) * kDeg * M);
}

/// waypoints.csv's rows as fields.
std::vector<std::vector<std::string>> rows(const std::string &csv)
{
    std::vector<std::vector<std::string>> out;
    std::istringstream in(csv);
    std::string line;
    while (std::getline(in, line))
    {
        std::vector<std::string> f;
        std::string cell;
        std::istringstream ls(line);
        while (std::getline(ls, cell, ','))
            f.push_back(cell);
        if (!line.empty() && line.back() == ',')
            f.emplace_back();
        out.push_back(f);
    }
    return out;
}
} // namespace true_bearings_test

using namespace true_bearings_test;

TEST(TrueBearings, WrittenHeadingsReflownAsTrueBearingsInLonLatEndWithinTenMetres)
{
    MissionSpec spec = loadMission(std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/jet_stations_execution.yaml");
    spec.execution.enabled = false; // the plan alone
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const auto w = rows(waypointsCsv(r, &problem));
    ASSERT_EQ(w.size(), r.waypoints.size() + 1);
    std::size_t col = 0;
    while (col < w[0].size() && w[0][col] != "heading_true_deg")
        ++col;
    ASSERT_LT(col, w[0].size()) << "no heading_true_deg column";
    std::size_t segments = 0;
    double worst = 0.0, worstGrid = 0.0, turned = 0.0;
    for (std::size_t i = 0; i + 1 < r.waypoints.size(); ++i)
    {
        if (w[i + 1][col].empty())
            continue;
        const MissionWaypoint &a = r.waypoints[i], &b = r.waypoints[i + 1];
        const double psi = std::stod(w[i + 1][col]);
        const LonLat end = flyTrue(problem, a.lonLat, a.time, b.time - a.time, psi);
        const double miss = true_bearings_test::metres(end, b.lonLat);
        EXPECT_LE(miss, 10.0) << "segment " << i << " (" << psi << " deg true)";
        worst = std::max(worst, miss);
        // the planner's grid heading flown as a true bearing: what the files said before
        worstGrid = std::max(worstGrid, true_bearings_test::metres(
                                            flyTrue(problem, a.lonLat, a.time, b.time - a.time, a.heading), b.lonLat));
        turned = std::max(turned, std::abs(std::remainder(psi - a.heading, 360.0)));
        ++segments;
    }
    std::printf("%zu segments of held headings: re-flown as true bearings in lon/lat, worst miss %.2f m (the grid "
                "headings flown as true: %.0f m); true - grid up to %.2f deg\n",
                segments, worst, worstGrid, turned);
    ASSERT_GT(segments, 0u) << "the example has no leg of held headings any more: this test needs one";
    EXPECT_GT(turned, 0.5); // the projection's north is off true north here: the conversion is not a no-op
    EXPECT_GT(worstGrid, 50.0);
}
