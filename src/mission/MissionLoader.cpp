// loadMission(): YAML mission files, validated field by field (003 Sec. IV mission contents, SPEC.md 6).
#include <netcdf.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/output/OutputFormats.h"
#include "ompl_glider/planners/PlannerRegistry.h"
#include "ompl_glider/current/CfTime.h"
#include "ompl_glider/mission/IsoTime.h"
#include "ompl_glider/mission/MissionSpec.h"

namespace ompl_glider
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string joinPath(const std::string &dir, const std::string &p)
{
    if (p.empty() || p[0] == '/' || dir.empty() || dir == ".")
        return p;
    return dir + "/" + p;
}

bool fileExists(const std::string &p)
{
    std::ifstream f(p);
    return static_cast<bool>(f);
}

/// Reads one mission; every accessor names the file, the line and the dotted field.
class Reader
{
public:
    Reader(std::string file, std::string dir) : file_(std::move(file)), dir_(std::move(dir))
    {
    }

    const std::string &file() const
    {
        return file_;
    }
    const std::string &dir() const
    {
        return dir_;
    }

    [[noreturn]] void fail(const YAML::Node &node, const std::string &field, const std::string &what) const
    {
        throw Error(where(node) + "field '" + field + "': " + what);
    }
    [[noreturn]] void failAt(int line, const std::string &field, const std::string &what) const
    {
        throw Error(file_ + ":" + std::to_string(line) + ": field '" + field + "': " + what);
    }

    std::string where(const YAML::Node &node) const
    {
        const YAML::Mark m = node.Mark();
        if (m.line < 0)
            return file_ + ": ";
        return file_ + ":" + std::to_string(m.line + 1) + ": ";
    }
    int line(const YAML::Node &node) const
    {
        return node.Mark().line + 1;
    }

    static std::string sub(const std::string &path, const std::string &key)
    {
        return path.empty() ? key : path + "." + key;
    }

    /// The node must be a map whose keys are all in @p allowed.
    void checkMap(const YAML::Node &node, const std::string &path, const std::set<std::string> &allowed) const
    {
        if (!node.IsMap())
            fail(node, path, "expected a mapping (key: value lines)");
        std::set<std::string> seen;
        for (auto it = node.begin(); it != node.end(); ++it)
        {
            const std::string key = it->first.Scalar();
            if (!seen.insert(key).second)
                throw Error(where(it->first) + "field '" + sub(path, key) + "' is given twice");
            if (!allowed.count(key))
            {
                std::string list;
                for (const auto &a : allowed)
                    list += (list.empty() ? "" : ", ") + a;
                throw Error(where(it->first) + "unknown field '" + sub(path, key) + "' (allowed here: " + list + ")");
            }
        }
    }

    double number(const YAML::Node &node, const std::string &field) const
    {
        if (!node.IsScalar())
            fail(node, field, "expected a number");
        double v;
        try
        {
            v = node.as<double>();
        }
        catch (const YAML::Exception &)
        {
            fail(node, field, "expected a number, got '" + node.Scalar() + "'");
        }
        if (std::isnan(v))
            fail(node, field, "expected a number, got NaN");
        return v;
    }
    double finite(const YAML::Node &node, const std::string &field) const
    {
        const double v = number(node, field);
        if (!std::isfinite(v))
            fail(node, field, "expected a finite number");
        return v;
    }
    double positive(const YAML::Node &node, const std::string &field) const
    {
        const double v = finite(node, field);
        if (!(v > 0))
            fail(node, field, "expected a number > 0, got " + node.Scalar());
        return v;
    }
    double nonNegative(const YAML::Node &node, const std::string &field) const
    {
        const double v = number(node, field);
        if (!(v >= 0) || !std::isfinite(v))
            fail(node, field, "expected a finite number >= 0, got " + node.Scalar());
        return v;
    }
    long integer(const YAML::Node &node, const std::string &field, long lo, long hi) const
    {
        if (!node.IsScalar())
            fail(node, field, "expected an integer");
        long v;
        try
        {
            v = node.as<long>();
        }
        catch (const YAML::Exception &)
        {
            fail(node, field, "expected an integer, got '" + node.Scalar() + "'");
        }
        if (v < lo || v > hi)
            fail(node, field, "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " +
                                  std::to_string(v));
        return v;
    }
    bool boolean(const YAML::Node &node, const std::string &field) const
    {
        if (!node.IsScalar())
            fail(node, field, "expected true or false");
        try
        {
            return node.as<bool>();
        }
        catch (const YAML::Exception &)
        {
            fail(node, field, "expected true or false, got '" + node.Scalar() + "'");
        }
    }
    std::string text(const YAML::Node &node, const std::string &field) const
    {
        if (!node.IsScalar() || node.Scalar().empty())
            fail(node, field, "expected a non-empty text");
        return node.Scalar();
    }
    std::string oneOf(const YAML::Node &node, const std::string &field, const std::set<std::string> &values) const
    {
        const std::string v = text(node, field);
        if (!values.count(v))
        {
            std::string list;
            for (const auto &a : values)
                list += (list.empty() ? "" : ", ") + a;
            fail(node, field, "'" + v + "' is not one of: " + list);
        }
        return v;
    }
    /// A time: a number in field units, or an ISO 8601 date converted with the mission's epoch.
    double time(const YAML::Node &node, const std::string &field, const MissionSpec &m) const
    {
        if (!node.IsScalar())
            fail(node, field, "expected a time (a number, or an ISO 8601 date when the mission has an epoch)");
        try
        {
            return finite(node, field);
        }
        catch (const Error &)
        {
            if (m.fileCalendar)
            {
                try
                {
                    const DateTime d = parseDateTime(node.Scalar());
                    return secondsSinceCalendarEpoch(d, m.fileCalendar->calendar) - m.fileCalendar->originSeconds;
                }
                catch (const Error &e)
                {
                    fail(node, field, e.what());
                }
            }
            if (!m.epoch)
                fail(node, field, "expected a number (an ISO 8601 date needs 'epoch' at the top of the mission)");
            try
            {
                return (parseIsoTime(node.Scalar()) - *m.epoch) / m.timeUnitSeconds;
            }
            catch (const Error &e)
            {
                fail(node, field, e.what());
            }
        }
    }
    /// A [a, b] pair of numbers.
    std::pair<double, double> pair(const YAML::Node &node, const std::string &field) const
    {
        if (!node.IsSequence() || node.size() != 2)
            fail(node, field, "expected a pair [a, b]");
        return {finite(node[0], field + "[0]"), finite(node[1], field + "[1]")};
    }
    std::vector<std::pair<double, double>> ring(const YAML::Node &node, const std::string &field) const
    {
        if (!node.IsSequence() || node.size() < 3)
            fail(node, field, "expected a list of at least 3 points [a, b]");
        std::vector<std::pair<double, double>> out;
        for (std::size_t i = 0; i < node.size(); ++i)
            out.push_back(pair(node[i], field + "[" + std::to_string(i) + "]"));
        return out;
    }

private:
    std::string file_, dir_;
};

