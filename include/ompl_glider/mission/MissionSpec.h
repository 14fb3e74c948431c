#pragma once
/// @file MissionSpec.h
/// @brief A glider mission as read from a YAML mission file ([EichhornOceans] Sec. IV: start, goal, start time, region,
/// restricted areas and obstacles, projection, dive-profile parameters).
///
/// Units: positions and times are in the current field's units: metres and seconds for NetCDF forecasts,
/// dimensionless for the analytic flows. `units.length_m` / `units.time_s` say how many metres / seconds one
/// unit is, so that geographic and calendar outputs are possible for analytic flows too.

#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/cost/DiveProfile.h"
#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/current/BeyondForecast.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/io/GeoBox.h"
#include "ompl_glider/current/Interpolation.h"
#include "ompl_glider/execution/Stints.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/OutputFormats.h"

namespace ompl_glider
{
struct GliderObservations;

/// @brief Where a value came from in the mission file (for messages after loading).
/// @brief What gave a value: a mission file (or a default), a command-line flag or a keyword of the Python module.
enum class Origin : std::uint8_t
{
    File = 0,
    Flag,
    Keyword,
    Program, ///< the calling program through the C++ API (ForecastInput without SettingWords)
    /// the glider's last fix, put in by a front end until the mission resumes there (resumeAtLastFix())
    Observations
};

/// @brief Where a value was given.
struct SourceMark
{
    /// mission file; for a flag or a keyword, how the front end names it ("--grid-size", "plan(): keyword 'speed'")
    std::string file;
    int line{0}; ///< 1-based line (0 = unknown, or a flag or keyword)
    Origin origin{Origin::File};

    /// @brief True for a flag or a keyword: its name says where, without a line.
    bool namesItself() const { return origin != Origin::File; }
};

/// @brief How a front end names the mission's settings to its user: a setting ("planner.time_limit", or a setting
/// with its value, "current.horizon: hold_last") mapped to the front end's word ("--time-limit" on the command line,
/// "time_limit=" in Python). A setting without a word is named as a mission file names it.
struct SettingWords
{
    std::map<std::string, std::string> words; ///< by setting
    /// How the front end names a value it gave for a setting ("start" -> "--start", "plan(): keyword 'start'");
    /// where missing, the word of `words`, else the setting
    std::map<std::string, std::string> given;
    Origin origin{Origin::Flag}; ///< what the front end's values are: flags or keywords

    /// @brief How the front end names a value it gave for @p setting (see `given`).
    std::string givenName(const std::string &setting) const;

