#pragma once
/// @file Sectors.h
/// @brief The range of the lattice's n-sector connectivity ([EichhornRAS] Sec. 4: 1 gives the 8 compass
/// neighbours), declared once for the planners, the mission loader, the command line and Python.

namespace ompl_glider
{
inline constexpr int kMinSectors = 1; ///< fewest sectors
inline constexpr int kMaxSectors = 5; ///< most sectors
} // namespace ompl_glider
