#pragma once
// What the files of src/mission/inputs/ share: each reads one kind of input into ProblemInputs (ProblemInputs.h),
// in the order loadProblemInputs() calls them (ProblemInputs.cpp).

#include <memory>
#include <string>

#include "ompl_glider/mission/ProblemInputs.h"

namespace ompl_glider
{
struct LoadedForecast;
struct CurrentFieldKind;

namespace inputs_detail
{
// ProblemField.cpp

/// The forecast (or analytic flow) and its frame's projection and units.
void loadField(ProblemInputs &in);
/// What a loaded gridded forecast gives the inputs besides its field: the frame's projection and units, the files
/// read, the notes, the remote sources, whether it is of winds.
void keepForecast(ProblemInputs &in, const LoadedForecast &forecast);
/// An ensemble's members after the first (the forecast); the field becomes their mean.
void loadMembers(ProblemInputs &in);
/// The truth an execution flies in (MissionSpec::execution.truth).
void loadTruth(ProblemInputs &in);
/// A current source other than the forecast (a truth, an ensemble member) on the forecast's frame and dates;
/// errors name @p field.
std::shared_ptr<const CurrentField> loadSource(const ProblemInputs &in, const CurrentSpec &source,
                                               const std::string &field);

// Runs.cpp

/// A forecast given as runs (current.runs): in.runs, in.run (the newest available at the departure) and the field,
/// frame and notes of that run, read as the mission given its file alone reads it.
void loadRuns(ProblemInputs &in, const CurrentFieldKind &kind);
/// With forecast runs and a correction by the DAC in use (the glider's observations, or an execution's dac or
/// replan_observed): in.runSpread over the planning box (reads every run), and a note saying what it gave.
void estimateRunSpread(ProblemInputs &in);

// FieldChecks.cpp

/// A glider's depth on a forecast without depth levels is refused.
void checkDepthAxis(const MissionSpec &m, const LoadedForecast &forecast);
/// Ensemble members without a common time are refused, each named with its span.
void checkCommonTime(const ProblemInputs &in);
/// Analytic fields are finite over the box (their parameters do not overflow), and the box is not too wide.
void checkAnalyticFields(const ProblemInputs &in);

// Frame.cpp

/// The planning box: the mission's region (x/y, or the projected outline of its lon/lat box), else the grid's
/// extent; the field's time span; the depth range. A lon/lat start or goal outside the region is refused.
Region planningBox(const ProblemInputs &in);

// Resume.cpp

/// The glider's observations (MissionSpec::observations), read once: what a front end read already, else read
/// now; null without files.
std::shared_ptr<const GliderObservations> observationsOf(const MissionSpec &m);
/// A glider resumed at a last fix after the forecast's end is refused, naming both.
void checkLastFixInForecast(const ProblemInputs &in);

// LandInputs.cpp

/// The coastline's land polygons that meet the box (with a margin of a tenth of its size), and what they gave.
void readCoastline(ProblemInputs &in);
/// The depth limit's bathymetry over the box (MissionSpec::safety): its own file, else the forecast's.
void readDepthLimit(ProblemInputs &in);
/// The dive profiles' bathymetry (MissionSpec::dive): a constant depth or a file over the box.
void readDiveBathymetry(ProblemInputs &in);
} // namespace inputs_detail
} // namespace ompl_glider
