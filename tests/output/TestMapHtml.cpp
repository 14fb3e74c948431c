// map.html's page (output/MapHtml.h): the template's three places filled, the data safe inside a <script> element
// (a name holding "</script><!--" neither ends the element nor opens a comment), the data read back from the page as
// it was given, a fleet's pages joined route by route, and the page of a planned mission carrying its route.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/MapHtml.h"
#include "ompl_glider/output/SummaryJson.h"

using namespace ompl_glider;
using json = nlohmann::json;

namespace
{
std::string readFile(const std::string &path)
{
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::size_t count(const std::string &text, const std::string &what)
{
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

const std::string kSample = std::string(OMPL_GLIDER_SOURCE_DIR) + "/tests/maphtml/sample_data.json";
} // namespace

TEST(MapHtml, PageHoldsLeafletAndTheDataSafelyAndGivesTheDataBack)
{
    const std::string data = readFile(kSample);
    ASSERT_NE(data.find("</script><!--"), std::string::npos) << "the sample must hold the escaping case";
    const std::string page = mapHtmlPage({data}, "sample");
    // no placeholder left; Leaflet is in the page (its source, not a link to it)
    for (const char *p : {"/*LEAFLET_CSS*/", "/*LEAFLET_JS*/", "/*MAP_DATA*/"})
        EXPECT_EQ(page.find(p), std::string::npos) << p;
    EXPECT_NE(page.find(".leaflet-container"), std::string::npos); // leaflet.css
    EXPECT_NE(page.find("version=\"1.6.0\""), std::string::npos);  // Debian's leaflet.min.js (1.7.1 says 1.6.0)
    EXPECT_EQ(page.find("src=\"http"), std::string::npos);         // nothing loaded from elsewhere
    // every <script> element is closed once by its own tag: the data's "</script>" is written \u003c/script>
    EXPECT_EQ(count(page, "\n<script>"), count(page, "</script>")); // (the template's comment names <script> too)
    EXPECT_EQ(page.find("</script><!--"), std::string::npos);
    // the data come back as given (the title is the page's)
    json given = json::parse(data), back = json::parse(mapHtmlDataOf(page));
    given["title"] = "sample";
    EXPECT_EQ(back, given);
}

TEST(MapHtml, AFleetsPageJoinsTheRoutesOfEveryGlider)
{
    const std::string data = readFile(kSample);
    const json one = json::parse(data);
    const std::string page = mapHtmlPage({data, data, data}, "fleet of 3");
    const json back = json::parse(mapHtmlDataOf(page));
    ASSERT_EQ(back["routes"].size(), 3 * one["routes"].size());
    EXPECT_EQ(back["routes"][one["routes"].size()], one["routes"][0]);
    EXPECT_EQ(back["tracks"].size(), 3 * one["tracks"].size());
    EXPECT_EQ(back["land"], one["land"]); // the first glider's frame, land and currents
    EXPECT_EQ(back["title"], "fleet of 3");
    EXPECT_THROW(mapHtmlPage({}, "none"), Error);
    EXPECT_THROW(mapHtmlPage({"not json"}, "bad"), Error);
    EXPECT_EQ(mapHtmlDataOf("<html>no map</html>"), "");
}

TEST(MapHtml, PlannedMissionsPageCarriesItsRouteAndWaypoints)
{
    const MissionProblem problem(defaultGulfStreamMission());
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved);
    const json d = json::parse(mapHtmlDataOf(mapHtml(r, problem)));
    ASSERT_EQ(d["routes"].size(), 1u);
    const json &route = d["routes"][0];
    ASSERT_EQ(route["points"].size(), r.plan.path.size());
    ASSERT_EQ(route["waypoints"].size(), r.waypoints.size());
    // without lon/lat the map's [y, x] are the planning frame's, the start first and the goal last
    EXPECT_DOUBLE_EQ(route["points"][0][0].get<double>(), problem.getStart().y);
    EXPECT_DOUBLE_EQ(route["points"][0][1].get<double>(), problem.getStart().x);
    EXPECT_NEAR(route["points"].back()[1].get<double>(), r.plan.path.back().x, 1e-6);
    EXPECT_FALSE(d["geographic"].get<bool>());
    // the current at a waypoint is the field's there, at its arrival time
    const MissionWaypoint &w = r.waypoints[3];
    const Velocity c = problem.getField()->velocity(w.position.x, w.position.y, 0.0, w.time);
    EXPECT_NEAR(route["waypoints"][3]["current"]["u"].get<double>(), c.u, 1e-4);
    EXPECT_NEAR(route["waypoints"][3]["current"]["v"].get<double>(), c.v, 1e-4);
    // six frames of arrows from the departure to the arrival
    EXPECT_EQ(d["currents"]["frames"].size(), 6u);
}

TEST(MapHtml, AClosureSaysWhenItIsClosed)
{
    // a zone closed only in [0, 5] and [8, 9]: the page gives those windows (as dates with an epoch), not "always";
    // a permanent restricted area has none
    const std::string yaml = "epoch: 2026-06-01T00:00:00Z\nunits: {length_m: 50000, time_s: 86400}\n"
                             "current: {type: uniform, parameters: {u: 0.1, v: 0}}\n"
                             "region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
                             "start: {x: 1, y: -3}\ngoal: {x: 8, y: 3}\nvehicle: {speed: 0.5}\n"
                             "planner: {grid_size: 0.4}\nforbidden:\n"
                             "  time_windows:\n"
                             "    - {name: exercise, points: [[4, -1], [5, -1], [5, 0], [4, 0]], "
                             "windows: [[0, 5], [8, 9]]}\n"
                             "  obstacles:\n"
                             "    - {name: reserve, kind: restricted area, points: [[6, 1], [7, 1], [7, 2], [6, 2]]}\n";
    const MissionProblem problem(parseMission(yaml));
    const MissionResult r = runMission(problem);
    const json d = json::parse(mapHtmlDataOf(mapHtml(r, problem)));
    ASSERT_EQ(d["forbidden"].size(), 2u);
    for (const json &f : d["forbidden"])
    {
        const std::string name = f["name"].get<std::string>();
        if (name.rfind("exercise", 0) == 0)
        {
            ASSERT_EQ(f["windows"].size(), 2u);
            EXPECT_EQ(f["windows"][0][0], "2026-06-01T00:00:00Z");
            EXPECT_EQ(f["windows"][0][1], "2026-06-06T00:00:00Z");
            EXPECT_EQ(f["windows"][1][0], "2026-06-09T00:00:00Z");
            EXPECT_EQ(f["windows"][1][1], "2026-06-10T00:00:00Z");
        }
        else
        {
            EXPECT_TRUE(f["windows"].empty()) << name;
        }
    }
}

TEST(MapHtml, NamesThatAreNotUtf8AreWrittenNotThrown)
{
    // a mission (or a forecast file) named in Latin-1: summary.json, map.html and the GeoJSON are written, with the
    // byte replaced by U+FFFD (nlohmann's type_error.316 ended a finished plan with exit 2)
    MissionSpec m = defaultGulfStreamMission();
    m.name = "caf\xe9 crossing";
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved);
    const json summary = json::parse(summaryJson(r, problem));
    EXPECT_EQ(summary["mission"], "caf\xef\xbf\xbd crossing");
    const json d = json::parse(mapHtmlDataOf(mapHtml(r, problem)));
    EXPECT_EQ(d["title"], "caf\xef\xbf\xbd crossing");
}
