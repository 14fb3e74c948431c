#include "ompl_glider/mission/ForecastMission.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <tuple>
#include <vector>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrentField.h"
#include "ompl_glider/current/NetCdfCurrents.h"
#include "ompl_glider/mission/IsoTime.h"
#include "ompl_glider/mission/MissionProblem.h"

namespace ompl_glider
{
namespace
{
std::string num(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}
}  // namespace

namespace
{
/// A plain number (seconds after the first forecast time), not a date.
bool isNumber(const std::string &text)
{
    char *end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    return !text.empty() && end && *end == '\0' && std::isfinite(v);
}

std::string pointText(double a, double b)
{
    char buf[80];
    std::snprintf(buf, sizeof buf, "%.6g,%.6g", a, b);
    return buf;
}
/// The reader's message in the command line's words: its option fields become the flags, and a departure or
/// region fault is prefixed with the flags that gave it.
std::string flagMessage(std::string what, const ForecastInput &q)
{
    // Name the command-line flags instead of the library's option fields.
    for (const auto &[field, flag] : std::vector<std::pair<std::string, std::string>>{
             {"NetCdfCurrentOptions::timeName/depthName/lonName/latName",
              "--time-var/--depth-var/--lon-var/--lat-var"},
             {"NetCdfCurrentOptions::lonName/latName", "--lon-var/--lat-var"},
             {"NetCdfCurrentOptions::uName/vName", "--u-var/--v-var"},
             {"NetCdfCurrentOptions::velocityUnits", "--velocity-units"},
             {"NetCdfCurrentOptions::timeUnits", "--time-units"},
             {"NetCdfCurrentOptions::steadyRecord", "--steady-record"},
             {"NetCdfCurrentOptions::uName", "--u-var"},
             {"NetCdfCurrentOptions::vName", "--v-var"},
             {"NetCdfCurrentOptions::lonName", "--lon-var"},
             {"NetCdfCurrentOptions::latName", "--lat-var"},
             {"NetCdfCurrentOptions::depthName", "--depth-var"},
             {"NetCdfCurrentOptions::timeName", "--time-var"},
             {"NetCdfCurrentOptions::departure", "--departure"},
             {"NetCdfCurrentOptions::maxDepth", "--depth"}})
        for (std::size_t at = what.find(field); at != std::string::npos; at = what.find(field, at))
            what.replace(at, field.size(), flag);
    const bool departure = what.find("depart") != std::string::npos;
    if (!q.departure.empty() && departure && what.find("--departure") == std::string::npos)
        what = "--departure " + q.departure + ": " + what;
    else if (what.find("region ") != std::string::npos && what.find("] is outside '") != std::string::npos)
        what = "--start " + pointText(q.start.x, q.start.y) + " / --goal " + pointText(q.goal.x, q.goal.y) +
               ": not on the grid: " + what;
    return what;
}
}  // namespace

MissionSpec forecastMission(const ForecastInput &q)
{
    namespace fs = std::filesystem;
    const std::string &file = q.file;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw Error("--currents: cannot open '" + file + "' (no such file)");
    if (!(q.speed > 0.0) || !std::isfinite(q.speed))
        throw Error("--speed must be > 0 (m/s)");
    if (!(q.depth >= 0.0))
        throw Error("--depth must be >= 0 (metres, positive down)");

    MissionSpec m;
    m.file = file;
    m.directory = ".";
    m.name = fs::path(file).stem().string();
    m.current.type = "netcdf";
    m.current.file = file;
    m.current.variables = q.variables;
    m.current.xyInterpolation = q.xyInterpolation;
    m.current.depthInterpolation = q.depthInterpolation;
    m.current.timeInterpolation = q.timeInterpolation;
    m.current.horizonPolicy = q.horizonPolicy;
    m.current.zeroVelocityLand = q.zeroVelocityLand;
    m.current.velocityUnits = q.velocityUnits;
    m.current.timeUnits = q.timeUnits;
    m.current.steadyRecord = q.steadyRecord;
    m.current.mark.file = file;

    // The file's coordinates are not known yet: take start and goal as lon/lat (the trip region is the same box
    // in x/y for a Cartesian file) and switch to x/y below when the file is Cartesian.
    m.start.geographic = m.goal.geographic = true;
    m.start.lon = m.start.x = q.start.x;
    m.start.lat = m.start.y = q.start.y;
    m.goal.lon = m.goal.x = q.goal.x;
    m.goal.lat = m.goal.y = q.goal.y;
    m.vehicle.depth = m.travel.depth = q.depth;
    // Load the trip's region as the mission will (netCdfLoadOptions) to check the request and convert the departure.
    NetCdfCurrentOptions o = netCdfLoadOptions(m);
    o.departure = q.departure;
    NetCdfCurrents nc;
    std::optional<double> epoch;  // the date of field time 0 of a steady file without dates
    try
    {
        if (!q.departure.empty() && !isNumber(q.departure))
        {
            const NetCdfTimeAxis axis = readNetCdfTimeAxis(file, o);
            if (axis.steady && !axis.dated)
            {
                try
                {
                    epoch = parseIsoTime(q.departure);
                }
                catch (const Error &e)
                {
                    throw Error("--departure " + q.departure + ": " + e.what());
                }
                o.departure.clear();  // departs at field time 0, which is that date
            }
        }
        nc = loadNetCdfCurrents(file, o);
    }
    catch (const Error &e)
    {
        throw Error(flagMessage(e.what(), q));
    }
    const GriddedCurrentField &g = *nc.field;
    // (Above the first layer is the surface layer's value, as forecasts put their first layer just below it.)
    if (g.nz() > 1 && q.depth > g.depthAxis().back())
        throw Error("--depth " + num(q.depth) + " m lies below the deepest layer of '" + file + "' (" +
                    num(g.depthAxis().back()) + " m)");
    const char *coords = nc.geographic ? "lon,lat" : "x,y";
    const Point2 start = nc.toLocal({q.start.x, q.start.y});
    const Point2 goal = nc.toLocal({q.goal.x, q.goal.y});
    const Region e = g.extent();
    for (const auto &[flag, a, b, x, y] :
         {std::tuple<const char *, double, double, double, double>{"--start", q.start.x, q.start.y, start.x, start.y},
          std::tuple<const char *, double, double, double, double>{"--goal", q.goal.x, q.goal.y, goal.x, goal.y}})
    {
        double fi, fj;
        if (!std::isfinite(x) || !std::isfinite(y) || !g.locate(x, y, fi, fj))
        {
            const LonLat lo = nc.toGeographic({e.xMin, e.yMin});
            const LonLat hi = nc.toGeographic({e.xMax, e.yMax});
            throw Error(std::string(flag) + " " + pointText(a, b) + " (" + coords + ") lies outside the grid of '" +
                        file + "' (about " + coords + " " + pointText(lo.lon, lo.lat) + " to " +
                        pointText(hi.lon, hi.lat) + ")");
        }
        if (!g.inWater(x, y, q.depth))
            throw Error(std::string(flag) + " " + pointText(a, b) + " (" + coords + ") is on land in '" + file +
                        "' (u/v are fill values there at depth " + num(q.depth) + " m)");
    }
    const double tDep = nc.departureTime;
    // a steady field (no time dimension, a single record, --steady-record) is the same at every time
    if (!nc.steady && (tDep < nc.forecastBegin || tDep > nc.forecastEnd))
        throw Error("--departure " + q.departure + " is outside the forecast (" + nc.isoTime(nc.forecastBegin) +
                    " to " + nc.isoTime(nc.forecastEnd) + ")");
    if (!nc.steady && tDep >= nc.forecastEnd && q.horizonPolicy == "refuse")
        throw Error("--departure " + (q.departure.empty() ? std::string("(default)") : q.departure) +
                    " is the last forecast time: no time is left to travel (use an earlier departure or --beyond hold)");

    m.start.geographic = m.goal.geographic = nc.geographic;
    if (nc.dated)
    {
        MissionSpec::FileCalendar fc;
        fc.calendar = nc.calendar;
        fc.originSeconds = nc.originSeconds;
        m.fileCalendar = fc;
        m.epoch = fc.originSeconds - secondsSinceCalendarEpoch(DateTime{}, fc.calendar);
    }
    else if (epoch)
        m.epoch = *epoch;
    m.current.steady = nc.steady;
    m.departure.time = tDep;
    m.vehicle.speed = q.speed;
    m.vehicle.depth = q.depth;
    m.travel.speed = q.speed;
    m.travel.depth = q.depth;
    m.travel.eps = 1.0;  // one second per integration step on trips of hours to days (as the example mission)
    m.outputs.files = {"summary", "path", "csv", "geojson", "goto", "map"};
    m.outputs.directory.clear();
    m.outputs.gotoNumber = 10;
    return m;
}

}  // namespace ompl_glider
