// A mission resumed at sea from the glider's last fix (resumeAtLastFix(), done by MissionProblem for every front
// end): the start and departure replaced, the stations already reached dropped (in the order listed), a stay under
// way finished first, the others kept whole; what cannot be resumed refused plainly.
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Observations.h"
#include "ompl_glider/mission/Overrides.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/MapHtml.h"
#include "ompl_glider/output/MissionMap.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/output/SummaryJson.h"

using namespace ompl_glider;
namespace fs = std::filesystem;

namespace
{
const std::string kSurvey = std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/survey_labrador.yaml";
const double kT0 = 1773554400.0; // 2026-03-15T06:00:00Z, the survey's departure

/// A CSV deployment of fixes (hours after the survey's departure, lon, lat), each with a small DAC.
std::string deployment(const std::string &name, const std::vector<std::array<double, 3>> &fixes)
{
    const fs::path dir = fs::temp_directory_path() / ("ompl_glider_resume_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / (name + ".csv");
    std::ofstream out(file);
    out << "time,lon,lat,u,v\n";
    for (const auto &[h, lon, lat] : fixes)
        out << formatIsoTime(kT0 + 3600.0 * h) << "," << lon << "," << lat << ",0.05,0.02\n";
    return file.string();
}

/// The survey with @p observations given as glider_plan's flag gives them (and @p more overrides).
MissionSpec survey(const std::string &observations, MissionOverrides o = {})
{
    MissionSpec m = loadMission(kSurvey);
    o.origin = Origin::Flag;
    o.observations = Given<std::string>{observations, "--observations"};
    applyOverrides(o, m);
    return m;
}

/// The survey's field time @p hours after its departure.
double hoursIn(const MissionSpec &m, double hours)
{
    return m.timeOf(formatIsoTime(kT0 + 3600.0 * hours));
}

/// Metres between two lon/lat points (a sphere; this file's own).
double metres(LonLat a, LonLat b)
{
    const double d = M_PI / 180.0;
    const double x = (b.lon - a.lon) * d * std::cos(0.5 * (a.lat + b.lat) * d), y = (b.lat - a.lat) * d;
    return 6371000.0 * std::hypot(x, y);
}
} // namespace

TEST(Resume, FromTheDeploymentsLastFixKeepingEveryStationNotYetReached)
{
    const MissionSpec given = loadMission(kSurvey);
    const MissionProblem p(survey(std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/deployment_ru29"));
    const MissionSpec &m = p.getSpec();
    ASSERT_TRUE(m.observations && m.observations->resumed);
    const MissionResume &r = *m.observations->resumed;
    // ru29's last profile: the eighth dive, 24 h after the departure, 8 x (0.045, 0.02) degrees north-east
    EXPECT_EQ(r.fixIso, "2026-03-16T06:00:00Z");
    EXPECT_NEAR(m.start.lonLat.lon, -52.7 + 8 * 0.045, 1e-9);
    EXPECT_NEAR(m.start.lonLat.lat, 47.9 + 8 * 0.02, 1e-9);
    EXPECT_EQ(m.isoTime(m.departure.time), "2026-03-16T06:00:00Z");
    EXPECT_FALSE(r.replacedStart.empty());
    EXPECT_TRUE(r.dropped.empty());
    // every station kept whole: names, radii, windows, stays
    ASSERT_EQ(m.waypoints.size(), given.waypoints.size());
    for (std::size_t i = 0; i < m.waypoints.size(); ++i)
    {
        EXPECT_EQ(m.waypoints[i].name, given.waypoints[i].name);
        EXPECT_EQ(m.waypoints[i].radius, given.waypoints[i].radius);
        EXPECT_EQ(m.waypoints[i].stay, given.waypoints[i].stay);
        EXPECT_EQ(m.waypoints[i].arrive.set, given.waypoints[i].arrive.set);
        EXPECT_EQ(m.waypoints[i].arrive.end, given.waypoints[i].arrive.end);
    }
    EXPECT_NE(resumeNote(m).find("replacing the mission's start -52.7, 47.9"), std::string::npos) << resumeNote(m);
}

TEST(Resume, AReachedStationIsDroppedAndItsStayFinishedFirst)
{
    // toward A (-52.2, 48.0; radius 500 m, a 6 h stay), 200 m from it at hour 20, held there until hour 22
    const std::string obs = deployment("at_a", {{4, -52.6, 47.93},
                                                {12, -52.4, 47.97},
                                                {20, -52.2018, 48.0008},
                                                {21, -52.2010, 47.9995},
                                                {22, -52.2005, 48.0004}});
    const MissionProblem p(survey(obs));
    const MissionSpec &m = p.getSpec();
    ASSERT_TRUE(m.observations->resumed);
    const MissionResume &r = *m.observations->resumed;
    ASSERT_EQ(r.dropped.size(), 1u);
    EXPECT_EQ(r.dropped[0].name, "A");
    EXPECT_EQ(r.dropped[0].reachedIso, "2026-03-16T02:00:00Z");
    EXPECT_NEAR(r.dropped[0].distance, metres({-52.2018, 48.0008}, {-52.2, 48.0}), 2.0);
    // the stay began at the first fix within the radius (hour 20): 4 of its 6 h are left at the last fix
    EXPECT_NEAR(r.dropped[0].stayLeft, 4 * 3600.0, 1e-6);
    EXPECT_EQ(m.isoTime(m.departure.time), "2026-03-16T08:00:00Z");
    ASSERT_EQ(m.waypoints.size(), 2u);
    EXPECT_EQ(m.waypoints[0].name, "B");
    EXPECT_EQ(m.waypoints[1].name, "C");
    EXPECT_TRUE(m.waypoints[1].arrive.set);
    // and it plans: from the last fix, through B and C
    const MissionResult res = runMission(p);
    ASSERT_TRUE(res.plan.solved) << res.plan.reason;
    ASSERT_EQ(res.legs.size(), 3u);
    EXPECT_EQ(res.legs[0].from, "start");
    EXPECT_EQ(res.legs[0].to, "B");
    EXPECT_NEAR(res.waypoints.front().lonLat.lon, -52.2005, 1e-9);
    EXPECT_EQ(res.waypoints.front().iso, "2026-03-16T08:00:00Z");
}

TEST(Resume, StationsCountOnlyInTheOrderListed)
{
    // the glider passes within B's radius before it reached A: with the order given B is not visited yet
    const std::string obs = deployment("b_first", {{2, -52.6, 47.93}, {10, -51.9005, 48.2003}, {12, -51.95, 48.15}});
    const MissionProblem p(survey(obs));
    EXPECT_TRUE(p.getSpec().observations->resumed->dropped.empty());
    EXPECT_EQ(p.getSpec().waypoints.size(), 3u);
    // with the order free, B counts
    MissionOverrides free;
    free.order = Given<std::string>{"free", "--order"};
    const MissionProblem q(survey(obs, free));
    ASSERT_EQ(q.getSpec().observations->resumed->dropped.size(), 1u);
    EXPECT_EQ(q.getSpec().observations->resumed->dropped[0].name, "B");
}

TEST(Resume, WhatCannotBeResumedIsRefusedPlainly)
{
    // every station and the goal reached (C within its window, from hour 42): nothing is left to plan
    const std::string done =
        deployment("done", {{10, -52.2, 48.0}, {20, -51.9, 48.2}, {44, -51.65, 48.3}, {50, -51.5, 48.45}});
    try
    {
        const MissionProblem p(survey(done));
        ADD_FAILURE() << "a finished mission was planned";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("nothing is left to plan"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("--observations"), std::string::npos) << e.what();
    }
    // every station reached, the goal not yet: a plan of one leg from the last fix to the goal, the three named
    const std::string stations =
        deployment("stations", {{10, -52.2, 48.0}, {20, -51.9, 48.2}, {44, -51.65, 48.3}, {46, -51.62, 48.33}});
    {
        const MissionProblem p(survey(stations));
        ASSERT_EQ(p.getSpec().observations->resumed->dropped.size(), 3u);
        EXPECT_TRUE(p.getSpec().waypoints.empty());
        EXPECT_NE(resumeNote(p.getSpec()).find("stations reached and dropped: A ("), std::string::npos);
    }
    // a departure given before the last fix: the glider was elsewhere then
    const std::string obs = deployment("early", {{4, -52.6, 47.93}, {12, -52.4, 47.97}});
    MissionOverrides o;
    o.departure = Given<std::string>{"2026-03-15T12:00:00Z", "--departure"};
    try
    {
        const MissionProblem p(survey(obs, o));
        ADD_FAILURE() << "a departure before the last fix was taken";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("before the last fix (2026-03-15T18:00:00Z)"), std::string::npos)
            << e.what();
    }
    // a departure after it is kept
    o.departure = Given<std::string>{"2026-03-15T20:00:00Z", "--departure"};
    const MissionProblem later(survey(obs, o));
    EXPECT_EQ(later.getSpec().isoTime(later.getSpec().departure.time), "2026-03-15T20:00:00Z");
    // C's window has closed at the last fix: refused naming the station's window
    const std::string late = deployment("late", {{4, -52.6, 47.93}, {90, -52.4, 47.97}});
    try
    {
        const MissionProblem p(survey(late));
        const MissionResult r = runMission(p);
        ADD_FAILURE() << "a station whose window closed before the last fix was planned: " << r.plan.reason;
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("field 'waypoints[2].arrive.end' (via point 'C')"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("before the glider can get there"), std::string::npos) << e.what();
    }
}

TEST(Resume, AStartGivenByTheCallerWins)
{
    MissionOverrides o;
    o.start = Given<Point2>{{-52.5, 47.95}, "--start"};
    o.departure = Given<std::string>{"2026-03-16T06:00:00Z", "--departure"};
    const MissionProblem p(survey(std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/deployment_ru29", o));
    EXPECT_FALSE(p.getSpec().observations->resumed);
    EXPECT_NEAR(p.getSpec().start.lonLat.lon, -52.5, 1e-12);
    EXPECT_EQ(p.getSpec().waypoints.size(), 3u);
}

// The maps of a resumed plan show the glider's history: its past fixes and the DAC it measured (map.png's legend,
// map.html's glider layer), at the places the deployment reported them.
TEST(Resume, TheMapsShowThePastFixesAndTheMeasuredDac)
{
    const MissionProblem p(survey(std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/deployment_ru29"));
    const MissionResult r = runMission(p);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const nlohmann::json d = nlohmann::json::parse(mapHtmlData(r, p));
    ASSERT_TRUE(d.contains("glider") && d["glider"].is_object());
    const auto &fixes = d["glider"]["fixes"];
    const auto &dac = d["glider"]["dac"];
    // eight profiles, each with its fix; its DAC's own place and time (half an hour earlier, mid-dive) is the DAC's,
    // not a fix (as on map.png below)
    ASSERT_EQ(fixes.size(), 8u);
    for (const auto &f : fixes)
        for (const auto &a : dac)
            EXPECT_FALSE(f["time"] == a["time"] && f["lon"] == a["lon"] && f["lat"] == a["lat"]) << f;
    ASSERT_EQ(dac.size(), 8u);
    EXPECT_NEAR(fixes.back()["lon"].get<double>(), -52.7 + 8 * 0.045, 1e-9);
    EXPECT_EQ(fixes.back()["time"], "2026-03-16T06:00:00Z");
    EXPECT_NEAR(dac[0]["lon"].get<double>(), -52.7 + 0.045 - 0.004, 1e-9);
    EXPECT_GT(d["glider"]["arrow_deg_per_ms"].get<double>(), 0.0);
    const fs::path svg = fs::temp_directory_path() / ("ompl_glider_resume_map_" + std::to_string(::getpid()) + ".svg");
    missionMap(r, p).writeSvg(svg.string());
    std::ifstream in(svg);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    fs::remove(svg);
    // map.png/svg: the 8 surfacing fixes are the fixes (the DAC's own places, mid-dive, are arrows, not fixes)
    EXPECT_NE(text.find("glider: 8 past fixes"), std::string::npos);
    EXPECT_EQ(text.find("glider: 16 past fixes"), std::string::npos);
    EXPECT_NE(text.find("glider: 8 measured DAC"), std::string::npos);
}

// The glider's history is judged from the deployment to the last fix, whatever departure the plan is made for: a
// departure given an hour after the last fix does not undo the station finished before it.
TEST(Resume, ADepartureGivenAfterTheLastFixKeepsTheStationsFinishedBefore)
{
    // at A from hour 12 to 18 (its 6 h stay held), on toward B at the last fix (hour 22)
    const std::string obs = deployment("finished_a", {{4, -52.6, 47.93},
                                                      {12, -52.2005, 48.0004},
                                                      {15, -52.2010, 47.9995},
                                                      {18, -52.2003, 48.0002},
                                                      {22, -52.05, 48.1}});
    MissionOverrides o;
    o.departure = Given<std::string>{"2026-03-16T05:00:00Z", "--departure"};
    const MissionProblem p(survey(obs, o));
    const MissionSpec &m = p.getSpec();
    EXPECT_EQ(m.isoTime(m.departure.replaced), "2026-03-15T06:00:00Z"); // the deployment's, kept
    const MissionResume &r = *m.observations->resumed;
    ASSERT_EQ(r.dropped.size(), 1u);
    EXPECT_EQ(r.dropped[0].name, "A");
    EXPECT_EQ(r.dropped[0].reachedIso, "2026-03-15T18:00:00Z");
    EXPECT_EQ(r.dropped[0].stayLeft, 0.0);
    EXPECT_TRUE(r.stayEnds.empty());
    EXPECT_EQ(m.isoTime(m.departure.time), "2026-03-16T05:00:00Z");
    ASSERT_EQ(m.waypoints.size(), 2u);
    EXPECT_EQ(m.waypoints[0].name, "B");
    const MissionResult res = runMission(p);
    ASSERT_TRUE(res.plan.solved) << res.plan.reason;
    EXPECT_EQ(res.legs.front().to, "B"); // not back to A for a second stay
    EXPECT_EQ(res.waypoints.front().iso, "2026-03-16T05:00:00Z");
}

// A station reached before its window opens counts when the glider is still there when it opens: held until then,
// then its stay; one the glider left before the window opened is still to visit.
TEST(Resume, AStationReachedBeforeItsWindowOpensIsHeldUntilItOpensThenItsStay)
{
    const std::vector<std::array<double, 3>> history = {
        {10, -52.2005, 48.0004},
        {13, -52.2010, 47.9995},
        {16, -52.2003, 48.0002},
        {24, -51.9003, 48.2002},
        {36, -51.651, 48.3005}}; // A's stay held, B, and C (window from hour 42, 2026-03-17T00:00:00Z) at hour 36
    auto withStayAtC = [](const std::string &obs) {
        MissionSpec m = survey(obs);
        m.waypoints[2].stay = 3 * 3600.0; // a 3 h stay at C
        return m;
    };
    auto still = history;
    still.push_back({38, -51.6495, 48.2998}); // still within C's 1 km at the last fix
    const MissionProblem p(withStayAtC(deployment("early_c", still)));
    const MissionSpec &m = p.getSpec();
    const MissionResume &r = *m.observations->resumed;
    ASSERT_EQ(r.dropped.size(), 3u);
    EXPECT_EQ(r.dropped[2].name, "C");
    EXPECT_EQ(r.dropped[2].windowOpens, "2026-03-17T00:00:00Z");
    EXPECT_NEAR(r.dropped[2].stayLeft, 7 * 3600.0, 1e-6); // 4 h until the window opens, then the 3 h stay
    EXPECT_EQ(r.stayEnds, "2026-03-17T03:00:00Z");
    EXPECT_EQ(m.isoTime(m.departure.time), "2026-03-17T03:00:00Z");
    EXPECT_TRUE(m.waypoints.empty());
    EXPECT_NE(resumeNote(m).find("holds there until it opens, 2026-03-17T00:00:00Z"), std::string::npos)
        << resumeNote(m);
    const MissionResult res = runMission(p);
    ASSERT_TRUE(res.plan.solved) << res.plan.reason;
    EXPECT_EQ(res.waypoints.front().iso, "2026-03-17T03:00:00Z");
    // the goto list holds at C first, until the stay's end
    const GotoList g = gotoList(res, &p);
    ASSERT_FALSE(g.waypoints.empty());
    EXPECT_NEAR(g.waypoints[0].lon, -51.65, 1e-9);
    EXPECT_NE(g.notes[0].find("leave at 2026-03-17T03:00:00Z"), std::string::npos) << g.notes[0];
    const nlohmann::json j = nlohmann::json::parse(summaryJson(res, p))["observations"]["resumed"];
    EXPECT_EQ(j["dropped"][2]["window_opens"], "2026-03-17T00:00:00Z");
    // gone from C (5 km away) before its window opened: C is still to visit, its window whole
    auto gone = history;
    gone.push_back({38, -51.7, 48.26});
    const MissionProblem q(withStayAtC(deployment("early_c_gone", gone)));
    ASSERT_EQ(q.getSpec().observations->resumed->dropped.size(), 2u);
    ASSERT_EQ(q.getSpec().waypoints.size(), 1u);
    EXPECT_EQ(q.getSpec().waypoints[0].name, "C");
    EXPECT_TRUE(q.getSpec().waypoints[0].arrive.set);
    EXPECT_EQ(q.getSpec().waypoints[0].stay, 3 * 3600.0);
    EXPECT_EQ(q.getSpec().isoTime(q.getSpec().departure.time), "2026-03-16T20:00:00Z");
}

// A glider that left the station's radius before its stay was over goes back to hold the rest, and the report says so;
// one first seen outside after the stay's end finished it.
TEST(Resume, AGliderThatLeftAStayUnfinishedIsSentBackToFinishIt)
{
    // at A at hours 20 and 21, 3.4 km north of it at the last fix (hour 22): 1 h of the 6 h held
    const std::string obs = deployment(
        "left_a", {{4, -52.6, 47.93}, {20, -52.2018, 48.0008}, {21, -52.2010, 47.9995}, {22, -52.2, 48.0306}});
    const MissionProblem p(survey(obs));
    const MissionSpec &m = p.getSpec();
    const MissionResume &r = *m.observations->resumed;
    EXPECT_TRUE(r.dropped.empty());
    EXPECT_TRUE(r.stayEnds.empty());
    ASSERT_TRUE(r.leftStay);
    EXPECT_EQ(r.leftStay->name, "A");
    EXPECT_EQ(r.leftStay->leftIso, "2026-03-16T04:00:00Z");
    EXPECT_NEAR(r.leftStay->held, 3600.0, 1e-6);
    EXPECT_NEAR(r.leftStay->stayLeft, 5 * 3600.0, 1e-6);
    EXPECT_NEAR(r.leftStay->distance, 3400.0, 20.0);
    ASSERT_EQ(m.waypoints.size(), 3u);
    EXPECT_EQ(m.waypoints[0].name, "A");
    EXPECT_NEAR(m.waypoints[0].stay, 5 * 3600.0, 1e-6);
    EXPECT_EQ(m.isoTime(m.departure.time), "2026-03-16T04:00:00Z"); // from the last fix, no hold where it is
    const std::vector<std::string> warnings = resumeWarnings(m);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("the glider left A's 500 m radius before its stay was over"), std::string::npos)
        << warnings[0];
    EXPECT_NE(warnings[0].find("the plan returns to A to hold the remaining 5 h"), std::string::npos) << warnings[0];
    EXPECT_NE(resumeNote(m).find("WARNING: the glider left A's"), std::string::npos) << resumeNote(m);
    const MissionResult res = runMission(p);
    ASSERT_TRUE(res.plan.solved) << res.plan.reason;
    ASSERT_EQ(res.legs.size(), 4u);
    EXPECT_EQ(res.legs[0].to, "A");
    EXPECT_NEAR(res.legs[1].departure() - res.legs[0].arrival(), 5 * 3600.0, 1.0); // the rest of the stay
    EXPECT_FALSE(resumedStay(res));                                                // nothing held where the glider is
    const nlohmann::json j = nlohmann::json::parse(summaryJson(res, p))["observations"]["resumed"];
    EXPECT_EQ(j["left_stay"]["name"], "A");
    EXPECT_NEAR(j["left_stay"]["stay_left"].get<double>(), 5 * 3600.0, 1e-6);
    ASSERT_EQ(j["warnings"].size(), 1u);
    // first seen outside at hour 27, after the stay's end (hour 26): the stay was held, A is done
    const std::string done =
        deployment("done_a", {{4, -52.6, 47.93}, {20, -52.2018, 48.0008}, {21, -52.2010, 47.9995}, {27, -52.1, 48.06}});
    const MissionProblem q(survey(done));
    ASSERT_EQ(q.getSpec().observations->resumed->dropped.size(), 1u);
    EXPECT_FALSE(q.getSpec().observations->resumed->leftStay);
    EXPECT_EQ(q.getSpec().waypoints.front().name, "B");
}

// A station reached after its window closed is dropped with a warning in the report and summary.json.
TEST(Resume, AStationReachedAfterItsWindowClosedIsDroppedWithAWarning)
{
    // C (window until hour 84, 2026-03-18T18:00:00Z) reached at hour 86
    const std::string obs = deployment("late_c", {{10, -52.2005, 48.0004},
                                                  {16, -52.2003, 48.0002},
                                                  {24, -51.9003, 48.2002},
                                                  {86, -51.6505, 48.3003},
                                                  {88, -51.6, 48.36}});
    const MissionProblem p(survey(obs));
    const MissionSpec &m = p.getSpec();
    const MissionResume &r = *m.observations->resumed;
    ASSERT_EQ(r.dropped.size(), 3u);
    EXPECT_TRUE(r.dropped[0].windowClosed.empty());
    EXPECT_EQ(r.dropped[2].windowClosed, "2026-03-18T18:00:00Z");
    const std::vector<std::string> warnings = resumeWarnings(m);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("C was reached after its window closed (reached 2026-03-18T20:00:00Z, the window "
                               "closed 2026-03-18T18:00:00Z)"),
              std::string::npos)
        << warnings[0];
    EXPECT_NE(resumeNote(m).find("C (2026-03-18T20:00:00Z, "), std::string::npos) << resumeNote(m);
    EXPECT_NE(resumeNote(m).find("m from it, after its window closed)"), std::string::npos) << resumeNote(m);
    const MissionResult res = runMission(p);
    ASSERT_TRUE(res.plan.solved) << res.plan.reason;
    const nlohmann::json j = nlohmann::json::parse(summaryJson(res, p))["observations"]["resumed"];
    EXPECT_EQ(j["dropped"][0]["why"], "reached");
    EXPECT_EQ(j["dropped"][2]["why"], "reached after its window closed");
    EXPECT_EQ(j["dropped"][2]["window_closed"], "2026-03-18T18:00:00Z");
    ASSERT_EQ(j["warnings"].size(), 1u);
}

TEST(Resume, ALastFixAfterTheForecastsEndIsRefusedNamingBoth)
{
    // the Labrador forecast ends 2026-03-20T00:00:00Z; the glider was last seen at hour 130 (C's window long closed)
    const std::string obs = deployment("after_end", {{4, -52.6, 47.93}, {130, -52.4, 47.97}});
    try
    {
        const MissionProblem p(survey(obs));
        ADD_FAILURE() << "a last fix after the forecast's end was taken";
    }
    catch (const Error &e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("--observations: the glider's last fix (2026-03-20T16:00:00Z) is after the forecast's end "
                            "(2026-03-20T00:00:00Z)"),
                  std::string::npos)
            << what;
        EXPECT_EQ(what.find("arrive"), std::string::npos) << what;
    }
}

// A glider a few tens of metres from its next station or its goal: each leg's automatic lattice spacing follows the
// leg's length, but never so fine that the box's lattice cannot hold it; a departure given during a stay under way
// finishes the stay first.
TEST(Resume, AGliderTensOfMetresFromTheGoalOrAStationPlans)
{
    // every station done, 60 m from the goal, the goto list's waypoint distance 50 m
    const std::string obs = deployment("near_goal", {{10, -52.2005, 48.0004},
                                                     {16, -52.2003, 48.0002},
                                                     {24, -51.9003, 48.2002},
                                                     {50, -51.6505, 48.3003},
                                                     {60, -51.5, 48.45054}});
    MissionSpec s = survey(obs);
    s.outputs.gotoWptDist = 50.0;
    const MissionProblem p(s);
    const MissionSpec &m = p.getSpec();
    EXPECT_TRUE(m.waypoints.empty());
    const Region box = p.getBox();
    const double finest = std::sqrt((box.xMax - box.xMin) * (box.yMax - box.yMin) / kAutomaticLatticeVertices);
    EXPECT_GE(m.planner.gridSize, finest);
    EXPECT_LE(m.planner.gridSize, 1.1 * finest);
    const MissionResult res = runMission(p);
    ASSERT_TRUE(res.plan.solved) << res.plan.reason;
    EXPECT_LT(res.plan.travelTime, 600.0); // 60 m at 0.3 m/s and the current
    // 36 m from the goal with every station still to visit: the mission is accepted, each leg its own spacing
    const MissionProblem q(survey(deployment("near_goal_stations", {{4, -52.6, 47.93}, {10, -51.5, 48.45032}})));
    EXPECT_EQ(q.getSpec().waypoints.size(), 3u);
    EXPECT_GE(q.getSpec().planner.gridSize, finest);
    const MissionProblem leg = q.withLeg(q.getStart(), q.getViaPoints()[0], {});
    const double d = std::hypot(q.getViaPoints()[0].x - q.getStart().x, q.getViaPoints()[0].y - q.getStart().y);
    EXPECT_GE(leg.getSpec().planner.gridSize, d / 200.0);
    EXPECT_LE(leg.getSpec().planner.gridSize, 1.02 * d / 25.0); // (two significant digits)
    // a departure given during the stay at A (36 m from it, hour 22; the stay ends at hour 26)
    MissionOverrides o;
    o.departure = Given<std::string>{"2026-03-16T05:00:00Z", "--departure"};
    const MissionProblem stay(survey(
        deployment("departure_in_stay", {{4, -52.6, 47.93}, {20, -52.2018, 48.0008}, {22, -52.2, 48.00032}}), o));
    const MissionResume &r = *stay.getSpec().observations->resumed;
    ASSERT_EQ(r.dropped.size(), 1u);
    EXPECT_EQ(r.stayEnds, "2026-03-16T08:00:00Z");
    EXPECT_EQ(r.departureDuringStay, "2026-03-16T05:00:00Z");
    EXPECT_EQ(stay.getSpec().isoTime(stay.getSpec().departure.time), "2026-03-16T08:00:00Z");
    EXPECT_NE(resumeNote(stay.getSpec()).find("not at the departure given, 2026-03-16T05:00:00Z, during the stay"),
              std::string::npos)
        << resumeNote(stay.getSpec());
    const MissionResult planned = runMission(stay);
    ASSERT_TRUE(planned.plan.solved) << planned.plan.reason;
    EXPECT_EQ(planned.legs.front().to, "B");
    EXPECT_NEAR(planned.waypoints.front().time, hoursIn(stay.getSpec(), 26), 1e-6);
}
