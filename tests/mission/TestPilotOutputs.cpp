// What a pilot reads and loads: dates of climatologies in their own calendars, route.kml for Google Earth, the goto
// list thinned to the turns, no-path reasons that name what blocks the route, lengths and durations in units for
// people (a Cartesian file in km), and zero velocity taken for land only where the file marks no land itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <netcdf.h>
#include <nlohmann/json.hpp>
#include <ogrsf_frmts.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/OutputWriter.h"
#include "ompl_glider/output/Report.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/output/SlocumGoto.h"

using namespace ompl_glider;
namespace fs = std::filesystem;

namespace
{
#define EXPECT_HAS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)
#define EXPECT_HAS_NOT(text, part) EXPECT_EQ(std::string(text).find(part), std::string::npos) << (text)

fs::path scratch(const std::string &name)
{
    const fs::path d = fs::path(::testing::TempDir()) / ("pilot_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

void nc(int status)
{
    ASSERT_EQ(status, NC_NOERR) << nc_strerror(status);
}

/// A small forecast: (time,) y, x axes (lon/lat in degrees, or x/y in @p xyUnits), u and v from @p uv (NaN: the
/// fill value -999, written only when @p fill), optionally a mask variable (1 water, 0 land) from @p mask.
struct Grid
{
    std::vector<double> x, y, t; ///< t empty: no time dimension
    std::string xyUnits;         ///< empty: geographic (degrees_east / degrees_north)
    std::string timeUnits{"days since 0000-01-01 00:00:00"}, calendar{"standard"};
    bool fill{false};
    std::function<std::pair<double, double>(std::size_t k, std::size_t j, std::size_t i)> uv;
    std::function<int(std::size_t j, std::size_t i)> mask; ///< empty: no mask variable
};

void writeGrid(const fs::path &path, const Grid &g)
{
    int id, dt = -1, dy, dx, vt = -1, vy, vx, vu, vv, vm = -1;
    nc(nc_create(path.c_str(), NC_CLOBBER, &id));
    const bool timed = !g.t.empty();
    if (timed)
        nc(nc_def_dim(id, "time", g.t.size(), &dt));
    nc(nc_def_dim(id, g.xyUnits.empty() ? "lat" : "y", g.y.size(), &dy));
    nc(nc_def_dim(id, g.xyUnits.empty() ? "lon" : "x", g.x.size(), &dx));
    auto text = [&](int var, const char *name, const std::string &value) {
        nc(nc_put_att_text(id, var, name, value.size(), value.c_str()));
    };
    if (timed)
    {
        nc(nc_def_var(id, "time", NC_DOUBLE, 1, &dt, &vt));
        text(vt, "units", g.timeUnits);
        text(vt, "calendar", g.calendar);
        text(vt, "standard_name", "time");
    }
    const bool geo = g.xyUnits.empty();
    nc(nc_def_var(id, geo ? "lat" : "y", NC_DOUBLE, 1, &dy, &vy));
    nc(nc_def_var(id, geo ? "lon" : "x", NC_DOUBLE, 1, &dx, &vx));
    text(vy, "units", geo ? "degrees_north" : g.xyUnits);
    text(vx, "units", geo ? "degrees_east" : g.xyUnits);
    text(vy, "standard_name", geo ? "latitude" : "projection_y_coordinate");
    text(vx, "standard_name", geo ? "longitude" : "projection_x_coordinate");
    const int dims3[3] = {dt, dy, dx};
    const int *dims = timed ? dims3 : dims3 + 1;
    const int nd = timed ? 3 : 2;
    nc(nc_def_var(id, "u", NC_FLOAT, nd, dims, &vu));
    nc(nc_def_var(id, "v", NC_FLOAT, nd, dims, &vv));
    for (int var : {vu, vv})
    {
        text(var, "units", "m s-1");
        if (g.fill)
        {
            const float f = -999.0f;
            nc(nc_put_att_float(id, var, "_FillValue", NC_FLOAT, 1, &f));
        }
    }
    text(vu, "standard_name", "eastward_sea_water_velocity");
    text(vv, "standard_name", "northward_sea_water_velocity");
    if (g.mask)
    {
        nc(nc_def_var(id, "mask", NC_INT, 2, dims3 + 1, &vm));
        text(vm, "standard_name", "sea_binary_mask");
    }
    nc(nc_enddef(id));
    if (timed)
        nc(nc_put_var_double(id, vt, g.t.data()));
    nc(nc_put_var_double(id, vy, g.y.data()));
    nc(nc_put_var_double(id, vx, g.x.data()));
    const std::size_t nt = timed ? g.t.size() : 1, n = nt * g.y.size() * g.x.size();
    std::vector<float> u(n), v(n);
    std::vector<int> m(g.y.size() * g.x.size());
    for (std::size_t k = 0, at = 0; k < nt; ++k)
        for (std::size_t j = 0; j < g.y.size(); ++j)
            for (std::size_t i = 0; i < g.x.size(); ++i, ++at)
            {
                const auto [a, b] = g.uv(k, j, i);
                u[at] = std::isnan(a) ? -999.0f : static_cast<float>(a);
                v[at] = std::isnan(b) ? -999.0f : static_cast<float>(b);
                if (g.mask && k == 0)
                    m[j * g.x.size() + i] = g.mask(j, i);
            }
    nc(nc_put_var_float(id, vu, u.data()));
    nc(nc_put_var_float(id, vv, v.data()));
    if (g.mask)
        nc(nc_put_var_int(id, vm, m.data()));
    nc(nc_close(id));
}

std::vector<double> axis(double from, double step, std::size_t n)
{
    std::vector<double> a;
    for (std::size_t i = 0; i < n; ++i)
        a.push_back(from + step * static_cast<double>(i));
    return a;
}

/// A year-0 climatology of a uniform current: 13 records 30 days apart from 0000-01-01 in @p calendar.
fs::path climatology(const fs::path &dir, const std::string &calendar)
{
    Grid g;
    g.x = axis(-60.0, 0.1, 11);
    g.y = axis(30.0, 0.1, 11);
    g.t = axis(0.0, 30.0, 13);
    g.calendar = calendar;
    g.uv = [](std::size_t, std::size_t, std::size_t) { return std::make_pair(0.1, 0.05); };
    const fs::path p = dir / ("clim_" + calendar + ".nc");
    writeGrid(p, g);
    return p;
}

std::string readPilotText(const fs::path &p)
{
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

ForecastInput forecastOf(const fs::path &file, Point2 start, Point2 goal, const std::string &departure = "")
{
    ForecastInput q;
    q.current.file = file.string();
    q.start = start;
    q.goal = goal;
    q.departure = departure;
    return q;
}

std::string reportOf(const MissionResult &r)
{
    std::ostringstream out;
    printReport(out, r);
    return out.str();
}

std::string pilotErrorOf(const std::function<void()> &f)
{
    try
    {
        f();
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

const fs::path kLabrador = fs::path(OMPL_GLIDER_SOURCE_DIR) / "examples" / "labrador_forecast.nc";
} // namespace

TEST(PilotCalendar, FormatCalendarTimeWritesTheFilesOwnDates)
{
    for (Calendar c :
         {Calendar::Standard, Calendar::ProlepticGregorian, Calendar::Julian, Calendar::NoLeap, Calendar::Day360})
        for (const char *date : {"0000-01-20T00:00:00Z", "0000-03-01T00:00:00Z", "0000-06-15T12:30:00Z"})
            EXPECT_EQ(formatCalendarTime(secondsSinceCalendarEpoch(parseDateTime(date), c), c), date)
                << calendarName(c);
    EXPECT_EQ(
        formatCalendarTime(secondsSinceCalendarEpoch(parseDateTime("0000-02-30"), Calendar::Day360), Calendar::Day360),
        "0000-02-30T00:00:00Z");
    EXPECT_THROW(formatCalendarTime(secondsSinceCalendarEpoch(parseDateTime("9999-12-31"), Calendar::NoLeap) + 86400.0,
                                    Calendar::NoLeap),
                 Error);
}

TEST(PilotCalendar, ClimatologyDatesRoundTripInEveryCalendar)
{
    const fs::path dir = scratch("calendars");
    for (const char *calendar : {"standard", "gregorian", "proleptic_gregorian", "julian", "noleap", "360_day"})
    {
        const fs::path file = climatology(dir, calendar);
        for (const char *day : {"0000-01-20", "0000-03-01", "0000-06-15"})
        {
            SCOPED_TRACE(std::string(calendar) + " " + day);
            const std::string date = std::string(day) + "T00:00:00Z";
            MissionSpec m = forecastMission(forecastOf(file, {-59.8, 30.2}, {-59.6, 30.4}, date));
            m.outputs.files = {OutputFormatId::Summary, OutputFormatId::Csv, OutputFormatId::GeoJson};
            m.outputs.directory = (dir / (std::string(calendar) + day)).string();
            const MissionProblem problem(m);
            const MissionResult r = runMission(problem);
            ASSERT_TRUE(r.plan.solved) << r.plan.reason;
            EXPECT_EQ(r.departureIso, date);
            EXPECT_HAS(reportOf(r), "(" + date + ")");
            writeOutputs(r, problem);
            const nlohmann::json s =
                nlohmann::json::parse(readPilotText(fs::path(m.outputs.directory) / "summary.json"));
            EXPECT_EQ(s["departure"]["iso"], date);
            EXPECT_HAS(readPilotText(fs::path(m.outputs.directory) / "waypoints.csv"), "," + date + ",");
            EXPECT_HAS(readPilotText(fs::path(m.outputs.directory) / "route.kml"), "departure " + date);
            // a year-0 date is not a Gregorian one for Google Earth: no TimeStamp
            EXPECT_HAS_NOT(readPilotText(fs::path(m.outputs.directory) / "route.kml"), "<TimeStamp>");
        }
    }
}

TEST(PilotCalendar, ADateOutsideAClimatologySaysItIsOne)
{
    const fs::path dir = scratch("outside");
    const fs::path file = climatology(dir, "noleap");
    const std::string e = pilotErrorOf([&] {
        forecastMission(forecastOf(file, {-59.8, 30.2}, {-59.6, 30.4}, "2024-01-20T00:00:00Z"));
    });
    EXPECT_HAS(e, "is outside the forecast");
    EXPECT_HAS(e, "the file is a climatology (its dates are in year 0000, noleap calendar)");
    EXPECT_HAS(e, "0000-01-01T00:00:00Z");
    // a day the calendar does not have is refused, naming the calendar
    EXPECT_HAS(pilotErrorOf([&] {
                   forecastMission(forecastOf(file, {-59.8, 30.2}, {-59.6, 30.4}, "0000-02-29"));
               }),
               "does not exist in the noleap calendar");
    // the 360_day calendar has a 30 February
    const fs::path d360 = climatology(dir, "360_day");
    const MissionSpec m = forecastMission(forecastOf(d360, {-59.8, 30.2}, {-59.6, 30.4}, "0000-02-30T00:00:00Z"));
    EXPECT_EQ(MissionProblem(m).isoTime(m.departure.time), "0000-02-30T00:00:00Z");
}

TEST(PilotKml, RouteKmlMatchesPathCsvAndCarriesTheIsochrones)
{
    const fs::path dir = scratch("kml");
    MissionSpec m = parseMission(R"(name: "jet & kml"
units: {length_m: 10000, time_s: 3600}
epoch: "2026-06-01T00:00:00Z"
projection: {lon0: 179.5, lat0: 36.0}
current: {type: meandering_jet}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: -3}
goal: {x: 8, y: 3}
vehicle: {speed: 0.5}
planner: {horizon: 60}
outputs: {files: [path, geojson, isochrones, summary]}
)",
                                 "kml.yaml");
    m.outputs.directory = (dir / "out").string();
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    ASSERT_TRUE(r.isochrones);
    writeOutputs(r, problem);
    // path.csv: lon/lat of every waypoint
    std::vector<LonLat> csv;
    {
        std::istringstream in(readPilotText(dir / "out" / "path.csv"));
        std::string line;
        std::getline(in, line);
        while (std::getline(in, line))
        {
            std::vector<std::string> c;
            std::stringstream ls(line);
            for (std::string cell; std::getline(ls, cell, ',');)
                c.push_back(cell);
            ASSERT_EQ(c.size(), 5u);
            csv.push_back({std::stod(c[3]), std::stod(c[4])});
        }
    }
    ASSERT_GE(csv.size(), 2u);
    // route.kml read by GDAL/OGR's KML driver: the route line, the waypoints with their dates, the isochrones
    GDALAllRegister();
    ASSERT_NE(GetGDALDriverManager()->GetDriverByName("KML"), nullptr);
    GDALDataset *ds = static_cast<GDALDataset *>(
        GDALOpenEx((dir / "out" / "route.kml").c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    ASSERT_NE(ds, nullptr);
    std::vector<LonLat> line;
    std::size_t points = 0, isochroneFeatures = 0;
    for (OGRLayer *layer : ds->GetLayers())
        for (auto &feature : *layer)
        {
            const OGRGeometry *g = feature->GetGeometryRef();
            ASSERT_NE(g, nullptr);
            const std::string layerName = layer->GetName();
            if (layerName == "isochrones")
                ++isochroneFeatures;
            else if (wkbFlatten(g->getGeometryType()) == wkbPoint)
            {
                const auto *p = g->toPoint();
                ASSERT_LT(points, csv.size());
                EXPECT_NEAR(p->getX(), csv[points].lon, 1e-7);
                EXPECT_NEAR(p->getY(), csv[points].lat, 1e-7);
                ++points;
            }
            else if (wkbFlatten(g->getGeometryType()) == wkbLineString)
                for (const OGRPoint &p : *g->toLineString())
                    line.push_back({p.getX(), p.getY()});
            else if (wkbFlatten(g->getGeometryType()) == wkbMultiLineString) // split at 180
                for (const OGRLineString *part : *g->toMultiLineString())
                    for (const OGRPoint &p : *part)
                        line.push_back({p.getX(), p.getY()});
        }
    GDALClose(ds);
    EXPECT_EQ(points, csv.size());
    EXPECT_EQ(isochroneFeatures, r.isochrones->contours.size());
    // the line passes through every waypoint of path.csv in order (plus the cut points at the antimeridian)
    std::size_t next = 0;
    for (const LonLat &p : line)
        if (next < csv.size() && std::abs(p.lon - csv[next].lon) < 1e-7 && std::abs(p.lat - csv[next].lat) < 1e-7)
            ++next;
    EXPECT_EQ(next, csv.size());
    const std::string kml = readPilotText(dir / "out" / "route.kml");
    EXPECT_HAS(kml, "<name>jet &amp; kml</name>");
    EXPECT_HAS(kml, "<TimeStamp><when>" + r.waypoints.back().iso + "</when></TimeStamp>");
    EXPECT_HAS(kml, "arrival " + r.waypoints.back().iso);
    EXPECT_HAS_NOT(kml, "without KML time stamps");
}

TEST(PilotKml, AYearZeroEpochGivesNoTimeStampsAndSaysSo)
{
    // xsd:dateTime (KML's TimeStamp) has no year 0: a climatology epoch's dates stay in the descriptions only
    const fs::path dir = scratch("kml0");
    MissionSpec m = parseMission(R"(name: climatology
units: {length_m: 10000, time_s: 86400}
epoch: "0000-03-01T00:00:00Z"
projection: {lon0: -60.0, lat0: 30.0}
current: {type: meandering_jet}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: -3}
goal: {x: 8, y: 3}
vehicle: {speed: 0.5}
outputs: {files: [summary]}
)",
                                 "kml0.yaml");
    m.outputs.directory = (dir / "out").string();
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    ASSERT_EQ(r.waypoints.front().iso.substr(0, 10), "0000-03-01");
    const std::string kml = routeKml(r, &problem);
    EXPECT_HAS_NOT(kml, "<TimeStamp>");
    EXPECT_HAS(kml, "departure " + r.waypoints.front().iso);
    EXPECT_HAS(kml, "the waypoints' dates are in their descriptions, without KML time stamps");
}

namespace
{
/// A result of straight legs through @p xy (planning frame, km units on a projection), one hour apart.
MissionResult straightResult(const std::vector<Point2> &xy)
{
    MissionResult r;
    r.spec = parseMission(R"(name: synthetic
units: {length_m: 1000, time_s: 3600}
epoch: "2026-06-01T00:00:00Z"
projection: {lon0: -60.0, lat0: 40.0}
current: {type: uniform}
region: {x_min: -100, x_max: 100, y_min: -100, y_max: 100}
start: {x: 0, y: 0}
goal: {x: 1, y: 1}
)",
                          "synthetic.yaml");
    const LocalProjection proj(-60.0, 40.0);
    for (std::size_t i = 0; i < xy.size(); ++i)
    {
        MissionWaypoint w;
        w.position = xy[i];
        w.time = static_cast<double>(i);
        w.geographic = true;
        w.lonLat = proj.inverse(xy[i].x * 1000.0, xy[i].y * 1000.0);
        r.waypoints.push_back(w);
    }
    return r;
}

/// Distance from @p p to the polyline @p line.
double distanceToLine(Point2 p, const std::vector<Point2> &line)
{
    double best = INFINITY;
    for (std::size_t i = 0; i + 1 < line.size(); ++i)
    {
        const Point2 a = line[i], b = line[i + 1];
        const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
        const double s = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(p.x - a.x - s * dx, p.y - a.y - s * dy));
    }
    return best;
}
} // namespace

TEST(PilotGoto, CollinearWaypointsGiveTheGoalAloneAndTurnsAreKept)
{
    // 61 waypoints on a straight 60 km line, each off it by up to 20 m: the glider needs the goal only
    std::vector<Point2> xy;
    for (int i = 0; i <= 60; ++i)
        xy.push_back({static_cast<double>(i), 0.02 * std::sin(1.7 * i)});
    MissionResult r = straightResult(xy);
    GotoList g = gotoList(r);
    ASSERT_EQ(g.waypoints.size(), 1u);
    EXPECT_NEAR(g.waypoints[0].lon, r.waypoints.back().lonLat.lon, 1e-12);
    EXPECT_EQ(g.listWhenWptDist, 100.0);
    r.spec.outputs.gotoIncludeStart = true;
    EXPECT_EQ(gotoList(r).waypoints.size(), 2u);
    r.spec.outputs.gotoTurnDeg = 0.0; // every waypoint
    EXPECT_EQ(gotoList(r).waypoints.size(), 61u);
    // a zigzag of 5 km legs turning 40 degrees at each corner: every corner is listed
    std::vector<Point2> zig{{0, 0}};
    for (int i = 1; i <= 8; ++i)
        zig.push_back({zig.back().x + 5.0 * std::sin((i % 2 ? 20.0 : -20.0) * M_PI / 180.0),
                       zig.back().y + 5.0 * std::cos(20.0 * M_PI / 180.0)});
    EXPECT_EQ(gotoList(straightResult(zig)).waypoints.size(), 8u);
    // a gentle arc (3 degrees a leg) is thinned, but never farther than goto_max_offset from a waypoint left out
    std::vector<Point2> arc;
    for (int i = 0; i <= 40; ++i)
        arc.push_back({20.0 * std::sin(i * 3.0 * M_PI / 180.0), 20.0 * (1.0 - std::cos(i * 3.0 * M_PI / 180.0))});
    const MissionResult ra = straightResult(arc);
    const std::vector<std::size_t> kept = gotoWaypointIndices(ra);
    EXPECT_LT(kept.size(), 20u);
    EXPECT_GT(kept.size(), 3u);
    std::vector<Point2> thin;
    for (std::size_t i : kept)
        thin.push_back(arc[i]);
    for (const Point2 &p : arc)
        EXPECT_LE(distanceToLine(p, thin), ra.spec.outputs.gotoMaxOffset / 1000.0 + 1e-9);
}

TEST(PilotGoto, ListWhenWptDistIsWrittenAndReadBack)
{
    GotoList g;
    g.waypoints = {{-70.5, 40.25}};
    g.listWhenWptDist = 250.0;
    const std::string text = formatGotoList(g);
    EXPECT_HAS(text, "    b_arg: list_when_wpt_dist(m) 250\n");
    EXPECT_LT(text.find("list_stop_when(enum) 7"), text.find("list_when_wpt_dist"));
    EXPECT_EQ(parseGotoList(text).listWhenWptDist, 250.0);
}

TEST(PilotGoto, AFineGridForecastRouteIsThinnedWithinTheStatedBound)
{
    // the Labrador forecast on a 500 m lattice: many refined waypoints, fewer of them listed (a waypoint is left out
    // only where the straight leg past it keeps the route's course, offset and time)
    ForecastInput q = forecastOf(kLabrador, {-52.7, 47.9}, {-51.5, 48.45});
    MissionSpec m = forecastMission(q);
    m.planner.gridSize = 500.0;
    m.outputs.files = {OutputFormatId::Summary, OutputFormatId::Goto};
    m.outputs.directory = (scratch("goto500") / "out").string();
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    writeOutputs(r, problem);
    const GotoList g = readGotoFile(m.outputs.directory + "/goto_l10.ma");
    EXPECT_EQ(g.listWhenWptDist, 100.0);
    ASSERT_GE(r.waypoints.size(), 20u);
    EXPECT_LT(g.waypoints.size() + 4, r.waypoints.size()) << g.waypoints.size() << " of " << r.waypoints.size();
    // the goal is the last waypoint; the route through the listed waypoints stays within goto_max_offset (1 km) of
    // every planned waypoint (DDMM.MMMM rounds by at most 0.2 m)
    EXPECT_NEAR(g.waypoints.back().lat, r.waypoints.back().lonLat.lat, 1e-5);
    std::vector<Point2> thin{problem.getStart()};
    for (const LonLat &p : g.waypoints)
        thin.push_back(problem.toLocal(p));
    for (const MissionWaypoint &w : r.waypoints)
        EXPECT_LE(distanceToLine(w.position, thin), m.outputs.gotoMaxOffset + 1.0);
    // and the listed legs, flown straight one after the other, arrive when the plan does (each merge keeps its time
    // within 0.1 % or 30 s)
    std::vector<TimedPoint> legs{{thin.front().x, thin.front().y, r.plan.departure}};
    for (std::size_t i = 1; i < thin.size(); ++i)
        legs.push_back({thin[i].x, thin[i].y, 0.0});
    const std::vector<TimedPoint> flown = retimePath(problem, problem.getField(), r.plan.speed, legs);
    ASSERT_EQ(flown.size(), legs.size());
    EXPECT_NEAR(flown.back().t, r.waypoints.back().time,
                std::max(1e-3 * r.plan.travelTime, 30.0 * static_cast<double>(thin.size())));
}

TEST(PilotNoPath, AForecastTooShortNamesItsEndAndBeyondHold)
{
    const MissionSpec m = forecastMission(forecastOf(kLabrador, {-52.7, 47.9}, {-51.5, 48.45}, "2026-03-19T00:00:00Z"));
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_FALSE(r.plan.solved);
    EXPECT_HAS(r.plan.reason, "the forecast ends at 2026-03-20T00:00:00Z, 1 d 0.0 h (86400.0 s) after the departure");
    EXPECT_HAS(r.plan.reason, "(current.horizon: hold_last)"); // a mission made by a program: the field named
    EXPECT_HAS_NOT(r.plan.reason, "a finer grid");
    // typed: the forecast's end bounds the arrival, one day after the departure; the words are the parts'
    EXPECT_EQ(r.plan.noPath.bound, ArrivalBound::ForecastEnd);
    EXPECT_DOUBLE_EQ(r.plan.noPath.boundSpan, 86400.0);
    EXPECT_EQ(r.plan.noPath.cause, NoPathCause::Unreachable);
    EXPECT_TRUE(r.plan.noPath.advice.empty());
    EXPECT_EQ(r.plan.reason, r.plan.noPath.text());
    EXPECT_EQ(r.departureIso, "2026-03-19T00:00:00Z");
    EXPECT_HAS(reportOf(r), "Departure:          345600 (2026-03-19T00:00:00Z)\n");
    // the same with --beyond hold: a route, on the frozen last field, said in the report and summary.json
    ForecastInput q = forecastOf(kLabrador, {-52.7, 47.9}, {-51.5, 48.45}, "2026-03-19T00:00:00Z");
    q.current.horizonPolicy = BeyondForecast::HoldLast;
    MissionSpec h = forecastMission(q);
    h.outputs.files = {OutputFormatId::Summary};
    h.outputs.directory = (scratch("hold") / "out").string();
    const MissionProblem held(h);
    const MissionResult rh = runMission(held);
    ASSERT_TRUE(rh.plan.solved) << rh.plan.reason;
    EXPECT_HAS(reportOf(rh), "Forecast:           planned past the forecast's last time");
    writeOutputs(rh, held);
    const nlohmann::json s = nlohmann::json::parse(readPilotText(fs::path(h.outputs.directory) / "summary.json"));
    ASSERT_TRUE(s.contains("forecast_notes"));
    EXPECT_HAS(s["forecast_notes"].dump(), "held frozen (current.horizon: hold_last)");
}

TEST(PilotNoPath, ACurrentFasterThanTheGliderGivesBothSpeeds)
{
    // 1 m/s against the glider's 0.4 m/s, the goal upstream; lengths in km, times in s: physical units
    const MissionSpec m = parseMission(R"(name: upstream
units: {length_m: 1000, time_s: 1000}
current: {type: uniform, parameters: {u: -1.0, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -2, y_max: 2}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
vehicle: {speed: 0.4}
planner: {horizon: 100}
)",
                                       "upstream.yaml");
    const MissionResult r = runMission(MissionProblem(m));
    ASSERT_FALSE(r.plan.solved);
    EXPECT_HAS(r.plan.reason, "the current reaches up to 1.00 m/s (1.9 kn) on the way, faster than the glider's V = "
                              "0.40 m/s (0.8 kn)");
    EXPECT_HAS_NOT(r.plan.reason, "a finer grid");
    EXPECT_HAS_NOT(r.plan.reason, "is enclosed");
    // the level set after the lattice proves it: no route exists, and the pipeline knows it by the cause
    EXPECT_EQ(r.plan.noPath.cause, NoPathCause::Unreachable);
    EXPECT_TRUE(r.plan.noPath.proven());
    EXPECT_EQ(r.plan.status, PlanStatus::NoPath);
}

TEST(PilotNoPath, AnEnclosedStartIsNamedWithWhatEnclosesIt)
{
    // a square island with a lagoon around the start: forbidden regions close it
    const MissionSpec m = parseMission(R"(name: lagoon
current: {type: uniform, parameters: {u: 0.05, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 2, y: 0}
goal: {x: 8, y: 0}
vehicle: {speed: 0.5}
planner: {horizon: 60}
forbidden:
  obstacles:
    - name: atoll
      kind: island
      points: [[0.5, -1.5], [3.5, -1.5], [3.5, 1.5], [0.5, 1.5]]
      holes: [[[1.5, -0.5], [2.5, -0.5], [2.5, 0.5], [1.5, 0.5]]]
)",
                                       "lagoon.yaml");
    const MissionResult r = runMission(MissionProblem(m));
    ASSERT_FALSE(r.plan.solved);
    EXPECT_HAS(r.plan.reason, "the start is enclosed: the water around it (");
    EXPECT_HAS(r.plan.reason, "closed by forbidden regions, coastline polygons or the keep-off distance");
    EXPECT_HAS_NOT(r.plan.reason, "a finer grid");
    EXPECT_EQ(r.plan.noPath.cause, NoPathCause::WalledOff);
}

TEST(PilotNoPath, APassageClosedAtTheModelsResolutionIsNamed)
{
    // a wall of land (fill values) across the grid at x = 5 km: the goal's water is cut off from the start's
    const fs::path dir = scratch("wall");
    Grid g;
    g.x = axis(0.0, 1.0, 11);
    g.y = axis(0.0, 1.0, 9);
    g.xyUnits = "km";
    g.fill = true;
    g.uv = [](std::size_t, std::size_t, std::size_t i) {
        return i == 5 ? std::make_pair(std::nan(""), std::nan("")) : std::make_pair(0.05, 0.0);
    };
    writeGrid(dir / "wall.nc", g);
    const MissionSpec m = forecastMission(forecastOf(dir / "wall.nc", {2.0, 4.0}, {8.5, 4.0}));
    const MissionResult r = runMission(MissionProblem(m));
    // no heading planner searches for a goal the start's water does not reach (the level set would take minutes)
    EXPECT_HAS_NOT(r.plan.reason, "Isochrone");
    ASSERT_FALSE(r.plan.solved);
    EXPECT_HAS(r.plan.reason, "is enclosed");
    EXPECT_HAS(r.plan.reason, "closed by the forecast's land at its resolution (cells of 1 km");
}

TEST(PilotUnits, ACartesianFileInKmTakesStartAndGoalInKm)
{
    const fs::path dir = scratch("cartesian");
    Grid g;
    g.x = axis(0.0, 2.0, 41); // 0..80 km
    g.y = axis(0.0, 2.0, 41);
    g.xyUnits = "km";
    g.uv = [](std::size_t, std::size_t, std::size_t) { return std::make_pair(0.1, 0.0); };
    writeGrid(dir / "km.nc", g);
    Grid gm = g; // the same grid in metres
    gm.x = axis(0.0, 2000.0, 41);
    gm.y = axis(0.0, 2000.0, 41);
    gm.xyUnits = "m";
    writeGrid(dir / "m.nc", gm);
    MissionSpec km = forecastMission(forecastOf(dir / "km.nc", {10.0, 10.0}, {60.0, 50.0}));
    km.outputs.files = {OutputFormatId::Summary};
    const MissionProblem pk(km);
    EXPECT_EQ(pk.getStart().x, 10000.0);
    EXPECT_EQ(pk.getGoal().y, 50000.0);
    const MissionResult rk = runMission(pk);
    ASSERT_TRUE(rk.plan.solved) << rk.plan.reason;
    const MissionResult rm =
        runMission(MissionProblem(forecastMission(forecastOf(dir / "m.nc", {10000.0, 10000.0}, {60000.0, 50000.0}))));
    ASSERT_TRUE(rm.plan.solved) << rm.plan.reason;
    EXPECT_NEAR(rk.plan.travelTime, rm.plan.travelTime, 1e-6 * rm.plan.travelTime);
    const std::string report = reportOf(rk);
    EXPECT_HAS(report, "read in the file's axis units (1000 m each)");
    EXPECT_HAS(report, "Path length:        64.031 km (straight 64.031 km)\n");
    EXPECT_HAS(report, " (grid 1.000 km, 3 sectors)");
    EXPECT_HAS(report, "Travel time:        1 d ");
    EXPECT_HAS(report, "Straight line:      1 d ");
    // a point outside the grid is named in the file's units
    EXPECT_HAS(pilotErrorOf([&] {
                   forecastMission(forecastOf(dir / "km.nc", {10.0, 10.0}, {90.0, 50.0}));
               }),
               "lies outside the grid");
}

TEST(PilotLand, ZeroVelocityIsLandOnlyWhereTheFileMarksNoLand)
{
    const fs::path dir = scratch("zero");
    Grid g;
    g.x = axis(-60.0, 0.1, 11);
    g.y = axis(30.0, 0.1, 11);
    g.t = axis(0.0, 1.0, 3);
    g.timeUnits = "days since 2026-01-01";
    // a calm 3 x 3 block (u = v = 0 in every record) in a 0.1 m/s flow
    auto calm = [](std::size_t j, std::size_t i) { return j >= 4 && j <= 6 && i >= 4 && i <= 6; };
    g.uv = [&](std::size_t, std::size_t j, std::size_t i) {
        return calm(j, i) ? std::make_pair(0.0, 0.0) : std::make_pair(0.1, 0.0);
    };
    GriddedCurrentOptions o;
    o.lonMin = -61.0, o.lonMax = -58.0, o.latMin = 29.0, o.latMax = 32.0;
    // nothing else says where land is: the calm nodes are land, counted and said
    writeGrid(dir / "plain.nc", g);
    GriddedCurrents plain = loadGriddedCurrents((dir / "plain.nc").string(), o);
    EXPECT_EQ(plain.zeroLandNodes, 9u);
    const Point2 centre = plain.toLocal({-59.5, 30.5});
    EXPECT_FALSE(plain.field->inWater(centre.x, centre.y, 0.0));
    const MissionSpec m = forecastMission(forecastOf(dir / "plain.nc", {-59.9, 30.1}, {-59.1, 30.9}));
    bool said = false;
    const MissionProblem problem(m);
    for (const std::string &note : problem.forecastNotes())
        said = said || note.find("9 of the 121 nodes loaded are land only because u = v = 0") != std::string::npos;
    EXPECT_TRUE(said);
    // fill values mark land in a corner: the file says where its land is, the calm block is water
    Grid f = g;
    f.fill = true;
    f.uv = [&](std::size_t k, std::size_t j, std::size_t i) {
        return j < 2 && i < 2 ? std::make_pair(std::nan(""), std::nan("")) : g.uv(k, j, i);
    };
    writeGrid(dir / "fill.nc", f);
    GriddedCurrents filled = loadGriddedCurrents((dir / "fill.nc").string(), o);
    EXPECT_EQ(filled.fillLandNodes, 4u);
    EXPECT_EQ(filled.zeroLandNodes, 0u);
    EXPECT_TRUE(filled.field->inWater(centre.x, centre.y, 0.0));
    // a mask variable marks land in a corner: the same
    Grid k = g;
    k.mask = [](std::size_t j, std::size_t i) { return j > 8 && i > 8 ? 0 : 1; };
    writeGrid(dir / "mask.nc", k);
    GriddedCurrents masked = loadGriddedCurrents((dir / "mask.nc").string(), o);
    EXPECT_EQ(masked.maskLandNodes, 4u);
    EXPECT_EQ(masked.zeroLandNodes, 0u);
    EXPECT_TRUE(masked.field->inWater(centre.x, centre.y, 0.0));
    // and the option turns the rule off
    o.zeroVelocityLand = false;
    EXPECT_EQ(loadGriddedCurrents((dir / "plain.nc").string(), o).zeroLandNodes, 0u);
}

TEST(PilotKml, ANameOfAnyBytesStillMakesWellFormedFiles)
{
    // a mission name in Latin-1 with a control character and a line break: route.kml stays well-formed UTF-8 XML
    // (GDAL/OGR's KML driver, expat underneath, reads it), the name's bad bytes as U+FFFD; summary.json and the map
    // are written too
    const fs::path dir = scratch("kml_bytes");
    MissionSpec m = parseMission(R"(units: {length_m: 10000, time_s: 3600}
epoch: "2026-06-01T00:00:00Z"
projection: {lon0: -70.0, lat0: 36.0}
current: {type: meandering_jet}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: -3}
goal: {x: 8, y: 3}
vehicle: {speed: 0.5}
outputs: {files: [path, geojson, summary, map]}
)",
                                 "bytes.yaml");
    m.name = std::string("Gl\xe9ne\x01 fjord\n<b>");
    m.outputs.directory = (dir / "out").string();
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    writeOutputs(r, problem);
    const std::string kml = readPilotText(dir / "out" / "route.kml");
    EXPECT_HAS(kml, "<name>Gl\xEF\xBF\xBDne  fjord\n&lt;b&gt;</name>");
    GDALAllRegister();
    GDALDataset *ds = static_cast<GDALDataset *>(
        GDALOpenEx((dir / "out" / "route.kml").c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    ASSERT_NE(ds, nullptr) << "route.kml is not well-formed:\n" << kml.substr(0, 400);
    std::size_t features = 0;
    for (OGRLayer *layer : ds->GetLayers())
        features += static_cast<std::size_t>(layer->GetFeatureCount());
    GDALClose(ds);
    EXPECT_EQ(features, r.waypoints.size() + 1); // the waypoints and the route line
    const nlohmann::json summary = nlohmann::json::parse(readPilotText(dir / "out" / "summary.json"));
    EXPECT_EQ(summary["mission"].get<std::string>().substr(0, 5), "Gl\xEF\xBF\xBD");
    EXPECT_TRUE(fs::exists(dir / "out" / "map.png"));
    // map.svg: the same name in its title, well-formed (the SVG driver of GDAL is not built in Debian's: the
    // bytes are checked here, one character at a time, against UTF-8's own rules)
    const std::string svg = readPilotText(dir / "out" / "map.svg");
    EXPECT_HAS(svg, ">Gl\xEF\xBF\xBDne  fjord\n&lt;b&gt;");
    EXPECT_HAS_NOT(svg, "\xe9");
    EXPECT_HAS_NOT(svg, "\x01");
}
