// Lengths given as text (see Length.h).
#include "ompl_glider/io/Length.h"

#include <cmath>
#include <cstdlib>
#include <map>

#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/io/UnitConversion.h"
#endif
#include "Quantity.h"

namespace ompl_glider
{
double parseLength(const std::string &text, double metresPerUnit, bool unitKnown)
{
    const std::string expected = "expected a length >= 0: a number in the mission's length unit, or e.g. '500 m', "
                                 "'2 km', '20 mi', '65000 ft'; got '" +
                                 text + "'";
    double value = 0.0;
    std::string unit;
    if (!io_detail::splitQuantity(text, value, unit))
        throw Error(expected);
    static const std::map<std::string, double> units = {{"m", 1.0}, {"km", 1000.0}, {"nmi", 1852.0}};
    double metres = 0.0;
    if (const auto it = units.find(unit); it != units.end())
        metres = it->second;
    else if (!unit.empty())
    {
#if OMPL_GLIDER_WITH_NETCDF
        // any length UDUNITS-2 reads: "500 cm", "20 mi", "65000 ft", "3 nautical_miles"
        try
        {
            const LinearConversion c = lengthToMetres(unit);
            if (c.offset != 0.0 || !(c.factor > 0.0))
                throw Error(expected);
            metres = c.factor;
        }
        catch (const Error &e)
        {
            throw Error(expected + " (" + e.what() + ")");
        }
#else
        throw Error(expected);
#endif
    }
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

double parseSpeed(const std::string &text)
{
    const std::string expected =
        "expected a speed > 0: a number in m/s, or e.g. '500 m/s', '1000 kn'; got '" + text + "'";
    double value = 0.0;
    std::string unit;
    if (!io_detail::splitQuantity(text, value, unit) || !std::isfinite(value) || !(value > 0.0))
        throw Error(expected);
    if (unit.empty() || unit == "m/s")
        return value;
#if OMPL_GLIDER_WITH_NETCDF
    try
    {
        const LinearConversion c = velocityToMetresPerSecond(unit);
        const double v = c(value);
        if (c.offset == 0.0 && std::isfinite(v) && v > 0.0)
            return v;
    }
    catch (const Error &e)
    {
        throw Error(expected + " (" + e.what() + ")");
    }
#endif
    throw Error(expected);
}
} // namespace ompl_glider
