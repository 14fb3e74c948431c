#pragma once
/// @file IsoTime.h
/// @brief ISO 8601 UTC date-times <-> seconds since 1970-01-01T00:00:00Z (proleptic Gregorian calendar), for
/// mission epochs and the arrival times of the outputs.

#include <string>

namespace ompl_glider
{
/// @brief Parses "YYYY-MM-DD", "YYYY-MM-DDThh:mm[:ss[.fff]]" (T or a space) with an optional "Z" or "+hh:mm" /
/// "-hh:mm" offset (converted to UTC). @throws Error naming the text when it is not such a date or the date
/// does not exist.
double parseIsoTime(const std::string &text);

/// @brief "YYYY-MM-DDThh:mm:ssZ" (rounded to the second).
std::string formatIsoTime(double secondsSince1970);

/// @brief A duration in field units: a number (field units), or "<number> s|min|h|d" (also without the space)
/// converted with @p timeUnitSeconds seconds per field unit; @p unitKnown false (an analytic flow without
/// units.time_s) refuses the second form. @throws Error saying what was expected (the caller adds where).
double parseDuration(const std::string &text, double timeUnitSeconds, bool unitKnown);
}  // namespace ompl_glider
