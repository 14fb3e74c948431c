// Lengths given as text (see Length.h).
#include "ompl_glider/io/Length.h"

#include <cmath>
#include <cstdlib>

#include "ompl_glider/Exception.h"
#include "Quantity.h"

namespace ompl_glider
{
double parseLength(const std::string &text, double metresPerUnit, bool unitKnown)
{
    const std::string expected =
        "expected a length >= 0: a number in the mission's length unit, or e.g. '500 m', '2 km'; got '" + text + "'";
    double value = 0.0;
    std::string unit;
    if (!io_detail::splitQuantity(text, value, unit))
        throw Error(expected);
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
        throw Error("'" + text +
                    "' needs the mission's length unit: give units.length_m, or the length as a number "
                    "in planning units");
    const double v = value * metres / metresPerUnit;
    if (!std::isfinite(v))
        throw Error(expected);
    return v;
}
} // namespace ompl_glider