void readPoint(const Reader &r, const YAML::Node &n, const std::string &field, PointSpec &p, const MissionSpec &m)
{
    r.checkMap(n, field, {"x", "y", "lon", "lat"});
    const bool xy = n["x"] || n["y"], geo = n["lon"] || n["lat"];
    if (xy == geo)
        r.fail(n, field, "give either x and y, or lon and lat");
    if (xy)
    {
        if (!n["x"] || !n["y"])
            r.fail(n, field, "both x and y are required");
        p.geographic = false;
        p.x = r.finite(n["x"], field + ".x");
        p.y = r.finite(n["y"], field + ".y");
    }
    else
    {
        if (!n["lon"] || !n["lat"])
            r.fail(n, field, "both lon and lat are required");
        if (!m.projection.set && m.current.type != "netcdf")
            r.fail(n, field, "lon/lat needs a 'projection' (lon0, lat0) in the mission");
        p.geographic = true;
        p.lon = r.finite(n["lon"], field + ".lon");
        p.lat = r.finite(n["lat"], field + ".lat");
        if (std::abs(p.lat) > 90)
            r.fail(n["lat"], field + ".lat", "latitude must be within [-90, 90]");
    }
}

void readPolygon(const Reader &r, const YAML::Node &n, const std::string &field, PolygonSpec &poly,
                 const MissionSpec &m)
{
    poly.mark = {r.file(), r.line(n)};
    if (n["name"])
        poly.name = r.text(n["name"], field + ".name");
    const bool xy = static_cast<bool>(n["points"]), geo = static_cast<bool>(n["lonlat"]);
    if (xy == geo)
        r.fail(n, field, "give the vertices either as 'points' ([x, y] ...) or as 'lonlat' ([lon, lat] ...)");
    if (geo && !m.projection.set && m.current.type != "netcdf")
        r.fail(n["lonlat"], field + ".lonlat", "lon/lat vertices need a 'projection' in the mission");
    poly.geographic = geo;
    poly.points = r.ring(geo ? n["lonlat"] : n["points"], field + (geo ? ".lonlat" : ".points"));
    if (n["holes"])
    {
        const YAML::Node &h = n["holes"];
        if (!h.IsSequence())
            r.fail(h, field + ".holes", "expected a list of rings");
        for (std::size_t i = 0; i < h.size(); ++i)
            poly.holes.push_back(r.ring(h[i], field + ".holes[" + std::to_string(i) + "]"));
    }
}

