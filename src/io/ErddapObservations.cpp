/// @file ErddapObservations.cpp
/// @brief A glider deployment's DAC and fixes from an ERDDAP tabledap answer (the IOOS Glider DAC's ERDDAP):
/// .csvp, .csv or .ncCF, fetched through the project's HTTP layer (HttpMirror.h) (ObservationReaders.h).
///
/// The answer's rows hold the profiles' `time, latitude, longitude` (fixes) and their depth-averaged current
/// `time_uv, lat_uv, lon_uv, u, v` (with `profile_id`, `u_qc`, `v_qc` when asked for). ERDDAP repeats a profile's
/// values on every row of the profile: a profile's DAC is taken from its first row. A profile whose DAC is a fill
/// value (empty, NaN, -999) or flagged 3, 4 or 9 is rejected and counted once, as an IOOS profile file would be.
///
/// No cache: an answer is real-time data that grows with every surfacing, and the same URL (a `time>=` constraint)
/// asked again must give the newest fixes, never a stored answer.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include "CsvCells.h"
#include "GdalModule.h"
#include "HttpMirror.h"
#include "GriddedDataset.h"
#include "NumberText.h"
#include "ObservationReaders.h"
#include "RemoteRecord.h"
#include "TextUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/MemoryDataset.h"
#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/io/Time.h"

