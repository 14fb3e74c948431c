#pragma once
/// @file NumberText.h
/// @brief Internal to the library (not installed): numbers as text in the messages, reports and route files.

#include <cmath>
#include <cstdio>
#include <string>

namespace ompl_glider::text
{
/// @brief @p v with @p digits significant digits, printf's "%.<digits>g" (number(0.1) is "0.1"); 17 digits give
/// back the same double when read.
inline std::string number(double v, int digits = 10)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

/// @brief printf's formatting of up to five numbers into a message ("%.3g time steps of %.3g"): estimates and
/// limits quoted with the precision the message chooses.
inline std::string formatted(const char *fmt, double a, double b = 0.0, double c = 0.0, double d = 0.0, double e = 0.0)
{
    char buf[512];
    std::snprintf(buf, sizeof buf, fmt, a, b, c, d, e);
    return buf;
}

/// @brief A number for a CSV cell: empty for NaN or an infinity (no value), else number(v, 10).
inline std::string csvNumber(double v)
{
    if (!std::isfinite(v))
        return ""; // no value (summary.json's null): "inf" is no number to a CSV reader
    return number(v, 10);
}

/// @brief A duration for people with its SI value beside it: "15 d 9.1 h (1328826.6 s)", "9.1 h (32760.0 s)",
/// "12.5 min (750.0 s)"; "inf" for an infinity, csvNumber() for NaN or a negative value.
inline std::string durationText(double seconds)
{
    if (std::isinf(seconds))
        return seconds > 0 ? "inf" : "-inf";
    if (!std::isfinite(seconds) || seconds < 0.0)
        return csvNumber(seconds);
    char buf[96];
    const double hours = seconds / 3600.0;
    if (hours < 1.0)
        std::snprintf(buf, sizeof buf, "%.1f min (%.1f s)", seconds / 60.0, seconds);
    else if (hours < 24.0)
        std::snprintf(buf, sizeof buf, "%.1f h (%.1f s)", hours, seconds);
    else
    {
        double days = std::floor(hours / 24.0), rest = std::round((hours - 24.0 * days) * 10.0) / 10.0;
        if (rest >= 24.0) // (23.96 h rounds to 24.0: one more day)
            days += 1.0, rest = 0.0;
        std::snprintf(buf, sizeof buf, "%.0f d %.1f h (%.1f s)", days, rest, seconds);
    }
    return buf;
}
} // namespace ompl_glider::text
