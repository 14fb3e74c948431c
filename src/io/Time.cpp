// Calendars, CF time units, ISO 8601 dates and durations (see Time.h).
#include "ompl_glider/io/Time.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <set>

#include "TextUtil.h"
#include "ompl_glider/Exception.h"
#include "Quantity.h"

namespace ompl_glider
{
namespace
{
using text::lower;
using text::trim;

bool gregorianLeap(long y)
{
    return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}
bool julianLeap(long y)
{
    return y % 4 == 0;
}

/// a / b rounded towards minus infinity (b > 0), so that the leap days before a year are counted right for years
/// before 1 too (0000-12-31 is the day before 0001-01-01).
long floorDiv(long a, long b)
{
    return a / b - (a % b < 0 ? 1 : 0);
}

/// Day of the date counted from 0001-01-01 = day 0 with the Gregorian or the Julian leap rule (proleptic).
long daysProleptic(long y, int m, int d, bool gregorian)
{
    static const int cum[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
    const long y1 = y - 1;
    long days = y1 * 365 + floorDiv(y1, 4);
    if (gregorian)
        days += -floorDiv(y1, 100) + floorDiv(y1, 400);
    days += cum[m - 1] + d - 1;
    const bool leap = gregorian ? gregorianLeap(y) : julianLeap(y);
    if (leap && m > 2)
        days += 1;
    return days;
}

int daysInMonth(long y, int m, Calendar cal)
{
    static const int dim[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    switch (cal)
    {
    case Calendar::Day360:
        return 30;
    case Calendar::NoLeap:
        return dim[m - 1];
    case Calendar::AllLeap:
        return m == 2 ? 29 : dim[m - 1];
    case Calendar::Julian:
        return m == 2 && julianLeap(y) ? 29 : dim[m - 1];
    case Calendar::ProlepticGregorian:
        return m == 2 && gregorianLeap(y) ? 29 : dim[m - 1];
    case Calendar::Standard:
        return m == 2 && (y < 1583 ? julianLeap(y) : gregorianLeap(y)) ? 29 : dim[m - 1];
    }
    return 31;
}

/// Day number of a date in the calendar (0001-01-01 = 0; for Standard, 0001-01-01 Julian = 0).
long dayNumber(long y, int m, int d, Calendar cal)
{
    static const int cum[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
    switch (cal)
    {
    case Calendar::Day360:
        return (y - 1) * 360 + (m - 1) * 30 + d - 1;
    case Calendar::NoLeap:
        return (y - 1) * 365 + cum[m - 1] + d - 1;
    case Calendar::AllLeap:
        return (y - 1) * 366 + cum[m - 1] + (m > 2 ? 1 : 0) + d - 1;
    case Calendar::Julian:
        return daysProleptic(y, m, d, false);
    case Calendar::ProlepticGregorian:
        return daysProleptic(y, m, d, true);
    case Calendar::Standard: {
        // Julian up to 1582-10-04, Gregorian from 1582-10-15 (the next day).
        const bool greg = y > 1582 || (y == 1582 && (m > 10 || (m == 10 && d >= 15)));
        if (!greg)
            return daysProleptic(y, m, d, false);
        // Gregorian 1582-10-15 follows Julian 1582-10-04
        const long offset = daysProleptic(1582, 10, 4, false) + 1 - daysProleptic(1582, 10, 15, true);
        return daysProleptic(y, m, d, true) + offset;
    }
    }
    return 0;
}
} // namespace

Calendar parseCalendar(const std::string &name)
{
    static const std::map<std::string, Calendar> calendars = {
        {"", Calendar::Standard},          {"standard", Calendar::Standard},
        {"gregorian", Calendar::Standard}, {"proleptic_gregorian", Calendar::ProlepticGregorian},
        {"julian", Calendar::Julian},      {"noleap", Calendar::NoLeap},
        {"365_day", Calendar::NoLeap},     {"all_leap", Calendar::AllLeap},
        {"366_day", Calendar::AllLeap},    {"360_day", Calendar::Day360}};
    if (const auto it = calendars.find(lower(trim(name))); it != calendars.end())
        return it->second;
    throw Error("calendar '" + name +
                "': expected standard, gregorian, proleptic_gregorian, julian, noleap, 365_day, all_leap, 366_day or "
                "360_day");
}

const char *calendarName(Calendar c)
{
    switch (c)
    {
    case Calendar::Standard:
        return "standard";
    case Calendar::ProlepticGregorian:
        return "proleptic_gregorian";
    case Calendar::Julian:
        return "julian";
    case Calendar::NoLeap:
        return "noleap";
    case Calendar::AllLeap:
        return "all_leap";
    case Calendar::Day360:
        return "360_day";
    }
    return "standard";
}

namespace
{
/// A date as written: its fields and the offset of its time zone, neither range-checked nor converted to UTC.
struct WrittenDate
{
    DateTime fields;
    double zoneOffset{0.0}; ///< seconds east of UTC
};

/// The Error of a date that cannot be read: what is wrong and the syntax expected.
Error dateError(const std::string &text, const std::string &why)
{
    return Error("date '" + text + "': " + why + " (expected YYYY-MM-DD[Thh:mm[:ss]][Z|+hh:mm])");
}

/// The one reader of ISO 8601 dates (parseDateTime(), parseIsoTime()): "[-]YYYY-MM-DD[Thh:mm[:ss[.fff]]]" (a
/// leading '-' for years before 1) with T, t or spaces before the time, single-digit fields allowed, then, after
/// optional white space, a zone "Z", "UTC", "GMT", "+hh[:mm]", "+hhmm" or "-...". @throws Error (dateError()) on a
/// syntax error.
WrittenDate readWrittenDate(const std::string &text)
{
    const std::string s = trim(text);
    WrittenDate w;
    DateTime &d = w.fields;
    std::size_t pos = 0;
    auto readInt = [&](int minDigits, int maxDigits) -> long {
        const std::size_t start = pos;
        while (pos < s.size() && std::isdigit(static_cast<unsigned char>(s[pos])) &&
               static_cast<int>(pos - start) < maxDigits)
            ++pos;
        if (static_cast<int>(pos - start) < minDigits)
            throw dateError(text, "bad number at position " + std::to_string(start));
        return std::stol(s.substr(start, pos - start));
    };
    auto expect = [&](char c) {
        if (pos >= s.size() || s[pos] != c)
            throw dateError(text, std::string("expected '") + c + "' at position " + std::to_string(pos));
        ++pos;
    };
    const bool beforeYear1 = !s.empty() && s[0] == '-'; // a year before 1 (proleptic calendars), as "-0001"
    if (beforeYear1)
        ++pos;
    d.year = static_cast<int>(readInt(1, 6)) * (beforeYear1 ? -1 : 1);
    expect('-');
    d.month = static_cast<int>(readInt(1, 2));
    expect('-');
    d.day = static_cast<int>(readInt(1, 2));
    if (pos < s.size() && (s[pos] == 'T' || s[pos] == 't' || s[pos] == ' '))
    {
        ++pos;
        while (pos < s.size() && s[pos] == ' ')
            ++pos;
        if (pos < s.size() && std::isdigit(static_cast<unsigned char>(s[pos])))
        {
            d.hour = static_cast<int>(readInt(1, 2));
            expect(':');
            d.minute = static_cast<int>(readInt(1, 2));
            if (pos < s.size() && s[pos] == ':')
            {
                ++pos;
                const std::size_t start = pos;
                while (pos < s.size() && (std::isdigit(static_cast<unsigned char>(s[pos])) || s[pos] == '.'))
                    ++pos;
                if (pos == start)
                    throw dateError(text, "missing seconds");
                try
                {
                    d.second = std::stod(s.substr(start, pos - start));
                }
                catch (const std::exception &) // "." or "..": no number
                {
                    throw dateError(text, "bad seconds at position " + std::to_string(start));
                }
            }
        }
    }
    while (pos < s.size() && std::isspace(static_cast<unsigned char>(s[pos])))
        ++pos;
    if (pos < s.size())
    {
        static const std::set<std::string> utc = {"z", "utc", "gmt"};
        if (utc.count(lower(s.substr(pos))))
            pos = s.size();
        else if (s[pos] == '+' || s[pos] == '-')
        {
            const double sign = s[pos] == '-' ? -1.0 : 1.0;
            ++pos;
            const long hh = readInt(1, 2);
            long mm = 0;
            if (pos < s.size() && s[pos] == ':')
            {
                ++pos;
                mm = readInt(1, 2);
            }
            else if (pos + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[pos])))
                mm = readInt(2, 2);
            if (hh > 23 || mm > 59) // (ISO 8601: an offset is less than a day; 24:00 or 01:75 is a typing error)
                throw dateError(text, "time zone offset out of range (hours 0-23, minutes 0-59)");
            w.zoneOffset = sign * (hh * 3600.0 + mm * 60.0);
        }
        if (pos != s.size())
            throw dateError(text, "unexpected text '" + s.substr(pos) + "'");
    }
    return w;
}

/// Day number of 1970-01-01 in the proleptic Gregorian calendar (dayNumber()): the epoch of parseIsoTime().
constexpr long kUnixEpochDay = 719162;
} // namespace

namespace
{
/// readWrittenDate() with its fields range-checked (not yet against a calendar).
WrittenDate readCheckedDate(const std::string &text)
{
    const WrittenDate w = readWrittenDate(text);
    const DateTime &d = w.fields;
    if (d.month < 1 || d.month > 12 || d.day < 1 || d.day > 31 || d.hour > 24 || d.minute > 59 || d.second >= 61)
        throw dateError(text, "field out of range");
    return w;
}
} // namespace

double secondsSinceCalendarEpoch(const std::string &text, Calendar cal)
{
    const WrittenDate w = readCheckedDate(text);
    return secondsSinceCalendarEpoch(w.fields, cal) - w.zoneOffset;
}

DateTime parseDateTime(const std::string &text)
{
    const WrittenDate w = readCheckedDate(text);
    DateTime d = w.fields;
    if (w.zoneOffset != 0.0)
    {
        // shift to UTC with proleptic Gregorian arithmetic (time zones only appear with real-world calendars)
        const double t = secondsSinceCalendarEpoch(d, Calendar::ProlepticGregorian) - w.zoneOffset;
        d = dateFromCalendarEpoch(t, Calendar::ProlepticGregorian);
    }
    return d;
}

double secondsSinceCalendarEpoch(const DateTime &d, Calendar cal)
{
    if (d.month < 1 || d.month > 12 || d.day < 1 || d.day > daysInMonth(d.year, d.month, cal))
        throw Error("date " + formatDateTime(d) + " does not exist in the " + calendarName(cal) + " calendar");
    if (cal == Calendar::Standard && d.year == 1582 && d.month == 10 && d.day > 4 && d.day < 15)
        throw Error("date " + formatDateTime(d) + " does not exist in the standard (mixed Julian/Gregorian) calendar");
    return static_cast<double>(dayNumber(d.year, d.month, d.day, cal)) * 86400.0 + d.hour * 3600.0 + d.minute * 60.0 +
           d.second;
}

DateTime dateFromCalendarEpoch(double seconds, Calendar cal)
{
    long day = static_cast<long>(std::floor(seconds / 86400.0));
    double rem = seconds - static_cast<double>(day) * 86400.0;
    if (rem >= 86400.0)
    {
        ++day;
        rem -= 86400.0;
    }
    DateTime d;
    // year estimate then correct
    const double yearLen = cal == Calendar::Day360    ? 360.0
                           : cal == Calendar::NoLeap  ? 365.0
                           : cal == Calendar::AllLeap ? 366.0
                                                      : 365.25;
    long y = static_cast<long>(std::floor(static_cast<double>(day) / yearLen)) + 1;
    while (dayNumber(y, 1, 1, cal) > day)
        --y;
    while (dayNumber(y + 1, 1, 1, cal) <= day)
        ++y;
    int m = 1;
    while (m < 12 && dayNumber(y, m + 1, 1, cal) <= day)
        ++m;
    int dd = static_cast<int>(day - dayNumber(y, m, 1, cal)) + 1;
    if (cal == Calendar::Standard && y == 1582 && m == 10 && dd > 4)
        dd += 10;
    d.year = static_cast<int>(y);
    d.month = m;
    d.day = dd;
    d.hour = static_cast<int>(rem / 3600.0);
    rem -= d.hour * 3600.0;
    d.minute = static_cast<int>(rem / 60.0);
    d.second = rem - d.minute * 60.0;
    if (std::abs(d.second - std::round(d.second)) < 1e-6)
        d.second = std::round(d.second);
    if (d.second >= 60.0)
    {
        // rounding pushed us over; recompute from the rounded value
        return dateFromCalendarEpoch(std::round(seconds), cal);
    }
    return d;
}

std::string formatDateTime(const DateTime &d)
{
    char buf[64];
    if (d.second == std::floor(d.second))
        std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02dZ", d.year, d.month, d.day, d.hour, d.minute,
                      static_cast<int>(d.second));
    else
        std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%06.3fZ", d.year, d.month, d.day, d.hour, d.minute,
                      d.second);
    return buf;
}

