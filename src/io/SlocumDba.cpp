/// @file SlocumDba.cpp
/// @brief A Slocum glider's DAC and fixes from its dba files, the ASCII tables dbd2asc writes of the glider's binary
/// data (ObservationReaders.h).
///
/// A dba file: `num_ascii_tags` header lines `key: value` (the first `dbd_label: DBD_ASC(dinkum_binary_data_ascii)
/// file`; `filename: ru29-2026-074-0-12` names the glider, `sensors_per_cycle`, `num_label_lines`), then the label
/// lines (sensor names; units; bytes per value), then one line per cycle of space-separated values, `NaN` where a
/// sensor has no new value.
///
/// Fixes: the rows with m_gps_lat and m_gps_lon ([-]DDMM.MMMM, unit `lat` / `lon`) at m_present_time (seconds since
/// 1970). A fix is rejected when its position is the glider's placeholder 69696969 (no fix), half missing, or when
/// the latest m_gps_status reported in the file is not 0 (a valid fix).
///
/// DAC: a row with m_water_vx and m_water_vy (m/s, east and north) carries the glider's new estimate of the dive it
/// has just ended, computed at the surface from the GPS fix where the dive ended. The record takes the time and the
/// position of the latest valid fix at or before that row (of any file of the deployment: a surfacing may straddle
/// two files), at most kFixAge before it; a DAC without such a fix is rejected, as is a DAC with only one component.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include "NumberText.h"
#include "ObservationReaders.h"
#include "TextUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/DegMin.h"

