#pragma once
/// @file Observations.h
/// @brief A glider's measurements in a mission: where the plan starts (the last fix) and what correcting the forecast
/// with its depth-averaged currents did (MissionProblem::observations()). (Only with OMPL_GLIDER_WITH_NETCDF.)

#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/current/CorrectedField.h"
#include "ompl_glider/current/EnsembleLearning.h"
#include "ompl_glider/io/GliderObservations.h"
#include "ompl_glider/mission/MissionSpec.h"

namespace ompl_glider
{
/// @brief What the observations gave and did.
struct ObservationReport
{
    std::string source;                          ///< the path given
    std::size_t files{0};                        ///< files read
    std::string platform;                        ///< the glider
    std::map<std::string, std::size_t> rejected; ///< by the reader, by reason
    std::map<std::string, std::size_t> notes;    ///< the reader's notes of what it kept (GliderObservations::notes)
    std::size_t future{0};                       ///< rejected: measured after the plan's departure
    /// rejected: farther from the mission's area (its planning box) than 10 length scales (farDistance)
    std::size_t far{0};
    double farDistance{0.0};      ///< that distance (planning units)
    CorrectionSummary correction; ///< what the correction used, rejected and did (RMS innovation before / after)
    /// correction.meanInnovation turned from the planning frame's x/y into east/north at the DAC's mean position
    /// (the frame's grid north is not true north away from the projection's centre); field units
    Velocity meanInnovationEastNorth;
    CorrectionParams params; ///< L, T, s_o / s_f as used (estimated ones in place of their priors)
    /// An ensemble forecast: each member's weight, RMS innovation and coefficient (EnsembleLearning.h); empty: none
    std::vector<MemberScore> members;
    std::optional<GliderFix> lastFix; ///< the latest position reported
    std::vector<GliderFix> fixes;     ///< every position reported, in time order (the glider's track on the maps)
    std::vector<DacRecord> dac;       ///< every DAC read (before the departure's cut), in time order
    /// What each DAC was compared with, for a pilot ("the forecast's 0-180 m average (current.depth_average)", "the
    /// surface current ..."): a DAC is an average over the dive, a surface current is not
    std::string comparedWith;
    /// The deepest dive the DAC report (m; NaN: their files give no depths)
    double deepestDive{std::numeric_limits<double>::quiet_NaN()};
};

/// @brief The glider's surfacing fixes of @p o: its fixes but the positions a source gives only for a DAC (IOOS files
/// and ERDDAP put a DAC at the middle of its dive: no fix); where the source gives no other position (a CSV of DAC),
/// every fix, and @p dacOnly (when given) says so. What the maps draw as the glider's track.
std::vector<GliderFix> surfacingFixes(const ObservationReport &o, bool *dacOnly = nullptr);

/// @brief The glider's observations at @p path (IOOS profile files, Slocum dba files, a CSV or an ERDDAP URL) read:
/// the one reader of them for the mission loader and forecastMission() (the command line's `--currents` and
/// Python's plan() without a start), whose last fix is the start's first guess. Handed on with keepObservations(),
/// the mission's inputs (ProblemInputs.h) take them from there instead of reading them again.
/// @throws Error when they cannot be read (without the place: the caller names it).
std::shared_ptr<const GliderObservations> readObservationsAt(const std::string &path, const std::string &cache = "");

/// @brief Keeps @p read in @p s (ObservationsSpec::read) as what its path and cache hold.
void keepObservations(ObservationsSpec &s, std::shared_ptr<const GliderObservations> read);

/// @brief Marks @p m's start (and its departure when @p departure) as the last fix's first guess (Origin::Observations
/// at @p mark's place), which resumeAtLastFix() replaces by the fix it reads when the mission is made.
void markLastFixGuess(MissionSpec &m, const SourceMark &mark, bool departure);

/// @brief Where @p m starts when it gives no start: its observations' last fix (lon/lat), and its departure at the
/// fix's time unless @p keepDeparture, marked as the observations' (Origin::Observations, at @p mark's place) until
/// the mission resumes there (resumeAtLastFix()): a front end's first guess, so that a forecast's region and
/// departure can be checked before the mission is made.
/// @throws Error (without the place: the caller names it) when they cannot be read or report no fix.
void startAtLastFix(MissionSpec &m, const SourceMark &mark, bool keepDeparture);

/// @brief The one place a mission resumes at the glider's last fix (loadProblemInputs() does it for every front
/// end): with observations that have files, a mission of one glider starts at the last fix unless a flag, a keyword or
/// the calling program gave the start (a mission file's start is the deployment's: replaced), and departs at the fix's
/// time unless they gave the departure (which may then not be before the fix). The fixes are judged from the
/// mission's own departure (the deployment's, also where a caller's departure replaced it: DepartureSpec::replaced;
/// every fix where the mission gives none) to the last fix. Via points already reached (in the order listed, any
/// order with `order: free`) are dropped: reached at a fix within their radius, but before their window opens only
/// when the glider is still there when it opens (else the visit does not count); one reached after its window
/// closed is dropped with a warning (DroppedStation::windowClosed). A stay counts the time between fixes within
/// the radius from the window's opening on. A stay under way at the last fix, the glider within the radius, is
/// finished first (the plan departs at its end, after the window's opening where the glider waits for it, and
/// after a departure given); a stay the glider left unfinished keeps the station, first, with what is left of its
/// stay (MissionResume::leftStay: the plan returns there). The others keep their names, radii, windows and stays.
/// What it did is kept in MissionSpec::observations->resumed. Done once.
/// Returns the observations (read once: ObservationsSpec::read when a front end read them), null when it did not
/// resume.
/// @throws Error (without the place) when the observations cannot be read, report no fix, a given departure is before
/// the last fix, or the glider has already reached every via point and the goal (nothing is left to plan).
std::shared_ptr<const GliderObservations> resumeAtLastFix(MissionSpec &m);

/// @brief What a pilot must be warned of in resuming @p m (empty when it was not resumed, or nothing is amiss): a
/// station reached after its window closed, a stay the glider left unfinished (the plan returns there), a last
/// fix older than the newest surfacing.
std::vector<std::string> resumeWarnings(const MissionSpec &m);
/// @brief "from the last fix -52.1, 48.0 at 2026-03-16T12:00:00Z (replacing the start -52.7, 47.9, the deployment's);
/// stations reached: A (2026-03-15T18:02:11Z, 120 m from it)"; empty when the mission was not resumed.
std::string resumeNote(const MissionSpec &m);

class MissionProblem;
/// @brief "glider observations 'PATH' (ru29): 12 DAC used; rejected 1 QC flag 4 (u_qc), 2 after the departure; RMS
/// innovation 0.12 m/s before, 0.01 m/s after the correction"; empty without observations.
std::string observationNote(const MissionProblem &problem);

/// @brief "L 31.2 km (estimated from 120 DAC), T 1 d 4 h (default), ratio 0.2 (given); ln likelihood +12.3 over the
/// priors; bias (0.05 m/s, -0.02 m/s), M2 0.11 m/s; members by weight: #3 0.61 (RMS 0.02 m/s), ..."; empty without
/// observations.
std::string correctionNote(const MissionProblem &problem);
} // namespace ompl_glider
