#pragma once
/// @file ForecastSource.h
/// @brief The seam of gridded current sources: what a mission asks of a forecast (ForecastRequest) and what any
/// source answers (LoadedForecast), whatever it reads (NetCDF files and OPeNDAP datasets, Zarr stores and GRIB
/// files through GDAL, or a source an application registers). A source is found by its kind's name in the
/// current-field registry (CurrentFieldRegistry.h: CurrentFieldKind::source); mission/ and the front ends know it
/// by that name only. docs/ARCHITECTURE.md has the recipe for adding one.

#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/current/BeyondForecast.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/current/Interpolation.h"
#include "ompl_glider/io/Time.h"

namespace ompl_glider
{
class LocalProjection;

/// @brief The settings of a request a message may name. Each front end calls them in its own words
/// (ForecastRequest::optionNames): `current.variables.u` in a mission file, `--u-var` on the command line.
enum class ForecastOption
{
    U,                ///< the eastward velocity's variable
    V,                ///< the northward velocity's variable
    Lon,              ///< the longitude (or x) coordinate
    Lat,              ///< the latitude (or y) coordinate
    Depth,            ///< the depth coordinate
    Time,             ///< the time coordinate
    VelocityUnits,    ///< the units given for u and v
    TimeUnits,        ///< the units given for the time axis
    SteadyRecord,     ///< the one record planned on as a steady field
    Departure,        ///< the departure
    MaxDepth,         ///< the glider's deepest depth
    ZeroVelocityLand, ///< still nodes taken as land
    Region,           ///< the region to load
    Angle,            ///< the grid angle's variable
    Mask,             ///< the land/sea mask's variable
    DepthAverage,     ///< the depth average's bounds
    MaxSpeed,         ///< the fastest current believed
    Run,              ///< the run read of a file of several forecast runs (a THREDDS FMRC)
};

/// @brief What a mission asks of a gridded source: where the forecast is, how to read it, and which part (the
/// trip's region, depth layers and times: [EichhornOceans] Sec. II.B). Every field but `files` has a usable
/// default. MissionProblem fills it from the mission (forecastRequest()).
struct ForecastRequest
{
    /// Paths, folders or URLs of the forecast: one, or several read as one forecast (ordered by their dates).
    std::vector<std::string> files;
    /// Variables by role (u, v, lon, lat, x, y, depth, time, mask, angle); a role not given is found by the source.
    std::map<std::string, std::string> variables;
    bool zeroVelocityLand{true}; ///< a node still (u = v = 0) in every record of the trip is land (source's rules)
    std::optional<std::pair<double, double>> depthAverage; ///< the current averaged over [top, bottom] metres
    std::string velocityUnits; ///< overrides the velocities' units (any velocity UDUNITS-2 reads)
    double maxSpeed{std::numeric_limits<double>::quiet_NaN()}; ///< the fastest current believed (m/s; NaN: default)
    std::string timeUnits;                   ///< overrides the time axis' units ("days since 2026-01-15")
    std::optional<std::size_t> steadyRecord; ///< plan on this record (0-based) only, as a steady field
    /// a file of several forecast runs (a THREDDS FMRC: a run dimension, 2-D time): the run read (0-based along the
    /// run dimension); required for such a file of more than one run (ForecastTimeAxis::runs lists them)
    std::optional<std::size_t> run;

    Interp2D xy{Interp2D::Bilinear};               ///< horizontal interpolation ([EichhornOceans] Fig. 2)
    Interp1D depth{Interp1D::Linear};              ///< depth interpolation
    Interp1D time{Interp1D::Linear};               ///< time interpolation
    BeyondForecast beyond{BeyondForecast::Refuse}; ///< after the last forecast time
    std::string name; ///< the field's name in maps and messages (no URL's password); empty: the source's own

    double maxDepth{std::numeric_limits<double>::infinity()}; ///< deepest depth the glider reaches (m, down)
    std::string departure; ///< ISO 8601 date or seconds after the first forecast time; empty: the first time
    double horizon{std::numeric_limits<double>::infinity()}; ///< seconds after the departure the trip may last
    /// The region to load: longitudes from lonMin east to lonMax (lonMax < lonMin or beyond 180 across the
    /// antimeridian), latitudes (x/y in a Cartesian forecast's own units); NaN: the whole forecast.
    double lonMin{std::numeric_limits<double>::quiet_NaN()};
    double lonMax{std::numeric_limits<double>::quiet_NaN()};
    double latMin{std::numeric_limits<double>::quiet_NaN()};
    double latMax{std::numeric_limits<double>::quiet_NaN()};
    /// Reference point of the planning frame's projection; NaN: the centre of the region.
    double refLon{std::numeric_limits<double>::quiet_NaN()};
    double refLat{std::numeric_limits<double>::quiet_NaN()};

