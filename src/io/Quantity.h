#pragma once
/// @file Quantity.h
/// @brief Internal to src/io: a number followed by an optional unit ("500 m", "1 h", "2.5"), as lengths and
/// durations are given.
#include <cstdlib>
#include <string>

namespace ompl_glider::io_detail
{
/// Splits @p text into its leading number and the unit after it (spaces trimmed; empty when none). False when the
/// text does not begin with a number.
inline bool splitQuantity(const std::string &text, double &value, std::string &unit)
{
    const char *begin = text.c_str();
    char *end = nullptr;
    value = std::strtod(begin, &end);
    if (end == begin)
        return false;
    unit = end;
    const std::size_t a = unit.find_first_not_of(' '), b = unit.find_last_not_of(' ');
    unit = a == std::string::npos ? std::string() : unit.substr(a, b - a + 1);
    return true;
}
} // namespace ompl_glider::io_detail
