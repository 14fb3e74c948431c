#pragma once
/// @file MissionProblem.h
/// @brief The one problem description every way in builds: a MissionSpec turned into the current field, the
/// forbidden regions, the planning frame (and its geographic projection), start and goal. The planning pipeline
/// (Planning.h) plans on it; the output layer (output/) writes from it.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/Geometry.h"
#include "ompl_glider/cost/DiveProfile.h"
#include "ompl_glider/current/CorrectedField.h"
#include "ompl_glider/current/ForecastRuns.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/current/ForecastSource.h"
#include "ompl_glider/environment/KeepOffZone.h"
#include "ompl_glider/environment/Environment.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/ProblemInputs.h"
#include "ompl_glider/ompl/GliderSetup.h"

namespace ompl_glider
{
class ForbiddenRegions;
class Polygon;
struct ObservationReport;
struct GliderObservations;
class ForbiddenCells;
struct LoadedForecast;
class LocalProjection;
struct LandPolygon;
struct GeoBox;

/// @brief A forbidden region in the planning frame (for maps and outputs).
struct MissionPolygon
{
    std::string name;                    ///< its name
    RegionKind kind{RegionKind::Island}; ///< what it is (its name: regionKindName())
    std::vector<Point2> points;          ///< outer ring, planning frame
    bool coastline{false};               ///< one of the coastline file's land polygons
    /// A closure's windows: the closed [from, to] intervals (field time units) in which it is forbidden; empty: at
    /// all times
    std::vector<std::pair<double, double>> windows;
};

/// @brief The problem of a mission: field, forbidden regions, frame conversions. Thread-safe for const use (the
/// departure-time search plans on it from several threads).
class MissionProblem
{
public:
    /// @brief Reads the mission's inputs (loadProblemInputs()) and builds the problem from them.
    /// @throws Error naming the mission file and field when something does not fit (start outside the box, ...).
    explicit MissionProblem(MissionSpec spec);
    /// @brief Builds the problem from what the mission read: start/goal in the planning frame (moved off land when
    /// the mission says so), the forecast corrected by the glider's DAC, the forbidden regions and the safety
    /// margins. Reads nothing.
    explicit MissionProblem(const ProblemInputs &inputs);
    ~MissionProblem();

