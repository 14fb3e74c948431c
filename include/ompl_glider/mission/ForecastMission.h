#pragma once
/// @file ForecastMission.h
/// @brief A mission on a NetCDF forecast from a handful of inputs (the command line's `--currents FILE` mode):
/// the file is read once to check the request and to convert the start, goal and departure, and the MissionSpec
/// it gives is planned by the same pipeline as every other mission.

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"

namespace ompl_glider
{
/// @brief What a forecast mission needs beyond the pipeline's settings.
struct ForecastInput
{
    /// The forecast as a mission file's `current` section describes it (type netcdf): `file` (one file) or `files`
    /// (several read as one, ordered by their dates; then `file` must be empty), variables, interpolation, horizon
    /// policy, unit overrides, steady record, zero-velocity land, depth average. The mission takes it as it is.
    CurrentSpec current;
    double depth{0.0}; ///< depth (m, positive down) at which the current is read
    Point2 start;      ///< start: lon,lat (x = lon, y = lat; longitude in -180..180 or 0..360, whatever the file's
                       ///< convention) for a geographic file, x,y for a Cartesian one
    Point2 goal;       ///< goal, as start
    /// Region to load and plan in, as given (unchecked): for a geographic file x = lon, y = lat (xMin = lon_min,
    /// xMax = lon_max, in either convention, xMax < xMin across the antimeridian: regionFault()); for a Cartesian
    /// file x/y bounds. Messages quote it in GeoJSON bbox order (xMin, yMin, xMax, yMax). None: the trip's region
    /// (netCdfLoadOptions()).
    std::optional<Box> region;
    /// ISO 8601 date or seconds after the first forecast time; empty: the first forecast time. A steady field takes
    /// any departure; for a steady file without dates, a date is the date of field time 0 (the outputs' ISO times).
    std::string departure;
    /// Start at the glider's last fix instead of `start`: the last fix of `observations` (readObservationsAt(); its
    /// time is the departure too where none is given), named in messages "the last fix of <observations' word>", marked
    /// as the observations' first guess until the mission resumes there (resumeAtLastFix())
    bool startAtLastFix{false};
    std::string observations;      ///< the glider's observations (MissionSpec::observations' path) for startAtLastFix
    std::string observationsCache; ///< the folder of a Slocum's cache files (ObservationsSpec::cache), or empty
    double speed{0.3};             ///< vehicle speed through water, m/s
    /// a start or goal on the forecast's land is moved to the nearest water (MissionSpec::safety.snapToWater); else
    /// it is refused, the message naming the nearest water
    bool snapToWater{false};
    /// How the caller names the settings in messages and marks ("start" -> "--start" on the command line,
    /// "plan(): keyword 'start'" in Python; MissionSpec::words of the mission made); null: by their mission fields,
    /// as values the calling program gave (Origin::Program)
    std::shared_ptr<const SettingWords> words;
};

/// @brief The MissionSpec of a forecast, the same as a mission file with the same current, region, start, goal,
/// departure and speed: checks the region (regionFault()) and that start and goal lie in it, loads the region (or
/// the trip's, netCdfLoadOptions()) once to check that start and goal lie on the grid and in water, that the depth
/// is not below the deepest layer and that the departure lies within the forecast (a steady field, without time
/// dimension, with a single record or with steadyRecord, takes any departure), and to convert the departure; sets
/// the outputs to every format. The planner settings are the defaults of
/// PlannerSpec (grid size automatic): change them in the returned spec. Writes nothing.
/// @throws Error with a one-line message naming the input (in the caller's words, ForecastInput::words), file or
/// variable at fault.
MissionSpec forecastMission(const ForecastInput &input);
} // namespace ompl_glider
