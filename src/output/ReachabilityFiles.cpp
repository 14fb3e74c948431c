/// @file ReachabilityFiles.cpp
/// @brief The output format "reachability": reachability.geojson, reachability.nc and summary.json's `reachability`.
#include "ompl_glider/output/ReachabilityFiles.h"

#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <tuple>

#include <nlohmann/json.hpp>

#include "JsonValues.h"
#include "SummaryParts.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/output/RouteFiles.h"
#if OMPL_GLIDER_WITH_NETCDF
#include <netcdf.h>

#include "../io/DatasetLock.h"
#include "ompl_glider/io/Time.h"
#endif

namespace ompl_glider
{
using output_json::jnum;
using output_json::jtext;
using json = output_json::json;

namespace
{
json numbers(const std::vector<double> &v)
{
    json a = json::array();
    for (const double x : v)
        a.push_back(jnum(x));
    return a;
}
} // namespace

std::string reachabilityGeoJson(const MissionResult &r)
{
    json features = json::array();
    const bool geo = r.reachability && !r.reachability->lon.empty();
    if (r.reachability)
        for (const ReachContour &c : r.reachability->contours)
        {
            json lines = json::array();
            if (geo)
                for (const auto &line : c.lonLat)
                    for (const auto &part : splitAtAntimeridian(line))
                    {
                        json l = json::array();
                        for (const LonLat &p : part)
                            l.push_back(json::array({p.lon, p.lat}));
                        lines.push_back(l);
                    }
            else
                for (const auto &line : c.lines)
                {
                    json l = json::array();
                    for (const Point2 &p : line)
                        l.push_back(json::array({p.x, p.y}));
                    lines.push_back(l);
                }
            features.push_back({{"type", "Feature"},
                                {"properties",
                                 {{"time", jnum(c.time)},
                                  {"time_iso", jtext(c.iso)},
                                  {"since_departure", jnum(c.time - r.reachability->departure)},
                                  {"level", c.level}}},
                                {"geometry", {{"type", "MultiLineString"}, {"coordinates", lines}}}});
        }
    json doc = {{"type", "FeatureCollection"},
                {"name", r.spec.name + " probability of reach"},
                {"members", r.reachability ? r.reachability->members : 0},
                {"resolution", r.reachability ? jnum(r.reachability->resolution) : jnum(0.0)},
                {"features", features}};
    return output_json::utf8Dump(doc, 1) + "\n";
}

namespace summary_detail
{
json reachabilityJson(const MissionResult &r)
{
    if (!r.reachability)
        return nullptr;
    const ReachProbability &p = *r.reachability;
    json frames = json::array();
    for (std::size_t f = 0; f < p.times.size(); ++f)
        frames.push_back({{"time", jnum(p.times[f])},
                          {"time_iso", jtext(p.iso[f])},
                          {"since_departure", jnum(p.times[f] - p.departure)}});
    json quantiles = json::array();
    for (const ReachQuantile &q : p.quantiles)
        quantiles.push_back({{"q", q.q},
                             {"travel_time", jnum(q.travelTime)},
                             {"arrival", jnum(q.arrival)},
                             {"arrival_iso", jtext(q.iso)}});
    std::vector<double> travel;
    for (const double t : p.goalTimes)
        travel.push_back(t - p.departure);
    return {{"members", p.members},
            {"weights", numbers(p.weights)},
            {"weighed_by_observations", p.weighed},
            {"resolution", jnum(p.resolution)},
            {"grid", {{"x0", jnum(p.x0)}, {"y0", jnum(p.y0)}, {"h", jnum(p.h)}, {"nx", p.nx}, {"ny", p.ny}}},
            {"departure", jnum(p.departure)},
            {"horizon", jnum(p.horizon - p.departure)},
            {"horizon_end", jnum(p.horizon)},
            {"horizon_iso", jtext(p.iso.empty() ? std::string() : p.iso.back())},
            {"levels", numbers(p.levels)},
            {"times", frames},
            {"goal",
             {{"probability", jnum(p.goalProbability)},
              {"member_arrivals", numbers(p.goalTimes)},
              {"member_travel_times", numbers(travel)},
              {"quantiles", quantiles}}},
            {"threads_per_solve", p.threadsPerSolve},
            {"stopped", p.stopped},
            {"wall_seconds", jnum(p.seconds)}};
}
} // namespace summary_detail

#if OMPL_GLIDER_WITH_NETCDF
namespace
{
/// NetCDF-C's calls, each checked: an error names the file and what was done.
struct NcFile
{
    std::string path;
    int id{-1};