    /// @brief The mission, with its automatic settings resolved (planner.grid_size).
    const MissionSpec &getSpec() const { return spec_; }
    /// @brief The current field.
    const std::shared_ptr<const CurrentField> &getField() const { return field_; }
    /// @brief The forecast's files (or URLs) read for the current, in time order (the one file, or those of a
    /// forecast in several files that hold the trip's records); empty for an analytic current.
    const std::vector<std::string> &forecastFiles() const { return forecastFiles_; }
    /// @brief The forecast's OPeNDAP sources (io/RemoteSource.h): what came from the network and from the cache,
    /// as read when the problem was built; empty for files.
    const std::vector<RemoteFetch> &remoteSources() const { return remoteSources_; }
    /// @brief The ocean an execution flies in (MissionSpec::execution.truth, on the forecast's frame and time
    /// axis); the forecast itself when no truth is given.
    const std::shared_ptr<const CurrentField> &getTruth() const { return truth_ ? truth_ : field_; }
    /// @brief The forecast's runs (MissionSpec current.runs; null: one forecast): getField() is run runIndex(), the
    /// newest available at the departure.
    const std::shared_ptr<const ForecastRuns> &runs() const { return runs_; }
    /// @brief The run planned on (with runs()).
    std::size_t runIndex() const { return run_; }
    /// @brief The forecast error's spread the runs show (ProblemInputs::runSpread; unset: not estimated): the
    /// priors of correctionParams() where the mission gives no scale.
    const std::optional<RunSpread> &runSpread() const { return runSpread_; }
    /// @brief The members of an ensemble current (on the forecast's frame and dates; the first read as the forecast);
    /// empty for a single source. getField() is then their mean (EnsembleMeanField).
    const std::vector<std::shared_ptr<const CurrentField>> &getMembers() const { return members_; }
    /// @brief The members of an ensemble current as read, when the glider's observations weighed them
    /// (observations()->members[k] is member k's weight): the plan is then made on the forecast they make
    /// (getField()) and getMembers() is empty; the probability of reach weighs these members. Empty otherwise.
    const std::vector<std::shared_ptr<const CurrentField>> &weighedMembers() const { return weighedMembers_; }
    /// @brief The same problem on one member's field alone (no ensemble): of getMembers(), or of weighedMembers()
    /// when the observations weighed them.
    MissionProblem withMember(std::size_t member) const;
    /// @brief The same problem between other endpoints (planning frame): field, truth, regions and box are shared.
    /// The spec's start and goal stay the mission's. The goal's arrival window (MissionSpec::goalWindow) is kept for
    /// the mission's goal (a replan from a fix) and dropped for another goal (the execution batch's random pairs).
    MissionProblem withEndpoints(Point2 start, Point2 goal) const;
    /// @brief One leg of a mission of several legs: the same problem from @p start to @p goal (planning frame) with
    /// @p window as the goal's arrival window and no via points; field, truth, regions and box are shared, and an
    /// automatic lattice spacing (planner.grid_size 0) is chosen for the leg's length as for a one-leg mission.
    MissionProblem withLeg(Point2 start, Point2 goal, const GoalWindowSpec &window) const;
    /// @brief The same problem on another field (the forecast corrected by a glider's measurements while it flies).
    MissionProblem withField(std::shared_ptr<const CurrentField> field) const;
    /// @brief The correction of the forecast by a glider's DAC as the mission sets it (MissionSpec::observations),
    /// its defaults resolved: L 20 km for a forecast (a tenth of the box's larger side for an analytic flow), T one
    /// day where the time unit is known (else a tenth of the field's span, or of the box's crossing at the
    /// vehicle's speed when the field has no end), the depth range of the dive profile or the vehicle's depth.
    CorrectionParams correctionParams() const;
    /// @brief The via points (MissionSpec::waypoints) in the planning frame, in the mission's order.
    const std::vector<Point2> &getViaPoints() const { return via_; }
    /// @brief What the glider's observations (MissionSpec::observations) gave and how they corrected the forecast;
    /// unset without observations (getField() is then the forecast itself, else the corrected one).
    const std::shared_ptr<const ObservationReport> &observations() const { return observations_; }
    /// @brief The forbidden regions (null when there are none).
    const std::shared_ptr<const Environment> &getEnvironment() const { return environment_; }
    /// @brief Land's boundary with the keep-off distance (MissionSpec::safety): the zone the planners keep off, and
    /// the distances of the closest approach; null when the problem has no land.
    const std::shared_ptr<const KeepOffZone> &getLand() const { return land_; }
    /// @brief What the depth limit read ("depth limit 50 m from 'gebco.nc' variable 'elevation' (elevation, positive
    /// up (attribute positive)): 1234 cells forbidden"); empty without one.
    const std::string &safetyNote() const { return safetyNote_; }
    /// @brief What reading the forecast decided that a pilot should know, one sentence each: how grid-relative
    /// velocities were turned ("grid angle derived from 'lon_rho'/'lat_rho': ..."), how many nodes are land only
    /// because u = v = 0; empty for analytic fields and forecasts with nothing to say.
    const std::vector<std::string> &forecastNotes() const { return forecastNotes_; }
    /// @brief Start or goal moved off land (MissionSpec::safety.snapToWater), one sentence each: from where to where.
    const std::vector<std::string> &endpointNotes() const { return endpointNotes_; }
    /// @brief What the field is: "wind" for a forecast of winds (uwnd, u10, ...), else "current".
    const std::string &fieldWord() const { return fieldWord_; }
    /// @brief What the coastline file gave (how many land polygons, which were repaired and why), or "".
    const std::string &coastlineNote() const { return coastlineNote_; }
    /// @brief Forbidden regions in the planning frame.
    const std::vector<MissionPolygon> &getPolygons() const { return polygons_; }
    /// @brief Planning box (x/y) and the field's time span.
    const Region &getBox() const { return frame_.box; }
    /// @brief planner.grid_size was not given (0): the lattice spacing is chosen from each leg's length
    /// (automaticGridSize()).
    bool gridSizeAutomatic() const { return gridSizeAutomatic_; }
    /// @brief Start position (planning frame).
    Point2 getStart() const { return start_; }
    /// @brief Goal position (planning frame).
    Point2 getGoal() const { return goal_; }

    /// @brief True when lon/lat can be computed (projection given or geographic forecast).
    bool isGeographic() const;
    /// @brief Planning frame -> lon/lat (longitude in -180..180). @throws Error when !isGeographic().
    LonLat toGeographic(Point2 p) const;
    /// @brief lon/lat -> planning frame. @throws Error when !isGeographic().
    Point2 toLocal(LonLat g) const;
    /// @brief ISO 8601 of a field time, empty without a calendar.
    std::string isoTime(double t) const;

    /// @brief The GliderProblem (field, travel parameters with @p speed, environment, box, departure, horizon,
    /// start, goal) for a departure at tDep.
    GliderProblem gliderProblem(double tDep, double speed) const;
    /// @brief How near the goal a path ends (planning units): planner.goal_tolerance, else a millionth of the box's
    /// larger side.
    double goalTolerance() const;
    /// @brief The planning horizon of a departure at @p tDep at @p speed (field time units): planner.horizon, else
    /// 50 crossings of the box and the trip at that speed, within the field's time.
    double horizon(double tDep, double speed) const;

    /// @brief Lower bound of the trip duration at @p speed: distance / (V + max|c|).
    double minTripDuration(double speed) const;