    /// How the caller calls the settings in messages; a setting not named here keeps the source's own word.
    std::map<ForecastOption, std::string> optionNames;

    /// @brief The variable given for @p role, or "".
    std::string variable(const std::string &role) const;
    /// @brief The caller's word for @p option, else @p fallback.
    std::string optionName(ForecastOption option, const std::string &fallback) const;
};

/// @brief The horizontal extent of a forecast, from its coordinates alone (no velocity read).
struct ForecastExtent
{
    bool geographic{false};          ///< longitude/latitude (else Cartesian x/y in the file's units)
    bool allLongitudes{false};       ///< the longitudes go round the globe: every longitude lies in the file
    double lonMin{0.0}, lonMax{0.0}; ///< lonMin in [-180, 180), lonMax = lonMin + width (x in Cartesian files)
    double latMin{0.0}, latMax{0.0}; ///< (y in Cartesian files)
    std::string xName, yName;        ///< the coordinate variables
    /// True when (a, b) (lon/lat in either convention, or x/y) lies within the bounds (a curvilinear grid's bounds
    /// are those of its nodes: a point inside them may still lie outside the grid).
    bool contains(double a, double b) const;
    /// "lon -80..-76, lat 25..28" (or "x 0..100, y 0..50").
    std::string text() const;
};

/// @brief The time axis of a forecast as its source will load it, read without its velocities: what a mission
/// needs to turn ISO dates into field times before the forecast is loaded. For a dated axis, field time t is the
/// date dateFromCalendarEpoch(originSeconds + t, calendar).
struct ForecastTimeAxis
{
    bool found{false};    ///< the velocities have a time dimension with a coordinate variable (else a steady field)
    bool steady{false};   ///< the loaded field is steady: no time dimension, a single record, or steadyRecord
    bool dated{false};    ///< units "<unit> since <date>" (else raw values, for Cartesian files only)
    std::string variable; ///< the time coordinate variable
    Calendar calendar{Calendar::Standard}; ///< its calendar (dated axes)
    double originSeconds{0.0};             ///< first time, seconds since the calendar epoch (dated axes; 0 otherwise)
    std::size_t size{0};                   ///< number of forecast times
    double span{0.0}; ///< last minus first time: seconds (dated axes) or the file's units (raw values)
    /// A forecast run's reference time (dated axes), seconds since the calendar epoch: CF `forecast_reference_time`
    /// (a variable of one value with that standard name or name, else a global attribute of that name holding a
    /// date), else the first time; NaN for an undated or steady axis
    double referenceSeconds{std::numeric_limits<double>::quiet_NaN()};
    std::string referenceFrom; ///< where referenceSeconds came from ("variable 'forecast_reference_time'", ...)
    /// A file of several forecast runs (a THREDDS FMRC: the velocities on a run dimension whose coordinate is the
    /// runs' reference times, time a 2-D coordinate time(run, time)): one entry per run that has times, in file
    /// order; empty for a file of one run. The fields above are then those of ForecastRequest::run (else the
    /// first run's); runAxis() gives each run's.
    struct Run
    {
        std::size_t index{0};      ///< along the run dimension (ForecastRequest::run)
        double originSeconds{0.0}; ///< its first time (its times that are fill values dropped)
        std::size_t size{0};       ///< its number of times
        double span{0.0};          ///< its last minus first time (seconds)
        double referenceSeconds{std::numeric_limits<double>::quiet_NaN()}; ///< its reference time
        std::string referenceFrom;                                         ///< where that was read
    };
    std::vector<Run> runs;
    /// @brief This axis as run runs[k] of the file has it (the fields above replaced by that run's).
    ForecastTimeAxis runAxis(std::size_t k) const
    {
        ForecastTimeAxis out = *this;
        const Run &r = runs.at(k);
        out.originSeconds = r.originSeconds;
        out.size = r.size;
        out.span = r.span;
        out.steady = r.size == 1;
        out.referenceSeconds = r.referenceSeconds;
        out.referenceFrom = r.referenceFrom;
        return out;
    }
};

/// @brief The frame and clock of a loaded forecast: how planning-frame points and field times become positions
/// and dates for the outputs.
struct ForecastFrame
{
    std::shared_ptr<const LocalProjection> projection; ///< null in Cartesian mode
    double xyMetres{1.0};   ///< Cartesian mode: metres per unit of the file's x/y axes (1000 for km)
    bool geographic{false}; ///< true when x/y come from longitude/latitude
    bool dated{false};      ///< true when the time axis has units "<unit> since <date>"
    bool steady{false};     ///< one time: the field is the same at all times and any departure is inside it
    Calendar calendar{Calendar::Standard}; ///< the forecast's calendar (dated forecasts)
    double originSeconds{0.0}; ///< field time 0 (the first forecast time, or a steady record's), seconds since
                               ///< the calendar epoch (dated forecasts)
    double departureTime{0.0}; ///< the departure in field time (0 when none was given)
    double forecastBegin{0.0}; ///< first forecast time, field time
    double forecastEnd{0.0};   ///< last forecast time, field time
    /// Bounds of the loaded nodes in the forecast's coordinates: longitudes from lonMin in [-180, 180) east to
    /// lonMax (beyond 180 across the antimeridian), latitudes; x and y in Cartesian mode (file units).
    double lonMin{0.0}, lonMax{0.0}, latMin{0.0}, latMax{0.0};
    /// The files (or URLs) read, in time order.
    std::vector<std::string> files;

