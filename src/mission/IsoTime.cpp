#include "ompl_glider/mission/IsoTime.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <regex>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
// Days from 1970-01-01 to y-m-d in the proleptic Gregorian calendar (H. Hinnant's civil-date algorithm).
long long daysFromCivil(long long y, unsigned m, unsigned d)
{
    y -= m <= 2;
    const long long era = (y >= 0 ? y : y - 399) / 400;
    const unsigned yoe = static_cast<unsigned>(y - era * 400);
    const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + static_cast<long long>(doe) - 719468;
}

void civilFromDays(long long z, long long &y, unsigned &m, unsigned &d)
{
    z += 719468;
    const long long era = (z >= 0 ? z : z - 146096) / 146097;
    const unsigned doe = static_cast<unsigned>(z - era * 146097);
    const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    y = static_cast<long long>(yoe) + era * 400;
    const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const unsigned mp = (5 * doy + 2) / 153;
    d = doy - (153 * mp + 2) / 5 + 1;
    m = mp < 10 ? mp + 3 : mp - 9;
    y += m <= 2;
}

unsigned daysInMonth(long long y, unsigned m)
{
    static const unsigned dm[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    return m == 2 && leap ? 29 : dm[m - 1];
}
}  // namespace

double parseIsoTime(const std::string &text)
{
    static const std::regex re(
        R"(^\s*(-?\d{4})-(\d{2})-(\d{2})(?:[T ](\d{2}):(\d{2})(?::(\d{2}(?:\.\d+)?))?)?\s*(Z|[+-]\d{2}(?::?\d{2})?)?\s*$)");
    std::smatch m;
    if (!std::regex_match(text, m, re))
        throw Error("'" + text + "' is not an ISO 8601 date-time (expected YYYY-MM-DDThh:mm:ssZ)");
    const long long y = std::stoll(m[1]);
    const unsigned mo = static_cast<unsigned>(std::stoul(m[2])), d = static_cast<unsigned>(std::stoul(m[3]));
    const int hh = m[4].matched ? std::stoi(m[4]) : 0, mm = m[5].matched ? std::stoi(m[5]) : 0;
    const double ss = m[6].matched ? std::stod(m[6]) : 0.0;
    if (mo < 1 || mo > 12 || d < 1 || d > daysInMonth(y, mo) || hh > 23 || mm > 59 || ss >= 61.0)
        throw Error("'" + text + "' is not a valid date-time");
    double offset = 0.0;
    if (m[7].matched && m[7].str() != "Z")
    {
        const std::string z = m[7];
        const int sign = z[0] == '-' ? -1 : 1;
        const int oh = std::stoi(z.substr(1, 2));
        const std::string rest = z.size() > 3 ? z.substr(z[3] == ':' ? 4 : 3) : "0";
        offset = sign * (oh * 3600.0 + std::stoi(rest) * 60.0);
    }
    return static_cast<double>(daysFromCivil(y, mo, d)) * 86400.0 + hh * 3600.0 + mm * 60.0 + ss - offset;
}

std::string formatIsoTime(double s)
{
    if (!std::isfinite(s))
        return "";
    const long long total = std::llround(s);
    long long days = total / 86400, rem = total % 86400;
    if (rem < 0)
    {
        rem += 86400;
        --days;
    }
    long long y;
    unsigned m, d;
    civilFromDays(days, y, m, d);
    char buf[48];
    std::snprintf(buf, sizeof buf, "%04lld-%02u-%02uT%02lld:%02lld:%02lldZ", y, m, d, rem / 3600, (rem / 60) % 60,
                  rem % 60);
    return buf;
}
double parseDuration(const std::string &text, double timeUnitSeconds, bool unitKnown)
{
    const std::string expected =
        "expected a duration > 0: a number in the mission's time unit, or e.g. '1 h', '30 min', '2 d'; got '" + text +
        "'";
    const char *begin = text.c_str();
    char *end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin)
        throw Error(expected);
    std::string unit(end);
    const std::size_t a = unit.find_first_not_of(' '), b = unit.find_last_not_of(' ');
    unit = a == std::string::npos ? std::string() : unit.substr(a, b - a + 1);
    double seconds = 0.0;
    if (unit == "s")
        seconds = 1.0;
    else if (unit == "min")
        seconds = 60.0;
    else if (unit == "h")
        seconds = 3600.0;
    else if (unit == "d")
        seconds = 86400.0;
    else if (!unit.empty())
        throw Error(expected);
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
}  // namespace ompl_glider
