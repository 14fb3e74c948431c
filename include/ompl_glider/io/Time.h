#pragma once
/// @file Time.h
/// @brief Dates and times of every layer: the CF calendars and time units of the forecasts ("<unit> since <date>"),
/// ISO 8601 dates (parsed once, for CF attributes and mission files alike), UTC seconds since 1970 for mission
/// epochs and the arrival times of the outputs, and durations such as "30 min".

#include <string>

namespace ompl_glider
{
/// @brief CF calendars (CF conventions 1.10, Sec. 4.4.1).
enum class Calendar
{
    Standard,           ///< "standard" / "gregorian": Julian before 1582-10-15, Gregorian from then on
    ProlepticGregorian, ///< Gregorian rules for all dates
    Julian,             ///< a leap year every 4 years
    NoLeap,             ///< "noleap" / "365_day"
    AllLeap,            ///< "all_leap" / "366_day"
    Day360              ///< "360_day": twelve 30-day months
};

/// @brief Parses a CF calendar attribute (case-insensitive; empty means standard).
/// @throws Error naming the value and the accepted names.
Calendar parseCalendar(const std::string &name);
/// @brief The CF name of a calendar, as parseCalendar() reads it ("standard", "noleap", "360_day", ...).
const char *calendarName(Calendar c);

/// @brief A calendar date and time of day (seconds may have a fraction). Always UTC.
struct DateTime
{
    int year{1970};
    int month{1};
    int day{1};
    int hour{0};
    int minute{0};
    double second{0.0};
};

/// @brief Parses "YYYY-MM-DD", "YYYY-MM-DDThh:mm[:ss[.fff]]" (also with a space instead of T; "-YYYY" for years
/// before 1) with an optional time zone "Z", " UTC", "+hh[:mm]" or "-hh[:mm]" (converted to UTC). Also accepts
/// single-digit fields ("1950-1-1 0:0:0") as CF files use them. @throws Error naming the text on a syntax error or
/// a field out of range.
DateTime parseDateTime(const std::string &text);

/// @brief Seconds from the calendar's epoch (0001-01-01 00:00 in that calendar) to the date; exact in the
/// calendar's own day count. @throws Error when the day does not exist in the calendar (Feb 29 in noleap, ...).
double secondsSinceCalendarEpoch(const DateTime &d, Calendar cal);
/// @brief The date @p text (as parseDateTime() reads it) in seconds from the epoch of @p cal, its time zone offset
/// subtracted in seconds, so that a zone works in every calendar (a 360_day date "2026-02-30T00:00+01:00" is
/// 2026-02-29T23:00 UTC there). @throws Error naming the text, or when the day does not exist in the calendar.
double secondsSinceCalendarEpoch(const std::string &text, Calendar cal);
/// @brief Inverse of secondsSinceCalendarEpoch().
DateTime dateFromCalendarEpoch(double seconds, Calendar cal);

/// @brief "YYYY-MM-DDThh:mm:ssZ" (seconds rounded to the nearest integer, milliseconds when not integral).
std::string formatDateTime(const DateTime &d);

/// @brief formatDateTime() of seconds since the calendar's epoch (secondsSinceCalendarEpoch()), rounded to the
/// second: the dates of a forecast in its own calendar. @throws Error outside the years 0000-9999.
std::string formatCalendarTime(double secondsSinceCalendarEpoch, Calendar cal);

/// @brief Parsed CF time units: value * secondsPerUnit + reference = seconds since the calendar epoch.
struct CfTimeUnits
{
    double secondsPerUnit{1.0}; ///< 1 (seconds), 60, 3600 or 86400
    double reference{0.0};      ///< the "since" date in seconds since the calendar epoch
    Calendar calendar{Calendar::Standard};
};

/// @brief Parses "seconds|minutes|hours|days since <date>" (also the abbreviations s, sec, min, h, hr, d; months
/// and years are rejected because CF defines them as fixed fractions of a year, which forecasts never mean).
/// @throws Error naming the text and what was expected.
CfTimeUnits parseCfTimeUnits(const std::string &units, const std::string &calendar);

/// @brief A UTC date as seconds since 1970-01-01T00:00:00Z in the proleptic Gregorian calendar (mission epochs):
/// the text as parseDateTime() reads it, offset converted to UTC, with hours up to 23 only.
/// @throws Error naming the text when it is not such a date or the date does not exist.
double parseIsoTime(const std::string &text);

/// @brief "YYYY-MM-DDThh:mm:ssZ" of seconds since 1970-01-01T00:00:00Z (proleptic Gregorian, rounded to the
/// second); "" when the value is not finite.
std::string formatIsoTime(double secondsSince1970);

/// @brief Whether @p secondsSince1970 lies in the years 0000-9999 (what formatIsoTime() writes; it throws Error
/// outside them).
bool isoYearInRange(double secondsSince1970);

/// @brief A duration in field units: a number (field units), or "<number> s|min|h|d" (also without the space)
/// converted with @p timeUnitSeconds seconds per field unit; @p unitKnown false (an analytic flow without
/// units.time_s) refuses the second form. @throws Error saying what was expected (the caller adds where).
double parseDuration(const std::string &text, double timeUnitSeconds, bool unitKnown);
} // namespace ompl_glider
