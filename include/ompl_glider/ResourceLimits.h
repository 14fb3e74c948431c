#pragma once
/// @file ResourceLimits.h
/// @brief The memory a planning run may plan to use, and the check made before a large allocation (a lattice's
/// arrays, a forecast's hyperslab): refuse with the estimate and a hint instead of failing inside the allocator.

#include <cstddef>
#include <string>

namespace ompl_glider
{
// The work a planner parameter controls, refused before the search with the estimate (PipelinePlanner::prepare())
inline constexpr double kMaxLevelSetSteps = 1e6;  ///< level-set time steps over the planning window
inline constexpr double kMaxLevelSetWork = 2e11;  ///< level-set grid nodes x time steps
inline constexpr double kMaxWavefrontNodes = 1e7; ///< Wavefront space-time nodes before the fastest arrival
inline constexpr double kMaxStintBearings = 360;  ///< CTS-A* bearings per expansion (1 degree)
inline constexpr double kMaxStintFlights = 7.2e7; ///< CTS-A* bearings x its expansion cap

/// @brief The memory limit in bytes: the environment variable OMPL_GLIDER_MEMORY_LIMIT (bytes, or a number with
/// the suffix K, M, G or T, powers of 1024) when set, else half of the physical memory, and never more than three
/// quarters of the address-space limit (ulimit -v) when one is set.
/// @throws Error when OMPL_GLIDER_MEMORY_LIMIT is not such a number.
std::size_t memoryLimitBytes();

/// @brief "1.5 GB", "820 MB", "12 kB": a byte count for messages.
std::string formatBytes(double bytes);

/// @brief Throws Error "<what> needs about <bytes>, more than the memory limit of <limit> (...): <hint>" when
/// @p bytes exceeds memoryLimitBytes().
void checkMemory(double bytes, const std::string &what, const std::string &hint);
} // namespace ompl_glider
