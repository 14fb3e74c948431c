#pragma once
/// @file ObservationReaders.h
/// @brief Internal to src/io (not installed): the readers of readGliderObservations() (GliderObservations.h) beyond
/// the IOOS profile files and the CSV of GliderObservations.cpp: an ERDDAP tabledap answer over HTTP
/// (ErddapObservations.cpp) and Slocum dba files (SlocumDba.cpp). Each fills what it reads into a GliderObservations:
/// files, platform, the usable DAC (in any order, per-profile repeats left out), every fix, the rejected records by
/// reason; readGliderObservations() then sorts them, counts the repeated times and sets the last fix when the reader
/// has not.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "ompl_glider/io/GliderObservations.h"

namespace ompl_glider::observations_detail
{
/// The reason a DAC record is not usable (no time or position, a position out of range, faster than
/// kMaxPlausibleDac); empty when it is usable. The checks every format shares.
std::string dacProblem(const DacRecord &r);

/// The name @p counts counts most (the first of the equals in name order): a deployment's glider among the files.
inline std::string mostNamed(const std::map<std::string, std::size_t> &counts)
{
    std::string most;
    for (const auto &[name, count] : counts)
        if (most.empty() || count > counts.at(most))
            most = name;
    return most;
}

/// The reason of a record whose u or v is a fill value (missing, NaN, -999).
inline const char *const kFillValue = "fill value";

/// True for units of metres per second as files spell them ("m/s", "m s-1", "m.s-1", "m s^-1", "meters/second"; an
/// empty unit is taken as m/s). Other velocity units are refused by the readers that cannot convert them (the unit
/// conversion of forecasts lives in current/, above this layer).
bool isMetresPerSecond(const std::string &units);

/// Reads an ERDDAP tabledap URL's answer (.csvp, .csv or .ncCF) into @p o (see GliderObservations.h).
/// @throws Error naming the URL: a server down, too slow or refusing (ERDDAP's own message quoted), an HTML page, an
/// answer without the expected columns, a cell that is not a number.
void readErddap(const std::string &url, GliderObservations &o);

/// True when @p file is a Slocum dba file (dbd2asc's output): a name ending ".dba", or a first line "dbd_label:".
bool isDbaFile(const std::string &file);

/// Reads Slocum dba files (one glider's deployment) into @p o. @throws Error naming the file and line of a file that
/// is not dbd2asc's layout, and the file and sensor when m_present_time, m_gps_lat/lon or m_water_vx/vy is missing.
void readDbaFiles(const std::vector<std::string> &files, GliderObservations &o);
} // namespace ompl_glider::observations_detail
