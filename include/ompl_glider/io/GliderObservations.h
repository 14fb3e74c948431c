#pragma once
/// @file GliderObservations.h
/// @brief A glider deployment's depth-averaged currents (DAC) and fixes, read from the IOOS glider DAC profile NetCDF
/// files (templates v2.0 to v4.0: one file per profile, scalars `time_uv`, `lat_uv`, `lon_uv`, `u`, `v`,
/// `profile_time/lat/lon`, fill values, `*_qc` flags) or from a plain CSV (`time,lon,lat,u,v`). Bad records are
/// rejected and counted by reason; a source with nothing usable is refused naming the file and variable.

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
/// @brief One depth-averaged current.
struct DacRecord
{
    double time{0.0}; ///< seconds since 1970-01-01T00:00:00Z: the middle of the dive it averages
    LonLat at;        ///< degrees (longitude -180..180): the middle of the dive
    double u{0.0};    ///< eastward, m/s
    double v{0.0};    ///< northward, m/s
    std::string file; ///< the file it came from
};

/// @brief A position the glider reported.
struct GliderFix
{
    double time{0.0}; ///< seconds since 1970-01-01T00:00:00Z
    LonLat at;        ///< degrees (longitude -180..180)
};

/// @brief What a deployment's files gave.
struct GliderObservations
{
    std::string source;               ///< the path given (file, folder or glob pattern)
    std::size_t files{0};             ///< files read
    std::string platform;             ///< the glider (IOOS `platform:id`, else `trajectory`); empty for a CSV
    std::vector<DacRecord> dac;       ///< usable records, in time order
    std::optional<GliderFix> lastFix; ///< the latest position reported (a profile's or a DAC's, a CSV row's)
    /// every position reported (profiles' fixes, usable DAC's positions, CSV rows), in time order, one per time:
    /// where the glider has been (the stations a resumed mission has reached, the glider's track on the map)
    std::vector<GliderFix> fixes;
    std::map<std::string, std::size_t> rejected; ///< rejected records by reason ("QC flag 4", "fill value", ...)
};

/// @brief The most a DAC may be (m/s): faster records are rejected as implausible.
constexpr double kMaxPlausibleDac = 3.0;

/// @brief Reads @p path: a .csv file, a NetCDF file, a folder of NetCDF (.nc) files, or a glob pattern of them (one
/// deployment). IOOS files of another glider than most of them are rejected with the reason. CSV: a header naming
/// the columns time, lon, lat, u, v (any order); time an ISO 8601 date or seconds since 1970; u and v empty for a fix
/// without a DAC. @throws Error naming the file (and line or variable) for a file that cannot be read, a CSV line that
/// is not numbers, a NetCDF file without the DAC variables, or when no record is usable.
GliderObservations readGliderObservations(const std::string &path);

/// @brief "12 used; rejected: 2 QC flag 4, 1 fill value" of what @p o holds.
std::string observationsText(const GliderObservations &o);
} // namespace ompl_glider
