/// @file SlocumDive.cpp
/// @brief A Slocum glider's fixes and DAC over its dives, from the tables of its dba or binary files (SlocumTable.h):
/// the one processing path of both (ObservationReaders.h).
///
/// Fixes: the cycles with m_gps_lat and m_gps_lon ([-]DDMM.MMMM, unit `lat` / `lon`) at m_present_time (seconds since
/// 1970). A fix is rejected when its position is the glider's placeholder 69696969 (no fix), half missing, or when
/// the latest m_gps_status reported in the file is not 0 (a valid fix).
///
/// Surfacings: consecutive valid fixes belong to one surfacing unless a dive lies between them: an m_depth reported
/// between them of kDiveDepth or more, or, where no depth is reported between them, more than kSurfaceGap between
/// them.
///
/// DAC: a cycle with m_water_vx and m_water_vy (m/s, east and north) carries the glider's estimate of the mean current
/// over the dive it has just ended, computed at the surface: over the segment from the fix before the dive (the last
/// valid fix of the surfacing before) to the fix after it (the first valid fix of this surfacing; the surfacing of the
/// latest valid fix at or before the cycle, at most kFixAge before it: none, the DAC is rejected). The record is
/// placed at the segment's mean time and mean position, as the IOOS profile files place theirs (time_uv, lat_uv,
/// lon_uv), with the segment's times and the depths reported over it. A DAC whose dive has no earlier fix (the first
/// surfacing of the files) is placed at the latest fix at or before it and counted in the notes.

#include <algorithm>
#include <cmath>
#include <iterator>

#include "NumberText.h"
#include "ObservationReaders.h"
#include "SlocumTable.h"
#include "TextUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/DegMin.h"

