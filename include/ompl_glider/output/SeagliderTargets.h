#pragma once
/// @file SeagliderTargets.h
/// @brief The Seaglider targets file: one target per line, `NAME lat=DDMM.MMMM lon=DDDMM.MMMM radius=R goto=NEXT`
/// (degrees and decimal minutes with the sign on the whole number, also below one degree: `-0030.0000`), lines
/// starting with `/` are comments, and the last target's `goto` names itself so that the glider holds there.

#include <cstddef>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
struct MissionResult;
class MissionProblem;

/// @brief One target of the file.
struct SeagliderTarget
{
    std::string name;     ///< letters, digits, '_' and '-'
    LonLat position;      ///< degrees (longitude in -180..180)
    double radius{100.0}; ///< metres: the target counts as reached within it
    std::string next;     ///< the target flown to after this one (its own name for the last)
    /// How the glider gets here where it is not by steering to the target, and what it does here: the heading to
    /// hold (headingNote()), the stay (stayNote()); written as a comment line before the target, empty: none
    std::string note;
};

/// @brief Signed degrees as the targets file's latitude, [-]DDMM.MMMM (two digits of degrees, minutes rounded to
/// 1e-4 on whole 1e-4 minutes, so that 41.99999999 gives "4200.0000").
std::string seagliderLatitude(double degrees);
/// @brief Signed degrees as the targets file's longitude, [-]DDDMM.MMMM (three digits of degrees).
std::string seagliderLongitude(double degrees);

/// @brief The targets of a planned route: one per turn the goto list keeps (gotoWaypointIndices(), every via point
/// among them) after the start, named after the via points (their radius where given), the other turns "T1", "T2",
/// ... and the goal "GOAL" (outputs.goto_wpt_dist as their radius), each pointing to the next, the last to itself.
/// A target reached by a held heading carries the heading and how long (the pilot sets $HEADING for that time), a via
/// point with a stay the stay (SeagliderTarget::note). A mission resumed during a stay (resumedStay()) begins with
/// the station, named after it, and that stay's note: the glider holds there until the plan departs.
/// @throws Error when the mission has no longitudes and latitudes.
std::vector<SeagliderTarget> seagliderTargets(const MissionResult &result, const MissionProblem *problem);

/// @brief The file's text: a comment header naming the mission, then one line per target, each after its note as a
/// comment line ("/ to here: hold heading ...", "/ stay at A: ...").
std::string formatSeagliderTargets(const std::vector<SeagliderTarget> &targets, const std::string &mission);
} // namespace ompl_glider