std::string formatCalendarTime(double seconds, Calendar cal)
{
    const DateTime d = dateFromCalendarEpoch(std::round(seconds), cal);
    if (d.year < 0 || d.year > 9999)
        throw Error("the date " + formatDateTime(d) + " (" + calendarName(cal) +
                    " calendar) falls outside the years 0000-9999, which ISO 8601 dates are written in");
    return formatDateTime(d);
}

CfTimeUnits parseCfTimeUnits(const std::string &units, const std::string &calendar)
{
    const std::string s = trim(units);
    const std::string ls = lower(s);
    const std::size_t since = ls.find(" since ");
    if (since == std::string::npos)
        throw Error("time units '" + units + "': expected '<seconds|minutes|hours|days> since <date>'");
    const std::string unit = trim(ls.substr(0, since));
    // the spellings of UDUNITS' time units the CF conventions name (a unit's singular, plural and abbreviations)
    static const std::map<std::string, double> seconds = {
        {"seconds", 1.0}, {"second", 1.0}, {"secs", 1.0},     {"sec", 1.0},      {"s", 1.0},       {"minutes", 60.0},
        {"minute", 60.0}, {"mins", 60.0},  {"min", 60.0},     {"hours", 3600.0}, {"hour", 3600.0}, {"hrs", 3600.0},
        {"hr", 3600.0},   {"h", 3600.0},   {"days", 86400.0}, {"day", 86400.0},  {"d", 86400.0}};
    CfTimeUnits u;
    if (const auto it = seconds.find(unit); it != seconds.end())
        u.secondsPerUnit = it->second;
    else
        throw Error("time units '" + units + "': unit '" + unit +
                    "' not supported; expected seconds, minutes, hours or days since <date>");
    u.calendar = parseCalendar(calendar);
    u.reference = secondsSinceCalendarEpoch(s.substr(since + 7), u.calendar);
    return u;
}