/// Time origin of a NetCDF forecast (its first time, as the loader uses it): ISO dates of the mission are field
/// times in the file's calendar, and the outputs get calendar dates.
void readFileCalendar(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    int nc = -1;
    if (nc_open(m.current.file.c_str(), NC_NOWRITE, &nc) != NC_NOERR)
        r.fail(n["file"], "current.file", "'" + m.current.file + "' is not a NetCDF file");
    struct Closer
    {
        int id;
        ~Closer()
        {
            nc_close(id);
        }
    } closer{nc};
    std::vector<std::string> names;
    if (m.current.variables.count("time"))
        names.push_back(m.current.variables.at("time"));
    else
        names = {"time", "ocean_time", "t", "Time", "MT"};
    int var = -1;
    std::string used;
    for (const auto &name : names)
        if (nc_inq_varid(nc, name.c_str(), &var) == NC_NOERR)
        {
            used = name;
            break;
        }
    if (var < 0)
    {
        if (m.current.variables.count("time"))
            r.fail(n["variables"]["time"], "current.variables.time",
                   "no variable '" + names[0] + "' in '" + m.current.file + "'");
        return;  // a steady field: no calendar
    }
    auto textAttribute = [&](const char *att) -> std::string {
        std::size_t len = 0;
        if (nc_inq_attlen(nc, var, att, &len) != NC_NOERR)
            return "";
        std::string v(len, '\0');
        if (nc_get_att_text(nc, var, att, v.data()) != NC_NOERR)
            return "";
        while (!v.empty() && v.back() == '\0')
            v.pop_back();
        return v;
    };
    const std::string units = textAttribute("units");
    if (units.find("since") == std::string::npos)
        return;  // undated
    double first = 0.0;
    const std::size_t index0 = 0;
    if (nc_get_var1_double(nc, var, &index0, &first) != NC_NOERR)
        r.fail(n["file"], "current.file", "cannot read the first value of '" + used + "' in '" + m.current.file + "'");
    try
    {
        const CfTimeUnits cf = parseCfTimeUnits(units, textAttribute("calendar"));
        MissionSpec::FileCalendar fc;
        fc.calendar = cf.calendar;
        fc.originSeconds = first * cf.secondsPerUnit + cf.reference;
        m.fileCalendar = fc;
        m.epoch = fc.originSeconds - secondsSinceCalendarEpoch(DateTime{}, cf.calendar);
    }
    catch (const Error &e)
    {
        r.fail(n["file"], "current.file", std::string("time axis '") + used + "': " + e.what());
    }
}

void readCurrent(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "current";
    r.checkMap(n, f, {"type", "parameters", "file", "variables", "interpolation", "horizon"});
    CurrentSpec &c = m.current;
    c.mark = {r.file(), r.line(n)};
    std::set<std::string> kinds;
    for (const CurrentFieldKind &k : currentFieldKinds())
        kinds.insert(k.name);
    if (!n["type"])
        r.fail(n, f + ".type", "missing (" + currentFieldKindList() + ")");
    c.type = r.oneOf(n["type"], f + ".type", kinds);
    const CurrentFieldKind &kind = *findCurrentFieldKind(c.type);
    if (n["parameters"])
    {
        std::set<std::string> names;
        for (const auto &[key, value] : kind.parameters)
            names.insert(key);
        r.checkMap(n["parameters"], f + ".parameters", names);
        for (auto it = n["parameters"].begin(); it != n["parameters"].end(); ++it)
        {
            const std::string key = it->first.Scalar();
            c.parameters[key] = r.finite(it->second, f + ".parameters." + key);
        }
    }
    if (c.type == "double_gyre" && c.parameters.count("length") && !(c.parameters["length"] > 0))
        r.fail(n["parameters"]["length"], f + ".parameters.length", "expected a number > 0");
    const bool netcdf = kind.gridded;
    for (const char *key : {"file", "variables", "interpolation", "horizon"})
        if (n[key] && !netcdf)
            r.fail(n[key], f + "." + key, "only for type netcdf");
    if (!netcdf)
        return;
    if (!n["file"])
        r.fail(n, f + ".file", "missing: the NetCDF forecast file");
    c.file = joinPath(r.dir(), r.text(n["file"], f + ".file"));
    if (!fileExists(c.file))
        r.fail(n["file"], f + ".file", "cannot open '" + c.file + "'");
    if (n["variables"])
    {
        r.checkMap(n["variables"], f + ".variables", {"u", "v", "x", "y", "lon", "lat", "depth", "time"});
        for (auto it = n["variables"].begin(); it != n["variables"].end(); ++it)
            c.variables[it->first.Scalar()] = r.text(it->second, f + ".variables." + it->first.Scalar());
    }
    if (n["interpolation"])
    {
        const YAML::Node &i = n["interpolation"];
        r.checkMap(i, f + ".interpolation", {"xy", "depth", "time"});
        if (i["xy"])
            c.xyInterpolation = r.oneOf(i["xy"], f + ".interpolation.xy", {"nearest", "bilinear", "bicubic"});
        if (i["depth"])
            c.depthInterpolation =
                r.oneOf(i["depth"], f + ".interpolation.depth", {"nearest", "linear", "cubic", "akima"});
        if (i["time"])
            c.timeInterpolation = r.oneOf(i["time"], f + ".interpolation.time", {"nearest", "linear", "cubic", "akima"});
    }
    if (n["horizon"])
        c.horizonPolicy = r.oneOf(n["horizon"], f + ".horizon", {"refuse", "hold_last"});
    readFileCalendar(r, n, m);
}

void readRegion(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "region";
    r.checkMap(n, f, {"x_min", "x_max", "y_min", "y_max", "lon_min", "lon_max", "lat_min", "lat_max"});
    RegionSpec &g = m.region;
    g.set = true;
    const bool xy = n["x_min"] || n["x_max"] || n["y_min"] || n["y_max"];
    const bool geo = n["lon_min"] || n["lon_max"] || n["lat_min"] || n["lat_max"];
    if (xy == geo)
        r.fail(n, f, "give either x_min, x_max, y_min, y_max or lon_min, lon_max, lat_min, lat_max");
    auto need = [&](const char *key) -> double {
        if (!n[key])
            r.fail(n, f + "." + key, "missing");
        return r.finite(n[key], f + "." + key);
    };
    g.geographic = geo;
    if (xy)
    {
        g.xMin = need("x_min");
        g.xMax = need("x_max");
        g.yMin = need("y_min");
        g.yMax = need("y_max");
        if (!(g.xMax > g.xMin))
            r.fail(n["x_max"], f + ".x_max", "must be > x_min");
        if (!(g.yMax > g.yMin))
            r.fail(n["y_max"], f + ".y_max", "must be > y_min");
    }
    else
    {
        if (!m.projection.set && m.current.type != "netcdf")
            r.fail(n, f, "lon/lat bounds need a 'projection' in the mission");
        g.lonMin = need("lon_min");
        g.lonMax = need("lon_max");
        g.latMin = need("lat_min");
        g.latMax = need("lat_max");
        if (!(g.lonMax > g.lonMin))
            r.fail(n["lon_max"], f + ".lon_max", "must be > lon_min");
        if (!(g.latMax > g.latMin))
            r.fail(n["lat_max"], f + ".lat_max", "must be > lat_min");
    }
}

