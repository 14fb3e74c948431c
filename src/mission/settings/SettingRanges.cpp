/// @file SettingRanges.cpp
/// @brief The declared ranges of the mission's numeric settings (SettingRanges.h) and their one check.

#include "ompl_glider/mission/SettingRanges.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "../../io/NumberText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Length.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/ompl/Sectors.h"

namespace ompl_glider
{
namespace
{
constexpr double kNone = std::numeric_limits<double>::infinity();

/// What the value is: "number", "length", ...
const char *noun(SettingValue v)
{
    switch (v)
    {
    case SettingValue::Integer:
        return "integer";
    case SettingValue::Length:
    case SettingValue::Depth:
        return "length";
    case SettingValue::Duration:
        return "duration";
    case SettingValue::Degrees:
        return "degrees";
    case SettingValue::Number:
        break;
    }
    return "number";
}

/// "a number", "an integer", "degrees"
std::string valueWord(SettingValue v)
{
    return std::string(v == SettingValue::Integer ? "an " : v == SettingValue::Degrees ? "" : "a ") + noun(v);
}

/// "waypoints[3].radius" -> "waypoints[].radius"
std::string rowName(const std::string &field)
{
    std::string out;
    bool inIndex = false;
    for (const char c : field)
    {
        if (c == '[')
            inIndex = true, out += c;
        else if (c == ']')
            inIndex = false, out += c;
        else if (!inIndex)
            out += c;
    }
    return out;
}
} // namespace

const std::vector<SettingRange> &settingRanges()
{
    using V = SettingValue;
    static const std::vector<SettingRange> rows = {
        {"vehicle.speed", V::Number, 0.0, false, kNone, "", ""},
        {"planner.grid_size", V::Number, 0.0, false, kNone, "", ""},
        {"planner.sectors", V::Integer, kMinSectors, true, kMaxSectors, "", ""},
        {"planner.time_limit", V::Number, 0.0, true, kMaxTimeLimit, "1e6 s (11.6 days)", ""},
        {"planner.horizon", V::Number, 0.0, false, kNone, "", ""},
        {"planner.goal_tolerance", V::Number, 0.0, true, kNone, "", ""},
        {"waypoints[].radius", V::Length, 0.0, false, kNone, "", "the glider counts the point as reached within it"},
        {"waypoints[].stay", V::Duration, 0.0, true, kNone, "", ""},
        {"observations.length_scale", V::Length, 0.0, false, kNone, "", ""},
        {"observations.time_scale", V::Duration, 0.0, false, kNone, "", ""},
        {"observations.error_ratio", V::Number, 0.0, false, kNone, "", "the DAC's error over the forecast's"},
        {"safety.keep_off", V::Length, 0.0, true, kNone, "", ""},
        {"safety.min_depth", V::Depth, 0.0, true, kNone, "", ""},
        {"outputs.goto_turn_deg", V::Degrees, 0.0, true, 180.0, "", "0: every waypoint"},
        {"outputs.hold_tolerance", V::Depth, 0.0, true, kNone, "", "metres; 0: every segment of held headings"},
        {"outputs.isochrone_interval", V::Duration, 0.0, false, kNone, "", ""},
        {"reachability.horizon", V::Duration, 0.0, false, kNone, "", ""},
        {"reachability.interval", V::Duration, 0.0, false, kNone, "", ""},
        {"reachability.resolution", V::Length, 0.0, false, kNone, "", "the level set's cell"},
        {"execution.surfacing_interval", V::Duration, 0.0, false, kNone, "", ""},
        {"execution.radius", V::Length, 0.0, false, kNone, "", "the goal counts as reached within it"},
        {"execution.batch.pairs", V::Integer, 0.0, true, 100000.0, "", ""},
        {"execution.batch.seed", V::Integer, 0.0, true, 4294967295.0, "", ""},
    };
    return rows;
}

const SettingRange &settingRange(const std::string &field)
{
    const std::string name = rowName(field);
    for (const SettingRange &s : settingRanges())
        if (s.field == name)
            return s;
    throw std::logic_error("no declared range for the setting '" + field + "'");
}

std::string rangeWords(const SettingRange &s)
{
    if (std::isfinite(s.high))
        return "in " + text::number(s.low) + ".." + (s.highText.empty() ? text::number(s.high) : s.highText);
    return std::string(s.lowIncluded ? ">= " : "> ") + text::number(s.low);
}

double checkSetting(const std::string &field, double v, const std::string &given)
{
    const SettingRange &s = settingRange(field);
    const std::string meaning = s.meaning.empty() ? "" : " (" + s.meaning + ")";
    if (s.value == SettingValue::Integer && !(v >= s.low && v <= s.high && v == std::floor(v)))
        throw Error("expected an integer " + rangeWords(s) + ", got " + given);
    if (std::isinf(v) && !std::isfinite(s.high))
        throw Error(std::string("expected a finite ") + noun(s.value) + " " + rangeWords(s) + meaning + ", got " +
                    given);
    if (std::isnan(v) || (s.lowIncluded ? !(v >= s.low) : !(v > s.low)))
        throw Error("expected " + valueWord(s.value) + " " + rangeWords(s) + meaning + ", got " + given);
    if (v > s.high && !s.highText.empty()) // a limit of the machine or of the method, said as such
        throw Error("at most " + s.highText + ", got " + given);
    if (v > s.high)
        throw Error("expected " + valueWord(s.value) + " " + rangeWords(s) + meaning + ", got " + given);
    if (!s.lowIncluded && s.low == 0.0 && !std::isnormal(v)) // a denormal (1e-310): divisions by it overflow
        throw Error("expected " + valueWord(s.value) + " > 0, got " + given +
                    ", below the smallest normal double (2.2e-308): too small to compute with");
    return v;
}

double settingFromText(const std::string &field, const std::string &text, const MissionSpec &m)
{
    const SettingRange &s = settingRange(field);
    // the number and what follows it (a unit, or nothing)
    const char *begin = text.c_str();
    char *end = nullptr;
    const double number = std::strtod(begin, &end);
    std::string unit = end == begin ? text : std::string(end);
    unit.erase(0, unit.find_first_not_of(' '));
    unit.erase(unit.find_last_not_of(' ') + 1);
    if (end != begin && unit.empty())
        return checkSetting(field, number, "'" + text + "'");
    if (s.value != SettingValue::Length && s.value != SettingValue::Depth && s.value != SettingValue::Duration)
        throw Error("expected " + valueWord(s.value) + ", got '" + text + "'");
    // with a unit: the unit's parser converts it (and refuses an unknown unit, or one the mission cannot convert)
    const auto convert = [&](const std::string &t) {
        switch (s.value)
        {
        case SettingValue::Length:
            return parseLength(t, m.metresPerUnit(), m.physicalUnits().length);
        case SettingValue::Depth:
            return parseLength(t, 1.0, true); // depths are metres for every field
        default:
            return parseDuration(t, m.timeUnitSeconds, m.hasTimeUnit());
        }
    };
    // a value of 0 or below is the setting's to judge, not the parser's (a stay may be "0 h")
    const double v = end != begin && number <= 0.0 ? number * convert("1 " + unit) : convert(text);
    return checkSetting(field, v, "'" + text + "'");
}

void checkDatesInRange(const MissionSpec &m)
{
    if (!m.epoch || m.fileCalendar)
        return;
    const double departure = m.departure.window ? m.departure.end : m.departure.time;
    const auto check = [&m](double from, double span, const std::string &field) {
        const double t = from + (std::isfinite(span) && span > 0.0 ? span : 0.0);
        if (std::isfinite(t) && !isoYearInRange(*m.epoch + t * m.timeUnitSeconds))
            throw Error(m.place(field) + ": " + (span > 0.0 ? "from the departure, " : "") +
                        "it reaches past the years 0000-9999 that the mission's dates are written in (ISO 8601, " +
                        "from its epoch " + formatIsoTime(*m.epoch) + "): " +
                        (span > 0.0 ? text::number(span * m.timeUnitSeconds / (365.25 * 86400.0)) + " years"
                                    : "t = " + text::number(t)));
    };
    check(departure, 0.0, m.departure.window ? "departure.window" : "departure.time");
    if (m.goalWindow.set)
        check(m.goalWindow.end, 0.0, "goal.window");
    double stays = 0.0;
    for (std::size_t k = 0; k < m.waypoints.size(); ++k)
    {
        const std::string at = "waypoints[" + std::to_string(k) + "]";
        if (m.waypoints[k].arrive.set)
            check(m.waypoints[k].arrive.end, 0.0, at + ".arrive");
        stays += m.waypoints[k].stay; // the stays so far: the first to pass the years is named
        check(departure, stays, at + ".stay");
    }
    check(departure, m.planner.horizon, "planner.horizon");
    if (m.stints.set)
        check(departure, m.stints.missionDuration, "stints.mission_duration");
    check(departure, m.reachability.horizon, "reachability.horizon");
    if (m.execution.enabled)
        check(departure, m.execution.duration, "execution.duration");
}
} // namespace ompl_glider