    /// @brief @p setting and the front end's word for it ("planner.time_limit, --time-limit"), else @p setting.
    std::string operator()(const std::string &setting) const;
};

/// @brief A point given as x/y (planning frame) or lon/lat (degrees; needs a projection).
struct PointSpec
{
    bool geographic{false}; ///< lon/lat given
    Point2 xy;              ///< x/y (planning units) when !geographic
    LonLat lonLat;          ///< lon/lat (degrees; longitude -180..180 or 0..360) when geographic
};

/// @brief Local projection of the mission: azimuthal equidistant about (lon0, lat0) (as the NetCDF loader uses).
struct ProjectionSpec
{
    bool set{false};  ///< a projection was given
    double lon0{0.0}; ///< reference longitude (degrees)
    double lat0{0.0}; ///< reference latitude (degrees)
};

/// @brief What a plan minimises over the members of an ensemble: the mean of their arrival times, the maximum or a
/// quantile (PlannerSpec::quantile).
enum class EnsembleObjective
{
    Expected, ///< "expected": the mean
    Worst,    ///< "worst": the maximum
    Quantile  ///< "quantile": the ceil(q M)-th smallest of M
};
/// @brief "expected", "worst" or "quantile".
const char *ensembleObjectiveName(EnsembleObjective o);
/// @brief The objective named @p name. @throws Error for another name (saying which are known).
EnsembleObjective parseEnsembleObjective(const std::string &name);

/// @brief Source of the current: an analytic flow, or a forecast read by a gridded source of the registry (NetCDF,
/// OPeNDAP, Zarr, GRIB: `gridded`, alias `netcdf`; ForecastSource.h), asked through a ForecastRequest
/// (forecastRequest(), ProblemInputs.h).
struct CurrentSpec
{
    /// The registry's name of the kind, or an alias of it (currentFieldKinds(), currentFieldKindList()); the
    /// registry says whether it is read from a file (CurrentFieldKind::gridded).
    std::string type{"meandering_jet"};
    /// @brief True for a kind read from files by a gridded source (planning in metres and seconds, positions in
    /// lon/lat); false for an analytic flow or an unknown name (refused by the loader and MissionProblem).
    bool isForecast() const
    {
        const CurrentFieldKind *kind = findCurrentFieldKind(type);
        return kind && kind->gridded();
    }
    /// Analytic parameters, by the names the kind declares (CurrentFieldKind::parameters, parameterNameList()).
    /// Missing ones take the kind's defaults.
    std::map<std::string, double> parameters;
    /// gridded: path or URL (relative paths resolved against the mission); with several files, the first given
    /// (for names and messages)
    std::string file;
    /// gridded: a forecast in several files read as one (ordered by their dates),
    /// resolved and glob patterns expanded; empty: `file` alone
    std::vector<std::string> files;
    /// @brief The forecast's files: `files`, else `file` alone.
    std::vector<std::string> forecastFiles() const { return files.empty() ? std::vector<std::string>{file} : files; }
    /// gridded: forecast runs (`current.runs`), each file one run (resolved, glob patterns expanded; `file` is the
    /// first, for names and messages); empty: one forecast. A plan at time t is made on the newest run available at
    /// t (ForecastRuns.h); an execution replans as runs arrive.
    std::vector<std::string> runs;
    /// gridded: the run `file` is of a file of several forecast runs (a THREDDS FMRC: a run dimension, 2-D time),
    /// 0-based along its run dimension (ForecastRequest::run); unset: a file of one run. A file of several runs
    /// given in `runs` is each of its runs.
    std::optional<std::size_t> runIndex;
    /// gridded runs: how long after its reference time a run becomes available (field time units: seconds)
    double runDelay{12.0 * 3600.0};
    /// gridded: role (u, v, lon, lat, x, y, depth, time, mask, angle) -> name (mask "none": no land/sea mask
    /// variable; angle "none": no grid angle)
    std::map<std::string, std::string> variables;
    Interp2D xyInterpolation{Interp2D::Bilinear};  ///< nearest | bilinear | bicubic (parseInterp2D())
    Interp1D depthInterpolation{Interp1D::Linear}; ///< nearest | linear | cubic | akima (parseInterp1D())
    Interp1D timeInterpolation{Interp1D::Linear};  ///< nearest | linear | cubic | akima (parseInterp1D())
    /// Refuse (trips past the forecast are infeasible; `horizon: refuse`) or HoldLast (`horizon: hold_last`)
    BeyondForecast horizonPolicy{BeyondForecast::Refuse};
    bool zeroVelocityLand{true}; ///< gridded: nodes with u = v = 0 exactly at every loaded time are land
    /// gridded: the current averaged over [top, bottom] metres (ForecastRequest::depthAverage)
    std::optional<std::pair<double, double>> depthAverage;
    std::string velocityUnits; ///< gridded: overrides the units of u and v (any velocity UDUNITS-2 reads)
    /// gridded: the fastest current believed, m/s (NaN: 300 m/s, a few fast nodes continuous with the flow passing)
    double maxSpeed{std::numeric_limits<double>::quiet_NaN()};
    std::string timeUnits; ///< gridded: overrides the units of the time variable ("days since 2026-01-15")
    std::optional<std::size_t> steadyRecord; ///< gridded: plan on this time record only, as a steady field
    /// An ensemble (`current: {ensemble: [...]}`): its members, each a source of this kind (the first is also this
    /// spec's own fields, for names, calendar and messages); empty: a single source. The planning field is the
    /// members' mean; planner.objective judges plans member by member.
    std::vector<CurrentSpec> members;
    /// @brief How an ensemble of an analytic flow was drawn from one set of parameters
    /// (`current: {type: ..., parameters: ..., members: N, spread: {...}, seed: S}`): member 0 is the parameters as
    /// given (the control run), members 1..N-1 draw each spread parameter p as p (1 + s U(-1, 1)).
    struct EnsembleDraw
    {
        std::map<std::string, double> spread; ///< relative half-width s in [0, 1) by parameter
        unsigned seed{1};                     ///< std::mt19937's seed
    };
    /// Set when `members` were drawn (drawEnsembleMembers()); unset for a listed ensemble or a single source
    std::optional<EnsembleDraw> drawn;
    /// gridded, set when the mission is read: the field is steady (no time dimension, a single record, or
    /// steadyRecord); a steady file without dated time axis takes the mission's `epoch`.
    bool steady{false};
    SourceMark mark; ///< where the current block is
};

/// @brief What a flight's learning from the DAC keeps when a new forecast run arrives.
enum class AcrossRuns
{
    Carry, ///< "carry": every DAC kept, compared again with the new run
    Reset  ///< "reset": only the DAC measured since the new run arrived (OceanPlatformControl's choice)
};
/// @brief "carry" or "reset".
const char *acrossRunsName(AcrossRuns a);
/// @brief The choice named @p name. @throws Error for another name (saying which are known).
AcrossRuns parseAcrossRuns(const std::string &name);

/// @brief The planning box (x/y or lon/lat; lon/lat boxes are projected to their x/y bounding box).
struct RegionSpec
{
    bool set{false};        ///< a region was given (else: the NetCDF grid extent, or required for analytic flows)
    bool geographic{false}; ///< given as lon/lat
    Box xy;                 ///< x/y bounds (planning units) when !geographic
    /// lon/lat bounds as loaded, when geographic: lonMin in -180..180, lonMax = lonMin + width (beyond 180 across
    /// the antimeridian), whatever convention the file used
    GeoBox lonLat;
};

/// @brief Departure: a fixed time, or a window searched for the optimal departure ([EichhornRAS] Sec. 5).
struct DepartureSpec
{
    double time{0.0};           ///< fixed departure time (field units; ISO dates are converted with the epoch)
    bool window{false};         ///< a departure window is given
    double begin{0.0};          ///< window start
    double end{0.0};            ///< window end
    double spacing{1.0};        ///< supporting-point spacing
    double tolerance{1e-3};     ///< Brent tolerance on the departure time
    double coarseGridSize{0.0}; ///< > 0: supporting points on a lattice of this spacing ([EichhornRAS] Sec. 5.3)
    int coarseSectors{0};       ///< sectors of the coarse lattice (0: same as the planner)
    unsigned threads{0};        ///< parallel searches (0: all cores)
    /// The mission's own departure (its window's beginning) where a caller's departure replaced it
    /// (applyOverrides()): a mission resumed at the glider's last fix counts its fixes from then on
    /// (resumeAtLastFix()); NaN: none was replaced
    double replaced{std::numeric_limits<double>::quiet_NaN()};
};

/// @brief The goal's arrival window ("goals in time"; [ThompsonICRA] Sec. III: a spatiotemporal goal, reached
/// at its earliest valid arrival): the glider must be at the goal at a time in [begin, end] (field time units).
struct GoalWindowSpec
{
    bool set{false};   ///< a window is given (mission `goal.window`, or `--arrive-between`)
    double begin{0.0}; ///< earliest accepted arrival
    double end{0.0};   ///< latest accepted arrival
};

/// @brief A via point of a mission of several legs: a station the glider visits
/// between the start and the goal. The leg that ends at it is planned to its position; `radius` is where the glider
/// counts it as reached (the Seaglider targets file's `radius=`, the goto list's waypoint distance).
struct ViaPointSpec
{
    std::string name;   ///< its name in reasons, outputs and the targets file (default "WP1", "WP2", ...)
    PointSpec position; ///< lon/lat or x/y, as the start and the goal
    /// Reached within this distance (planning units, metres for a forecast); NaN: the goal's tolerance
    double radius{std::numeric_limits<double>::quiet_NaN()};
    GoalWindowSpec arrive; ///< arrival window at this point (unset: any time), as the goal's window works
    /// Hold here for this long after the arrival (field time units): a "virtual mooring", possible only where the
    /// current is slower than the glider; 0: leave at once
    double stay{0.0};
    int line{0}; ///< its line in the mission file (0: a flag or a keyword)
};

/// @brief The order in which a mission's via points are visited.
enum class VisitOrder
{
    Given, ///< "given": in the order listed
    Free   ///< "free": the fastest order (branch and bound over orders, MissionLegs.h)
};
/// @brief "given" or "free".
const char *visitOrderName(VisitOrder o);
/// @brief The order named @p name. @throws Error for another name (saying which are known).
VisitOrder parseVisitOrder(const std::string &name);
/// @brief True for a via point's name: a letter, then letters, digits, '_' or '-', at most 16 characters (it is
/// written into the Seaglider targets file).
bool plainViaPointName(const std::string &name);
/// @brief @p name as names are compared (in lower case: the Seaglider's targets file and a pilot reading it do not
/// tell GOAL from goal); no via point's key may be another's, "start" or "goal".
std::string viaPointKey(const std::string &name);
/// @brief The most via points `order: free` accepts (the search is exponential in their number).
constexpr std::size_t kMaxFreeOrderViaPoints = 8;

/// @brief Vehicle.
struct VehicleSpec
{
    double speed{0.5}; ///< speed through water (field units)
    double depth{0.0}; ///< depth at which the 2-D planner reads the current
};

/// @brief Dive profiles ([EichhornOceans] Sec. III.B) and bathymetry. Depths are metres (positive down) for every
/// field; the analytic flows are depth-uniform, so there every profile flies the 2-D travel time.
struct DiveSpec
{
    bool enabled{false}; ///< dive profiles evaluated on the planned legs
    DiveProfileParams params;
    /// Where the seafloor depth comes from: nowhere, one depth, or a file (the mission file's `type: netcdf`)
    enum class Bathymetry
    {
        None,
        Constant,
        File
    } bathymetry{Bathymetry::None};
    double bathymetryDepth{std::numeric_limits<double>::infinity()}; ///< constant seafloor depth
    std::string bathymetryFile;                                      ///< a file of seafloor depth (positive down)
    std::string bathymetryVariable{"depth"};
    unsigned threads{0}; ///< pool for the profiles (0: all cores)
};

/// @brief A polygon of the mission (x/y or lon/lat vertices).
struct PolygonSpec
{
    std::string name;                                          ///< used in messages and outputs
    bool geographic{false};                                    ///< vertices are lon/lat
    std::vector<std::pair<double, double>> points;             ///< outer ring
    std::vector<std::vector<std::pair<double, double>>> holes; ///< holes
    SourceMark mark;                                           ///< where it was given
};

/// @brief What a forbidden polygon of the mission is: an obstacle (forbidden at all times: island, land, restricted
/// area), a zone closed during time windows, or a drifting ice zone. Its name (regionKindName()) is the mission
/// file's word for it and what the outputs print.
enum class RegionKind
{
    Island,
    Land,
    RestrictedArea,
    Closure,
    Ice
};

/// @brief "island", "land", "restricted area", "closure", "ice".
const char *regionKindName(RegionKind k);

/// @brief The kind named @p name (regionKindName()); none for another text.
std::optional<RegionKind> parseRegionKind(const std::string &name);

/// @brief An obstacle forbidden at all times (island, land, restricted area).
struct ObstacleSpec
{
    PolygonSpec polygon;
    RegionKind kind{RegionKind::Island}; ///< Island, Land or RestrictedArea
};

/// @brief A zone forbidden during time windows.
struct TimeWindowSpec
{
    PolygonSpec polygon;
    std::vector<std::pair<double, double>> windows; ///< closed [from, to] intervals (field time units)
};

/// @brief A drifting ice zone under which the glider may stay submerged for a limited time.
struct IceSpec
{
    PolygonSpec polygon;          ///< shape at tRef
    double tRef{0.0};             ///< time at which the shape is given
    double vx{0.0}, vy{0.0};      ///< constant drift velocity (ignored when carried)
    bool carried{false};          ///< drift with the current at the polygon's first vertex instead
    double maxSubmergedTime{0.0}; ///< longest continuous stay under ice
};

/// @brief Forbidden regions: inline, or from a GeoJSON FeatureCollection.
struct ForbiddenSpec
{
    std::vector<ObstacleSpec> obstacles;
    std::vector<TimeWindowSpec> timeWindows;
    std::vector<IceSpec> ice;
    std::string geojson;          ///< GeoJSON file (Polygon / MultiPolygon features), resolved path
    bool geojsonGeographic{true}; ///< GeoJSON coordinates are lon/lat (RFC 7946); false: planning x/y
    std::string coastline;        ///< land polygons from a GIS file (readLandPolygons()), resolved path
    SourceMark coastlineMark;     ///< where it was given
};

/// @brief Safety margins: a keep-off distance from land and a depth limit from a bathymetry grid. Both become
/// forbidden regions of the one environment (KeepOffZone, ForbiddenCells), so every planner, the motion validator
/// and the re-flights keep them.
struct SafetySpec
{
    /// Keep-off distance from land (the field's land cells, coastline polygons, islands and land obstacles), planning
    /// units (metres for a forecast); 0: none (the closest approach is still reported)
    double keepOff{0.0};
    std::string bathymetry;         ///< NetCDF seafloor depth or elevation (resolved path); empty: none
    std::string bathymetryVariable; ///< its variable; empty: detected (DepthGrid.h)
    double minDepth{0.0};           ///< metres: water shallower than this is forbidden (needs a bathymetry)
    /// A start or goal on a forecast's land is moved to the nearest water (MissionProblem::endpointNotes() says
    /// where); false: such a start or goal is refused, the message naming the nearest water
    bool snapToWater{false};
};

/// The longest planner time limit (seconds): beyond it OMPL's time point arithmetic overflows. The mission file,
/// the command line and Python check it alike (through the overrides).
constexpr double kMaxTimeLimit = 1e6;

/// @brief The planner and its parameters.
struct PlannerSpec
{
    /// A name of the planner registry (PlannerRegistry.h, plannerNameList(); any accepted spelling is stored as the
    /// canonical name): a lattice search, the level set, held headings, a stint planner or an OMPL planner on the
    /// time-augmented space, each of a PlannerFamily.
    std::string name{"ZA*TVE"};
    /// Lattice spacing; 0 = automatic: for the analytic flows 0.4 ([EichhornRAS] Sec. 6.1) within 1/200..1/25 of
    /// the start-goal distance (defaultAnalyticGridSize()), for a forecast half
    /// the smallest grid cell kept within 1/200..1/25 of the start-goal distance (defaultForecastGridSize()).
    double gridSize{0.0};
    int sectors{3};        ///< n-sector connectivity (1..5)
    bool smoothing{true};  ///< [EichhornRAS] Table 3
    bool refinement{true}; ///< waypoint refinement after smoothing
    /// Seconds; 0 = no limit for the planners that run to their own end (every family but sampling), 10 s for the
    /// sampling planners (which use all they get).
    double timeLimit{0.0};
    double horizon{0.0};        ///< planning time window length; 0 = automatic
    double goalTolerance{-1.0}; ///< < 0: automatic (1e-6 of the box size)
    /// Planner parameters by their OMPL names (declareParam: delta_phi_max, zermelo_steps, certify_tolerance, ...;
    /// plus refiner_max_evaluations for the refinement), as text; checked against the planner before planning.
    std::map<std::string, std::string> parameters;
    std::map<std::string, SourceMark> parameterMarks; ///< where each parameter was given
    /// With an ensemble current: what a plan minimises over the members' arrival times: expected (their mean),
    /// worst (their maximum) or quantile (the `quantile` quantile).
    EnsembleObjective objective{EnsembleObjective::Expected};
    double quantile{0.9}; ///< objective quantile: in (0, 1]
    /// The global check of the route class after a lattice planner (checkGlobally(), src/mission/planning/
    /// GlobalCheck.cpp; the result's GlobalCheck in Planning.h): extremals shot from the start, a faster route of
    /// another class taken instead of the planner's
    bool globalCheck{true};
};

/// @brief Constant-bearing stints ([IsernObstacles]): the settings of the stint planners (init_optim, optim,
/// cts_astar, direct), and, with any other planner, the conversion of its path to stints (a heading per surfacing).
/// Times in field units.
struct StintSpec : StintSettings
{
    bool set{false}; ///< a `stints` section was given (its duration and mission_duration are required)
    /// The section's settings (execution/Stints.h: the one stint settings struct of the mission, the stint planners
    /// and the conversion); without a section nothing is set. A radius of 0 gives a conversion an automatic one.
    StintSpec()
    {
        duration = 0.0;
        missionDuration = 0.0;
    }
};

/// @brief What to write.
struct OutputSpec
{
    std::string directory{"."}; ///< resolved against the mission file's folder
    /// Output formats (OutputFormats.h: outputFormats() lists them with their names); summary.json is always
    /// written.
    std::vector<OutputFormatId> files{OutputFormatId::Csv, OutputFormatId::GeoJson, OutputFormatId::Goto,
                                      OutputFormatId::Summary};
    /// @brief True when @p id is among `files`.
    bool wants(OutputFormatId id) const
    {
        for (OutputFormatId f : files)
            if (f == id)
                return true;
        return false;
    }
    int gotoNumber{10};           ///< goto_lNN.ma
    bool gotoIncludeStart{false}; ///< also list the start position in the goto file
    /// goto list: a waypoint is listed where the course turns by more than this (degrees), or where leaving it out
    /// would take the route farther than gotoMaxOffset from it or across land; 0 lists every waypoint
    double gotoTurnDeg{10.0};
    double gotoMaxOffset{1000.0}; ///< goto list: the farthest a waypoint left out may lie from the listed legs (m)
    double gotoWptDist{100.0};    ///< goto list: list_when_wpt_dist, the waypoint radius in metres
    /// uploads (goto list, targets): a run of held headings is written as the fewest holds whose flights pass its
    /// planned segment ends within this many metres (0: every segment; outputs.hold_tolerance, --hold-tolerance)
    double holdTolerance{300.0};
    std::string prefix; ///< non-empty: also a copy of every file named <prefix>_<file> (a plain name)
    double mapTime{std::numeric_limits<double>::quiet_NaN()}; ///< time of the map's current arrows (NaN: departure)
    /// Time between two isochrones (format "isochrones"; the mission's time unit); NaN: eight up to the arrival.
    double isochroneInterval{std::numeric_limits<double>::quiet_NaN()};
};

/// @brief The probability of reach over an ensemble's members (mission `reachability`, output format
/// "reachability": mission/ReachProbability.h). NaN and empty lists: the defaults.
struct ReachabilitySpec
{
    /// How long after the departure (the mission's time unit); NaN: 1.5 times the plan's travel time when it has a
    /// route, else the planning horizon; either capped at the field's end
    double horizon{std::numeric_limits<double>::quiet_NaN()};
    double interval{std::numeric_limits<double>::quiet_NaN()}; ///< between two frames; NaN: the horizon / 10
    std::vector<double> levels;    ///< probability contours, each in (0, 1); empty: 0.5 and 0.9
    std::vector<double> quantiles; ///< arrival-time quantiles at the goal, each in (0, 1); empty: 0.1, 0.5, 0.9
    /// The cell (length unit); NaN: the level-set planner's default cell (1/200 of the region's larger side)
    double resolution{std::numeric_limits<double>::quiet_NaN()};
    bool memberArrival{false}; ///< also write each member's first-arrival field into reachability.nc
};

/// @brief One glider of a fleet (mission `fleet`): its own start, goal and, optionally, speed and departure; every
/// other setting is the mission's. fleetGliderMission() (mission/Fleet.h) makes its mission.
struct FleetGliderSpec
{
    std::string name; ///< a folder name under the output directory (letters, digits, '_', '-', '.')
    PointSpec start;
    PointSpec goal;
    std::optional<double> speed;         ///< vehicle speed (unset: the mission's)
    std::optional<double> departure;     ///< fixed departure time, field units (unset: the mission's departure)
    std::vector<ViaPointSpec> waypoints; ///< its via points (MissionSpec::waypoints), visited between start and goal
    std::optional<VisitOrder> order;     ///< its visiting order (unset: the mission's)
    int line{0};                         ///< the entry's line in the mission file
};

/// @brief The word for "the truth is the forecast itself" (`execution.truth: forecast`, --truth forecast, and the
/// name of that truth in the outputs).
inline constexpr const char *kTruthIsForecast = "forecast";

/// @brief Flying the plan in another ocean ([ThompsonICRA]): the "truth" current, the surfacings, the
/// control strategies compared, and a batch of other start/goal pairs.
struct ExecutionSpec
{
    bool enabled{false}; ///< an `execution` section (or --truth / --execution) was given
    /// The ocean the glider flies in: a current source of the same family as `current` (an analytic flow, or a
    /// NetCDF file on the same calendar); unset: the forecast itself (truth = forecast).
    std::optional<CurrentSpec> truth;
    /// Time between surfacings (field units); NaN: one hour (3600 s / units.time_s, or 3600 for a forecast), or
    /// for a mission without a time unit (no units.time_s, no epoch, not a forecast) a twentieth of the planned trip.
    double surfacingInterval{std::numeric_limits<double>::quiet_NaN()};
    /// Strategies by name (current_sensitive, current_blind, greedy, replan, planned_headings, dac, replan_observed),
    /// in the order given.
    std::vector<std::string> strategies{"current_sensitive", "current_blind", "greedy", "replan"};
    /// The goal counts as reached within this distance (length units); NaN: 1 % of the start-goal distance.
    double radius{std::numeric_limits<double>::quiet_NaN()};
    unsigned replanEvery{1}; ///< replan at every n-th surfacing
    /// Strategies dac and replan_observed: the standard deviation of the noise on each measured DAC component
    /// (field units: m/s for a forecast); 0: none
    double dacNoise{0.0};
    /// The run ends at departure + this (field units); NaN: twice the planned travel time.
    double duration{std::numeric_limits<double>::quiet_NaN()};
    unsigned pairs{0}; ///< batch: random start/goal pairs besides the mission's own (0: none)
    unsigned seed{1};  ///< batch: seed of the pairs
    double minDistance{std::numeric_limits<double>::quiet_NaN()}; ///< batch: shortest start-goal distance;
                                                                  ///< NaN: a quarter of the box's diagonal
    unsigned threads{0};                                          ///< batch: parallel runs (0: all cores)
    /// With forecast runs: what the DAC learning keeps when a new run arrives
    AcrossRuns acrossRuns{AcrossRuns::Carry};
    SourceMark mark; ///< where the section is
};

/// @brief A via point a resumed mission dropped: the glider reached it before its last fix.
struct DroppedStation
{
    std::string name;       ///< the via point
    std::string reachedIso; ///< the first fix within its radius (ISO 8601)
    double distance{0.0};   ///< that fix's distance from it, metres
    /// of its stay, what was still to hold at the last fix, the wait for its window included (field time units; 0:
    /// none)
    double stayLeft{0.0};
    LonLat at;          ///< the via point's position (where a stay under way is held)
    double radius{0.0}; ///< its radius, metres (the goto list's waypoint distance where it has none)
    /// reached before its arrival window opened and still there at the last fix: the window's opening (ISO 8601 or
    /// field time), until which the glider holds there before its stay; else empty
    std::string windowOpens;
    /// reached after its arrival window closed: the window's end (ISO 8601 or field time), else empty
    std::string windowClosed;
};

/// @brief A stay the glider left unfinished: at the last fix it was outside the station's radius before the stay
/// was over. The station is kept, first, with what is left of its stay (resumeAtLastFix()).
struct LeftStay
{
    std::string name;       ///< the via point
    std::string reachedIso; ///< the fix its stay was counted from (ISO 8601)
    std::string leftIso;    ///< the first fix outside its radius before the stay was over (ISO 8601)
    double held{0.0};       ///< the stay held there (field time units): between fixes within the radius
    double stayLeft{0.0};   ///< what is left of it (field time units), held when the glider is back
    double distance{0.0};   ///< the last fix's distance from the station, metres
    double radius{0.0};     ///< its radius, metres
};

/// @brief What resuming a mission at the glider's last fix did (resumeAtLastFix()).
struct MissionResume
{
    LonLat fix;                ///< the last fix
    std::string fixIso;        ///< its time
    std::string replacedStart; ///< "lon, lat" of the start it replaced (the deployment's), empty when none was given
    std::string replacedDeparture;       ///< the departure it replaced (ISO 8601 or field time), empty when none
    std::vector<DroppedStation> dropped; ///< the stations reached, in the order reached
    /// a stay under way at the last fix: the plan departs at its end (ISO 8601 or field time), else empty
    std::string stayEnds;
    /// a departure a caller gave before the end of the stay under way (ISO 8601 or field time): the stay is finished
    /// first, the plan departs at its end; else empty
    std::string departureDuringStay;
    /// the glider left a station's radius before its stay was over: the plan returns there first to finish it
    std::optional<LeftStay> leftStay;
    /// the glider surfaced after the last fix without a valid fix (69696969, a bad GPS status): a warning that the
    /// plan departs from an older position ("the newest surfacing, 2026-03-15T11:00:00Z, gave no valid fix: ..."),
    /// else empty
    std::string staleFix;
};

/// @brief A glider's own measurements (its depth-averaged currents, DAC) and how they correct the forecast
/// (current/CorrectedField.h: optimal interpolation, [BrethertonOI]).
struct ObservationsSpec
{
    /// IOOS profile files (a file, folder or glob pattern) or a CSV; resolved. Empty: no files, the section only sets
    /// the correction's parameters (those of the execution's replan_observed)
    std::string path;
    /// The folder of a Slocum's cache files (the sensor lists of its binary files, `<crc>.cac`), searched before the
    /// files' own folder and a `cache/` folder beside them; empty: those two only
    std::string cache;
    /// L (planning units); NaN: 20 km for a forecast, a tenth of the region's larger side for an analytic flow
    double lengthScale{std::numeric_limits<double>::quiet_NaN()};
    /// T (field time units); NaN: one day where the time unit is known, else a tenth of the planning horizon
    double timeScale{std::numeric_limits<double>::quiet_NaN()};
    /// s_o / s_f: the DAC's error over the forecast's (> 0; CorrectionParams); NaN: 0.2
    double errorRatio{std::numeric_limits<double>::quiet_NaN()};
    /// Learn from the DAC (CorrectionParams::learn): the scales not given estimated from them, a bias and the tides
    /// carried ahead, an ensemble's members weighed and updated (current/EnsembleLearning.h); false: the given
    /// values and the defaults as they are
    bool learn{true};
    SourceMark mark; ///< where it was given
    /// set once the mission was resumed at the last fix (resumeAtLastFix()): what it replaced and dropped
    std::optional<MissionResume> resumed;
    /// What a front end read of these files already (to start at the last fix), handed on so that a mission reads
    /// each of its inputs once (ProblemInputs.h); null: not read yet. Used while path and cache are readFrom's.
    std::shared_ptr<const GliderObservations> read;
    std::string readFrom; ///< path and cache (a line between) that `read` was read from
    /// @brief Whether a glider's files are given (not only the correction's parameters).
    bool hasFiles() const { return !path.empty(); }
};

/// @brief A complete mission.
struct MissionSpec
{
    std::string file;             ///< the mission file
    std::string directory;        ///< its folder (relative paths are resolved against it)
    std::string name{"mission"};  ///< mission name
    double lengthUnitMetres{1.0}; ///< metres per planning length unit
    double timeUnitSeconds{1.0};  ///< seconds per planning time unit
    std::optional<double> epoch;  ///< calendar time (seconds since 1970, UTC) of field time 0, if any
    /// @brief Time axis of a dated NetCDF forecast: field time 0 is its first time, in its calendar.
    struct FileCalendar
    {
        Calendar calendar{Calendar::Standard}; ///< CF calendar of the file
        double originSeconds{0.0};             ///< first forecast time, seconds since the calendar's epoch (io/Time.h)
    };
    std::optional<FileCalendar> fileCalendar; ///< set for dated NetCDF forecasts
    ProjectionSpec projection;
    CurrentSpec current;
    RegionSpec region;
    PointSpec start;
    PointSpec goal;
    GoalWindowSpec goalWindow; ///< arrival window at the goal (unset: any time)
    /// Via points between start and goal (a mission of several legs, one leg per pair of consecutive points, planned
    /// in sequence on one clock: runMission()); empty: one leg from start to goal
    std::vector<ViaPointSpec> waypoints;
    VisitOrder order{VisitOrder::Given}; ///< the via points' visiting order
    DepartureSpec departure;
    VehicleSpec vehicle;
    /// The travel-time integration's settings (h, h_min, h_max, eps, tau, max step); its speed and depth are not
    /// read: the vehicle's are flown (MissionProblem::gliderProblem() sets them)
    TravelTimeParams travel;
    DiveSpec dive;
    ForbiddenSpec forbidden;
    SafetySpec safety; ///< keep-off distance and depth limit
    PlannerSpec planner;
    StintSpec stints;
    OutputSpec outputs;
    ReachabilitySpec reachability; ///< the probability of reach (output format "reachability")
    std::vector<double> speeds;    ///< speed sweep ([EichhornOceans] Table VI); empty = none
    ExecutionSpec execution;       ///< flying the plan in another ocean
    /// The glider's measurements: the forecast is corrected by them, and without a start the plan starts at the last
    /// fix (and without a departure at its time)
    std::optional<ObservationsSpec> observations;
    /// A fleet: one plan per glider, each from its own start to its own goal (empty: one plan, start to goal)
    std::vector<FleetGliderSpec> fleet;
    /// Where each value was given, by dotted field name ("planner.grid_size"): a line of the mission file, or the
    /// command-line flag. Checks made after loading (those that need the field or the region) name it with place().
    std::map<std::string, SourceMark> marks;
    /// How the front end that made the mission names its settings (SettingWords); null: as a mission file does.
    std::shared_ptr<const SettingWords> words;