void readDeparture(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "departure";
    r.checkMap(n, f, {"time", "window"});
    DepartureSpec &d = m.departure;
    if (n["time"] && n["window"])
        r.fail(n, f, "give either a departure time or a departure window, not both");
    if (n["time"])
        d.time = r.time(n["time"], f + ".time", m);
    if (!n["window"])
        return;
    const YAML::Node &w = n["window"];
    const std::string g = f + ".window";
    r.checkMap(w, g, {"begin", "end", "spacing", "tolerance", "coarse_grid_size", "coarse_sectors", "threads"});
    if (!w["begin"] || !w["end"])
        r.fail(w, g, "begin and end are required");
    d.window = true;
    d.begin = r.time(w["begin"], g + ".begin", m);
    d.end = r.time(w["end"], g + ".end", m);
    if (!(d.end >= d.begin))
        r.fail(w["end"], g + ".end", "must not be before begin");
    d.time = d.begin;
    if (w["spacing"])
        d.spacing = r.positive(w["spacing"], g + ".spacing");
    if (w["tolerance"])
        d.tolerance = r.positive(w["tolerance"], g + ".tolerance");
    if (w["coarse_grid_size"])
        d.coarseGridSize = r.positive(w["coarse_grid_size"], g + ".coarse_grid_size");
    if (w["coarse_sectors"])
        d.coarseSectors = static_cast<int>(r.integer(w["coarse_sectors"], g + ".coarse_sectors", 1, 5));
    if (w["threads"])
        d.threads = static_cast<unsigned>(r.integer(w["threads"], g + ".threads", 0, 1024));
}

void readDive(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "dive_profile";
    r.checkMap(n, f,
               {"z_min", "z_max", "climb_to_max", "min_range", "climb_to_levels", "dive_to_levels", "step",
                "selection", "max_time_factor", "max_time", "clearance", "threads", "bathymetry"});
    DiveSpec &d = m.dive;
    d.enabled = true;
    DiveProfileParams &p = d.params;
    for (const char *key : {"z_min", "z_max"})
        if (!n[key])
            r.fail(n, f + "." + key, "missing");
    p.zMin = r.nonNegative(n["z_min"], f + ".z_min");
    p.zMax = r.positive(n["z_max"], f + ".z_max");
    p.climbToMax = n["climb_to_max"] ? r.nonNegative(n["climb_to_max"], f + ".climb_to_max") : p.zMin;
    p.minRange = n["min_range"] ? r.nonNegative(n["min_range"], f + ".min_range") : 0.0;
    if (n["climb_to_levels"])
        p.climbToLevels = static_cast<int>(r.integer(n["climb_to_levels"], f + ".climb_to_levels", 1, 100));
    if (n["dive_to_levels"])
        p.diveToLevels = static_cast<int>(r.integer(n["dive_to_levels"], f + ".dive_to_levels", 1, 100));
    if (n["step"])
        p.step = r.positive(n["step"], f + ".step");
    if (n["selection"])
        p.selection = diveProfileSelectionFromString(
            r.oneOf(n["selection"], f + ".selection", {"fastest", "deepest_under_limit"}));
    if (n["max_time_factor"])
        p.maxTimeFactor = r.finite(n["max_time_factor"], f + ".max_time_factor");
    if (n["max_time"])
        p.maxTime = r.positive(n["max_time"], f + ".max_time");
    if (n["clearance"])
        p.clearance = r.nonNegative(n["clearance"], f + ".clearance");
    if (n["threads"])
        d.threads = static_cast<unsigned>(r.integer(n["threads"], f + ".threads", 0, 1024));
    try
    {
        makeDiveProfiles(p);
    }
    catch (const Error &e)
    {
        r.fail(n, f, e.what());
    }
    if (n["bathymetry"])
    {
        const YAML::Node &b = n["bathymetry"];
        const std::string g = f + ".bathymetry";
        r.checkMap(b, g, {"type", "depth", "file", "variable"});
        if (!b["type"])
            r.fail(b, g + ".type", "missing (constant or netcdf)");
        d.bathymetryType = r.oneOf(b["type"], g + ".type", {"constant", "netcdf"});
        if (d.bathymetryType == "constant")
        {
            if (!b["depth"])
                r.fail(b, g + ".depth", "missing: the seafloor depth");
            d.bathymetryDepth = r.positive(b["depth"], g + ".depth");
        }
        else
        {
            if (!b["file"])
                r.fail(b, g + ".file", "missing: the NetCDF file with the seafloor depth");
            d.bathymetryFile = joinPath(r.dir(), r.text(b["file"], g + ".file"));
            if (!fileExists(d.bathymetryFile))
                r.fail(b["file"], g + ".file", "cannot open '" + d.bathymetryFile + "'");
            if (b["variable"])
                d.bathymetryVariable = r.text(b["variable"], g + ".variable");
        }
    }
}

