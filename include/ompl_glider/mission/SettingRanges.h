#pragma once
/// @file SettingRanges.h
/// @brief The declared range of each numeric mission setting that a mission file, a flag and a Python keyword can all
/// give: one row per setting, read by the mission loader and by applyOverrides() (Overrides.h), so that the three ways
/// in accept the same values and refuse the others in the same words. A test walks the table and tries every bound.

#include <string>
#include <vector>

namespace ompl_glider
{
struct MissionSpec;

/// @brief How a setting's value is written.
enum class SettingValue
{
    Number,   ///< a plain number
    Integer,  ///< a whole number
    Length,   ///< a number in the mission's length unit, or with a unit ("20 km", "500 m")
    Depth,    ///< metres, or with a unit: a bare number is metres whatever the mission's unit
    Duration, ///< a number in the mission's time unit, or with a unit ("6 h", "1 d")
    Degrees   ///< a number of degrees
};

/// @brief One setting's range: low (included or not), and at most high.
struct SettingRange
{
    std::string field; ///< the dotted mission field ("observations.length_scale"; "waypoints[].radius" for each)
    SettingValue value{SettingValue::Number};
    double low{0.0};
    bool lowIncluded{false}; ///< >= low (true) or > low (false)
    double high;             ///< at most this (+inf: no bound above)
    std::string highText;    ///< high as a pilot reads it ("1e6 s (11.6 days)"); empty: the number
    std::string meaning;     ///< what the value is, appended to a fault ("0: every waypoint"); may be empty
};

/// @brief Every declared setting range, in the order of the mission file's sections.
const std::vector<SettingRange> &settingRanges();

/// @brief The row of @p field ("waypoints[3].radius" finds "waypoints[].radius").
/// @throws std::logic_error when no row declares it (a programming error, not an input's).
const SettingRange &settingRange(const std::string &field);

/// @brief The range as words after "a number": "> 0", ">= 0", "in 0..180".
std::string rangeWords(const SettingRange &s);

/// @brief @p v checked against @p field's range (@p given: the value as the user wrote it, for the message).
/// @throws Error "expected a length > 0, got '0 km'" (no place: the caller adds its file:line or flag)
double checkSetting(const std::string &field, double v, const std::string &given);

/// @brief @p text read as @p field of @p m (a length or duration in the mission's units or with its unit, else a
/// number) and checked as checkSetting() does. @throws Error as checkSetting(), or the unit parser's.
double settingFromText(const std::string &field, const std::string &text, const MissionSpec &m);

/// @brief A mission dated by its `epoch` writes its times as ISO 8601 dates, years 0000-9999: each time setting that
/// reaches past them (the departure, a window, a station's stay, the planning, reach and execution horizons, the
/// stints' mission duration, each from the departure) is refused naming that setting (MissionSpec::place()), not
/// the epoch. Nothing to check without an epoch (a forecast's own calendar writes any year). @throws Error.
void checkDatesInRange(const MissionSpec &m);
} // namespace ompl_glider
