/// @file DegMin.cpp
/// @brief The Slocum's decimal-minute coordinates (DegMin.h).

#include "ompl_glider/io/DegMin.h"

#include <cmath>
#include <exception>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
double parseDegMin(const std::string &text)
{
    std::size_t pos = 0;
    double v = 0.0;
    try
    {
        v = std::stod(text, &pos);
    }
    catch (const std::exception &)
    {
        throw Error("'" + text + "' is not a [-]DDDMM.MMMM coordinate");
    }
    if (pos != text.size() || !std::isfinite(v))
        throw Error("'" + text + "' is not a [-]DDDMM.MMMM coordinate");
    const double a = std::abs(v);
    const double deg = std::floor(a / 100.0);
    const double minutes = a - 100.0 * deg;
    if (minutes >= 60.0)
        throw Error("'" + text + "': minutes must be < 60");
    const double d = deg + minutes / 60.0;
    return v < 0 ? -d : d;
}
} // namespace ompl_glider