void readForbidden(const Reader &r, const YAML::Node &n, MissionSpec &m);

void readPlanner(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "planner";
    r.checkMap(n, f,
               {"name", "grid_size", "sectors", "smoothing", "refinement", "time_limit", "horizon", "goal_tolerance",
                "parameters"});
    PlannerSpec &p = m.planner;
    if (n["name"])
    {
        const std::string name = r.text(n["name"], f + ".name");
        const PlannerEntry *entry = findPlanner(name);
        if (!entry)
            r.fail(n["name"], f + ".name", "unknown planner '" + name + "' (expected one of " + plannerNameList() + ")");
        p.name = entry->name;
    }
    if (n["grid_size"])
        p.gridSize = r.positive(n["grid_size"], f + ".grid_size");
    if (n["sectors"])
        p.sectors = static_cast<int>(r.integer(n["sectors"], f + ".sectors", 1, 5));
    if (n["smoothing"])
        p.smoothing = r.boolean(n["smoothing"], f + ".smoothing");
    if (n["refinement"])
        p.refinement = r.boolean(n["refinement"], f + ".refinement");
    if (n["time_limit"])
        p.timeLimit = r.nonNegative(n["time_limit"], f + ".time_limit");
    if (n["horizon"])
        p.horizon = r.positive(n["horizon"], f + ".horizon");
    if (n["goal_tolerance"])
        p.goalTolerance = r.nonNegative(n["goal_tolerance"], f + ".goal_tolerance");
    if (n["parameters"])
    {
        // Names and values are checked against the planner's declared parameters before planning (Planning.cpp).
        const YAML::Node &params = n["parameters"];
        if (!params.IsMap())
            r.fail(params, f + ".parameters", "expected a map of planner parameter names to values");
        for (auto it = params.begin(); it != params.end(); ++it)
        {
            const std::string key = it->first.Scalar();
            const std::string field = f + ".parameters." + key;
            if (!it->second.IsScalar())
                r.fail(it->second, field, "expected a value (number or boolean)");
            if (p.parameters.count(key))
                r.fail(it->first, field, "given twice");
            p.parameters[key] = it->second.Scalar();
            p.parameterMarks[key] = {r.file(), r.line(it->first)};
        }
    }
}

void readOutputs(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "outputs";
    r.checkMap(n, f, {"directory", "files", "goto_number", "goto_include_start", "prefix", "map_time"});
    OutputSpec &o = m.outputs;
    if (n["directory"])
        o.directory = joinPath(r.dir(), r.text(n["directory"], f + ".directory"));
    if (n["files"])
    {
        const YAML::Node &l = n["files"];
        if (!l.IsSequence())
            r.fail(l, f + ".files", "expected a list such as [csv, geojson, goto, summary, map]");
        o.files.clear();
        std::set<std::string> formats;
        for (const OutputFormat &format : outputFormats())
            formats.insert(format.name);
        for (std::size_t i = 0; i < l.size(); ++i)
        {
            const std::string kind = r.oneOf(l[i], f + ".files[" + std::to_string(i) + "]", formats);
            if (kind == "goto" && !m.projection.set && m.current.type != "netcdf")
                r.fail(l[i], f + ".files[" + std::to_string(i) + "]",
                       "a goto list needs longitudes and latitudes: give a 'projection' in the mission");
            o.files.push_back(kind);
        }
    }
    if (n["goto_number"])
        o.gotoNumber = static_cast<int>(r.integer(n["goto_number"], f + ".goto_number", 0, 99));
    if (n["goto_include_start"])
        o.gotoIncludeStart = r.boolean(n["goto_include_start"], f + ".goto_include_start");
    if (n["prefix"])
    {
        o.prefix = r.text(n["prefix"], f + ".prefix");
        if (o.prefix.empty() || o.prefix.find_first_of("/\\") != std::string::npos || o.prefix == "." ||
            o.prefix == ".." || o.prefix.find_first_of(std::string("\0:*?\"<>|", 8)) != std::string::npos)
            r.fail(n["prefix"], f + ".prefix",
                   "expected a plain file-name part (letters, digits, '_', '-', '.'; no '/' or '..'), got '" +
                       o.prefix + "'");
    }
    if (n["map_time"])
        o.mapTime = r.time(n["map_time"], f + ".map_time", m);
}

// --- GeoJSON forbidden regions ---------------------------------------------------------------------------------