namespace ompl_glider::observations_detail
{
namespace
{
/// What an answer is, from the URL's file type.
enum class Answer
{
    Csvp, ///< CSV, one header line whose names carry their units in parentheses: `u (m s-1)`
    Csv,  ///< CSV, a line of names, then a line of units
    NcCf  ///< NetCDF, CF discrete sampling geometries (a contiguous ragged or a flat layout)
};

const char *const kRequired[] = {"time", "latitude", "longitude", "time_uv", "lat_uv", "lon_uv", "u", "v"};
const char *const kFlags[] = {"u_qc", "v_qc", "time_uv_qc", "lat_uv_qc", "lon_uv_qc"};

/// One row of an answer: a profile's fix and its DAC.
struct Row
{
    double time{NAN}, lat{NAN}, lon{NAN};
    double timeUv{NAN}, latUv{NAN}, lonUv{NAN}, u{NAN}, v{NAN};
    std::string profile;                               // profile_id ("" when not asked for)
    std::vector<std::pair<std::string, double>> flags; // the *_qc columns asked for
};

/// The path of @p url without its query or fragment.
std::string pathOf(const std::string &url)
{
    return url.substr(0, url.find_first_of("?#"));
}

Answer answerOf(const std::string &url, const std::string &who)
{
    const std::string path = pathOf(url);
    const std::size_t slash = path.rfind('/'), dot = path.rfind('.');
    const std::string type =
        dot == std::string::npos || (slash != std::string::npos && dot < slash) ? std::string() : path.substr(dot);
    static const std::map<std::string, Answer> answers = {
        {".csvp", Answer::Csvp}, {".csv", Answer::Csv}, {".nccf", Answer::NcCf}};
    if (const auto it = answers.find(text::lower(type)); it != answers.end())
        return it->second;
    throw Error(who + ": not an ERDDAP tabledap answer this reader knows (the file type " +
                (type.empty() ? std::string("is missing") : "'" + type + "'") +
                "; expected .csvp, .csv or .ncCF, e.g. https://gliders.ioos.us/erddap/tabledap/<dataset>.csvp?time,"
                "latitude,longitude,profile_id,time_uv,lat_uv,lon_uv,u,v,u_qc,v_qc&time>=2026-03-15T00:00:00Z)");
}

/// The glider of an IOOS Glider DAC dataset id ("ru29-20260315T0000", "ru29-20260315T0000-delayed" -> "ru29"); the
/// id itself when it is not of that form.
std::string platformOf(const std::string &url)
{
    std::string id = pathOf(url);
    id = id.substr(id.rfind('/') + 1);
    id = id.substr(0, id.rfind('.'));
    const std::string delayed = "-delayed";
    if (id.size() > delayed.size() && id.compare(id.size() - delayed.size(), delayed.size(), delayed) == 0)
        id.resize(id.size() - delayed.size());
    // "-YYYYMMDDTHHMM": the deployment's start
    if (id.size() > 14 && id[id.size() - 14] == '-' && id[id.size() - 5] == 'T')
    {
        const std::string stamp = id.substr(id.size() - 13);
        const bool digits = std::all_of(stamp.begin(), stamp.end(),
                                        [](char c) { return c == 'T' || std::isdigit(static_cast<unsigned char>(c)); });
        if (digits)
            id.resize(id.size() - 14);
    }
    return id;
}

bool looksHtml(const std::string &body)
{
    const std::string head = text::lower(body.substr(0, 1024));
    return head.find("<html") != std::string::npos || head.find("<!doctype html") != std::string::npos;
}

/// An HTML page's <title>, on one line; empty without one.
std::string htmlTitle(const std::string &body)
{
    const std::string lower = text::lower(body);
    const std::size_t open = lower.find("<title"), begin = lower.find('>', open);
    const std::size_t end = lower.find("</title>", begin);
    if (open == std::string::npos || begin == std::string::npos || end == std::string::npos)
        return "";
    return text::trim(text::oneLine(body.substr(begin + 1, std::min<std::size_t>(end - begin - 1, 200))));
}

/// ERDDAP's message in its error answer `Error {\n code=404;\n message="...";\n}`; empty when @p body is not one.
std::string erddapMessage(const std::string &body)
{
    const std::size_t error = body.find("Error {");
    const std::size_t key = body.find("message", error);
    if (error == std::string::npos || key == std::string::npos)
        return "";
    std::size_t at = body.find_first_not_of(" \t", key + 7);
    if (at == std::string::npos || body[at] != '=')
        return "";
    at = body.find_first_not_of(" \t", at + 1);
    std::string message;
    if (at != std::string::npos && body[at] == '"')
        for (std::size_t i = at + 1; i < body.size() && body[i] != '"'; ++i)
            message += body[i] == '\\' && i + 1 < body.size() ? body[++i] : body[i];
    else if (at != std::string::npos)
        message = body.substr(at, body.find_first_of(";\n", at) - at);
    return text::trim(text::oneLine(message));
}

/// What a server's answer says, for a message: ERDDAP's message, an HTML page's title, or the text's first line.
std::string serverWords(const std::string &body)
{
    if (const std::string m = erddapMessage(body); !m.empty())
        return m;
    if (looksHtml(body))
    {
        const std::string title = htmlTitle(body);
        return "an HTML page" + (title.empty() ? std::string() : " ('" + title + "')");
    }
    const std::string first = text::trim(text::oneLine(body.substr(0, body.find('\n')).substr(0, 200)));
    return first.empty() ? "" : "'" + first + "'";
}

/// The answer's bytes. @throws Error naming the URL with what the server said, or httpGet()'s for the network.
std::string fetch(const std::string &url, const std::string &source)
{
    const std::size_t record = remote_detail::newFetchRecord(source);
    remote_detail::updateFetchRecord(record, [](RemoteFetch &f) { f.kind = RemoteKind::Erddap; });
    const std::string who = "ERDDAP '" + source + "'";
    std::string body;
    gridded_detail::HttpFailure failure;
    bool found = false;
    try
    {
        found = gdal_detail::gdalPart().httpGet(url, record, "ERDDAP", source, body, &failure, nullptr);
    }
    catch (const Error &)
    {
        const std::string said = serverWords(failure.body);
        if (failure.status == 0 || said.empty())
            throw; // the network, a time limit, a stop: httpGet's message names the URL
        throw Error(who + ": the server answered HTTP " + std::to_string(failure.status) + ": " + said);
    }
    if (!found)
    {
        const std::string said = serverWords(failure.body);
        throw Error(who + ": the server answered HTTP 404: " + (said.empty() ? "no such dataset" : said));
    }
    remote_detail::updateFetchRecord(record, [](RemoteFetch &f) { f.opened = true; });
    if (const std::string m = erddapMessage(body.substr(0, 4096)); !m.empty() && body.rfind("Error", 0) == 0)
        throw Error(who + ": ERDDAP answered an error: " + m);
    if (looksHtml(body))
    {
        const std::string title = htmlTitle(body);
        throw Error(who + ": the answer is an HTML page" + (title.empty() ? std::string() : " ('" + title + "')") +
                    ", not ERDDAP data (a tabledap URL of file type .csvp, .csv or .ncCF expected)");
    }
    if (body.empty())
        throw Error(who + ": the answer is empty");
    return body;
}

/// Seconds since 1970 of @p v in @p units (CF "<unit> since <date>"; "UTC" or none: seconds since 1970).
double secondsOf(double v, const std::string &units)
{
    if (units.find(" since ") == std::string::npos || !std::isfinite(v))
        return v;
    const CfTimeUnits u = parseCfTimeUnits(units, "standard");
    return v * u.secondsPerUnit + u.reference -
           secondsSinceCalendarEpoch(parseDateTime("1970-01-01T00:00:00Z"), u.calendar);
}

/// Seconds since 1970 of a time cell: an ISO 8601 date, or a number in @p units (secondsOf()). NaN for an empty cell
/// or NaN.
double timeOf(const std::string &cell, const std::string &units, const std::string &where)
{
    if (cell.empty() || text::lower(cell) == "nan")
        return NAN;
    try
    {
        if (cell.find('T') != std::string::npos)
            return parseIsoTime(cell);
        char *end = nullptr;
        const double v = std::strtod(cell.c_str(), &end);
        if (end == cell.c_str() || *end != '\0')
            throw Error("expected an ISO 8601 date or a number, got '" + cell + "'");
        return secondsOf(v, units);
    }
    catch (const Error &e)
    {
        throw Error(where + ": " + e.what());
    }
}

double numberOf(const std::string &cell, const std::string &where)
{
    if (cell.empty() || text::lower(cell) == "nan")
        return NAN;
    char *end = nullptr;
    const double v = std::strtod(cell.c_str(), &end);
    if (end == cell.c_str() || *end != '\0' || std::isinf(v))
        throw Error(where + ": expected a number, got '" + cell + "'");
    return v;
}

/// The columns' positions; @throws Error naming the URL and every expected column missing.
std::map<std::string, std::size_t> columnsOf(const std::vector<std::string> &names, const std::string &who,
                                             const char *what)
{
    std::map<std::string, std::size_t> col;
    for (std::size_t i = 0; i < names.size(); ++i)
        col.emplace(names[i], i);
    std::vector<std::string> missing;
    for (const char *k : kRequired)
        if (!col.count(k))
            missing.push_back(std::string("'") + k + "'");
    if (!missing.empty())
        throw Error(who + ": the answer has no " + what + " " + text::joinNames(missing) +
                    " (a glider DAC answer holds time, latitude, longitude, time_uv, lat_uv, lon_uv, u, v; ask for "
                    "them in the URL's query)");
    return col;
}

/// The unit of u and v (one for both); @throws Error naming the URL for a unit that is no velocity, or two units.
VelocityUnits velocityOf(const std::string &unitsU, const std::string &unitsV, const std::string &who)
{
    VelocityUnits velocity = velocityUnits("u", unitsU, who);
    if (velocityUnits("v", unitsV, who).toMetres.factor != velocity.toMetres.factor)
        throw Error(who + ": 'u' is in '" + unitsU + "' and 'v' in '" + unitsV + "': one unit for both expected");
    return velocity;
}

std::vector<Row> csvRows(const std::string &body, Answer kind, const std::string &who, VelocityUnits &velocity)
{
    std::vector<std::string> lines;
    for (std::size_t at = 0; at < body.size();)
    {
        const std::size_t end = std::min(body.find('\n', at), body.size());
        lines.push_back(body.substr(at, end - at));
        at = end + 1;
    }
    std::vector<std::string> names = io_detail::csvCells(lines.front(), ',', true), units(names.size());
    if (kind == Answer::Csvp)
        for (std::size_t i = 0; i < names.size(); ++i)
            if (const std::size_t open = names[i].rfind(" ("); open != std::string::npos && names[i].back() == ')')
            {
                units[i] = names[i].substr(open + 2, names[i].size() - open - 3);
                names[i] = text::trim(names[i].substr(0, open));
            }
    const auto col = columnsOf(names, who, "column");
    std::size_t first = 1;
    if (kind == Answer::Csv && lines.size() > 1) // the line of units
    {
        const std::vector<std::string> u = io_detail::csvCells(lines[1], ',', true);
        for (std::size_t i = 0; i < units.size() && i < u.size(); ++i)
            units[i] = u[i];
        first = 2;
    }
    velocity = velocityOf(units[col.at("u")], units[col.at("v")], who);
    std::vector<Row> rows;
    for (std::size_t n = first; n < lines.size(); ++n)
    {
        if (text::trim(lines[n]).empty())
            continue;
        const std::vector<std::string> cells = io_detail::csvCells(lines[n], ',', true);
        if (cells.size() != names.size())
            throw Error(who + ": answer line " + std::to_string(n + 1) + ": " + std::to_string(cells.size()) +
                        " cells, the header names " + std::to_string(names.size()));
        const auto where = [&](const char *k) {
            return who + ": answer line " + std::to_string(n + 1) + ": '" + k + "'";
        };
        const auto time = [&](const char *k) { return timeOf(cells[col.at(k)], units[col.at(k)], where(k)); };
        const auto number = [&](const char *k) { return numberOf(cells[col.at(k)], where(k)); };
        Row r;
        r.time = time("time");
        r.timeUv = time("time_uv");
        r.lat = number("latitude");
        r.lon = number("longitude");
        r.latUv = number("lat_uv");
        r.lonUv = number("lon_uv");
        r.u = velocity(number("u"));
        r.v = velocity(number("v"));
        if (const auto p = col.find("profile_id"); p != col.end())
            r.profile = cells[p->second];
        for (const char *k : kFlags)
            if (col.count(k))
                r.flags.emplace_back(k, number(k));
        rows.push_back(std::move(r));
    }
    return rows;
}

/// Keeps the bytes of an in-memory dataset registered while it is read.
struct MemoryName
{
    std::string name;
    ~MemoryName() { releaseMemoryDataset(name); }
};

std::vector<Row> ncCfRows(const std::string &body, const std::string &who, VelocityUnits &velocity)
{
    const bool netcdf = body.rfind("CDF\x01", 0) == 0 || body.rfind("CDF\x02", 0) == 0 ||
                        body.rfind("CDF\x05", 0) == 0 || body.rfind("\x89HDF\r\n\x1a\n", 0) == 0;
    if (!netcdf)
        throw Error(who + ": the answer is not NetCDF (it begins '" +
                    text::validUtf8(text::oneLine(body.substr(0, 40))) + "')");
    if (body.rfind("CDF", 0) == 0) // a classic file: whole, as its header declares (NetCDF-C reads past a cut one)
    {
        std::istringstream in(body);
        const gridded_detail::ClassicExtent e = gridded_detail::classicExtent(in, body.size());
        if (!e.corrupt.empty() || e.headerCut || e.dataEnd() > body.size())
            throw Error(who + ": the .ncCF answer is cut short or corrupt (" +
                        (e.corrupt.empty() ? std::to_string(body.size()) + " bytes, its header declares " +
                                                 (e.headerCut ? std::string("more") : std::to_string(e.dataEnd()))
                                           : e.corrupt) +
                        ")");
    }
    const MemoryName memory{registerMemoryDataset(body)};
    std::map<std::string, std::vector<double>> values;
    std::vector<std::string> names, profiles;
    std::string unitsU, unitsV;
    const std::map<std::string, std::string *> velocityUnits = {{"u", &unitsU}, {"v", &unitsV}};
    static const std::set<std::string> times = {"time", "time_uv"};
    try
    {
        const gridded_detail::GriddedDataset nc(memory.name);
        for (int v = 0; v < nc.nvars(); ++v)
            names.push_back(nc.varName(v));
        for (const std::string &name : names)
        {
            const bool wanted = name == "profile_id" || std::count(std::begin(kRequired), std::end(kRequired), name) ||
                                std::count(std::begin(kFlags), std::end(kFlags), name);
            if (!wanted)
                continue;
            const int id = *nc.findVar(name);
            using gridded_detail::ValueType;
            if (name == "profile_id" && nc.varType(id) == ValueType::Char && nc.varDims(id).size() == 2)
            {
                const std::size_t n = nc.dimLen(nc.varDims(id)[0]), len = nc.dimLen(nc.varDims(id)[1]);
                const std::string chars = nc.readChars(id);
                for (std::size_t i = 0; i < n; ++i)
                    profiles.push_back(text::trim(std::string(chars.data() + i * len, len)));
                continue;
            }
            if (nc.varType(id) == ValueType::Char || nc.varType(id) == ValueType::String || nc.varDims(id).size() > 1)
                throw nc.error("variable '" + name + "' is not a list of numbers");
            std::vector<double> v = nc.readAll1D(id);
            std::vector<double> fills = nc.attDoubles(id, "_FillValue");
            for (const double m : nc.attDoubles(id, "missing_value"))
                fills.push_back(m);
            const std::string units = nc.attText(id, "units").value_or("");
            for (double &x : v)
                x = std::find(fills.begin(), fills.end(), x) != fills.end() ? NAN : x;
            if (name == "profile_id")
                for (const double x : v)
                    profiles.push_back(std::isfinite(x) ? text::number(x, 17) : "");
            else if (velocityUnits.count(name))
                *velocityUnits.at(name) = units;
            else if (times.count(name))
                for (double &x : v)
                    x = secondsOf(x, units);
            if (name != "profile_id")
                values[name] = std::move(v);
        }
    }
    catch (const Error &e)
    {
        throw Error(who + ": the .ncCF answer: " + e.what());
    }
    columnsOf(names, who, "variable");
    velocity = velocityOf(unitsU, unitsV, who);
    const std::size_t n = values.at("time").size();
    for (const auto &[name, v] : values)
        if (v.size() != n)
            throw Error(who + ": the .ncCF answer's variables are not on one dimension ('time' has " +
                        std::to_string(n) + " values, '" + name + "' " + std::to_string(v.size()) +
                        "): ask for the profiles' variables only (time, latitude, longitude, profile_id, time_uv, "
                        "lat_uv, lon_uv, u, v, u_qc, v_qc)");
    if (!profiles.empty() && profiles.size() != n)
        throw Error(who + ": the .ncCF answer's 'profile_id' has " + std::to_string(profiles.size()) +
                    " values, 'time' " + std::to_string(n));
    std::vector<Row> rows(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        Row &r = rows[i];
        r.time = values["time"][i];
        r.timeUv = values["time_uv"][i];
        r.lat = values["latitude"][i];
        r.lon = values["longitude"][i];
        r.latUv = values["lat_uv"][i];
        r.lonUv = values["lon_uv"][i];
        r.u = velocity(values["u"][i]);
        r.v = velocity(values["v"][i]);
        r.profile = profiles.empty() ? "" : profiles[i];
        for (const char *k : kFlags)
            if (values.count(k))
                r.flags.emplace_back(k, values[k][i]);
    }
    return rows;
}

/// The rows into @p o: every row's fix; each profile's DAC once (its first row), rejected with the reason.
void useRows(const std::vector<Row> &rows, const VelocityUnits &velocity, const std::string &source,
             GliderObservations &o)
{
    std::set<std::string> seen;                                        // the profiles whose DAC is taken (or rejected)
    const auto value = [](double x) { return x == -999.0 ? NAN : x; }; // the glider DAC's fill value
    for (const Row &row : rows)
    {
        const GliderFix fix{value(row.time), {value(row.lon), value(row.lat)}};
        if (std::isfinite(fix.time) && std::isfinite(fix.at.lon) && std::abs(fix.at.lat) <= 90.0 &&
            fix.at.lon >= -180.0 && fix.at.lon <= 360.0)
            o.fixes.push_back(GliderFix{fix.time, {fix.at.lon > 180.0 ? fix.at.lon - 360.0 : fix.at.lon, fix.at.lat}});
        // a profile's rows repeat its DAC: the profile by its id, else by the DAC's time
        const std::string key = row.profile.empty() ? "time_uv " + text::number(row.timeUv, 17) : row.profile;
        if (!seen.insert(key).second)
            continue;
        DacRecord r;
        r.file = source;
        r.time = value(row.timeUv);
        r.at = {value(row.lonUv), value(row.latUv)};
        if (r.at.lon > 180.0)
            r.at.lon -= 360.0;
        r.u = value(row.u);
        r.v = value(row.v);
        std::string why;
        for (const auto &[name, flag] : row.flags)
            if (why.empty() && (flag == 3.0 || flag == 4.0 || flag == 9.0))
                why = "QC flag " + text::number(flag) + " (" + name + ")";
        if (why.empty() && (!std::isfinite(r.u) || !std::isfinite(r.v)))
            why = kFillValue;
        if (why.empty())
            why = dacProblem(r, velocity);
        if (!why.empty())
        {
            ++o.rejected[why];
            continue;
        }
        o.dac.push_back(r);
        o.fixes.push_back(GliderFix{r.time, r.at});
    }
}
} // namespace

void readErddap(const std::string &url, GliderObservations &o)
{
    const std::string source = withoutCredentials(url);
    const std::string who = "ERDDAP '" + source + "'";
    if (url.rfind("http://", 0) != 0 && url.rfind("https://", 0) != 0)
        throw Error(who + ": an ERDDAP URL begins http:// or https://");
    const Answer kind = answerOf(url, who);
    const std::string body = fetch(url, source);
    VelocityUnits velocity;
    const std::vector<Row> rows =
        kind == Answer::NcCf ? ncCfRows(body, who, velocity) : csvRows(body, kind, who, velocity);
    o.files = 1;
    o.platform = platformOf(url);
    useRows(rows, velocity, source, o);
}
} // namespace ompl_glider::observations_detail