    /// @brief True when the mission's time unit is known in seconds (a forecast, units.time_s, or an epoch), so that
    /// durations such as "1 h" can be converted (parseDuration()).
    bool hasTimeUnit() const { return physicalUnits().time || epoch.has_value(); }

    /// @brief Which of the mission's units are physical: a forecast plans in metres and seconds; an analytic flow
    /// only where `units` gives length_m / time_s other than 1. Outputs print hours/days and km for physical units,
    /// the field's numbers otherwise (the one rule for every output).
    struct PhysicalUnits
    {
        bool time{false};   ///< times are in known seconds (durations in hours and days)
        bool length{false}; ///< lengths are in known metres (distances in km)
    };
    /// @brief Metres per planning length unit: 1 for a forecast (planned in metres), else `lengthUnitMetres`.
    double metresPerUnit() const { return current.isForecast() ? 1.0 : lengthUnitMetres; }
    /// @brief The mission's PhysicalUnits.
    PhysicalUnits physicalUnits() const
    {
        const bool forecast = current.isForecast();
        return {forecast || timeUnitSeconds != 1.0, forecast || lengthUnitMetres != 1.0};
    }

    /// @brief A time given as text, read as the mission's departure times are: a number in field units, or an ISO 8601
    /// date converted with the dated forecast's calendar or the mission's epoch. @throws Error saying what was
    /// expected (the caller adds where).
    double timeOf(const std::string &text) const;
    /// @brief Field time @p t as an ISO 8601 date in the mission's calendar (the dated forecast's, or the epoch's);
    /// empty without dates or for a time that is not finite. @throws Error outside the years 0000-9999.
    std::string isoTime(double t) const;
    /// @brief A duration @p d in field time units: "3 d 4.2 h" where the time unit is known, else the number.
    std::string durationText(double d) const;

