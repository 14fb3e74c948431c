// The Seaglider targets file read back by a reader of its own (degrees and minutes, signs, the goto chain) against
// the route's turns, and its coordinates near the equator and the prime meridian.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/output/SeagliderTargets.h"

using namespace ompl_glider;

namespace
{
/// [-]D..DMM.MMMM -> signed degrees, by hand: the sign, then the digits before the last two of the whole part are
/// degrees, those two and the fraction minutes (shares nothing with the writer).
double readDegMin(const std::string &s)
{
    const bool negative = !s.empty() && s[0] == '-';
    const std::string body = negative ? s.substr(1) : s;
    const std::size_t dot = body.find('.');
    EXPECT_NE(dot, std::string::npos) << s;
    EXPECT_GE(dot, 3u) << s;
    const double degrees = std::stod(body.substr(0, dot - 2));
    const double minutes = std::stod(body.substr(dot - 2));
    EXPECT_LT(minutes, 60.0) << s;
    return (negative ? -1.0 : 1.0) * (degrees + minutes / 60.0);
}

struct Target
{
    std::string name, next;
    double lat, lon, radius;
};

std::vector<Target> readTargets(const std::string &text)
{
    std::vector<Target> out;
    std::istringstream in(text);
    std::string line;
    const std::regex re(
        R"(^([A-Za-z][A-Za-z0-9_-]*) lat=(-?\d{4}\.\d{4}) lon=(-?\d{5}\.\d{4}) radius=(\d+) goto=([A-Za-z][A-Za-z0-9_-]*)$)");
    while (std::getline(in, line))
    {
        if (line.empty() || line[0] == '/')
            continue;
        std::smatch m;
        EXPECT_TRUE(std::regex_match(line, m, re)) << "not a target line: " << line;
        if (m.empty())
            continue;
        out.push_back({m[1], m[5], readDegMin(m[2]), readDegMin(m[3]), std::stod(m[4])});
    }
    return out;
}

double metresBetween(double lat1, double lon1, double lat2, double lon2)
{
    constexpr double r = 6371000.0, d = M_PI / 180.0;
    const double a = std::pow(std::sin((lat2 - lat1) * d / 2), 2) +
                     std::cos(lat1 * d) * std::cos(lat2 * d) * std::pow(std::sin((lon2 - lon1) * d / 2), 2);
    return 2 * r * std::asin(std::sqrt(a));
}
} // namespace

TEST(SeagliderTargets, SignsAndDigitsNearTheEquatorAndThePrimeMeridian)
{
    EXPECT_EQ(seagliderLatitude(-0.5), "-0030.0000");
    EXPECT_EQ(seagliderLatitude(0.5), "0030.0000");
    EXPECT_EQ(seagliderLongitude(-0.25), "-00015.0000");
    EXPECT_EQ(seagliderLongitude(0.0), "00000.0000");
    EXPECT_EQ(seagliderLatitude(41.99999999), "4200.0000");
    EXPECT_EQ(seagliderLongitude(-122.5), "-12230.0000");
    EXPECT_EQ(seagliderLongitude(359.5), "-00030.0000"); // written in -180..180
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> lat(-2.0, 2.0), lon(-2.0, 2.0);
    for (int i = 0; i < 2000; ++i)
    {
        const double a = lat(rng), b = lon(rng);
        EXPECT_NEAR(readDegMin(seagliderLatitude(a)), a, 1e-4 / 60.0 + 1e-12);
        EXPECT_NEAR(readDegMin(seagliderLongitude(b)), b, 1e-4 / 60.0 + 1e-12);
    }
}

// The survey mission on the Labrador forecast: every turn of the route (the goto list's, every via point among them)
// is a target within 1 m, in order, each pointing to the next and the last to itself.
TEST(SeagliderTargets, ReadBackMatchesTheRoutesTurns)
{
    const MissionSpec m = loadMission(std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/survey_labrador.yaml");
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const std::vector<Target> t = readTargets(formatSeagliderTargets(seagliderTargets(r, &problem), m.name));
    std::vector<std::size_t> turns = gotoWaypointIndices(r, &problem);
    turns.erase(turns.begin()); // the start is where the glider is
    ASSERT_EQ(t.size(), turns.size());
    std::set<std::string> names;
    for (std::size_t k = 0; k < t.size(); ++k)
    {
        const MissionWaypoint &w = r.waypoints[turns[k]];
        EXPECT_LT(metresBetween(t[k].lat, t[k].lon, w.lonLat.lat, w.lonLat.lon), 1.0) << t[k].name;
        EXPECT_TRUE(names.insert(t[k].name).second) << "name used twice: " << t[k].name;
        EXPECT_EQ(t[k].next, k + 1 < t.size() ? t[k + 1].name : t[k].name);
    }
    // every via point is a target with its radius, in the order flown
    std::size_t at = 0;
    for (const std::size_t i : r.order)
    {
        const ViaPointSpec &v = m.waypoints[i];
        while (at < t.size() && t[at].name != v.name)
            ++at;
        ASSERT_LT(at, t.size()) << v.name << " is not a target (in order)";
        EXPECT_NEAR(t[at].radius, v.radius, 0.5);
        EXPECT_LT(metresBetween(t[at].lat, t[at].lon, v.position.lonLat.lat, v.position.lonLat.lon), 1.0);
    }
    EXPECT_EQ(t.back().name, "GOAL");
    EXPECT_LT(metresBetween(t.back().lat, t.back().lon, m.goal.lonLat.lat, m.goal.lonLat.lon), 1.0);
}

TEST(SeagliderTargets, AMissionNameWithLineBreaksStaysInTheHeader)
{
    // the name is written in the header comment: its line breaks must not start target lines of their own
    SeagliderTarget a;
    a.name = "GOAL";
    a.next = "GOAL";
    a.position = {-51.5, 48.45};
    a.radius = 500.0;
    const std::string text = formatSeagliderTargets({a}, "evil\nX lat=0000.0000 lon=00000.0000 radius=1 goto=X");
    const std::vector<Target> t = readTargets(text);
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].name, "GOAL");
    EXPECT_NEAR(t[0].lat, 48.45, 1e-6);
}
