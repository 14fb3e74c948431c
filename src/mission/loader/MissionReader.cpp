// The mission loader's YAML reader: accessors that name file:line and the dotted field in every error, and the
// readers of points and polygons shared by the sections.
#include <cmath>
#include <fstream>

#include <yaml-cpp/depthguard.h>

#include "MissionReader.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/SettingRanges.h"

namespace ompl_glider::mission_loader
{
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

std::string yamlErrorMessage(const std::string &file, const YAML::ParserException &e, const std::string &what)
{
    const std::string where = file + ":" + std::to_string(e.mark.line + 1) + ": ";
    if (dynamic_cast<const YAML::DeepRecursion *>(&e))
        return where + what + ": lists or mappings nested more than 500 levels deep";
    return where + what + ": " + e.msg;
}

void Reader::fail(const YAML::Node &node, const std::string &field, const std::string &what) const
{
    // an empty value ("start:" and nothing) carries the mark of the next token, lines below: its key's line
    const auto key = keyLines_.find(field);
    if (node.IsNull() && key != keyLines_.end())
        failAt(key->second, field, what);
    throw Error(where(node) + "field '" + field + "': " + what);
}

void Reader::failAt(int line, const std::string &field, const std::string &what) const
{
    throw Error(file_ + ":" + std::to_string(line) + ": field '" + field + "': " + what);
}

std::string Reader::where(const YAML::Node &node) const
{
    const YAML::Mark m = node.Mark();
    if (m.line < 0)
        return file_ + ": ";
    return file_ + ":" + std::to_string(m.line + 1) + ": ";
}

void Reader::checkMap(const YAML::Node &node, const std::string &path, const std::set<std::string> &allowed) const
{
    if (!node.IsMap())
        fail(node, path,
             node.IsNull() ? "has no value; expected a mapping (key: value lines)"
                           : "expected a mapping (key: value lines)");
    std::set<std::string> seen;
    auto allowedList = [&allowed] {
        std::string list;
        for (const auto &a : allowed)
            list += (list.empty() ? "" : ", ") + a;
        return list;
    };
    for (auto it = node.begin(); it != node.end(); ++it)
    {
        if (!it->first.IsScalar())
            throw Error(where(it->first) + (path.empty() ? std::string("a key") : "a key in '" + path + "'") + " is " +
                        (it->first.IsMap()        ? "a mapping"
                         : it->first.IsSequence() ? "a list"
                                                  : "empty") +
                        ": keys are plain names (allowed here: " + allowedList() + ")");
        const std::string key = it->first.Scalar();
        keyLines_[sub(path, key)] = it->first.Mark().line + 1;
        if (!seen.insert(key).second)
            throw Error(where(it->first) + "field '" + sub(path, key) + "' is given twice");
        if (!allowed.count(key))
            throw Error(where(it->first) + "unknown field '" + sub(path, key) + "' (allowed here: " + allowedList() +
                        ")");
    }
}

double Reader::number(const YAML::Node &node, const std::string &field) const
{
    remember(node, field);
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

double Reader::finite(const YAML::Node &node, const std::string &field) const
{
    const double v = number(node, field);
    if (!std::isfinite(v))
        fail(node, field, "expected a finite number");
    return v;
}

double Reader::positive(const YAML::Node &node, const std::string &field) const
{
    const double v = finite(node, field);
    if (!(v > 0))
        fail(node, field, "expected a number > 0, got " + node.Scalar());
    if (!std::isnormal(v)) // a denormal (1e-310): divisions by it overflow
        fail(node, field,
             "expected a number > 0, got " + node.Scalar() +
                 ", below the smallest normal double (2.2e-308): too small to compute with");
    return v;
}

double Reader::nonNegative(const YAML::Node &node, const std::string &field) const
{
    const double v = number(node, field);
    if (!(v >= 0) || !std::isfinite(v))
        fail(node, field, "expected a finite number >= 0, got " + node.Scalar());
    return v;
}

long Reader::integer(const YAML::Node &node, const std::string &field, long lo, long hi) const
{
    remember(node, field);
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
        fail(node, field,
             "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " + std::to_string(v));
    return v;
}

bool Reader::boolean(const YAML::Node &node, const std::string &field) const
{
    remember(node, field);
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

std::string Reader::text(const YAML::Node &node, const std::string &field) const
{
    remember(node, field);
    if (!node.IsScalar() || node.Scalar().empty())
        fail(node, field, "expected a non-empty text");
    return node.Scalar();
}

std::string Reader::oneOf(const YAML::Node &node, const std::string &field, const std::set<std::string> &values) const
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

double Reader::time(const YAML::Node &node, const std::string &field, const MissionSpec &m) const
{
    remember(node, field);
    if (!node.IsScalar())
        fail(node, field, "expected a time (a number, or an ISO 8601 date when the mission has an epoch)");
    try
    {
        return finite(node, field);
    }
    catch (const Error &)
    {
        try
        {
            return m.timeOf(node.Scalar());
        }
        catch (const Error &e)
        {
            fail(node, field, e.what());
        }
    }
}

double Reader::setting(const YAML::Node &node, const std::string &field, const MissionSpec &m) const
{
    const SettingRange &s = settingRange(field);
    if (s.value == SettingValue::Length || s.value == SettingValue::Depth || s.value == SettingValue::Duration)
    {
        if (!node.IsScalar())
            fail(node, field,
                 s.value == SettingValue::Duration
                     ? "expected a duration: a number in the mission's time unit, or e.g. '6 h', '1 d'"
                     : "expected a length: a number, or e.g. '500 m', '2 km'");
        remember(node, field);
        try
        {
            return settingFromText(field, node.Scalar(), m);
        }
        catch (const Error &e)
        {
            fail(node, field, e.what());
        }
    }
    const double v = number(node, field);
    try
    {
        return checkSetting(field, v, node.Scalar());
    }
    catch (const Error &e)
    {
        fail(node, field, e.what());
    }
}

std::pair<double, double> Reader::pair(const YAML::Node &node, const std::string &field) const
{
    if (!node.IsSequence() || node.size() != 2)
        fail(node, field, "expected a pair [a, b]");
    return {finite(node[0], field + "[0]"), finite(node[1], field + "[1]")};
}

std::vector<std::pair<double, double>> Reader::ring(const YAML::Node &node, const std::string &field) const
{
    if (!node.IsSequence() || node.size() < 3)
        fail(node, field, "expected a list of at least 3 points [a, b]");
    std::vector<std::pair<double, double>> out;
    for (std::size_t i = 0; i < node.size(); ++i)
        out.push_back(pair(node[i], field + "[" + std::to_string(i) + "]"));
    return out;
}

void readPoint(const Reader &r, const YAML::Node &n, const std::string &field, PointSpec &p, const MissionSpec &m,
               const std::set<std::string> &extraKeys)
{
    std::set<std::string> keys{"x", "y", "lon", "lat"};
    keys.insert(extraKeys.begin(), extraKeys.end());
    if (field == "goal")
        keys.insert("window"); // goal.window: readGoalWindow()
    r.checkMap(n, field, keys);
    const bool xy = n["x"] || n["y"], geo = n["lon"] || n["lat"];
    if (xy == geo)
        r.fail(n, field, "give either x and y, or lon and lat");
    if (xy)
    {
        if (!n["x"] || !n["y"])
            r.fail(n, field, "both x and y are required");
        p.geographic = false;
        p.xy.x = r.finite(n["x"], field + ".x");
        p.xy.y = r.finite(n["y"], field + ".y");
    }
    else
    {
        if (!n["lon"] || !n["lat"])
            r.fail(n, field, "both lon and lat are required");
        if (!m.projection.set && !m.current.isForecast())
            r.fail(n, field, "lon/lat needs a 'projection' (lon0, lat0) in the mission");
        p.geographic = true;
        p.lonLat.lon = r.finite(n["lon"], field + ".lon");
        p.lonLat.lat = r.finite(n["lat"], field + ".lat");
        if (std::abs(p.lonLat.lat) > 90)
            r.fail(n["lat"], field + ".lat", "latitude must be within [-90, 90]");
        if (p.lonLat.lon < -180.0 || p.lonLat.lon > 360.0)
            r.fail(n["lon"], field + ".lon", "longitude must be within -180..180 or 0..360");
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
    if (geo && !m.projection.set && !m.current.isForecast())
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

/// @brief The optional key `threads` of @p n (path @p f + ".threads" in messages): an integer 0 .. 1024 into
/// @p threads when given (0: all cores); @p threads keeps its value otherwise.
void readThreads(const Reader &r, const YAML::Node &n, const std::string &f, unsigned &threads)
{
    if (n["threads"])
        threads = static_cast<unsigned>(r.integer(n["threads"], f + ".threads", 0, 1024));
}

/// A duration: a number in field units, or a text "<number> s|min|h|d" converted with units.time_s.
double duration(const Reader &r, const YAML::Node &n, const std::string &f, const MissionSpec &m)
{
    if (!n.IsScalar())
        r.fail(n, f, "expected a duration: a number in the mission's time unit, or e.g. '1 h', '30 min', '2 d'");
    r.mark(n, f);
    try
    {
        return parseDuration(n.Scalar(), m.timeUnitSeconds, m.hasTimeUnit());
    }
    catch (const Error &e)
    {
        r.fail(n, f, e.what());
    }
}
} // namespace ompl_glider::mission_loader
