#pragma once
/// @file UnitConversion.h
/// @brief Unit strings read with UDUNITS-2 (part of the NetCDF component: the forecasts, the depths and a glider's
/// DAC): velocities to m/s, lengths to metres.
///
/// Any spelling UDUNITS-2 parses is understood ("m s-1", "m/s", "cm/s", "centimeter/s", "cm s-1", "centimeters per
/// second", "knots", "kt", "km/h", "mm/s", "furlongs/fortnight", ...). UDUNITS-2 is case-sensitive ("S" is the
/// siemens); a string it does not read as the wanted quantity is tried again in lower case, so "M/S", "CM/S" and
/// "KT" keep working. A few spellings found in forecast files that UDUNITS-2 does not read as velocities ("mps",
/// "kn", "ms-1" written without a space, ...) are translated first. The unit database is loaded once (thread-safely)
/// from UDUNITS-2's installed XML files (or the file named by the environment variable UDUNITS2_XML_PATH); every
/// call into UDUNITS-2 is serialised, and its error messages are silenced while it runs.

#include <string>

namespace ompl_glider
{
/// @brief y = factor * x + offset.
struct LinearConversion
{
    double factor{1.0};
    double offset{0.0};

    double operator()(double x) const { return factor * x + offset; }
    bool identity() const { return factor == 1.0 && offset == 0.0; }
};

/// @brief The conversion of values in `units` to metres per second.
/// @throws Error "units '<units>' not understood (UDUNITS-2 cannot parse them); expected a velocity such as m/s,
/// cm/s, knots" or "units '<units>' are not a velocity (UDUNITS-2 reads them as '<canonical>', not convertible to
/// m/s)".
LinearConversion velocityToMetresPerSecond(const std::string &units);

/// @brief The conversion of values in `units` to metres.
/// @throws Error "units '<units>' not understood ..." or "units '<units>' are not a length ...".
LinearConversion lengthToMetres(const std::string &units);

/// @brief True when UDUNITS-2 reads `units` as dimensionless: "" , "1", "count", "percent", and angles such as
/// "degrees_east" (the radian is dimensionless). False when it cannot parse them.
bool isDimensionless(const std::string &units);
} // namespace ompl_glider
