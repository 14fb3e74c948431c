#pragma once
/// @file InputDigest.h
/// @brief A digest of what a mission reads, for the processes of a job to agree on (TaskSpreader::agree()).

#include <cstdint>

#include "ompl_glider/mission/MissionSpec.h"

namespace ompl_glider
{
/// @brief A 64-bit digest (FNV-1a) of what planning @p spec reads: the mission file's bytes, and of every input file
/// it names (forecast files, ensemble members, the truth, bathymetry, coastline, forbidden-region GeoJSON) its size
/// and first and last 64 KiB: contents, not paths. Two processes that read different versions of a file get
/// different digests (a change only in the middle of a large file excepted). Files that cannot be read count as their
/// path alone.
std::uint64_t inputDigest(const MissionSpec &spec);
} // namespace ompl_glider
