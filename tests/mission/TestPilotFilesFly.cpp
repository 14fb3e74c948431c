// The pilot files of a mission flown as the vehicle flies them: the Slocum goto list and the Seaglider targets file
// read back (their waypoints and the comment lines before them), then flown by an integrator of this file's own
// through the forecast: a straight leg between two listed points with the heading that keeps the glider on the line
// (the cross current cancelled), a held heading for its time where the file says so, a hold at a stay until the
// time it says to leave. Every station and the goal must be reached within their radius, when the summary says.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/Overrides.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/output/SeagliderTargets.h"
#include "ompl_glider/output/SlocumGoto.h"

using namespace ompl_glider;

namespace
{
/// One instruction of a pilot file: go to a point (straight, or by a held heading), then perhaps hold.
struct Instruction
{
    LonLat to;
    std::string name; ///< the target's name (targets file), empty in a goto list
    double heading{std::numeric_limits<double>::quiet_NaN()}; ///< degrees: held instead of steering to the point
    double hours{0.0};                                        ///< for this long
    std::string leaveIso;                                     ///< a stay here: leave at this date
};

/// The heading and the stay a note says ("to here: hold heading 348.3 deg for 0.32 h; then stay at A: hold within
/// 500 m for 6.00 h, leave at 2026-...Z"), read with patterns of this file's own.
void readNote(const std::string &note, Instruction &in)
{
    std::smatch m;
    static const std::regex heading(R"(hold heading (\d+\.\d) deg true for (\d+\.\d+) h)");
    static const std::regex stay(R"(stay at [A-Za-z0-9_-]+: hold within \d+ m for \d+\.\d+ h, leave at (\S+))");
    if (std::regex_search(note, m, heading))
    {
        in.heading = std::stod(m[1]);
        in.hours = std::stod(m[2]);
    }
    if (std::regex_search(note, m, stay))
        in.leaveIso = m[1];
}

/// The goto list's instructions (the start is where the glider is).
std::vector<Instruction> gotoInstructions(const std::string &text)
{
    const GotoList g = parseGotoList(text, "goto");
    std::vector<Instruction> out;
    for (std::size_t i = 0; i < g.waypoints.size(); ++i)
    {
        Instruction in;
        in.to = g.waypoints[i];
        if (i < g.notes.size())
            readNote(g.notes[i], in);
        out.push_back(in);
    }
    return out;
}

/// [-]D..DMM.MMMM -> degrees (by hand).
double degMin(const std::string &s)
{
    const double v = std::stod(s);
    const double a = std::abs(v), deg = std::floor(a / 100.0);
    return (v < 0 ? -1.0 : 1.0) * (deg + (a - 100.0 * deg) / 60.0);
}

/// The targets file's instructions, followed from the first target along the goto chain.
std::vector<Instruction> targetInstructions(const std::string &text)
{
    std::istringstream in(text);
    std::string line, note;
    std::vector<Instruction> all;
    std::vector<std::string> next;
    static const std::regex target(R"(^(\S+) lat=(\S+) lon=(\S+) radius=(\d+) goto=(\S+)$)");
    while (std::getline(in, line))
    {
        if (line.rfind("/ ", 0) == 0)
        {
            note = line.substr(2);
            continue;
        }
        std::smatch m;
        if (!std::regex_match(line, m, target))
            continue;
        Instruction t;
        t.name = m[1];
        t.to = {degMin(m[3]), degMin(m[2])};
        readNote(note, t);
        note.clear();
        all.push_back(t);
        next.push_back(m[5]);
    }
    std::vector<Instruction> out;
    std::size_t k = 0;
    while (k < all.size() && out.size() <= all.size())
    {
        out.push_back(all[k]);
        if (next[k] == all[k].name)
            break;
        std::size_t j = 0;
        while (j < all.size() && all[j].name != next[k])
            ++j;
        k = j;
    }
    return out;
}

/// Where the flight is.
struct State
{
    Point2 p;
    double t{0.0};
};

/// The plane direction of a TRUE bearing (degrees clockwise from true north) at @p p: a short step along the bearing
/// on the WGS84 ellipsoid (its radii of curvature), projected (the frame's own north where it has no lon/lat).
Point2 trueDirection(const MissionProblem &problem, Point2 p, double bearing)
{
    const double b = bearing * M_PI / 180.0;
    if (!problem.isGeographic())
        return {std::sin(b), std::cos(b)};
    const LonLat g = problem.toGeographic(p);
    const double phi = g.lat * M_PI / 180.0, e2 = 6.69437999014e-3, w = 1.0 - e2 * std::sin(phi) * std::sin(phi);
    const double M = 6378137.0 * (1.0 - e2) / (w * std::sqrt(w)), N = 6378137.0 / std::sqrt(w);
    const double step = 5.0; // metres each way
    const double dlat = step * std::cos(b) / M * 180.0 / M_PI,
                 dlon = step * std::sin(b) / (N * std::cos(phi)) * 180.0 / M_PI;
    const Point2 a = problem.toLocal({g.lon - dlon, g.lat - dlat}), z = problem.toLocal({g.lon + dlon, g.lat + dlat});
    const double n = std::hypot(z.x - a.x, z.y - a.y);
    return {(z.x - a.x) / n, (z.y - a.y) / n};
}

/// dp/dt of a held true heading at speed V.
Point2 headingRate(const MissionProblem &pr, Point2 p, double t, double bearing, double speed, double depth)
{
    const Point2 d = trueDirection(pr, p, bearing);
    const Velocity c = pr.getField()->velocity(p.x, p.y, depth, t);
    return {speed * d.x + c.u, speed * d.y + c.v};
}

/// Holds the true @p bearing for @p duration (RK4, 200 steps at least, one per minute of a forecast at most).
State flyHeading(const MissionProblem &f, State s, double bearing, double duration, double speed, double depth)
{
    const int n = std::max(200, static_cast<int>(std::ceil(duration / 60.0)));
    const double h = duration / n;
    for (int i = 0; i < n; ++i)
    {
        const Point2 k1 = headingRate(f, s.p, s.t, bearing, speed, depth);
        const Point2 k2 =
            headingRate(f, {s.p.x + 0.5 * h * k1.x, s.p.y + 0.5 * h * k1.y}, s.t + 0.5 * h, bearing, speed, depth);
        const Point2 k3 =
            headingRate(f, {s.p.x + 0.5 * h * k2.x, s.p.y + 0.5 * h * k2.y}, s.t + 0.5 * h, bearing, speed, depth);
        const Point2 k4 = headingRate(f, {s.p.x + h * k3.x, s.p.y + h * k3.y}, s.t + h, bearing, speed, depth);
        s.p.x += h / 6.0 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x);
        s.p.y += h / 6.0 * (k1.y + 2 * k2.y + 2 * k3.y + k4.y);
        s.t += h;
    }
    return s;
}