void readGeoJson(const Reader &r, const YAML::Node &where, MissionSpec &m)
{
    const std::string &path = m.forbidden.geojson;
    YAML::Node doc;
    try
    {
        doc = YAML::LoadFile(path);
    }
    catch (const YAML::BadFile &)
    {
        r.fail(where, "forbidden.geojson", "cannot open '" + path + "'");
    }
    catch (const YAML::ParserException &e)
    {
        throw Error(path + ":" + std::to_string(e.mark.line + 1) + ": not valid GeoJSON: " + e.msg);
    }
    const Reader g(path, r.dir());
    if (!doc.IsMap() || !doc["type"] || doc["type"].Scalar() != "FeatureCollection" || !doc["features"] ||
        !doc["features"].IsSequence())
        g.fail(doc, "type", "expected a GeoJSON FeatureCollection with a 'features' list");
    const bool geo = m.forbidden.geojsonGeographic;
    if (geo && !m.projection.set && m.current.type != "netcdf")
        r.fail(where, "forbidden.geojson", "GeoJSON coordinates are lon/lat: give a 'projection' in the mission");
    const YAML::Node &features = doc["features"];
    for (std::size_t i = 0; i < features.size(); ++i)
    {
        const YAML::Node &ft = features[i];
        const std::string fld = "features[" + std::to_string(i) + "]";
        if (!ft.IsMap() || !ft["geometry"] || !ft["geometry"].IsMap() || !ft["geometry"]["type"])
            g.fail(ft, fld, "expected a Feature with a geometry");
        const YAML::Node &geom = ft["geometry"];
        const std::string type = geom["type"].Scalar();
        if (type != "Polygon" && type != "MultiPolygon")
            g.fail(geom, fld + ".geometry.type", "only Polygon and MultiPolygon are forbidden regions (got " + type + ")");
        YAML::Node props = ft["properties"];
        std::string name = "feature " + std::to_string(i), kind = "island";
        if (props && props.IsMap())
        {
            g.checkMap(props, fld + ".properties",
                       {"name", "kind", "windows", "max_submerged_time", "drift", "t_ref", "carried"});
            if (props["name"])
                name = g.text(props["name"], fld + ".properties.name");
            if (props["kind"])
                kind = g.oneOf(props["kind"], fld + ".properties.kind",
                               {"island", "land", "restricted area", "closure", "ice"});
        }
        std::vector<YAML::Node> polys;
        if (type == "Polygon")
            polys.push_back(geom["coordinates"]);
        else if (geom["coordinates"].IsSequence())
            for (std::size_t k = 0; k < geom["coordinates"].size(); ++k)
                polys.push_back(geom["coordinates"][k]);
        for (std::size_t k = 0; k < polys.size(); ++k)
        {
            const YAML::Node &rings = polys[k];
            const std::string pf = fld + ".geometry.coordinates" + (type == "Polygon" ? "" : "[" + std::to_string(k) + "]");
            if (!rings.IsSequence() || rings.size() < 1)
                g.fail(rings, pf, "expected a list of linear rings");
            PolygonSpec poly;
            poly.name = polys.size() > 1 ? name + " #" + std::to_string(k + 1) : name;
            poly.geographic = geo;
            poly.mark = {path, g.line(rings)};
            poly.points = g.ring(rings[0], pf + "[0]");
            for (std::size_t h = 1; h < rings.size(); ++h)
                poly.holes.push_back(g.ring(rings[h], pf + "[" + std::to_string(h) + "]"));
            if (kind == "closure")
            {
                TimeWindowSpec tw;
                tw.polygon = poly;
                if (!props["windows"] || !props["windows"].IsSequence())
                    g.fail(ft, fld + ".properties.windows", "a closure needs windows: [[from, to], ...]");
                for (std::size_t w = 0; w < props["windows"].size(); ++w)
                    tw.windows.push_back(
                        g.pair(props["windows"][w], fld + ".properties.windows[" + std::to_string(w) + "]"));
                m.forbidden.timeWindows.push_back(tw);
            }
            else if (kind == "ice")
            {
                IceSpec ice;
                ice.polygon = poly;
                if (!props["max_submerged_time"])
                    g.fail(ft, fld + ".properties.max_submerged_time", "an ice zone needs max_submerged_time");
                ice.maxSubmergedTime = g.nonNegative(props["max_submerged_time"], fld + ".properties.max_submerged_time");
                if (props["t_ref"])
                    ice.tRef = g.finite(props["t_ref"], fld + ".properties.t_ref");
                if (props["drift"])
                    std::tie(ice.vx, ice.vy) = g.pair(props["drift"], fld + ".properties.drift");
                if (props["carried"])
                    ice.carried = g.boolean(props["carried"], fld + ".properties.carried");
                m.forbidden.ice.push_back(ice);
            }
            else
                m.forbidden.obstacles.push_back({poly, kind});
        }
    }
}

