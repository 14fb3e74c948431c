#pragma once
/// @file Observations.h
/// @brief A glider's measurements in a mission: where the plan starts (the last fix) and what correcting the forecast
/// with its depth-averaged currents did (MissionProblem::observations()). (Only with OMPL_GLIDER_WITH_NETCDF.)

#include <cstddef>
#include <map>
#include <optional>
#include <string>

#include "ompl_glider/current/CorrectedField.h"
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
    std::size_t future{0};                       ///< rejected: measured after the plan's departure
    CorrectionSummary correction;     ///< what the correction used, rejected and did (RMS innovation before / after)
    CorrectionParams params;          ///< L, T, s_o / s_f as used
    std::optional<GliderFix> lastFix; ///< the latest position reported
};

/// @brief Where @p m starts when it gives no start: its observations' last fix (lon/lat), and its departure at the
/// fix's time unless @p keepDeparture. The start and departure are marked as given at @p mark (the observations'
/// line, or the flag or keyword that gave them).
/// @throws Error (without the place: the caller names it) when they cannot be read or report no fix.
void startAtLastFix(MissionSpec &m, const SourceMark &mark, bool keepDeparture);

class MissionProblem;
/// @brief "glider observations 'PATH' (ru29): 12 DAC used; rejected 1 QC flag 4 (u_qc), 2 after the departure; RMS
/// innovation 0.12 m/s before, 0.01 m/s after the correction"; empty without observations.
std::string observationNote(const MissionProblem &problem);
} // namespace ompl_glider