/// Flies the straight line to @p to with the cross current cancelled (the ground speed along the line is
/// c.d + sqrt(V^2 - (c x d)^2)); small steps in distance. False where the cross current beats the glider.
bool flyStraight(const CurrentField &f, State &s, Point2 to, double speed, double depth)
{
    const Point2 from = s.p;
    const double length = std::hypot(to.x - from.x, to.y - from.y);
    if (length == 0.0)
        return true;
    const Point2 d{(to.x - from.x) / length, (to.y - from.y) / length};
    const int n = std::max(400, static_cast<int>(std::ceil(length / 25.0)));
    // the time to cover each piece of the line: the midpoint rule on 1 / ground speed at the piece's middle
    const auto ground = [&](Point2 p, double t, double &g) {
        const Velocity c = f.velocity(p.x, p.y, depth, t);
        const double along = c.u * d.x + c.v * d.y, cross = c.u * d.y - c.v * d.x;
        if (speed * speed < cross * cross)
            return false;
        g = along + std::sqrt(speed * speed - cross * cross);
        return g > 0.0;
    };
    const double ds = length / n;
    for (int i = 0; i < n; ++i)
    {
        double g1 = 0.0, g2 = 0.0;
        const double s0 = i * ds;
        if (!ground({from.x + (s0 + 0.5 * ds) * d.x, from.y + (s0 + 0.5 * ds) * d.y}, s.t, g1))
            return false;
        // one correction of the middle's time
        if (!ground({from.x + (s0 + 0.5 * ds) * d.x, from.y + (s0 + 0.5 * ds) * d.y}, s.t + 0.5 * ds / g1, g2))
            return false;
        s.t += ds / g2;
    }
    s.p = to;
    return true;
}

