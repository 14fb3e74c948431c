#pragma once
/// @file GliderObservations.h
/// @brief A glider deployment's depth-averaged currents (DAC) and fixes, read from the IOOS glider DAC profile NetCDF
/// files (templates v2.0 to v4.0: one file per profile, scalars `time_uv`, `lat_uv`, `lon_uv`, `u`, `v`,
/// `profile_time/lat/lon`, fill values, `*_qc` flags), from a plain CSV (`time,lon,lat,u,v`), and in real time from
/// the IOOS Glider DAC's ERDDAP (a tabledap URL answering .csvp, .csv or .ncCF) or a Slocum glider's own dba files
/// (dbd2asc's ASCII tables: m_present_time, m_gps_lat/lon, m_gps_status, m_water_vx/vy). Bad records are rejected and
/// counted by reason; a source with nothing usable is refused naming the file and variable, or the URL.

#include <cstddef>
#include <limits>
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
    /// the segment the DAC averages over: the fix before the dive and the fix after it (seconds since 1970); NaN
    /// where the source does not say (IOOS files and ERDDAP give only the segment's mean time and position)
    double segmentStart{std::numeric_limits<double>::quiet_NaN()};
    double segmentEnd{std::numeric_limits<double>::quiet_NaN()}; ///< see segmentStart
    /// the dive's depth range (m, positive down) where the source gives it (the depths the glider reported over the
    /// segment, a profile's depth variable); NaN where it does not
    double depthMin{std::numeric_limits<double>::quiet_NaN()};
    double depthMax{std::numeric_limits<double>::quiet_NaN()}; ///< see depthMin
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
    std::string source;   ///< the path given (file, folder or glob pattern), or the URL (no credentials)
    std::size_t files{0}; ///< files read (1 for a URL: its answer)
    /// the glider (IOOS `platform:id`, else `trajectory`; ERDDAP: the dataset id without its deployment date,
    /// "ru29-20260315T0000" -> "ru29"; dba: the header's `filename` without its year, day, mission and segment,
    /// "ru29-2026-074-0-12" -> "ru29"); empty for a CSV
    std::string platform;
    std::vector<DacRecord> dac;       ///< usable records, in time order
    std::optional<GliderFix> lastFix; ///< the latest position reported (a profile's or a DAC's, a CSV row's)
    /// every position reported (profiles' fixes, usable DAC's positions, CSV rows), in time order, one per time:
    /// where the glider has been (the stations a resumed mission has reached, the glider's track on the map)
    std::vector<GliderFix> fixes;
    std::map<std::string, std::size_t> rejected; ///< rejected records by reason ("QC flag 4", "fill value", ...)
    /// what the reader did that a pilot should know, by what, counted (records kept, files skipped): Slocum files,
    /// "DAC placed at the surfacing's fix (no fix before the dive: its start unknown)", science files without fixes
    std::map<std::string, std::size_t> notes;
    /// the time of the newest surfacing the source reports, its fix rejected or not (seconds since 1970; NaN when
    /// none is known): later than lastFix when the newest fixes were rejected (69696969, a bad GPS status). Slocum
    /// files: the newest GPS fix reported, valid or not; a CSV: its newest row; IOOS files and ERDDAP: NaN (they give
    /// profiles and the DAC's mean times, no surfacing)
    double newestSurfacing{std::numeric_limits<double>::quiet_NaN()};
};

/// @brief The most a DAC may be (m/s): faster records are rejected as implausible.
constexpr double kMaxPlausibleDac = 3.0;

/// @brief How readGliderObservations() reads.
struct ObservationReadOptions
{
    /// the folder of a Slocum's cache files (`<sensor_list_crc>.cac`, the sensor lists factored out of its binary
    /// files); empty: beside the files, then a `cache/` folder beside them (searched after this one too)
    std::string cache;
};

/// @brief Reads @p path (one deployment): a .csv file; a NetCDF file, a folder of NetCDF (.nc) files, or a glob
/// pattern of them; a Slocum dba file (.dba, or a first line `dbd_label:`), a folder of .dba files or a glob pattern
/// of them; Slocum binary files (SlocumBinary.h), a folder or a pattern of them; or an ERDDAP tabledap URL (http://
/// or https://). Files of another glider than most of them are rejected with the reason.
///
/// CSV: a header naming the columns time, lon, lat, u, v (any order); time an ISO 8601 date or seconds since 1970;
/// u and v empty for a fix without a DAC.
///
/// ERDDAP (the IOOS Glider DAC's, e.g. `https://gliders.ioos.us/erddap/tabledap/ru29-20260315T0000.csvp?time,latitude,
/// longitude,profile_id,time_uv,lat_uv,lon_uv,u,v,u_qc,v_qc&time>=2026-03-15T00:00:00Z`): the answer's kind from the
/// URL's file type, .csvp (units in the header's parentheses), .csv (a line of units) or .ncCF (read in memory; the
/// variables by name, all on one dimension: a contiguous ragged profile dimension or flat rows). Each row's time,
/// latitude, longitude is a fix; a profile's DAC (time_uv, lat_uv, lon_uv, u, v) is taken once, from its first row
/// (by profile_id, else by time_uv), and rejected for a fill value (empty, NaN, -999) or a QC flag 3, 4 or 9. Fetched
/// with the process's request time limit and retries (RemoteSource.h), never cached (real-time data).
///
/// Slocum dba and binary files (one table of sensors either way, then one processing): fixes from m_gps_lat/m_gps_lon
/// ([-]DDMM.MMMM) at m_present_time, rejected for the placeholder 69696969, half a position, or a latest m_gps_status
/// other than 0. Consecutive valid fixes are one surfacing unless a dive lies between them (an m_depth of 4 m or more
/// reported between them; without depths, more than 15 min between them). A DAC from a cycle with m_water_vx,
/// m_water_vy (m/s; other units refused) is the mean current over the dive that ended at the surfacing of the latest
/// valid fix at or before it (at most 30 min before; none: rejected): it is placed at the mean time and position of
/// the segment from the fix before the dive (the last valid fix of the surfacing before) to the fix after it (the
/// first valid fix of this surfacing), as the IOOS files place theirs, with segmentStart, segmentEnd and the m_depth
/// range over the segment; with no fix before the dive, at the latest fix at or before it (counted in notes).
/// Binary files without the glider's fixes and DAC (science files) are skipped and counted in notes.
///
/// @throws Error naming the file (and line or variable) for a file that cannot be read, a CSV or dba line that is not
/// numbers, a NetCDF file without the DAC variables, a dba file without its label lines or a sensor, a binary file
/// cut short, of an unknown encoding version, with bad known bytes or without its cache file; naming the URL
/// for a server down, too slow or refusing (ERDDAP's own message), an HTML page, an answer without the columns; or
/// when no record is usable.
GliderObservations readGliderObservations(const std::string &path, const ObservationReadOptions &options = {});

/// @brief "12 DAC from 3 file(s) of glider 'ru29'; rejected: 2 QC flag 4, 1 fill value; 1 DAC placed at ..." of what
/// @p o holds: its DAC, files, glider, rejected records and notes.
std::string observationsText(const GliderObservations &o);
} // namespace ompl_glider