    /// @brief "m.yaml:12: field 'planner.grid_size'", "--grid-size" for a flag, "plan(): keyword 'speed'" for a
    /// keyword of the Python module, or "m.yaml: field '...'" when the value was not given (a default).
    std::string place(const std::string &field) const;

    /// @brief @p setting with the front end's word for it (SettingWords): "planner.time_limit, --time-limit" from
    /// the command line, "planner.time_limit, time_limit=" from Python, "planner.time_limit" from a mission file.
    std::string term(const std::string &setting) const;
};

/// @brief Reads and validates a YAML mission file. Every field is checked: an unknown field, a wrong type, a
/// missing required field or a value out of range throws ompl_glider::Error "FILE:LINE: field 'a.b.c': what was
/// expected" (line from the YAML node, 1-based).
MissionSpec loadMission(const std::string &path);

/// @brief The same from YAML text; @p file names it in messages and @p directory resolves relative paths.
MissionSpec parseMission(const std::string &yamlText, const std::string &file = "<mission>",
                         const std::string &directory = ".");

/// @brief The built-in Gulf Stream mission, defined once for the command line, the tests and the benchmarks:
/// meandering jet ([EichhornRAS] Sec. 6.1), x in [0, 10], y in [-4, 4], V = 0.5, start (1, -3) south of the jet,
/// goal (8, 3) north of it, departure 0, horizon 60, goal tolerance 1e-3, ZA*TVE on a 0.4 lattice with 3 sectors.
MissionSpec defaultGulfStreamMission();

/// @brief Default lattice spacing on an analytic flow (planner.grid_size 0), the forecasts' rule
/// (defaultForecastGridSize()) with 0.4 ([EichhornRAS] Sec. 6.1) in place of half a grid cell: 0.4 kept within
/// 1/200..1/25 of the start-goal @p distance, two significant digits (a 1-unit trip gets 0.04, 25 steps across).
/// The built-in mission's trip (the meandering jet from (1, -3) to (8, 3), built in or from a file) keeps 0.4, the
/// paper's lattice for it (its 9.2 units would give 0.37), so its figures stay the paper's.
double defaultAnalyticGridSize(const MissionSpec &m, double distance);

/// @brief "FILE:LINE: " of a mark from a mission file, else "MISSION_FILE: ".
std::string sourcePlace(const MissionSpec &m, const SourceMark &mark = {});
} // namespace ompl_glider
