#pragma once
/// @file Length.h
/// @brief Lengths given as text: a keep-off distance, a depth limit.

#include <string>

namespace ompl_glider
{
/// @brief A length >= 0 in planning units: a number (planning units), or "<number> m|km" (also without the space)
/// converted with @p metresPerUnit metres per planning unit; @p unitKnown false (an analytic flow without
/// units.length_m) refuses the second form. @throws Error saying what was expected (the caller adds where).
double parseLength(const std::string &text, double metresPerUnit, bool unitKnown);
} // namespace ompl_glider
