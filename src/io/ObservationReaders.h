#pragma once
/// @file ObservationReaders.h
/// @brief Internal to src/io (not installed): the readers of readGliderObservations() (GliderObservations.h) beyond
/// the IOOS profile files and the CSV of GliderObservations.cpp: an ERDDAP tabledap answer over HTTP
/// (ErddapObservations.cpp) and a Slocum glider's dba and binary files (SlocumDba.cpp, SlocumBinary.cpp: one table,
/// SlocumTable.h; SlocumDive.cpp: its fixes and DAC over the dives). Each fills what it reads into a
/// GliderObservations: files, platform, the usable DAC (in any order, per-profile repeats left out), every fix, the
/// rejected records by reason; readGliderObservations() then sorts them, counts the repeated times and sets the last
/// fix when the reader has not.

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "ompl_glider/Exception.h"
#include "ompl_glider/io/GliderObservations.h"
#include "ompl_glider/io/UnitConversion.h"

namespace ompl_glider::observations_detail
{
/// How a reader's DAC velocities become m/s: the unit as the source wrote it and its conversion (UDUNITS-2,
/// UnitConversion.h).
struct VelocityUnits
{
    std::string units;         ///< as written ("" when the source gives none: read as m/s)
    LinearConversion toMetres; ///< to m/s
    /// @p x in m/s; a NaN or the fill value -999 as it is (the readers reject them as fill values)
    double operator()(double x) const { return !std::isfinite(x) || x == -999.0 ? x : toMetres(x); }
};

/// The conversion of @p units (of the DAC variable or column @p name) to m/s: any velocity UDUNITS-2 reads ("m s-1",
/// "cm/s", "knots", ...); none is m/s. @throws Error "<where>: '<name>' is in '<units>': <why>" for a unit that is no
/// velocity ("degC") or that UDUNITS-2 cannot read.
VelocityUnits velocityUnits(const std::string &name, const std::string &units, const std::string &where);

/// The reason a DAC record is not usable (no time or position, a position out of range, faster than
/// kMaxPlausibleDac, with the unit @p units it was read in); empty when it is usable. The checks every format shares.
std::string dacProblem(const DacRecord &r, const VelocityUnits &units = {});

/// The glider most of a deployment's files name (@p counts: files by glider). @throws Error naming @p source when two
/// gliders have as many files each: which one is meant is the pilot's to say.
inline std::string mostNamed(const std::map<std::string, std::size_t> &counts, const std::string &source)
{
    std::string most;
    for (const auto &[name, count] : counts)
        if (most.empty() || count > counts.at(most))
            most = name;
    for (const auto &[name, count] : counts)
        if (name != most && count == counts.at(most))
        {
            const auto named = [](const std::string &g) { return g.empty() ? std::string("(unnamed)") : g; };
            throw Error("observations '" + source + "': as many files of glider '" + named(most) + "' as of '" +
                        named(name) + "' (" + std::to_string(count) +
                        " each): give one glider's files (a folder of its own, or a pattern such as '" +
                        (most.empty() ? name : most) + "*')");
        }
    return most;
}

/// The reason of a record whose u or v is a fill value (missing, NaN, -999).
inline const char *const kFillValue = "fill value";

/// Reads an ERDDAP tabledap URL's answer (.csvp, .csv or .ncCF) into @p o (see GliderObservations.h).
/// @throws Error naming the URL: a server down, too slow or refusing (ERDDAP's own message quoted), an HTML page, an
/// answer without the expected columns, a cell that is not a number.
void readErddap(const std::string &url, GliderObservations &o);

/// True when @p file is a Slocum dba file (dbd2asc's output): a name ending ".dba", or a first line "dbd_label:".
bool isDbaFile(const std::string &file);

/// True when @p file is a Slocum binary file (SlocumBinary.h): its extension (isSlocumBinaryName()), or a first line
/// "dbd_label: DBD(dinkum_binary_data)file".
bool isSlocumBinaryFile(const std::string &file);

/// Reads a Slocum glider's dba and binary files (one glider's deployment; @p cacheDir: the folder of the binary files'
/// cache files, or empty) into @p o. @throws Error naming the file and line (or byte) of a file that is not dbd2asc's
/// layout or the binary format, and the file and sensor when m_present_time, m_gps_lat/lon or m_water_vx/vy is
/// missing.
void readSlocumFiles(const std::vector<std::string> &files, const std::string &cacheDir, GliderObservations &o);
} // namespace ompl_glider::observations_detail
