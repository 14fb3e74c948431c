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

/// @brief A number for a CSV cell: empty for NaN, "inf" or "-inf" for an infinity, else number(v, 10).
inline std::string csvNumber(double v)
{
    if (std::isnan(v))
        return "";
    if (std::isinf(v))
        return v > 0 ? "inf" : "-inf";
    return number(v, 10);
}
}  // namespace ompl_glider::text
