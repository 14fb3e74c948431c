#pragma once
/// @file Length.h
/// @brief Lengths given as text: a keep-off distance, a depth limit.

#include <string>

namespace ompl_glider
{
/// @brief A length >= 0 in planning units: a number (planning units), or "<number> <unit>" (also without the space;
/// m, km, nmi, and with the NetCDF component any length UDUNITS-2 reads: cm, mi, ft, yd, ...) converted with @p
/// metresPerUnit metres per planning unit; @p unitKnown false (an analytic flow without units.length_m) refuses the
/// second form. @throws Error saying what was expected (the caller adds where).
double parseLength(const std::string &text, double metresPerUnit, bool unitKnown);

/// @brief A speed > 0 in m/s: a number (m/s), or "<number> <unit>" in any velocity UDUNITS-2 reads (m/s, kn, km/h,
/// cm/s; with the NetCDF component). @throws Error saying what was expected (the caller adds where).
double parseSpeed(const std::string &text);
} // namespace ompl_glider