    /// @brief Field time of an ISO 8601 date in the forecast's calendar, or of a plain number (seconds after field
    /// time 0). @throws Error for a forecast without dates given a date.
    double fieldTime(const std::string &isoOrSeconds) const;
    /// @brief ISO 8601 date of a field time (dated forecasts; else the number).
    std::string isoTime(double t) const;
    /// @brief Planning-frame point (metres) -> (lon, lat), longitude in [-180, 180); the file's x/y in Cartesian
    /// mode.
    LonLat toGeographic(Point2 p) const;
    /// @brief (lon, lat) in either longitude convention (x/y in Cartesian mode) -> planning-frame point (metres).
    Point2 toLocal(LonLat g) const;
};

/// @brief What a gridded source gives: the field ready to plan on (its grid: CurrentField::grid(); its land:
/// CurrentField::inWater() and landBoundary()), the frame and clock, and what a pilot should know of it.
struct LoadedForecast : ForecastFrame
{
    std::shared_ptr<const CurrentField> field; ///< x east / y north in metres, t in seconds after field time 0
    bool depthLevels{false};                   ///< the velocities have depth levels (else they are of one level)
    std::string uVariable;                     ///< what the eastward velocity is called in the forecast (messages)
    bool wind{false};                          ///< a forecast of winds (uwnd, u10, eastward_wind, ...): "wind" on maps
    /// What reading the forecast decided that a pilot should know, one sentence each (grid angle, land from still
    /// nodes, what came from a server or the cache).
    std::vector<std::string> notes;
    /// What makes land in this forecast, one phrase each ("fill values of 'u'/'v'", "the mask variable 'mask'"):
    /// named where a start or goal falls on land.
    std::vector<std::string> landCauses;
};

/// @brief A gridded source: reads a forecast as a ForecastRequest asks. Implementations are thread-compatible
/// (called from one thread at a time; the field they return is thread-safe for const use).
class GriddedSource
{
public:
    virtual ~GriddedSource() = default;
    /// @brief Whether the forecast's positions are longitude/latitude (true) or Cartesian x/y (false), read from
    /// its description only. @throws Error naming the file and what is wrong.
    virtual bool geographic(const ForecastRequest &request) const = 0;
    /// @brief The extent of the first file's grid, from its coordinates only. @throws Error as load().
    virtual ForecastExtent extent(const ForecastRequest &request) const = 0;
    /// @brief The time axis the forecast will be loaded with (its velocities are not read). @throws Error as load().
    virtual ForecastTimeAxis timeAxis(const ForecastRequest &request) const = 0;
    /// @brief The forecast over the request's region, depths and times. @throws Error naming the file, the
    /// variable and the setting at fault (in the caller's words: ForecastRequest::optionNames).
    virtual LoadedForecast load(const ForecastRequest &request) const = 0;
};
} // namespace ompl_glider
