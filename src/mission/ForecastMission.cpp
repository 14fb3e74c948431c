#include "ompl_glider/mission/ForecastMission.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <tuple>
#include <vector>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrentField.h"
#include "ompl_glider/current/NetCdfCurrents.h"
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

double defaultForecastGridSize(double minCellSize, double distance)
{
    double g = 0.5 * minCellSize;
    if (distance > 0.0)
        g = std::clamp(g, distance / 200.0, distance / 25.0);
    if (!(g > 0.0) || !std::isfinite(g))
        throw Error("cannot choose a grid size (cell size " + num(minCellSize) + ", start-goal distance " +
                    num(distance) + "): give --grid-size");
    const double scale = std::pow(10.0, std::floor(std::log10(g)) - 1.0);  // two significant digits
    return std::round(g / scale) * scale;
}

namespace
{
std::string pointText(double a, double b)
{
    char buf[80];
    std::snprintf(buf, sizeof buf, "%.6g,%.6g", a, b);
    return buf;
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
    m.current.mark.file = file;

    // Load once as the mission runner will (same names, schemes, depth range, default projection) to check the
    // request and convert the start, goal and departure.
    NetCdfCurrentOptions o = netCdfCurrentOptions(m.current);
    o.maxDepth = q.depth;
    o.departure = q.departure;
    // Load only the region of the trip (issue 5): the start-goal box plus half its larger side (at least 0.2
    // degrees or units) on each side; the whole file when the trip crosses the antimeridian.
    const double spanA = std::abs(q.goal.x - q.start.x), spanB = std::abs(q.goal.y - q.start.y);
    const double pad = std::max(0.5 * std::max(spanA, spanB), 0.2);
    const bool subset = spanA < 180.0;
    if (subset)
    {
        o.lonMin = std::min(q.start.x, q.goal.x) - pad;
        o.lonMax = std::max(q.start.x, q.goal.x) + pad;
        o.latMin = std::max(std::min(q.start.y, q.goal.y) - pad, -90.0);
        o.latMax = std::min(std::max(q.start.y, q.goal.y) + pad, 90.0);
    }
    NetCdfCurrents nc;
    try
    {
        nc = loadNetCdfCurrents(file, o);
    }
    catch (const Error &e)
    {
        // Name the command-line flags instead of the library's option fields.
        std::string what = e.what();
        for (const auto &[field, flag] : std::vector<std::pair<std::string, std::string>>{
                 {"NetCdfCurrentOptions::timeName/depthName/lonName/latName",
                  "--time-var/--depth-var/--lon-var/--lat-var"},
                 {"NetCdfCurrentOptions::lonName/latName", "--lon-var/--lat-var"},
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
        if (!q.departure.empty() && what.find("depart") != std::string::npos && what.find("--departure") == std::string::npos)
            what = "--departure " + q.departure + ": " + what;
        else if (what.find("region ") != std::string::npos)
            what = "--start " + pointText(q.start.x, q.start.y) + " / --goal " + pointText(q.goal.x, q.goal.y) +
                   ": not on the grid: " + what;
        throw Error(what);
    }
    const GriddedCurrentField &g = *nc.field;
    // (Above the first layer is the surface layer's value, as forecasts put their first layer just below it.)
    if (g.nz() > 1 && q.depth > g.depthAxis().back())
        throw Error("--depth " + num(q.depth) + " m lies below the deepest layer of '" + file + "' (" +
                    num(g.depthAxis().back()) + " m)");
    const char *coords = nc.geographic ? "lon,lat" : "x,y";
    double sx, sy, gx, gy;
    nc.toLocal(q.start.x, q.start.y, sx, sy);
    nc.toLocal(q.goal.x, q.goal.y, gx, gy);
    const Region e = g.extent();
    for (const auto &[flag, a, b, x, y] :
         {std::tuple<const char *, double, double, double, double>{"--start", q.start.x, q.start.y, sx, sy},
          std::tuple<const char *, double, double, double, double>{"--goal", q.goal.x, q.goal.y, gx, gy}})
    {
        double fi, fj;
        if (!std::isfinite(x) || !std::isfinite(y) || !g.locate(x, y, fi, fj))
        {
            double lo0, la0, lo1, la1;
            nc.toGeographic(e.xMin, e.yMin, lo0, la0);
            nc.toGeographic(e.xMax, e.yMax, lo1, la1);
            throw Error(std::string(flag) + " " + pointText(a, b) + " (" + coords + ") lies outside the grid of '" +
                        file + "' (about " + coords + " " + pointText(lo0, la0) + " to " + pointText(lo1, la1) +
                        ")");
        }
        if (!g.inWater(x, y, q.depth))
            throw Error(std::string(flag) + " " + pointText(a, b) + " (" + coords + ") is on land in '" + file +
                        "' (u/v are fill values there at depth " + num(q.depth) + " m)");
    }
    const double tDep = nc.departureTime;
    if (tDep < nc.forecastBegin || tDep > nc.forecastEnd)
        throw Error("--departure " + q.departure + " is outside the forecast (" + nc.isoTime(nc.forecastBegin) +
                    " to " + nc.isoTime(nc.forecastEnd) + ")");
    if (tDep >= nc.forecastEnd && q.horizonPolicy == "refuse")
        throw Error("--departure " + (q.departure.empty() ? std::string("(default)") : q.departure) +
                    " is the last forecast time: no time is left to travel (use an earlier departure or --beyond hold)");

    if (nc.geographic)
    {
        if (subset && o.latMax - o.latMin < 120.0)
        {
            // The same subset for the mission's load, clipped to the grid loaded here, and the same local frame.
            double lo0, la0, lo1, la1, lo2, la2, lo3, la3;
            nc.toGeographic(e.xMin, e.yMin, lo0, la0);
            nc.toGeographic(e.xMax, e.yMax, lo1, la1);
            nc.toGeographic(e.xMin, e.yMax, lo2, la2);
            nc.toGeographic(e.xMax, e.yMin, lo3, la3);
            (void)lo2;
            (void)lo3;
            m.region.set = m.region.geographic = true;
            m.region.lonMin = std::max(o.lonMin, std::min(lo0, lo2));
            m.region.lonMax = std::min(o.lonMax, std::max(lo1, lo3));
            m.region.latMin = std::max(o.latMin, std::min(la0, la3));
            m.region.latMax = std::min(o.latMax, std::max(la1, la2));
            double lon0, lat0;
            nc.toGeographic(0.0, 0.0, lon0, lat0);
            m.projection.set = true;
            m.projection.lon0 = lon0;
            m.projection.lat0 = lat0;
            if (!(m.region.lonMin < m.region.lonMax && m.region.latMin < m.region.latMax))
                m.region.set = m.region.geographic = false;
        }
        m.start.geographic = m.goal.geographic = true;
        m.start.lon = q.start.x;
        m.start.lat = q.start.y;
        m.goal.lon = q.goal.x;
        m.goal.lat = q.goal.y;
    }
    else
    {
        m.start.x = q.start.x;
        m.start.y = q.start.y;
        m.goal.x = q.goal.x;
        m.goal.y = q.goal.y;
    }
    if (nc.dated)
    {
        MissionSpec::FileCalendar fc;
        fc.calendar = nc.calendar;
        fc.originSeconds = nc.originSeconds;
        m.fileCalendar = fc;
        m.epoch = fc.originSeconds - secondsSinceCalendarEpoch(DateTime{}, fc.calendar);
    }
    m.departure.time = tDep;
    m.vehicle.speed = q.speed;
    m.vehicle.depth = q.depth;
    m.travel.speed = q.speed;
    m.travel.depth = q.depth;
    m.travel.eps = 1.0;  // one second per integration step on trips of hours to days (as the example mission)
    m.planner.gridSize = defaultForecastGridSize(g.minCellSize(), std::hypot(gx - sx, gy - sy));
    m.outputs.files = {"summary", "path", "csv", "geojson", "goto", "map"};
    m.outputs.directory.clear();
    m.outputs.gotoNumber = 10;
    return m;
}

}  // namespace ompl_glider