/// Flies @p plan's instructions from the start; checks every station and the goal against the summary (the
/// waypoints of @p r at the legs' ends). @p what names the file in messages.
void flyAndCheck(const MissionProblem &problem, const MissionResult &r, const std::vector<Instruction> &plan,
                 const std::string &what, bool targets)
{
    const MissionSpec &m = problem.getSpec();
    const CurrentField &f = *problem.getField();
    const double speed = m.vehicle.speed, depth = m.vehicle.depth;
    // a resumed mission: the glider is at the last fix when the files are loaded (before the plan's departure when a
    // stay was under way there)
    const auto &resumed = m.observations ? m.observations->resumed : std::nullopt;
    State s{r.waypoints.front().position, resumed ? m.timeOf(resumed->fixIso) : r.waypoints.front().time};
    // the stations in the order flown, with the summary's arrival at each and their radius
    struct Stop
    {
        std::string name;
        Point2 at;
        double arrival, radius;
    };
    std::vector<Stop> stops;
    for (const PlannedLeg &l : r.legs)
    {
        double radius = m.outputs.gotoWptDist;
        if (l.toVia >= 0 && std::isfinite(m.waypoints[l.toVia].radius))
            radius = m.waypoints[l.toVia].radius * m.metresPerUnit();
        stops.push_back({l.to, r.waypoints[l.lastPoint].position, r.waypoints[l.lastPoint].time, radius});
    }
    ASSERT_FALSE(stops.empty());
    std::size_t next = 0;
    int headings = 0, stays = 0;
    for (const Instruction &in : plan)
    {
        const Point2 to = problem.toLocal(in.to);
        if (std::isfinite(in.heading))
        {
            s = flyHeading(problem, s, in.heading, in.hours * 3600.0 / m.timeUnitSeconds, speed, depth);
            ++headings;
        }
        else
            ASSERT_TRUE(flyStraight(f, s, to, speed, depth)) << what << ": a straight leg the current forbids";
        // a station listed here: reached within its radius at the summary's time
        // (a station's point is written to 1e-4 minutes: within 0.2 m)
        if (next < stops.size() &&
            std::hypot(to.x - stops[next].at.x, to.y - stops[next].at.y) * m.metresPerUnit() < 1.0)
        {
            const Stop &st = stops[next];
            const double off = std::hypot(s.p.x - st.at.x, s.p.y - st.at.y) * m.metresPerUnit();
            EXPECT_LE(off, st.radius) << what << ": " << st.name << " missed by " << off << " m";
            const double elapsed = st.arrival - r.waypoints.front().time;
            EXPECT_NEAR(s.t, st.arrival, std::max(120.0 / m.timeUnitSeconds, 2e-3 * elapsed))
                << what << ": " << st.name << " reached at " << s.t << ", the summary says " << st.arrival;
            std::printf("%s: %s reached %.1f m from it, %+.1f s against the summary\n", what.c_str(), st.name.c_str(),
                        off, (s.t - st.arrival) * m.timeUnitSeconds);
            if (targets && next + 1 < stops.size())
            {
                EXPECT_EQ(in.name, st.name) << what;
            }
            ++next;
        }
        if (!in.leaveIso.empty())
        {
            const double leave = m.timeOf(in.leaveIso);
            EXPECT_GE(leave, s.t - std::max(120.0 / m.timeUnitSeconds, 1e-3 * std::abs(s.t))) << what;
            s.t = std::max(s.t, leave); // held in place (the stay is where the current is slower than the glider)
            ++stays;
        }
    }
    EXPECT_EQ(next, stops.size()) << what << ": stations not listed";
    int stayLegs = 0, headingLegs = 0;
    for (const PlannedLeg &l : r.legs)
    {
        stayLegs += l.stay > 0.0 && &l != &r.legs.back();
        headingLegs += l.plan.headingRoute();
    }
    EXPECT_EQ(stays, stayLegs + (resumed && !resumed->stayEnds.empty())) << what << ": a stay missing from the file";
    if (headingLegs > 0)
    {
        EXPECT_GT(headings, 0) << what << ": a leg of held headings written as straight legs";
    }
}

