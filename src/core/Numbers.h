#pragma once
// Constants the library's files share: each is defined once here, never again in a file's own unnamed namespace, so
// that files compiled together (the unity build, CMakeLists.txt) see one definition.
#include <limits>

namespace ompl_glider
{
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kRadPerDeg = kPi / 180.0; ///< degrees to radians
inline constexpr double kDegPerRad = 180.0 / kPi; ///< radians to degrees
} // namespace ompl_glider
