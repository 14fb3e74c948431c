#pragma once
/// @file ProblemInputs.h
/// @brief Everything a mission reads from files and URLs, read once and in one place (src/mission/inputs/): the
/// glider's observations, the forecast (or analytic flow), an ensemble's members, the truth, the coastline, the
/// bathymetry of the depth limit and of the dive profiles, and the planning frame they are read in. The problem
/// (MissionProblem.h) is built from them and reads nothing itself.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/current/ForecastRuns.h"
#include "ompl_glider/current/ForecastSource.h"
#include "ompl_glider/io/Coastline.h"
#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/mission/MissionSpec.h"

namespace ompl_glider
{
class LocalProjection;
class Bathymetry;
struct DepthGrid; // io/DepthGrid.h (installed with NetCDF)
struct GliderObservations;

/// @brief The planning frame: its projection (lon/lat <-> x/y), its units and its box.
struct PlanningFrame
{
    std::shared_ptr<const LocalProjection> projection; ///< null: the mission has no lon/lat
    double projectionScale{1.0};                       ///< metres per planning unit
    double xyScale{1.0}; ///< planning units per x/y unit given (a Cartesian forecast's axes in km: 1000)
    Region box;          ///< the planning box (x/y) and the field's time span
    std::string file;    ///< the mission file, for messages

    /// @brief True when lon/lat can be computed (projection given or geographic forecast).
    bool isGeographic() const { return static_cast<bool>(projection); }
    /// @brief Planning frame -> lon/lat (longitude in -180..180). @throws Error without a projection.
    LonLat toGeographic(Point2 p) const;
    /// @brief lon/lat -> planning frame. @throws Error without a projection.
    Point2 toLocal(LonLat g) const;
};

/// @brief What a mission read, once: the inputs of MissionProblem.
struct ProblemInputs
{
    /// The mission as read: resumed at the glider's last fix (its start, departure and stations left), the
    /// integration's step bounded by the forecast's grid (travel.maxStep)
    MissionSpec spec;
    /// The glider's observations as read (null: the mission gives none)
    std::shared_ptr<const GliderObservations> observations;
    /// The field planned on before the observations correct it: the forecast or analytic flow, an ensemble's mean
    std::shared_ptr<const CurrentField> field;
    /// An ensemble's members (the first read as the forecast); empty for a single source
    std::vector<std::shared_ptr<const CurrentField>> members;
    /// The ocean an execution flies in (null: the forecast)
    std::shared_ptr<const CurrentField> truth;
    /// The forecast's runs (`current.runs`; null: one forecast): `field` is run `run`, the newest available at the
    /// departure
    std::shared_ptr<const ForecastRuns> runs;
    std::size_t run{0}; ///< the run planned on
    /// The forecast error's spread the runs show where they overlap (the correction's priors; unset: not estimated)
    std::optional<RunSpread> runSpread;
    PlanningFrame frame;                    ///< the frame everything is read in
    std::vector<std::string> forecastFiles; ///< the forecast's files or URLs read, in time order
    std::vector<std::string> forecastNotes; ///< what reading the forecast decided that a pilot should know
    std::vector<RemoteFetch> remoteSources; ///< the forecast's OPeNDAP sources: network or cache
    bool wind{false};                       ///< the forecast is of winds (uwnd, u10, ...)
    std::vector<LandPolygon> coastline;     ///< the coastline's land polygons about the box (lon/lat)
    std::string coastlineNote;              ///< what the coastline gave and what was repaired; "" without one
    /// The depth limit's bathymetry about the box (null without a depth limit) and the file it came from
    std::shared_ptr<const DepthGrid> depthGrid;
    std::string depthGridFile;
    /// The dive profiles' bathymetry (null: dive profiles off, or no bathymetry)
    std::shared_ptr<const Bathymetry> diveBathymetry;
};

/// @brief Reads what @p spec names (src/mission/inputs/): each file and URL once.
/// @throws Error naming the setting and file when something cannot be read or does not fit.
ProblemInputs loadProblemInputs(MissionSpec spec);

/// @brief Smallest margin of a trip's region (km).
constexpr double kMinTripMarginKm = 25.0;

/// @brief The margin (km) of a trip's region around its start and goal: half their great-circle distance, at
/// least kMinTripMarginKm (room for the detours a current forces).
double tripMarginKm(LonLat start, LonLat goal);

/// @brief What a mission asks of its gridded source (ForecastSource.h): the files, variable names (lon/lat, else
/// x/y), interpolation schemes, horizon policy, depth range, projection, the settings' names in the mission file's
/// words (forecastFieldNames("current")) and the region to load: the mission's region, else the trip's. For
/// lon/lat start and goal that is tripBox() of the two with tripMarginKm(): their lon/lat box the shorter way
/// round (across the antimeridian or Greenwich when that is shorter, in whatever convention they are written),
/// widened by the margin converted to degrees of latitude and of longitude at the box's highest |latitude|, up to
/// +-kMaxGridLatitude; never rebuilt from projected corners. For x/y start and goal (a Cartesian file): their box
/// plus half its larger side (at least 0.2 units) on each side. The projection's reference is the region's
/// centre. Shared by loadProblemInputs() and forecastMission() so that a forecast from the command line and the
/// same forecast in a mission file are the same problem.
/// @throws Error for a lon/lat start or goal within 90 - kMaxGridLatitude degrees of a pole (naming it).
ForecastRequest forecastRequest(const MissionSpec &mission);

/// @brief How a mission file calls the settings of a forecast request in its section @p section ("current",
/// "execution.truth", "current.ensemble[1]"): "current.variables.u", "current.time_units", ...
std::map<ForecastOption, std::string> forecastFieldNames(const std::string &section);
} // namespace ompl_glider
