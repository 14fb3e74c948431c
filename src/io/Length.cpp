// Lengths given as text (see Length.h).
#include "ompl_glider/io/Length.h"

#include <cmath>
#include <cstdlib>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
double parseLength(const std::string &text, double metresPerUnit, bool unitKnown)
{
    const std::string expected =
        "expected a length >= 0: a number in the mission's length unit, or e.g. '500 m', '2 km'; got '" + text + "'";
    const char *begin = text.c_str();
    char *end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin)
        throw Error(expected);
    std::string unit(end);
    const std::size_t a = unit.find_first_not_of(' '), b = unit.find_last_not_of(' ');
    unit = a == std::string::npos ? std::string() : unit.substr(a, b - a + 1);
    double metres = 0.0;
    if (unit == "m")
        metres = 1.0;
    else if (unit == "km")
        metres = 1000.0;
    else if (unit == "nmi")
        metres = 1852.0;
    else if (!unit.empty())
        throw Error(expected);
    if (!std::isfinite(value) || !(value >= 0.0))
        throw Error(expected);
    if (unit.empty())
        return value;
    if (!unitKnown)
        throw Error("'" + text + "' needs the mission's length unit: give units.length_m, or the length as a number "
                    "in planning units");
    const double v = value * metres / metresPerUnit;
    if (!std::isfinite(v))
        throw Error(expected);
    return v;
}
}  // namespace ompl_glider
