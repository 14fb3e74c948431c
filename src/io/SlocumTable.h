#pragma once
/// @file SlocumTable.h
/// @brief Internal to src/io (not installed): the one table a Slocum glider's files give the observations, whether
/// read from a dba file (dbd2asc's ASCII, SlocumDba.cpp) or decoded from the glider's binary files (SlocumBinary.h):
/// per cycle the values of the sensors the DAC and the fixes are read from, NaN where a sensor reported nothing.
/// One processing path (SlocumDive.cpp) turns the tables of a deployment into fixes and DAC over the dives.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace ompl_glider::observations_detail
{
/// The sensors the observations are read from, as the columns of a SlocumTable.
enum SlocumColumn : std::size_t
{
    kTime,   ///< m_present_time (s since 1970)
    kLat,    ///< m_gps_lat ([-]DDMM.MMMM)
    kLon,    ///< m_gps_lon ([-]DDMM.MMMM)
    kStatus, ///< m_gps_status (0: a valid fix)
    kVx,     ///< m_water_vx (the DAC's east component)
    kVy,     ///< m_water_vy (its north component)
    kDepth,  ///< m_depth (m)
    kColumns
};

/// The sensors' names, in the columns' order.
inline const std::array<const char *, kColumns> kSlocumSensors = {
    "m_present_time", "m_gps_lat", "m_gps_lon", "m_gps_status", "m_water_vx", "m_water_vy", "m_depth"};

/// One Slocum file's cycles of the sensors the observations need.
struct SlocumTable
{
    std::string file;
    std::string platform;     ///< the glider (the file name without year, day, mission, segment)
    std::string sensorsWhere; ///< where the sensor names are, for the messages ("f.dba:15", "f.sbd (its sensor list)")
    std::string unitsWhere;   ///< where their units are ("f.dba:16")
    bool binary{false};       ///< decoded from a binary file (a file without the sensors is a science file, skipped)
    std::array<bool, kColumns> present{};           ///< the file has the sensor
    std::array<std::string, kColumns> units;        ///< as the file writes them
    std::vector<std::array<double, kColumns>> rows; ///< the cycles reporting any of them (NaN: no value)
};

/// The glider of a Slocum file name "<glider>-<year>-<day>-<mission>-<segment>" ("ru29-2026-074-0-12" -> "ru29").
std::string slocumGliderOf(const std::string &filename);

/// The table of a dba file. @throws Error naming the file and line of a file that is not dbd2asc's layout.
SlocumTable readDbaTable(const std::string &file);

/// The table of a Slocum binary file (SlocumBinary.h; @p cacheDir: the cache folder given, or empty).
SlocumTable readBinaryTable(const std::string &file, const std::string &cacheDir);
} // namespace ompl_glider::observations_detail
