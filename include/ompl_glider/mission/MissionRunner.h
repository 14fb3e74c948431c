#pragma once
/// @file MissionRunner.h
/// @brief A mission end to end (SPEC.md 4, 6; 003 Sec. IV): the problem built from a MissionSpec, the optimal
/// departure (000 Sec. 5), the lattice search (ZA*TVE family) with smoothing and refinement, dive profiles per leg
/// (003 Sec. III), the speed sweep (003 Table VI) and the outputs a pilot uses.

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/cost/DiveProfile.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/environment/Environment.h"
#include "ompl_glider/mission/DepartureTimeSearch.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/planners/TveSearch.h"

namespace ompl_glider
{
struct NetCdfCurrentOptions;
class LocalProjection;

/// @brief A forbidden region in the planning frame (for maps and outputs).
struct MissionPolygon
{
    std::string name;                                ///< its name
    std::string kind;                                ///< island / land / restricted area / closure / ice
    std::vector<std::pair<double, double>> points;   ///< outer ring, x/y
};

/// @brief Overrides of the mission's planner settings for one plan (NaN / 0 / unset: the mission's value).
struct PlanOptions
{
    double speed{std::numeric_limits<double>::quiet_NaN()};  ///< vehicle speed
    double gridSize{0.0};                                    ///< lattice spacing
    int sectors{0};                                          ///< lattice sectors
    std::optional<bool> smoothing;                           ///< smoothing (000 Table 3)
    std::optional<bool> refinement;                          ///< waypoint refinement
};

/// @brief One planned path.
struct PlannedPath
{
    bool solved{false};                 ///< a path to the goal was found
    std::string status;                 ///< "exact", "no path on the lattice", "invalid start: ...", ...
    double departure{0.0};              ///< departure time (field units)
    double speed{0.0};                  ///< vehicle speed used
    std::vector<TimedWaypoint> raw;     ///< lattice path (times re-simulated)
    std::vector<TimedWaypoint> path;    ///< final path (smoothed / refined when asked), times re-simulated
    std::size_t smoothedWaypoints{0};   ///< waypoints after smoothing, before refinement (= raw without smoothing)
    double rawTravelTime{std::numeric_limits<double>::infinity()};  ///< lattice path travel time
    double travelTime{std::numeric_limits<double>::infinity()};     ///< final path travel time
    double rawPathLength{0.0};          ///< lattice path length
    double pathLength{0.0};             ///< final path length
    double straightLineTime{std::numeric_limits<double>::infinity()};  ///< direct leg (+inf: impassable)
    double straightLineLength{0.0};     ///< start-goal distance
    std::uint64_t costFunctionCalls{0}; ///< CFC of search + smoothing + refinement
    std::uint64_t currentModelCalls{0}; ///< CMC of the search (000 Table 4)
    std::uint64_t expansions{0};        ///< lattice vertices expanded
    double wallSeconds{0.0};            ///< planning wall time (search + post-processing)
};

/// @brief A waypoint as written for the pilot.
struct MissionWaypoint
{
    double x{0.0}, y{0.0};            ///< planning frame
    bool geographic{false};           ///< lon/lat known
    double lon{0.0}, lat{0.0};        ///< degrees
    double time{0.0};                 ///< arrival (field units), with the dive profiles when they are enabled
    std::string iso;                  ///< arrival as ISO 8601 UTC when the mission has a calendar, else empty
    int profile{-1};                  ///< dive profile index of the leg that reaches this waypoint (-1: none)
    DiveProfile dive;                 ///< that profile (climb-to / dive-to depths)
    double legTime{0.0};              ///< travel time of the leg that reaches it
};

/// @brief One row of the speed sweep (003 Table VI).
struct SpeedSweepRow
{
    double speed{0.0};               ///< vehicle speed
    bool solved{false};              ///< path found
    double travelTime{std::numeric_limits<double>::infinity()};        ///< path travel time
    double pathLength{0.0};          ///< path length
    double straightLineTime{std::numeric_limits<double>::infinity()};  ///< direct leg (+inf: impassable)
    double straightLineLength{0.0};  ///< direct distance
};

/// @brief The problem of a mission: field, forbidden regions, frame conversions and the planning calls.
/// Thread-safe for const use (departure searches call plan() from several threads).
class MissionProblem
{
public:
    /// @brief Builds the field (analytic or NetCDF), the projection, the box, start/goal and the environment.
    /// @throws Error naming the mission file and field when something does not fit (start outside the box, ...).
    explicit MissionProblem(MissionSpec spec);
    ~MissionProblem();

    /// @brief The mission.
    const MissionSpec &spec() const
    {
        return spec_;
    }
    /// @brief The current field.
    const std::shared_ptr<const CurrentField> &field() const
    {
        return field_;
    }
    /// @brief The forbidden regions (null when there are none).
    const std::shared_ptr<const Environment> &environment() const
    {
        return environment_;
    }
    /// @brief Forbidden regions in the planning frame.
    const std::vector<MissionPolygon> &polygons() const
    {
        return polygons_;
    }
    /// @brief Planning box (x/y) and the field's time span.
    const Region &box() const
    {
        return box_;
    }
    double startX() const { return sx_; }  ///< start x
    double startY() const { return sy_; }  ///< start y
    double goalX() const { return gx_; }   ///< goal x
    double goalY() const { return gy_; }   ///< goal y