void readForbidden(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "forbidden";
    r.checkMap(n, f, {"obstacles", "time_windows", "ice", "geojson", "geojson_coordinates"});
    auto list = [&](const char *key) -> YAML::Node {
        const YAML::Node &l = n[key];
        if (l && !l.IsSequence())
            r.fail(l, f + "." + key, "expected a list");
        return l;
    };
    if (const YAML::Node l = list("obstacles"))
        for (std::size_t i = 0; i < l.size(); ++i)
        {
            const std::string g = f + ".obstacles[" + std::to_string(i) + "]";
            r.checkMap(l[i], g, {"name", "kind", "points", "lonlat", "holes"});
            ObstacleSpec o;
            readPolygon(r, l[i], g, o.polygon, m);
            if (o.polygon.name.empty())
                o.polygon.name = "obstacle " + std::to_string(i + 1);
            if (l[i]["kind"])
                o.kind = r.oneOf(l[i]["kind"], g + ".kind", {"island", "land", "restricted area"});
            m.forbidden.obstacles.push_back(o);
        }
    if (const YAML::Node l = list("time_windows"))
        for (std::size_t i = 0; i < l.size(); ++i)
        {
            const std::string g = f + ".time_windows[" + std::to_string(i) + "]";
            r.checkMap(l[i], g, {"name", "points", "lonlat", "holes", "windows"});
            TimeWindowSpec tw;
            readPolygon(r, l[i], g, tw.polygon, m);
            if (tw.polygon.name.empty())
                tw.polygon.name = "closure " + std::to_string(i + 1);
            const YAML::Node &w = l[i]["windows"];
            if (!w || !w.IsSequence() || w.size() == 0)
                r.fail(w ? w : l[i], g + ".windows", "expected a list of [from, to] time intervals");
            for (std::size_t k = 0; k < w.size(); ++k)
            {
                const std::string wf = g + ".windows[" + std::to_string(k) + "]";
                if (!w[k].IsSequence() || w[k].size() != 2)
                    r.fail(w[k], wf, "expected [from, to]");
                const double a = r.time(w[k][0], wf + "[0]", m), b = r.time(w[k][1], wf + "[1]", m);
                if (!(b >= a))
                    r.fail(w[k], wf, "'to' must not be before 'from'");
                tw.windows.push_back({a, b});
            }
            m.forbidden.timeWindows.push_back(tw);
        }
    if (const YAML::Node l = list("ice"))
        for (std::size_t i = 0; i < l.size(); ++i)
        {
            const std::string g = f + ".ice[" + std::to_string(i) + "]";
            r.checkMap(l[i], g, {"name", "points", "lonlat", "holes", "t_ref", "drift", "carried", "max_submerged_time"});
            IceSpec ice;
            readPolygon(r, l[i], g, ice.polygon, m);
            if (ice.polygon.name.empty())
                ice.polygon.name = "ice " + std::to_string(i + 1);
            if (!l[i]["max_submerged_time"])
                r.fail(l[i], g + ".max_submerged_time", "missing: the longest continuous stay under the ice");
            ice.maxSubmergedTime = r.nonNegative(l[i]["max_submerged_time"], g + ".max_submerged_time");
            if (l[i]["t_ref"])
                ice.tRef = r.time(l[i]["t_ref"], g + ".t_ref", m);
            if (l[i]["drift"] && l[i]["carried"])
                r.fail(l[i], g, "give either drift [vx, vy] or carried: true");
            if (l[i]["drift"])
                std::tie(ice.vx, ice.vy) = r.pair(l[i]["drift"], g + ".drift");
            if (l[i]["carried"])
                ice.carried = r.boolean(l[i]["carried"], g + ".carried");
            m.forbidden.ice.push_back(ice);
        }
    if (n["geojson_coordinates"])
        m.forbidden.geojsonGeographic =
            r.oneOf(n["geojson_coordinates"], f + ".geojson_coordinates", {"geographic", "local"}) == "geographic";
    if (n["geojson"])
    {
        m.forbidden.geojson = joinPath(r.dir(), r.text(n["geojson"], f + ".geojson"));
        readGeoJson(r, n["geojson"], m);
    }
}