namespace ompl_glider::observations_detail
{
namespace
{
/// The Slocum's placeholder for a position it has no fix for.
constexpr double kNoFix = 69696969.0;
/// How long before a DAC row its surfacing's fix may be (s): a surfacing lasts minutes, a dive hours.
constexpr double kFixAge = 1800.0;

/// The rows of a dba file that report a fix or a DAC.
struct DbaRow
{
    double time{NAN};
    std::string lat, lon;    // the sensors' text ([-]DDMM.MMMM), "NaN" when not reported
    double status{0.0};      // the latest m_gps_status reported in the file (0 when none)
    double vx{NAN}, vy{NAN}; // m_water_vx, m_water_vy
    bool fix{false}, dac{false};
};

struct DbaFile
{
    std::string file, platform;
    std::vector<DbaRow> rows;
    VelocityUnits velocity; ///< of m_water_vx, m_water_vy (the rows' vx, vy are in m/s)
};

/// The glider of a Slocum file name "<glider>-<year>-<day>-<mission>-<segment>" ("ru29-2026-074-0-12" -> "ru29").
std::string gliderOf(const std::string &filename)
{
    std::vector<std::size_t> dashes;
    for (std::size_t i = 0; i < filename.size(); ++i)
        if (filename[i] == '-')
            dashes.push_back(i);
    return dashes.size() >= 4 ? filename.substr(0, dashes[dashes.size() - 4]) : filename;
}

std::vector<std::string> words(const std::string &line)
{
    std::vector<std::string> out;
    std::istringstream in(line);
    for (std::string w; in >> w;)
        out.push_back(w);
    return out;
}

/// A header count ("num_ascii_tags: 14"); -1 when @p text is not one.
long countOf(const std::string &text)
{
    char *end = nullptr;
    const long n = std::strtol(text.c_str(), &end, 10);
    return end != text.c_str() && *end == '\0' && n >= 0 && n < 100000 ? n : -1;
}

/// A dba file's header and label lines.
struct Header
{
    std::map<std::string, std::string> tags; // "key: value"
    std::vector<std::string> names, units;   // the sensors
    int namesLine{0};                        // the line of the names (the units' is the next)
};

/// Reads the header and the label lines of a dba file; @p n counts the lines read.
Header readHeader(std::istream &in, const std::string &file, int &n)
{
    const auto fail = [&](const std::string &what) { throw Error(file + ":" + std::to_string(n) + ": " + what); };
    Header h;
    long tags = -1;
    std::string line;
    for (long read = 0; tags < 0 || read < tags; ++read)
    {
        if (!std::getline(in, line))
            fail("the file ends in its header (dbd2asc writes num_ascii_tags lines 'key: value')");
        ++n;
        const std::size_t colon = line.find(':');
        if (n == 1 && line.rfind("dbd_label:", 0) != 0)
            fail("not a Slocum dba file (dbd2asc's first line is 'dbd_label: DBD_ASC(dinkum_binary_data_ascii)file')");
        if (colon == std::string::npos || colon == 0)
            fail(tags < 0 ? "the header has no num_ascii_tags line (the number of header lines)"
                          : "a header line 'key: value' expected (num_ascii_tags says " + std::to_string(tags) + ")");
        const std::string key = text::trim(line.substr(0, colon)), value = text::trim(line.substr(colon + 1));
        h.tags[key] = value;
        if (key == "num_ascii_tags" && (tags = countOf(value)) < 0)
            fail("num_ascii_tags: a count expected, got '" + value + "'");
    }
    const long labels = h.tags.count("num_label_lines") ? countOf(h.tags["num_label_lines"]) : 3;
    if (labels < 2)
        fail("num_label_lines: 2 or more expected (sensor names, units, bytes), got '" + h.tags["num_label_lines"] +
             "'");
    const long perCycle = h.tags.count("sensors_per_cycle") ? countOf(h.tags["sensors_per_cycle"]) : -1;
    for (long k = 0; k < labels; ++k)
    {
        if (!std::getline(in, line))
            throw Error(file + ":" + std::to_string(n + 1) + ": the file ends before its label lines (" +
                        std::to_string(labels) + ": sensor names, units, bytes per value)");
        ++n;
        const std::vector<std::string> w = words(line);
        if (k == 0)
        {
            h.names = w;
            h.namesLine = n;
            if (perCycle >= 0 && static_cast<long>(w.size()) != perCycle)
                fail("the label line names " + std::to_string(w.size()) + " sensors, sensors_per_cycle says " +
                     std::to_string(perCycle));
        }
        else if (w.size() != h.names.size())
            fail("label line " + std::to_string(k + 1) + " has " + std::to_string(w.size()) + " entries for " +
                 std::to_string(h.names.size()) + " sensors");
        if (k == 1)
            h.units = w;
    }
    return h;
}

DbaFile readDba(const std::string &file)
{
    std::ifstream in(file);
    if (!in)
        throw Error("observations '" + file + "': cannot open the file");
    DbaFile d;
    d.file = file;
    int n = 0;
    const Header h = readHeader(in, file, n);
    const std::vector<std::string> &names = h.names;
    d.platform = h.tags.count("filename") ? gliderOf(h.tags.at("filename")) : "";
    const auto column = [&](const char *sensor) -> std::size_t {
        const auto it = std::find(names.begin(), names.end(), sensor);
        if (it == names.end())
            throw Error(file + ":" + std::to_string(h.namesLine) + ": no sensor '" + sensor +
                        "' (a glider's DAC and fixes are read from m_present_time, m_gps_lat, m_gps_lon, m_water_vx, "
                        "m_water_vy: give dbd2asc the files that hold them, or a sensor list with them)");
        return static_cast<std::size_t>(it - names.begin());
    };
    const auto refuseUnit = [&](std::size_t k, const std::string &expected) {
        throw Error(file + ":" + std::to_string(h.namesLine + 1) + ": sensor '" + names[k] + "' is in '" + h.units[k] +
                    "': " + expected + " expected");
    };
    const std::size_t time = column("m_present_time"), lat = column("m_gps_lat"), lon = column("m_gps_lon");
    const std::size_t vx = column("m_water_vx"), vy = column("m_water_vy");
    if (!text::inList(h.units[time], {"timestamp", "s", "sec"}))
        refuseUnit(time, "'timestamp' (seconds since 1970)");
    if (h.units[lat] != "lat")
        refuseUnit(lat, "'lat' ([-]DDMM.MMMM)");
    if (h.units[lon] != "lon")
        refuseUnit(lon, "'lon' ([-]DDMM.MMMM)");
    const std::string where = file + ":" + std::to_string(h.namesLine + 1);
    d.velocity = velocityUnits(names[vx], h.units[vx], where);
    if (velocityUnits(names[vy], h.units[vy], where).toMetres.factor != d.velocity.toMetres.factor)
        throw Error(where + ": sensor 'm_water_vx' is in '" + h.units[vx] + "' and 'm_water_vy' in '" + h.units[vy] +
                    "': one unit for both expected");
    const auto statusAt = std::find(names.begin(), names.end(), "m_gps_status");
    double status = 0.0;
    std::string line;
    std::vector<double> values(names.size());
    while (std::getline(in, line))
    {
        ++n;
        const std::vector<std::string> w = words(line);
        if (w.empty())
            continue;
        if (w.size() != names.size())
            throw Error(file + ":" + std::to_string(n) + ": " + std::to_string(w.size()) + " values, the label line (" +
                        std::to_string(h.namesLine) + ") names " + std::to_string(names.size()) + " sensors");
        for (std::size_t k = 0; k < w.size(); ++k)
        {
            char *end = nullptr;
            values[k] = std::strtod(w[k].c_str(), &end);
            if (end == w[k].c_str() || *end != '\0' || std::isinf(values[k]))
                throw Error(file + ":" + std::to_string(n) + ": sensor '" + names[k] + "': '" + w[k] +
                            "' is not a number (or NaN)");
        }
        if (statusAt != names.end() && std::isfinite(values[statusAt - names.begin()]))
            status = values[statusAt - names.begin()];
        DbaRow r;
        r.time = values[time];
        r.lat = w[lat];
        r.lon = w[lon];
        r.status = status;
        r.vx = d.velocity(values[vx]);
        r.vy = d.velocity(values[vy]);
        r.fix = !std::isnan(values[lat]) || !std::isnan(values[lon]);
        r.dac = !std::isnan(r.vx) || !std::isnan(r.vy);
        if (r.fix || r.dac)
            d.rows.push_back(std::move(r));
    }
    return d;
}

/// The reason a fix row is rejected; empty when @p at holds its position.
std::string fixProblem(const DbaRow &r, LonLat &at)
{
    if (!std::isfinite(r.time))
        return "no time (m_present_time NaN)";
    const double la = std::strtod(r.lat.c_str(), nullptr), lo = std::strtod(r.lon.c_str(), nullptr);
    if (std::isnan(la) || std::isnan(lo))
        return "no GPS fix (m_gps_lat or m_gps_lon NaN)";
    if (std::abs(la) == kNoFix || std::abs(lo) == kNoFix)
        return "no GPS fix (69696969)";
    if (r.status != 0.0)
        return "GPS status " + text::number(r.status) + " (m_gps_status)";
    try
    {
        at = {parseDegMin(r.lon), parseDegMin(r.lat)};
    }
    catch (const Error &)
    {
        return "GPS position not [-]DDMM.MMMM";
    }
    if (std::abs(at.lat) > 90.0 || std::abs(at.lon) > 180.0)
        return "position out of range";
    return "";
}
} // namespace

void readDbaFiles(const std::vector<std::string> &files, GliderObservations &o)
{
    std::vector<DbaFile> dba;
    std::map<std::string, std::size_t> gliders;
    for (const std::string &f : files)
    {
        dba.push_back(readDba(f));
        ++gliders[dba.back().platform];
    }
    o.platform = mostNamed(gliders, o.source);
    std::vector<GliderFix> fixes;               // the valid fixes of every file
    std::vector<DacRecord> dac;                 // the DAC rows (their time; the position to be found)
    std::map<std::string, VelocityUnits> units; // of each file's DAC
    for (const DbaFile &d : dba)
    {
        if (d.platform != o.platform)
        {
            ++o.rejected["another glider ('" + d.platform + "')"];
            continue;
        }
        units[d.file] = d.velocity;
        for (const DbaRow &r : d.rows)
        {
            if (r.fix)
            {
                LonLat at;
                const std::string why = fixProblem(r, at);
                if (why.empty())
                    fixes.push_back(GliderFix{r.time, at});
                else
                    ++o.rejected[why];
            }
            if (!r.dac)
                continue;
            if (std::isnan(r.vx) || std::isnan(r.vy) || !std::isfinite(r.time))
                ++o.rejected[std::isfinite(r.time) ? kFillValue : "no time (m_present_time NaN)"];
            else
                dac.push_back(DacRecord{r.time, {}, r.vx, r.vy, d.file});
        }
    }
    std::stable_sort(fixes.begin(), fixes.end(),
                     [](const GliderFix &a, const GliderFix &b) { return a.time < b.time; });
    for (DacRecord r : dac)
    {
        // the latest valid fix at or before the row
        const auto after = std::upper_bound(fixes.begin(), fixes.end(), r.time,
                                            [](double t, const GliderFix &f) { return t < f.time; });
        if (after == fixes.begin() || r.time - std::prev(after)->time > kFixAge)
        {
            ++o.rejected["no GPS fix in the " + std::to_string(static_cast<int>(kFixAge / 60)) + " min before it"];
            continue;
        }
        r.time = std::prev(after)->time;
        r.at = std::prev(after)->at;
        const std::string why = dacProblem(r, units[r.file]);
        if (why.empty())
            o.dac.push_back(r);
        else
            ++o.rejected[why];
    }
    o.fixes.insert(o.fixes.end(), fixes.begin(), fixes.end());
}
} // namespace ompl_glider::observations_detail
