#pragma once
/// @file Overrides.h
/// @brief What a front end may change in a mission: one typed set for glider_plan's flags and the Python module's
/// keywords, checked once here. Each value carries the name the user gave it by (a flag, "--speed", or a keyword,
/// "plan(): keyword 'speed'"), so that this check and every later one (MissionSpec::place()) name it.

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/mission/MissionSpec.h"

namespace ompl_glider
{
/// @brief A value a front end gives, with the name it was given by.
template <class T> struct Given
{
    T value{};
    std::string source; ///< "--speed", "plan(): keyword 'speed'"
};

/// @brief The changes a front end asks of a mission; what is not set stays as the mission has it.
struct MissionOverrides
{
    Origin origin{Origin::Flag}; ///< what gives the values: a flag or a keyword (their sources name them)
    /// How the front end names the mission's settings; set on the mission (MissionSpec::words) when given
    std::shared_ptr<const SettingWords> words;
    std::optional<Given<std::string>> planner; ///< a name or alias of the registry
    /// planner parameters by name (merged over the mission's; a planner other than the mission's drops them first)
    std::optional<Given<std::map<std::string, std::string>>> plannerParameters;
    std::optional<Given<double>> gridSize;      ///< > 0, finite
    std::optional<Given<int>> sectors;          ///< kMinSectors..kMaxSectors
    std::optional<Given<double>> timeLimit;     ///< seconds > 0
    std::optional<Given<double>> horizon;       ///< > 0, in the mission's time unit
    std::optional<Given<double>> goalTolerance; ///< > 0, in the mission's length unit
    std::optional<Given<bool>> smoothing, refinement, globalCheck;
    std::optional<Given<double>> speed; ///< through the water, > 0 (vehicle and travel-time speed)
    /// one departure (a number in the mission's time unit, or an ISO 8601 date): replaces a departure window
    std::optional<Given<std::string>> departure;
    /// lon, lat where the mission gives lon/lat, else x, y
    std::optional<Given<Point2>> start, goal;
    /// x_min, y_min, x_max, y_max (lon/lat likewise)
    std::optional<Given<std::array<double, 4>>> region;
    std::optional<Given<std::string>> coastline;    ///< a coastline file (GeoJSON, shapefile, ...)
    std::optional<Given<std::string>> outDirectory; ///< outputs.directory
    /// the goal's arrival window: begin and end, each read as the departure is
    std::optional<Given<std::pair<std::string, std::string>>> arrivalWindow;
    std::optional<Given<bool>> isochrones;               ///< add the isochrone output
    std::optional<Given<std::string>> isochroneInterval; ///< a duration ("6 h", or a number in the time unit)
    std::optional<Given<double>> gotoTurn;               ///< the goto list's turn threshold, degrees in 0..180
    std::optional<Given<std::string>> holdTolerance;     ///< the uploads' merged holds: metres, or "0.5 km"
    std::optional<Given<bool>> reachability; ///< add the probability-of-reach output (format "reachability")
    /// the probability of reach's horizon, frame interval (durations: "10 d", or a number in the time unit) and cell
    /// (a length: "2 km", or a number in the length unit); each also adds the output
    std::optional<Given<std::string>> reachHorizon;
    std::optional<Given<std::string>> reachInterval;   ///< see reachHorizon
    std::optional<Given<std::string>> reachResolution; ///< see reachHorizon
    /// via points in place of the mission's (positions lon, lat where the mission gives lon/lat, else x, y; names,
    /// radii, windows and stays as the front end gives them: an empty name becomes "WP1", "WP2", ...)
    std::optional<Given<std::vector<ViaPointSpec>>> via;
    std::optional<Given<std::string>> order; ///< "given" or "free"
    /// the glider's observations (IOOS profile files or a CSV: MissionSpec::observations; the mission's correction
    /// parameters kept, else the defaults)
    std::optional<Given<std::string>> observations;
    /// the folder of a Slocum's cache files for the observations' binary files (ObservationsSpec::cache)
    std::optional<Given<std::string>> observationsCache;
    /// the correction's settings (ObservationsSpec): length and time scales as text (a number in the mission's units,
    /// or with a unit: "20 km", "1 d"), the error ratio (> 0), whether to learn from the DAC
    std::optional<Given<std::string>> correctionLength;
    std::optional<Given<std::string>> correctionTime; ///< see correctionLength
    std::optional<Given<double>> errorRatio;          ///< see correctionLength
    std::optional<Given<bool>> learn;                 ///< see correctionLength

    // safety (safety.*): lengths as text, a number in the mission's length unit or with a unit ("2 km", "500 m")
    std::optional<Given<std::string>> keepOff;            ///< the keep-off distance from land, >= 0
    std::optional<Given<std::string>> minDepth;           ///< the depth limit (a bare number is metres), >= 0
    std::optional<Given<std::string>> bathymetry;         ///< a NetCDF file of seafloor depth or elevation
    std::optional<Given<std::string>> bathymetryVariable; ///< its depth variable (needs a bathymetry or forecast)
    std::optional<Given<bool>> snapToWater;               ///< a start or goal on land moved to the nearest water

    // execution in another ocean (execution.*): any of these flies the plan
    /// the ocean flown in: "forecast", another forecast (files: a comma-separated list or glob, read with the
    /// forecast's variables) for a forecast mission, NAME=VALUE,... of the analytic flow's parameters otherwise
    std::optional<Given<std::string>> truth;
    std::optional<Given<std::string>> surfacingInterval;       ///< a duration ("1 h", or a number in the time unit)
    std::optional<Given<std::vector<std::string>>> strategies; ///< ExecutionStrategy names, each once
    std::optional<Given<double>> radius;                       ///< the goal radius, > 0 (length unit)
    std::optional<Given<long long>> executionPairs;            ///< random start/goal pairs, 0..100000
    std::optional<Given<long long>> executionSeed;             ///< their seed, 0..4294967295
    std::optional<Given<std::string>> acrossRuns;              ///< "carry" or "reset" (forecast runs only)
};

/// @brief Applies @p o to @p m: each value checked (finite, in its range, a planner of the registry, a time the
/// mission can read), the mission's marks set to the value's source so that later checks name it.
/// @throws Error "SOURCE: what was wrong" for the first bad value; @p m is then unchanged.
void applyOverrides(const MissionOverrides &o, MissionSpec &m);

/// @brief The fields MissionOverrides can change, as text (numbers in the shortest form that reads back as the same
/// double), by their dotted names, then "given": those of them the file, a flag or a keyword gave. What two front
/// ends must agree on when given the same overrides (glider_plan --show-mission, Python's Mission.fields()).
std::vector<std::pair<std::string, std::string>> overridableFields(const MissionSpec &m);
} // namespace ompl_glider