namespace ompl_glider::observations_detail
{
namespace
{
/// The Slocum's placeholder for a position it has no fix for.
constexpr double kNoFix = 69696969.0;
/// How long before a DAC cycle its surfacing's fix may be (s): a surfacing lasts minutes, a dive hours.
constexpr double kFixAge = 1800.0;
/// The depth (m) that tells a dive between two fixes: at the surface the glider reads a metre or two (waves).
constexpr double kDiveDepth = 4.0;
/// Without depths reported between two fixes: more time between them than this (s) is a dive.
constexpr double kSurfaceGap = 900.0;

/// The note of the DAC placed at the surfacing's fix.
const char *const kNoSegment = "DAC placed at the surfacing's fix (no fix before the dive: its start unknown)";

/// @p x ([-]DDMM.MMMM) in degrees.
double degreesOf(double x)
{
    const double a = std::abs(x), deg = std::floor(a / 100.0), d = deg + (a - 100.0 * deg) / 60.0;
    return x < 0 ? -d : d;
}

/// The reason a fix cycle is rejected; empty when @p at holds its position.
std::string fixProblem(double time, double lat, double lon, double status, LonLat &at)
{
    if (!std::isfinite(time))
        return "no time (m_present_time NaN)";
    if (std::isnan(lat) || std::isnan(lon))
        return "no GPS fix (m_gps_lat or m_gps_lon NaN)";
    if (std::abs(lat) == kNoFix || std::abs(lon) == kNoFix)
        return "no GPS fix (69696969)";
    if (status != 0.0)
        return "GPS status " + text::number(status) + " (m_gps_status)";
    if (std::fmod(std::abs(lat), 100.0) >= 60.0 || std::fmod(std::abs(lon), 100.0) >= 60.0)
        return "GPS position not [-]DDMM.MMMM";
    at = {degreesOf(lon), degreesOf(lat)};
    if (std::abs(at.lat) > 90.0 || std::abs(at.lon) > 180.0)
        return "position out of range";
    return "";
}

/// Checks the sensors and units of @p t; false for a binary file without the glider's fixes and DAC (a science file).
bool checkSensors(const SlocumTable &t, VelocityUnits &velocity)
{
    const std::size_t needed[] = {kTime, kLat, kLon, kVx, kVy};
    if (t.binary && std::none_of(std::begin(needed), std::end(needed), [&](std::size_t c) { return t.present[c]; }))
        return false;
    for (const std::size_t c : needed)
        if (!t.present[c])
            throw Error(t.sensorsWhere + ": no sensor '" + kSlocumSensors[c] +
                        "' (a glider's DAC and fixes are read from m_present_time, m_gps_lat, m_gps_lon, m_water_vx, "
                        "m_water_vy: give the files that hold them" +
                        (t.binary ? std::string(")") : ", or dbd2asc a sensor list with them)"));
    const auto refuseUnit = [&](std::size_t c, const std::string &expected) {
        throw Error(t.unitsWhere + ": sensor '" + kSlocumSensors[c] + "' is in '" + t.units[c] + "': " + expected +
                    " expected");
    };
    if (!text::inList(t.units[kTime], {"timestamp", "s", "sec"}))
        refuseUnit(kTime, "'timestamp' (seconds since 1970)");
    if (t.units[kLat] != "lat")
        refuseUnit(kLat, "'lat' ([-]DDMM.MMMM)");
    if (t.units[kLon] != "lon")
        refuseUnit(kLon, "'lon' ([-]DDMM.MMMM)");
    velocity = velocityUnits(kSlocumSensors[kVx], t.units[kVx], t.unitsWhere);
    if (velocityUnits(kSlocumSensors[kVy], t.units[kVy], t.unitsWhere).toMetres.factor != velocity.toMetres.factor)
        throw Error(t.unitsWhere + ": sensor 'm_water_vx' is in '" + t.units[kVx] + "' and 'm_water_vy' in '" +
                    t.units[kVy] + "': one unit for both expected");
    return true;
}

/// What the tables of one glider give, before the DAC are placed.
struct Reported
{
    std::vector<GliderFix> fixes;                  ///< valid, in time order
    std::vector<std::pair<double, double>> depths; ///< (time, m_depth), in time order
    std::vector<DacRecord> dac;                    ///< the DAC cycles (their time; the place to be found)
    std::map<std::string, VelocityUnits> units;    ///< of each file's DAC
};

void collect(const SlocumTable &t, const VelocityUnits &velocity, Reported &r, GliderObservations &o)
{
    r.units[t.file] = velocity;
    double status = 0.0; // the latest m_gps_status reported in the file
    for (const auto &row : t.rows)
    {
        const double time = row[kTime];
        if (std::isfinite(row[kStatus]))
            status = row[kStatus];
        if (std::isfinite(time) && std::isfinite(row[kDepth]))
            r.depths.emplace_back(time, row[kDepth]);
        if (!std::isnan(row[kLat]) || !std::isnan(row[kLon]))
        {
            if (std::isfinite(time) && !(o.newestSurfacing >= time))
                o.newestSurfacing = time;
            LonLat at;
            const std::string why = fixProblem(time, row[kLat], row[kLon], status, at);
            if (why.empty())
                r.fixes.push_back(GliderFix{time, at});
            else
                ++o.rejected[why];
        }
        const double vx = velocity(row[kVx]), vy = velocity(row[kVy]);
        if (std::isnan(vx) && std::isnan(vy))
            continue;
        if (std::isnan(vx) || std::isnan(vy) || !std::isfinite(time))
            ++o.rejected[std::isfinite(time) ? kFillValue : "no time (m_present_time NaN)"];
        else
            r.dac.push_back(DacRecord{time, {}, vx, vy, t.file});
    }
}

/// True when a dive lies between the fixes @p a and @p b (a before b).
bool diveBetween(const GliderFix &a, const GliderFix &b, const std::vector<std::pair<double, double>> &depths)
{
    const auto from =
        std::upper_bound(depths.begin(), depths.end(), std::make_pair(a.time, static_cast<double>(INFINITY)));
    bool reported = false;
    for (auto it = from; it != depths.end() && it->first < b.time; ++it)
    {
        reported = true;
        if (it->second >= kDiveDepth)
            return true;
    }
    return !reported && b.time - a.time > kSurfaceGap;
}

/// Places @p d over its dive (see the file's comment); the reason it is rejected, or empty.
std::string place(DacRecord &d, const Reported &r)
{
    const std::vector<GliderFix> &fixes = r.fixes;
    const auto after =
        std::upper_bound(fixes.begin(), fixes.end(), d.time, [](double t, const GliderFix &f) { return t < f.time; });
    if (after == fixes.begin() || d.time - std::prev(after)->time > kFixAge)
        return "no GPS fix in the " + std::to_string(static_cast<int>(kFixAge / 60)) + " min before it";
    auto first = std::prev(after); // the surfacing's first valid fix
    while (first != fixes.begin() && !diveBetween(*std::prev(first), *first, r.depths))
        --first;
    d.segmentEnd = first->time;
    if (first == fixes.begin())
    {
        d.time = std::prev(after)->time;
        d.at = std::prev(after)->at;
        return "";
    }
    const GliderFix &start = *std::prev(first), &end = *first;
    d.segmentStart = start.time;
    d.time = 0.5 * (start.time + end.time);
    double lon = end.at.lon;
    if (lon - start.at.lon > 180.0)
        lon -= 360.0;
    else if (start.at.lon - lon > 180.0)
        lon += 360.0;
    d.at = {0.5 * (start.at.lon + lon), 0.5 * (start.at.lat + end.at.lat)};
    if (d.at.lon > 180.0)
        d.at.lon -= 360.0;
    else if (d.at.lon < -180.0)
        d.at.lon += 360.0;
    const auto from =
        std::lower_bound(r.depths.begin(), r.depths.end(), std::make_pair(start.time, -static_cast<double>(INFINITY)));
    for (auto it = from; it != r.depths.end() && it->first <= end.time; ++it)
    {
        d.depthMin = std::isnan(d.depthMin) ? it->second : std::min(d.depthMin, it->second);
        d.depthMax = std::isnan(d.depthMax) ? it->second : std::max(d.depthMax, it->second);
    }
    return "";
}
} // namespace

void readSlocumFiles(const std::vector<std::string> &files, const std::string &cacheDir, GliderObservations &o)
{
    std::vector<SlocumTable> tables;
    std::map<std::string, std::size_t> gliders;
    for (const std::string &f : files)
    {
        tables.push_back(isDbaFile(f) ? readDbaTable(f) : readBinaryTable(f, cacheDir));
        ++gliders[tables.back().platform];
    }
    o.platform = mostNamed(gliders, o.source);
    Reported r;
    for (const SlocumTable &t : tables)
    {
        if (t.platform != o.platform)
        {
            ++o.rejected["another glider ('" + t.platform + "')"];
            continue;
        }
        VelocityUnits velocity;
        if (checkSensors(t, velocity))
            collect(t, velocity, r, o);
        else
            ++o.notes["files without the glider's fixes and DAC (science files: m_present_time, m_gps_lat, "
                      "m_water_vx, ... not in them)"];
    }
    const auto byTime = [](const GliderFix &a, const GliderFix &b) { return a.time < b.time; };
    std::stable_sort(r.fixes.begin(), r.fixes.end(), byTime);
    std::stable_sort(r.depths.begin(), r.depths.end());
    for (DacRecord d : r.dac)
    {
        std::string why = place(d, r);
        if (why.empty())
            why = dacProblem(d, r.units[d.file]);
        if (!why.empty())
            ++o.rejected[why];
        else
        {
            o.dac.push_back(d);
            if (std::isnan(d.segmentStart))
                ++o.notes[kNoSegment];
        }
    }
    o.fixes.insert(o.fixes.end(), r.fixes.begin(), r.fixes.end());
}
} // namespace ompl_glider::observations_detail
