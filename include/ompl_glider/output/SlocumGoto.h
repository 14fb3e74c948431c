#pragma once
/// @file SlocumGoto.h
/// @brief The Slocum glider goto list file (goto_lNN.ma) and its [-]DDDMM.MMMM coordinates ([EichhornOceans]
/// Sec. IV).

#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/io/DegMin.h" // parseDegMin(): the inverse of formatDegMin()

namespace ompl_glider
{
/// @brief Decimal degrees as the Slocum [-]DDDMM.MMMM text: degrees * 100 + minutes, minutes rounded to 1e-4.
/// The rounding is done on whole 1e-4 minutes so that 41.99999999 gives "4200.0000", never "4160.0000".
std::string formatDegMin(double degrees);

/// @brief Contents of a goto list file.
struct GotoList
{
    int number{10};                ///< NN of goto_lNN.ma (0..99)
    std::vector<LonLat> waypoints; ///< in the order the glider flies them (written with longitudes in -180..180)
    int numLegsToRun{-2};          ///< b_arg num_legs_to_run: -2 = traverse the list once, -1 = loop
    int startWhen{0};              ///< b_arg start_when: 0 = immediately
    int listStopWhen{7};           ///< b_arg list_stop_when: 7 = when the waypoint distance is reached
    int initialWpt{0};             ///< b_arg initial_wpt: 0 = the first waypoint
    double listWhenWptDist{100.0}; ///< b_arg list_when_wpt_dist (m): a waypoint is reached this close (stop when 7)
    std::string comment;           ///< free comment written under the behavior line (one line)
    /// Per waypoint (same index; shorter or empty: none): a comment line written just before its waypoint line
    /// (a heading route's heading to hold, a stay: gotoList()); one line each, read back by parseGotoList()
    std::vector<std::string> notes;
};

/// @brief "goto_lNN.ma" for a list number (two digits); throws Error outside 0..99.
std::string gotoFileName(int number);

/// @brief The goto list as text: behavior_name=goto_list, a `<start:b_arg>` ... `<end:b_arg>` block with
/// num_legs_to_run, start_when, list_stop_when, list_when_wpt_dist, initial_wpt and num_waypoints, then
/// `<start:waypoints>`, one waypoint per line as "longitude latitude" in [-]DDDMM.MMMM (preceded by a line "# note"
/// where GotoList::notes has one), and `<end:waypoints>`.
std::string formatGotoList(const GotoList &list);

/// @brief Writes formatGotoList() to @p path (throws Error when the file cannot be written).
void writeGotoFile(const std::string &path, const GotoList &list);

/// @brief Parses goto-list text (comments after '#' ignored, but for a comment line just before a waypoint line:
/// its note); checks that num_waypoints matches the waypoint lines.
/// @p source names the text in error messages.
GotoList parseGotoList(const std::string &text, const std::string &source = "goto list");

/// @brief Reads and parses a goto list file; the number is taken from the name when it is goto_lNN.ma.
GotoList readGotoFile(const std::string &path);
} // namespace ompl_glider