double parseIsoTime(const std::string &text)
{
    const WrittenDate w = readWrittenDate(text);
    const DateTime &d = w.fields;
    const Calendar gregorian = Calendar::ProlepticGregorian;
    if (d.month < 1 || d.month > 12 || d.day < 1 || d.day > daysInMonth(d.year, d.month, gregorian) || d.hour > 23 ||
        d.minute > 59 || d.second >= 61.0)
        throw Error("'" + text + "' is not a valid date-time");
    const long days = dayNumber(d.year, d.month, d.day, gregorian) - kUnixEpochDay;
    return static_cast<double>(days) * 86400.0 + d.hour * 3600.0 + d.minute * 60.0 + d.second - w.zoneOffset;
}

bool isoYearInRange(double s)
{
    // 0000-01-01T00:00:00Z and 10000-01-01T00:00:00Z in seconds since 1970 (proleptic Gregorian)
    return s >= -62167219200.0 && s < 253402300799.5; // formatIsoTime() rounds to the second
}

std::string formatIsoTime(double s)
{
    if (!std::isfinite(s))
        return "";
    if (!isoYearInRange(s))
        throw Error("the time " + std::to_string(s) +
                    " s since 1970 falls outside the years 0000-9999, which ISO "
                    "8601 dates are written in");
    // whole seconds: the date is exact (dateFromCalendarEpoch() of an integral number of seconds)
    const long long since1 = std::llround(s) + static_cast<long long>(kUnixEpochDay) * 86400;
    return formatDateTime(dateFromCalendarEpoch(static_cast<double>(since1), Calendar::ProlepticGregorian));
}

double parseDuration(const std::string &text, double timeUnitSeconds, bool unitKnown)
{
    const std::string expected =
        "expected a duration > 0: a number in the mission's time unit, or e.g. '1 h', '30 min', '2 d'; got '" + text +
        "'";
    double value = 0.0;
    std::string unit;
    if (!io_detail::splitQuantity(text, value, unit))
        throw Error(expected);
    static const std::map<std::string, double> units = {{"s", 1.0}, {"min", 60.0}, {"h", 3600.0}, {"d", 86400.0}};
    const auto it = units.find(unit);
    if (it == units.end() && !unit.empty())
        throw Error(expected);
    const double seconds = it == units.end() ? 0.0 : it->second;
    if (!std::isfinite(value) || !(value > 0.0))
        throw Error(expected);
    if (unit.empty())
        return value;
    if (!unitKnown)
        throw Error("'" + text + "' needs the mission's time unit: give units.time_s, or the duration as a number");
    const double v = value * seconds / timeUnitSeconds;
    if (!std::isfinite(v))
        throw Error(expected);
    return v;
}
} // namespace ompl_glider