void checkPilotFiles(const MissionProblem &problem, const MissionResult &r)
{
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    flyAndCheck(problem, r, gotoInstructions(formatGotoList(gotoList(r, &problem))), "goto list", false);
    flyAndCheck(problem, r, targetInstructions(formatSeagliderTargets(seagliderTargets(r, &problem), r.spec.name)),
                "targets file", true);
}
} // namespace

// The survey on the Labrador forecast: leg A -> B is held headings, A has a six-hour stay.
TEST(PilotFilesFly, SurveyGotoListAndTargetsReachEveryStationWhenTheSummarySays)
{
    const MissionProblem problem(loadMission(std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/survey_labrador.yaml"));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    bool mixed = false;
    for (const PlannedLeg &l : r.legs)
        mixed = mixed || l.plan.headingRoute();
    EXPECT_TRUE(mixed) << "the survey has no leg of held headings any more: this test needs one";
    // waypoints.csv keeps every planned segment (for the map): a true heading on each, none elsewhere
    const std::string csv = waypointsCsv(r, &problem);
    EXPECT_NE(csv.find(",heading_true_deg,segment_duration,"), std::string::npos);
    std::size_t headed = 0;
    for (const MissionWaypoint &w : r.waypoints)
        headed += std::isfinite(w.heading);
    EXPECT_GT(headed, 20u);
    // the uploads: the leg of held headings as at most 8 holds (outputs.hold_tolerance, 300 m by default)
    const GotoList g = gotoList(r, &problem);
    std::size_t holds = 0;
    for (const std::string &note : g.notes)
        holds += note.find("hold heading") != std::string::npos;
    std::printf("survey: %zu planned segments of held headings, uploaded as %zu holds\n", headed, holds);
    EXPECT_GE(holds, 1u);
    EXPECT_LE(holds, 8u);
    const std::string targets = formatSeagliderTargets(seagliderTargets(r, &problem), r.spec.name);
    std::size_t targetHolds = 0;
    for (std::size_t k = targets.find("hold heading"); k != std::string::npos; k = targets.find("hold heading", k + 1))
        ++targetHolds;
    EXPECT_EQ(targetHolds, holds);
    // and they re-fly through the forecast to every station within its radius, when the summary says
    checkPilotFiles(problem, r);
    // with a tolerance of 0 every segment is its own hold
    MissionResult fine = r;
    fine.spec.outputs.holdTolerance = 0.0;
    std::size_t every = 0;
    for (const std::string &note : gotoList(fine, &problem).notes)
        every += note.find("hold heading") != std::string::npos;
    EXPECT_EQ(every, headed);
}

// A mission in a linear shear (u = y, V = 0.5, a 10 km unit, a projection for lon/lat): leg 1 east in the slack water
// (straight legs), leg 2 north across currents up to four times the glider's speed (held headings: no straight leg
// exists), leg 3 downstream (straight legs); a 2 h stay at A.
TEST(PilotFilesFly, ShearMissionWithAHeadingLegReachesEveryStationWhenTheSummarySays)
{
    const MissionProblem problem(parseMission(R"(name: shear_mixed
units: {length_m: 10000, time_s: 3600}
epoch: "2026-06-01T00:00:00Z"
projection: {lon0: -70.0, lat0: 36.0}
current: {type: linear_shear, parameters: {a: 1}}
region: {x_min: -6, x_max: 10, y_min: -4, y_max: 4}
start: {x: 0, y: 0.1}
waypoints:
  - {name: A, x: 1.5, y: 0.1, radius: 500 m, stay: 2 h}
  - {name: B, x: 2.5, y: 2.0, radius: 500 m}
goal: {x: 5.0, y: 2.0}
vehicle: {speed: 0.5}
)",
                                              "shear.yaml"));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    ASSERT_EQ(r.legs.size(), 3u);
    EXPECT_FALSE(r.legs[0].plan.headingRoute());
    EXPECT_TRUE(r.legs[1].plan.headingRoute());
    EXPECT_FALSE(r.legs[2].plan.headingRoute());
    checkPilotFiles(problem, r);
}

// The survey resumed during A's stay: the glider reached A (-52.2, 48.0; 500 m, a 6 h stay) at 02:00 and is still
// there at its last fix, 05:00; the plan departs when the stay ends, 08:00. Both uploads begin with the hold at A until
// then; flown from the last fix at 05:00 as the vehicle flies them, they reach B and C when the summary says (a list
// that left at 05:00 would arrive three hours early).
TEST(PilotFilesFly, AMissionResumedDuringAStayHoldsItFirstInBothUploads)
{
    const double t0 = 1773554400.0; // 2026-03-15T06:00:00Z, the survey's departure
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("ompl_glider_fly_resume_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string csv = (dir / "at_a.csv").string();
    {
        std::ofstream out(csv);
        out << "time,lon,lat,u,v\n";
        const double fixes[][3] = {
            {4, -52.6, 47.93}, {12, -52.4, 47.97}, {20, -52.2003, 48.0002}, {23, -52.2002, 47.9998}};
        for (const auto &f : fixes)
            out << formatIsoTime(t0 + 3600.0 * f[0]) << "," << f[1] << "," << f[2] << ",0.05,0.02\n";
    }
    MissionSpec m = loadMission(std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/survey_labrador.yaml");
    MissionOverrides o;
    o.origin = Origin::Flag;
    o.observations = Given<std::string>{csv, "--observations"};
    applyOverrides(o, m);
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    std::filesystem::remove_all(dir);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    ASSERT_EQ(r.waypoints.front().iso, "2026-03-16T08:00:00Z"); // the stay's end: 3 h after the last fix
    // the first waypoint of each file: A, with the stay's note
    const std::string note = "stay at A: hold within 500 m for 3.0000 h, leave at 2026-03-16T08:00:00Z";
    const GotoList g = parseGotoList(formatGotoList(gotoList(r, &problem)), "goto");
    ASSERT_FALSE(g.waypoints.empty());
    EXPECT_NEAR(g.waypoints[0].lon, -52.2, 1e-6);
    EXPECT_NEAR(g.waypoints[0].lat, 48.0, 1e-6);
    ASSERT_FALSE(g.notes.empty());
    EXPECT_EQ(g.notes[0], note);
    const std::string targets = formatSeagliderTargets(seagliderTargets(r, &problem), r.spec.name);
    EXPECT_NE(targets.find("/ " + note + "\nA lat=4800.0000 lon=-05212.0000 radius=500 goto="), std::string::npos)
        << targets;
    checkPilotFiles(problem, r);
}