    /// @brief Dive-profile travel time over the mission's field (null when dive profiles are off).
    std::shared_ptr<const DiveProfileTravelTime> diveProfiles(double speed) const;

private:
    /// A start or goal on the forecast's land (Endpoints.cpp): refused naming the nearest water, or moved there
    /// with MissionSpec::safety.snapToWater.
    void snapEndpoints();
    /// Start, goal and via points inside the planning box, else refused naming the one outside.
    void checkPointsInBox() const;
    /// The forecast corrected by the glider's DAC @p o (Correction.cpp).
    void applyObservations(const GliderObservations &o);
    /// Via points in the region, in water, their stays within the forecast (Endpoints.cpp).
    void checkViaPoints() const;
    /// The automatic lattice spacing (planner.grid_size 0) of a leg from @p a to @p b (Endpoints.cpp): the
    /// default for its length (defaultForecastGridSize(), defaultAnalyticGridSize()), never so fine that the
    /// planning box's lattice holds more than kAutomaticLatticeVertices.
    double automaticGridSize(Point2 a, Point2 b) const;
    /// The forbidden regions and the coastline's land polygons @p in read (Land.cpp).
    void buildRegions(const ProblemInputs &in);
    /// A polygon as given, checked and placed in the planning frame, and kept for the maps (Land.cpp).
    Polygon placedPolygon(const PolygonSpec &p, RegionKind kind);
    /// The coastline's land polygons as read (ProblemInputs::coastline), added to @p regions (Land.cpp).
    void addCoastline(ForbiddenRegions &regions, const ProblemInputs &in);
    /// A GeoJSON of forbidden regions none of whose polygons lies in or near the box (lon and lat swapped, another
    /// region) is refused (Safety.cpp).
    void checkGeoJsonNearBox() const;
    /// The keep-off zone and the shallow water of @p in's depth grid (Safety.cpp), added to @p regions.
    void addSafety(ForbiddenRegions &regions, const ProblemInputs &in);
    /// The shallow water of the depth limit (Safety.cpp); null without a bathymetry.
    std::shared_ptr<const ForbiddenCells> shallowWater(const ProblemInputs &in);
    /// A point given (lon/lat, or x/y in a Cartesian forecast's own axis units) in the planning frame (Endpoints.cpp).
    Point2 localPoint(const PointSpec &p, const std::string &what) const;
    std::vector<Point2> ring(const std::vector<std::pair<double, double>> &pts, bool geographic,
                             const std::string &what) const;

    MissionSpec spec_;
    std::shared_ptr<const CurrentField> field_;
    std::shared_ptr<const CurrentField> truth_;                       // null: the forecast
    std::vector<std::shared_ptr<const CurrentField>> members_;        // ensemble members (empty: one source)
    std::vector<std::shared_ptr<const CurrentField>> weighedMembers_; // the members the observations weighed
    std::shared_ptr<const ForecastRuns> runs_;                        // the forecast's runs (null: one forecast)
    std::size_t run_{0};                                              // the run planned on
    std::optional<RunSpread> runSpread_; // the runs' spread: the correction's priors (unset: not estimated)
    std::shared_ptr<const Environment> environment_;
    PlanningFrame frame_; // projection, units and box
    std::vector<std::string> forecastFiles_;
    std::vector<std::string> forecastNotes_;
    std::vector<RemoteFetch> remoteSources_;
    std::vector<std::string> endpointNotes_;
    std::vector<MissionPolygon> polygons_;
    Point2 start_, goal_;
    std::vector<Point2> via_;                               // via points, planning frame
    std::shared_ptr<const ObservationReport> observations_; // what the observations gave (null: none)
    bool gridSizeAutomatic_{false};                         // planner.grid_size was 0: chosen from each leg's length
    std::shared_ptr<const KeepOffZone> land_;               // land's boundary and the keep-off distance (null: no land)
    std::string safetyNote_;                                // what the depth limit read, and how
    std::string fieldWord_{"current"};                      // "current" or "wind"
    std::shared_ptr<const Bathymetry> diveBathymetry_;      // the dive profiles' bathymetry (null: none)
    std::string coastlineNote_;                             // what the coastline gave, and what was repaired
};

/// @brief The GliderProblem of the built-in Gulf Stream mission (defaultGulfStreamMission()) departing at 0, for
/// tests and benchmarks that use the OMPL layer directly.
GliderProblem gulfStreamProblem();

/// @brief The water point nearest to @p p at depth z: just beyond (by @p step, in planning units) the closest point
/// of the field's land boundary (CurrentField::landBoundary()), checked with inWater(); nullopt when none is found.
std::optional<Point2> nearestWater(const CurrentField &field, Point2 p, double z, double step);

/// @brief The most vertices an automatic lattice spacing gives the planning box's lattice (2^22): a leg of a few tens
/// of metres (a glider resumed beside its next station or its goal) gets a spacing the box's lattice can hold, its
/// start and goal then joined by the lattice's direct edge, not a thousandth of the box's side.
constexpr double kAutomaticLatticeVertices = 4194304.0;

/// @brief Default lattice spacing (metres) on a forecast: half the smallest grid cell, but no coarser than 1/25
/// of the start-goal distance and no finer than 1/200 of it, rounded to two significant digits. (Half a cell
/// resolves the interpolated field; 25 steps keep the path's shape; 200 steps bound the search on fine grids.)
/// @throws Error when no finite size results.
double defaultForecastGridSize(double minCellSize, double startGoalDistance);
} // namespace ompl_glider