    void check(int status, const std::string &what) const
    {
        if (status != NC_NOERR)
            throw Error(path + ": writing the probability of reach: " + what + ": " + nc_strerror(status));
    }
    int dim(const char *name, std::size_t len) const
    {
        int d = -1;
        check(nc_def_dim(id, name, len, &d), std::string("define dimension ") + name);
        return d;
    }
    int var(const char *name, nc_type type, std::vector<int> dims) const
    {
        int v = -1;
        check(nc_def_var(id, name, type, static_cast<int>(dims.size()), dims.data(), &v),
              std::string("define variable ") + name);
        if (dims.size() >= 2)
            check(nc_def_var_deflate(id, v, 1, 1, 4), std::string("compress variable ") + name);
        return v;
    }
    void text(int var, const char *name, const std::string &value) const
    {
        check(nc_put_att_text(id, var, name, value.size(), value.c_str()), std::string("attribute ") + name);
    }
    void number(int var, const char *name, double value) const
    {
        check(nc_put_att_double(id, var, name, NC_DOUBLE, 1, &value), std::string("attribute ") + name);
    }
};

/// The frames' time coordinate: "days since <departure>" in the mission's calendar where it has dates; else the time
/// since the departure in the mission's time unit.
struct TimeAxis
{
    std::string units, calendar;
    double scale{1.0}; ///< field units -> the axis' units
};

TimeAxis timeAxisOf(const MissionResult &r, const ReachProbability &p)
{
    TimeAxis a;
    const std::string iso = r.spec.isoTime(p.departure);
    if (!iso.empty())
    {
        std::string date = iso; // "2026-06-01T00:00:00Z" -> "2026-06-01 00:00:00" (UDUNITS' reference time)
        for (char &c : date)
            if (c == 'T')
                c = ' ';
        if (!date.empty() && date.back() == 'Z')
            date.pop_back();
        a.units = "days since " + date;
        a.calendar = r.spec.fileCalendar ? calendarName(r.spec.fileCalendar->calendar) : "standard";
        a.scale = r.spec.timeUnitSeconds / 86400.0;
    }
    else if (r.spec.physicalUnits().time)
    {
        a.units = "s";
        a.scale = r.spec.timeUnitSeconds;
    }
    else
        a.units = "1"; // the mission's own time unit
    return a;
}

std::string utcNow()
{
    const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

/// The variables' ids.
struct ReachVars
{
    int time{-1}, fieldTime{-1}, x{-1}, y{-1}, lon{-1}, lat{-1}, probability{-1}, weight{-1}, goal{-1}, quantile{-1},
        goalQuantile{-1}, arrival{-1};
};

/// A variable of times on @p axis (units, calendar), whose fill value means "not by the horizon".
int timeVar(const NcFile &nc, const char *name, const std::vector<int> &dims, const TimeAxis &axis,
            const std::string &longName)
{
    const int v = nc.var(name, NC_DOUBLE, dims);
    nc.text(v, "long_name", longName);
    nc.text(v, "units", axis.units);
    if (!axis.calendar.empty())
        nc.text(v, "calendar", axis.calendar);
    const double fill = NC_FILL_DOUBLE;
    nc.check(nc_def_var_fill(nc.id, v, 0, &fill), std::string("fill value of ") + name);
    return v;
}

/// The dimensions, coordinates, variables and attributes of reachability.nc (CF-1.8).
ReachVars defineReachVars(const NcFile &nc, const MissionResult &r, const TimeAxis &axis, bool arrivals)
{
    const ReachProbability &p = *r.reachability;
    const bool geo = !p.lon.empty();
    ReachVars v;
    const int dTime = nc.dim("time", p.times.size()), dY = nc.dim("y", static_cast<std::size_t>(p.ny)),
              dX = nc.dim("x", static_cast<std::size_t>(p.nx));
    const int dMember = nc.dim("member", p.memberArrival.size()), dQuantile = nc.dim("quantile", p.quantiles.size());
    v.time = nc.var("time", NC_DOUBLE, {dTime});
    nc.text(v.time, "standard_name", "time");
    nc.text(v.time, "long_name", axis.calendar.empty() ? "time since the departure" : "time");
    nc.text(v.time, "units", axis.units);
    if (!axis.calendar.empty())
        nc.text(v.time, "calendar", axis.calendar);
    nc.text(v.time, "axis", "T");
    v.fieldTime = nc.var("field_time", NC_DOUBLE, {dTime});
    nc.text(v.fieldTime, "long_name", "the frame's time on the current field's clock (the mission's time unit)");
    nc.text(v.fieldTime, "units", "1");
    v.x = nc.var("x", NC_DOUBLE, {dX});
    v.y = nc.var("y", NC_DOUBLE, {dY});
    for (const auto &[id, name] : {std::make_pair(v.x, "x"), std::make_pair(v.y, "y")})
    {
        const std::string n = name;
        nc.text(id, "long_name", n + " in the planning frame" + (geo ? " (local projection about the region)" : ""));
        nc.text(id, "units", r.spec.physicalUnits().length ? "m" : "1");
        if (geo)
            nc.text(id, "standard_name", "projection_" + n + "_coordinate");
        nc.text(id, "axis", n == "x" ? "X" : "Y");
    }
    if (geo)
        for (const auto &[id, name, units] : {std::make_tuple(&v.lon, "longitude", "degrees_east"),
                                              std::make_tuple(&v.lat, "latitude", "degrees_north")})
        {
            *id = nc.var(id == &v.lon ? "lon" : "lat", NC_DOUBLE, {dY, dX});
            nc.text(*id, "standard_name", name);
            nc.text(*id, "long_name", name);
            nc.text(*id, "units", units);
        }
    v.probability = nc.var("probability", NC_FLOAT, {dTime, dY, dX});
    nc.text(v.probability, "long_name",
            "probability of reach by the time: the weight of the ensemble's members whose level-set front came to "
            "the node by then");
    nc.text(v.probability, "units", "1");
    const float range[2] = {0.0f, 1.0f};
    nc.check(nc_put_att_float(nc.id, v.probability, "valid_range", NC_FLOAT, 2, range), "attribute valid_range");
    if (geo)
        nc.text(v.probability, "coordinates", "lon lat");
    v.weight = nc.var("weight", NC_DOUBLE, {dMember});
    nc.text(v.weight, "long_name", "the member's weight (sum 1)");
    nc.text(v.weight, "units", "1");
    v.goal = timeVar(nc, "goal_arrival", {dMember}, axis,
                     "the member's first arrival at the goal (fill: not by the horizon)");
    v.quantile = nc.var("quantile", NC_DOUBLE, {dQuantile});
    nc.text(v.quantile, "long_name", "probability of the arrival-time quantile");
    nc.text(v.quantile, "units", "1");
    v.goalQuantile = timeVar(nc, "goal_arrival_quantile", {dQuantile}, axis,
                             "weighted quantile of the members' first arrival at the goal (fill: not attained by the "
                             "horizon)");
    if (arrivals)
    {
        v.arrival =
            timeVar(nc, "arrival", {dMember, dY, dX}, axis, "the member's first arrival (fill: not by the horizon)");
        if (geo)
            nc.text(v.arrival, "coordinates", "lon lat");
    }
    nc.text(NC_GLOBAL, "Conventions", "CF-1.8");
    nc.text(NC_GLOBAL, "title", "Probability of reach: " + r.spec.name);
    nc.text(NC_GLOBAL, "institution", "ompl_glider");
    nc.text(NC_GLOBAL, "source",
            std::string("ompl_glider ") + OMPL_GLIDER_VERSION +
                ": one level-set front per ensemble member from the start (LollaLevelSet), p = the weight of the "
                "members reached by the time");
    nc.text(NC_GLOBAL, "history",
            utcNow() + " written by ompl_glider " + OMPL_GLIDER_VERSION + " (mission " +
                (r.spec.file.empty() ? std::string("built in") : r.spec.file) + ")");
    nc.number(NC_GLOBAL, "members", static_cast<double>(p.members));
    nc.number(NC_GLOBAL, "resolution", p.resolution);
    nc.number(NC_GLOBAL, "departure", p.departure);
    nc.number(NC_GLOBAL, "horizon", p.horizon - p.departure);
    nc.number(NC_GLOBAL, "goal_probability", p.goalProbability);
    nc.text(NC_GLOBAL, "departure_iso", r.spec.isoTime(p.departure));
    return v;
}

/// The values of reachability.nc.
void writeReachValues(const NcFile &nc, const MissionResult &r, const TimeAxis &axis, const ReachVars &v)
{
    const ReachProbability &p = *r.reachability;
    const std::size_t nx = static_cast<std::size_t>(p.nx), ny = static_cast<std::size_t>(p.ny);
    const double length = r.spec.physicalUnits().length ? r.spec.metresPerUnit() : 1.0;
    const auto since = [&](double t) { return std::isfinite(t) ? (t - p.departure) * axis.scale : NC_FILL_DOUBLE; };
    const auto put = [&](int var, const std::vector<double> &values, const char *what) {
        nc.check(nc_put_var_double(nc.id, var, values.data()), std::string("write ") + what);
    };
    std::vector<double> t, q, x, y, w, g;
    for (const double time : p.times)
        t.push_back(since(time));
    for (std::size_t i = 0; i < nx; ++i)
        x.push_back((p.x0 + static_cast<double>(i) * p.h) * length);
    for (std::size_t j = 0; j < ny; ++j)
        y.push_back((p.y0 + static_cast<double>(j) * p.h) * length);
    for (const double time : p.goalTimes)
        g.push_back(since(time));
    for (const ReachQuantile &rq : p.quantiles)
    {
        q.push_back(rq.q);
        w.push_back(rq.reached ? since(rq.arrival) : NC_FILL_DOUBLE);
    }
    put(v.time, t, "time");
    put(v.fieldTime, p.times, "field_time");
    put(v.x, x, "x");
    put(v.y, y, "y");
    if (v.lon >= 0)
    {
        put(v.lon, p.lon, "lon");
        put(v.lat, p.lat, "lat");
    }
    for (std::size_t f = 0; f < p.probability.size(); ++f)
    {
        const std::size_t start[3] = {f, 0, 0}, count[3] = {1, ny, nx};
        nc.check(nc_put_vara_float(nc.id, v.probability, start, count, p.probability[f].data()), "write probability");
    }
    put(v.weight, p.weights, "weight");
    put(v.goal, g, "goal_arrival");
    put(v.quantile, q, "quantile");
    put(v.goalQuantile, w, "goal_arrival_quantile");
    if (v.arrival >= 0)
        for (std::size_t k = 0; k < p.memberArrival.size(); ++k)
        {
            std::vector<double> a;
            for (const double time : p.memberArrival[k])
                a.push_back(since(time));
            const std::size_t start[3] = {k, 0, 0}, count[3] = {1, ny, nx};
            nc.check(nc_put_vara_double(nc.id, v.arrival, start, count, a.data()), "write arrival");
        }
}
} // namespace

void writeReachabilityNetCdf(const std::string &path, const MissionResult &r, const MissionProblem &)
{
    if (!r.reachability)
        throw Error(path + ": the run computed no probability of reach");
    const TimeAxis axis = timeAxisOf(r, *r.reachability);
    const bool arrivals = r.spec.reachability.memberArrival && !r.reachability->memberArrival.empty();
    gridded_detail::DatasetLock lock; // NetCDF-C is not thread-safe: the process's one lock
    NcFile nc{path};
    nc.check(nc_create(path.c_str(), NC_NETCDF4 | NC_CLOBBER, &nc.id), "create");
    try
    {
        const ReachVars v = defineReachVars(nc, r, axis, arrivals);
        nc.check(nc_enddef(nc.id), "end the definitions");
        writeReachValues(nc, r, axis, v);
    }
    catch (...)
    {
        nc_close(nc.id);
        throw;
    }
    nc.check(nc_close(nc.id), "close");
}
#else
void writeReachabilityNetCdf(const std::string &path, const MissionResult &, const MissionProblem &)
{
    throw Error(path + ": this build of ompl_glider writes no NetCDF (OMPL_GLIDER_WITH_NETCDF=OFF)");
}
#endif
} // namespace ompl_glider
