#pragma once
/// @file DegMin.h
/// @brief Coordinates in the Slocum glider's decimal-minute format [-]DDDMM.MMMM (the sign on the whole number), as
/// goto lists (output/SlocumGoto.h) and the glider's own sensors (m_gps_lat, m_gps_lon of its dba files) write them.

#include <string>

namespace ompl_glider
{
/// @brief "-7030.5000" -> -70.508333... (degrees); the inverse of formatDegMin() (output/SlocumGoto.h). Throws Error
/// on text that is not a number or whose minutes are >= 60.
double parseDegMin(const std::string &text);
} // namespace ompl_glider