MissionSpec readMission(const YAML::Node &root, const Reader &r)
{
    MissionSpec m;
    m.file = r.file();
    m.directory = r.dir();
    if (!root.IsDefined() || root.IsNull())
        throw Error(r.file() + ": the mission file is empty");
    r.checkMap(root, "",
               {"name", "units", "epoch", "projection", "current", "region", "start", "goal", "departure", "vehicle",
                "travel_time", "dive_profile", "forbidden", "planner", "outputs", "speeds"});
    if (root["name"])
        m.name = r.text(root["name"], "name");
    if (root["units"])
    {
        r.checkMap(root["units"], "units", {"length_m", "time_s"});
        if (root["units"]["length_m"])
            m.lengthUnitMetres = r.positive(root["units"]["length_m"], "units.length_m");
        if (root["units"]["time_s"])
            m.timeUnitSeconds = r.positive(root["units"]["time_s"], "units.time_s");
    }
    if (root["epoch"])
    {
        try
        {
            m.epoch = parseIsoTime(r.text(root["epoch"], "epoch"));
        }
        catch (const Error &e)
        {
            r.fail(root["epoch"], "epoch", e.what());
        }
    }
    if (root["projection"])
    {
        const YAML::Node &p = root["projection"];
        r.checkMap(p, "projection", {"lon0", "lat0"});
        if (!p["lon0"] || !p["lat0"])
            r.fail(p, "projection", "lon0 and lat0 (the reference point) are required");
        m.projection.set = true;
        m.projection.lon0 = r.finite(p["lon0"], "projection.lon0");
        m.projection.lat0 = r.finite(p["lat0"], "projection.lat0");
        if (std::abs(m.projection.lat0) >= 90)
            r.fail(p["lat0"], "projection.lat0", "must be within (-90, 90)");
    }
    if (!root["current"])
        r.fail(root, "current", "missing: the current source (type: meandering_jet | uniform | ... | netcdf)");
    readCurrent(r, root["current"], m);
    if (m.current.type == "netcdf" && root["units"])
        r.fail(root["units"], "units", "a NetCDF forecast is planned in metres and seconds: remove 'units'");
    if (m.current.type == "netcdf" && root["epoch"])
        r.fail(root["epoch"], "epoch", "the NetCDF forecast defines the time origin (its first time): remove 'epoch'");
    if (root["region"])
        readRegion(r, root["region"], m);
    else if (m.current.type != "netcdf")
        r.fail(root, "region", "missing: an analytic current needs the planning region");
    for (const char *key : {"start", "goal"})
    {
        if (!root[key])
            r.fail(root, key, "missing");
        readPoint(r, root[key], key, std::string(key) == "start" ? m.start : m.goal, m);
    }
    if (root["departure"])
        readDeparture(r, root["departure"], m);
    if (root["vehicle"])
    {
        const YAML::Node &v = root["vehicle"];
        r.checkMap(v, "vehicle", {"speed", "depth"});
        if (v["speed"])
            m.vehicle.speed = r.positive(v["speed"], "vehicle.speed");
        if (v["depth"])
            m.vehicle.depth = r.nonNegative(v["depth"], "vehicle.depth");
    }
    if (root["travel_time"])
    {
        const YAML::Node &t = root["travel_time"];
        r.checkMap(t, "travel_time", {"h", "h_min", "h_max", "eps", "tau"});
        if (t["h"])
            m.travel.h = r.positive(t["h"], "travel_time.h");
        if (t["h_min"])
            m.travel.hMin = r.positive(t["h_min"], "travel_time.h_min");
        if (t["h_max"])
            m.travel.hMax = r.positive(t["h_max"], "travel_time.h_max");
        if (t["eps"])
            m.travel.eps = r.positive(t["eps"], "travel_time.eps");
        if (t["tau"])
            m.travel.tau = r.positive(t["tau"], "travel_time.tau");
    }
    // eps is absolute in the field's time unit: 1 s for forecasts in seconds, unless given.
    if (m.current.type == "netcdf" && !(root["travel_time"] && root["travel_time"]["eps"]))
        m.travel.eps = 1.0;
    m.travel.speed = m.vehicle.speed;
    m.travel.depth = m.vehicle.depth;
    try
    {
        TravelTimeParams check = m.travel;
        if (!(check.hMin > 0.0) || !(check.hMax >= check.hMin) || !(check.h >= check.hMin) || check.hMax > 1.0 ||
            !(check.tau > 0.0 && check.tau <= 1.0))
            throw Error("need 0 < h_min <= h, h_min <= h_max <= 1 and 0 < tau <= 1");
    }
    catch (const Error &e)
    {
        r.fail(root["travel_time"] ? root["travel_time"] : root, "travel_time", e.what());
    }
    if (root["dive_profile"])
        readDive(r, root["dive_profile"], m);
    if (root["forbidden"])
        readForbidden(r, root["forbidden"], m);
    if (root["planner"])
        readPlanner(r, root["planner"], m);
    if (root["outputs"])
        readOutputs(r, root["outputs"], m);
    else
        m.outputs.directory = joinPath(r.dir(), ".");
    if ((!root["outputs"] || !root["outputs"]["files"]) && !m.projection.set && m.current.type != "netcdf")
        m.outputs.files = {"csv", "geojson", "summary"};  // no lon/lat: no goto list by default
    if (root["speeds"])
    {
        const YAML::Node &s = root["speeds"];
        if (!s.IsSequence() || s.size() == 0)
            r.fail(s, "speeds", "expected a list of vehicle speeds, e.g. [0.25, 0.30, 0.35]");
        for (std::size_t i = 0; i < s.size(); ++i)
            m.speeds.push_back(r.positive(s[i], "speeds[" + std::to_string(i) + "]"));
    }
    // Cross-field checks that can be made without building the field.
    if (m.region.set && !m.region.geographic)
    {
        for (const auto *p : {&m.start, &m.goal})
            if (!p->geographic && (p->x < m.region.xMin || p->x > m.region.xMax || p->y < m.region.yMin ||
                                   p->y > m.region.yMax))
            {
                const char *key = p == &m.start ? "start" : "goal";
                r.fail(root[key], key, "lies outside the region");
            }
    }
    return m;
}
}  // namespace

MissionSpec parseMission(const std::string &yamlText, const std::string &file, const std::string &directory)
{
    YAML::Node root;
    try
    {
        root = YAML::Load(yamlText);
    }
    catch (const YAML::ParserException &e)
    {
        throw Error(file + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
    }
    return readMission(root, Reader(file, directory));
}

MissionSpec loadMission(const std::string &path)
{
    std::ifstream in(path);
    if (!in)
        throw Error("cannot read mission file '" + path + "'");
    std::ostringstream s;
    s << in.rdbuf();
    const auto slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash);
    return parseMission(s.str(), path, dir);
}

MissionSpec defaultGulfStreamMission()
{
    MissionSpec m;
    m.file = "<built-in>";
    m.name = "gulf_stream";
    m.current.type = "meandering_jet";
    m.region.set = true;
    m.region.xMin = 0;
    m.region.xMax = 10;
    m.region.yMin = -4;
    m.region.yMax = 4;
    // South of the jet to north of it.
    m.start.x = 1.0;
    m.start.y = -3.0;
    m.goal.x = 8.0;
    m.goal.y = 3.0;
    m.vehicle.speed = 0.5;
    m.travel.speed = 0.5;
    m.planner.horizon = 60.0;
    m.planner.goalTolerance = 1e-3;
    m.outputs.files = {"summary", "path", "csv", "geojson", "map"};
    return m;
}
}  // namespace ompl_glider