    /// @brief True when lon/lat can be computed (projection given or geographic forecast).
    bool geographic() const;
    /// @brief Planning frame -> lon/lat. @throws Error when !geographic().
    void toGeographic(double x, double y, double &lon, double &lat) const;
    /// @brief lon/lat -> planning frame. @throws Error when !geographic().
    void toLocal(double lon, double lat, double &x, double &y) const;
    /// @brief ISO 8601 of a field time, empty without a calendar.
    std::string isoTime(double t) const;

    /// @brief The GliderProblem (field, travel parameters with @p speed, environment, box, t0, horizon, start,
    /// goal) for a departure at tDep.
    GliderProblem gliderProblem(double tDep, double speed) const;

    /// @brief Plans from the start at tDep: lattice search (TveSearch configured as TVE / A*TVE / ZTVE / ZA*TVE by
    /// planner.name; an OMPL planner name goes through runPlan() of PlanRun.h), then smoothing (PathSmoother,
    /// 000 Table 3) and refinement (WaypointRefiner) as asked; the straight-line time for comparison.
    /// Planning is 2-D at vehicle.depth; dive profiles are evaluated on the planned legs (missionWaypoints()).
    /// No path is an outcome (solved false, status says why), not an exception.
    PlannedPath plan(double tDep, const PlanOptions &options = {}) const;

    /// @brief Travel time of a full lattice search against departure time (000 Sec. 5), for the departure search:
    /// thread-safe, +inf when no path. @p gridSize / @p sectors 0: the planner's.
    TravelTimeOfDeparture departureFunction(double gridSize = 0.0, int sectors = 0) const;

    /// @brief Lower bound of the trip duration at @p speed: distance / (V + max|c|).
    double minTripDuration(double speed) const;

    /// @brief Dive-profile travel time over the mission's field (null when dive profiles are off).
    std::shared_ptr<const DiveProfileTravelTime> diveProfiles(double speed) const;

private:
    MissionSpec spec_;
    std::shared_ptr<const CurrentField> field_;
    std::shared_ptr<const Environment> environment_;
    std::shared_ptr<const LocalProjection> projection_;
    double projectionScale_{1.0};  // metres per planning unit
    std::vector<MissionPolygon> polygons_;
    Region box_;
    double sx_{0}, sy_{0}, gx_{0}, gy_{0};
    std::string netcdfIsoHint_;
};

/// @brief How runMission() runs.
struct RunOptions
{
    bool writeOutputs{true};  ///< write the files listed in the mission's outputs
    bool progress{false};     ///< progress lines on stderr (departure search, speed sweep)
    std::optional<std::vector<double>> speeds;  ///< speed sweep (overrides the mission's `speeds`)
    std::optional<std::string> outputDirectory; ///< overrides outputs.directory
};

/// @brief Everything a mission produced.
struct MissionResult
{
    MissionSpec spec;                       ///< the mission
    PlannedPath plan;                       ///< the path at the chosen departure
    std::vector<MissionWaypoint> waypoints; ///< final path for the pilot (start first)
    bool diveProfiles{false};               ///< dive profiles evaluated
    std::vector<DiveProfile> profileSet;    ///< the generated profile set (003 Sec. III.B)
    double diveTravelTime{std::numeric_limits<double>::infinity()};  ///< travel time flying the chosen profiles
    std::optional<DepartureSearchResult> departureSearch;  ///< when a window was given
    std::vector<SpeedSweepRow> speedSweep;  ///< speed sweep rows (003 Table VI)
    std::vector<std::string> files;         ///< files written
    double wallSeconds{0.0};                ///< whole run
};

/// @brief The NetCDF load options of a `current: {type: netcdf}` block: variable names (lon/lat, else x/y),
/// interpolation schemes, horizon policy and field name. The caller adds the region, depth range and projection.
/// Shared by MissionProblem and the --currents CLI path so that both read the file the same way.
/// @throws Error for an unknown interpolation scheme.
NetCdfCurrentOptions netCdfCurrentOptions(const CurrentSpec &current);

/// @brief Runs a mission: problem, departure search (window), plan, dive profiles, speed sweep, outputs.
/// A mission without a path is an outcome (plan.solved false, summary written), not an exception.
/// @throws Error for configuration or I/O errors.
MissionResult runMission(const MissionSpec &spec, const RunOptions &options = {});
/// @brief The same on a problem already built (its current field already loaded), e.g. to reuse the problem for
/// the map afterwards. wallSeconds then excludes building the problem.
MissionResult runMission(const MissionProblem &problem, const RunOptions &options = {});

/// @brief The speed sweep (003 Table VI): plans at every speed from the departure tDep.
std::vector<SpeedSweepRow> speedSweep(const MissionProblem &problem, double tDep, const std::vector<double> &speeds,
                                      bool progress = false);

/// @brief Waypoints for the pilot and the travel time flying them.
struct PilotWaypoints
{
    std::vector<MissionWaypoint> waypoints;  ///< start first
    /// Travel time with the chosen dive profiles (+inf when a leg is impassable with every profile); the 2-D travel
    /// time when dive profiles are off.
    double travelTime{std::numeric_limits<double>::infinity()};
};

/// @brief Waypoints for the pilot from a planned path: geographic coordinates, ISO times and, with dive profiles
/// (003 Sec. III), the profile chosen for each leg (evaluated in parallel) and the arrival times flying it.
PilotWaypoints missionWaypoints(const MissionProblem &problem, const PlannedPath &plan);
}  // namespace ompl_glider
