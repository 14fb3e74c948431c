#pragma once
/// @file GriddedCurrents.h
/// @brief Loading ocean-current forecasts from NetCDF files (ROMS, HYCOM, Copernicus Marine, NEMO, POP...) into
/// a GriddedCurrentField in local Cartesian metres and seconds ([EichhornOceans] Sec. II.B-C, [EichhornRAS] Sec. 3.4).

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/current/ForecastSource.h"
#include "ompl_glider/current/GriddedCurrentField.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/io/FileList.h"

namespace ompl_glider
{
/// @brief How the horizontal coordinates of the file are read.
enum class CoordinateMode
{
    Auto,       ///< geographic when longitude/latitude are found (degrees_east/north or standard_name), else Cartesian
    Geographic, ///< longitude/latitude in degrees, projected with LocalProjection about a reference point
    Cartesian   ///< x/y axes used as they are ("no projection"; units m, km or dimensionless); a time axis without
                ///< "since" is then read as raw values, and velocities without units as dimensionless
};

/// @brief Options of loadGriddedCurrents(). Every field has a usable default: only the path is required.
struct GriddedCurrentOptions
{
    // --- variables (empty: found automatically) ---
    std::string uName;     ///< eastward velocity; default: CF standard_name eastward_sea_water_velocity and
                           ///< variants (surface_, baroclinic_, barotropic_, ..._assuming_no_tide, eastward_current,
                           ///< sea_water_x_velocity), then the names uo, u, water_u, uvel, urot, u_eastward,
                           ///< vozocrtx, ucur, u_current, uwnd, u10 in any case (UVEL, UWND, U)
    std::string vName;     ///< northward velocity (same rules with northward / y / v)
    std::string lonName;   ///< longitude or x coordinate variable (1-D axis or 2-D curvilinear)
    std::string latName;   ///< latitude or y coordinate variable
    std::string depthName; ///< depth coordinate variable
    std::string timeName;  ///< time coordinate variable
    CoordinateMode coordinates{CoordinateMode::Auto}; ///< how to read x/y
    std::string velocityUnits; ///< overrides the units attribute of u and v: any velocity UDUNITS-2 reads ("m/s",
                               ///< "cm s-1", "knots", "km/h"; UnitConversion.h)
    /// the fastest current believed (m/s; NaN: 300 m/s, where a few fast nodes continuous with their neighbours
    /// pass, e.g. beside a vortex's core); a node faster than it is refused (a fill value not declared, wrong units)
    double maxSpeed{std::numeric_limits<double>::quiet_NaN()};
    std::string timeUnits; ///< overrides the units attribute of the time variable: "<unit> since <date>"
                           ///< ("days since 2026-01-15"), e.g. for an axis in "month", "hours" or without units
    std::optional<std::size_t> steadyRecord; ///< read only this time record (0-based) and plan on it as a steady
                                             ///< field (dated by the record's time when the axis is dated)
    /// a file of several forecast runs (a THREDDS FMRC: velocities on a run dimension, `run`/`reftime` with CF
    /// standard_name forecast_reference_time, and a 2-D time(run, time)): the run read (0-based along the run
    /// dimension); required by loadGriddedCurrents() when that dimension holds more than one run
    std::optional<std::size_t> runIndex;

    std::string angleName; ///< angle (radians or degrees) from the grid's i direction to east, for velocities given
                           ///< along the grid (ROMS angle, POP ANGLE); empty: a variable named "angle" on the
                           ///< velocities' grid unless u says it is eastward (standard_name eastward_*, or
                           ///< "east" in its name, as ROMS' u_eastward); "none": none

    // --- land (besides fill values of u/v, which are always land; every signal's land is land: the union) ---
    std::string maskName; ///< land/sea mask variable; empty: found automatically (loadGriddedCurrents()); "none": none
    std::string tracerName;      ///< tracer (temperature, salinity) whose missing values mark land; empty: found
                                 ///< automatically (loadGriddedCurrents()); "none": none
    bool zeroVelocityLand{true}; ///< a node whose u and v are exactly 0 in every record of the trip is land (models
                                 ///< such as POP store coastal velocity points as zeros, not fill values) where it
                                 ///< touches other land or the file marks none (rules at loadGriddedCurrents())

    // --- model ---
    GriddedFieldOptions field; ///< schemes (xy bilinear, depth linear, time linear), BeyondForecast, name

    // --- what to load ([EichhornOceans] Sec. II.B: only the region, depth layers and times the mission needs) ---
    double lonMin{std::numeric_limits<double>::quiet_NaN()}; ///< region of interest (x in Cartesian mode);
    double lonMax{std::numeric_limits<double>::quiet_NaN()}; ///< NaN = the whole file. lonMax < lonMin means
    double latMin{std::numeric_limits<double>::quiet_NaN()}; ///< the region crosses the antimeridian.
    double latMax{std::numeric_limits<double>::quiet_NaN()};
    double margin{0.0}; ///< extra margin around the region (degrees, or x/y units in Cartesian mode)
    int marginNodes{2}; ///< extra grid nodes on each side (2 keeps bicubic stencils inside the data)
    /// Depth-averaged current over [first, second] metres (positive down, first <= second): the layers covering the
    /// range are loaded and averaged (the trapezoid rule on the piecewise-linear profile, which is exact for a
    /// current linear in depth between layers; constant above the first layer and below the last), giving a 2-D
    /// field; a node that is land at any layer within the range is land. What pilots read off a forecast for the
    /// glider's working depth. Replaces maxDepth.
    std::optional<std::pair<double, double>> depthAverage;
    double maxDepth{std::numeric_limits<double>::infinity()}; ///< deepest depth the glider reaches (m, positive
                                                              ///< down): loads the layers down to the first at or
                                                              ///< below it, plus 2 for cubic/Akima stencils
    std::string departure; ///< ISO 8601 date/time, or a number of seconds after the first forecast time; empty
                           ///< = the first forecast time. Outside the forecast -> Error (a steady field takes
                           ///< any time; a date only when it is dated).
    double horizon{std::numeric_limits<double>::infinity()}; ///< seconds after departure to load (plus 2 time
                                                             ///< steps of margin); infinity = to the end

    // --- projection ---
    double refLon{std::numeric_limits<double>::quiet_NaN()}; ///< reference point of the local frame; NaN = the
    double refLat{std::numeric_limits<double>::quiet_NaN()}; ///< centre of the region (or of the loaded grid)
};

/// @brief A loaded forecast: the field (x east / y north in metres, t in seconds since the first forecast time of
/// the file, or of the earliest file of a forecast in several files; raw units in Cartesian mode), its frame and
/// clock (ForecastFrame: projection, calendar, departure, the loaded bounds, the files read) and what the reader
/// decided.
struct GriddedCurrents : ForecastFrame
{
    std::shared_ptr<GriddedCurrentField> field; ///< ready to plan on
    std::string uVariable, vVariable;           ///< variables read
    bool depthAxis{false};                      ///< u has a depth dimension (else its currents are of one level)
    std::vector<std::size_t> loadedShape;       ///< nt, nz, ny, nx actually loaded
    std::string maskVariable;                   ///< the land/sea mask read ("" when none)
    /// How grid-relative velocities were turned to eastward/northward: "" (the velocities are eastward/northward,
    /// or the grid is not rotated), "variable 'angle'", or "derived from lon_rho/lat_rho: the grid's i direction
    /// 29.7..30.3 degrees counter-clockwise from east" (a rotated curvilinear grid without angle variable)
    std::string gridAngle;
    /// The tracer whose missing values mark land ("" when none), and where its cells lie: "same points", or
    /// "B grid: velocity points at the north-east corners of the tracer cells" (or south-west): a velocity point is
    /// then land when any of the 4 tracer cells around it is.
    std::string tracerVariable, tracerPlacement;
    /// The velocities are a B grid's (POP, MOM): the corners of the tracer cells, where the model writes every
    /// point that touches a land cell as zero velocity; every still node is then land.
    bool cornerGrid{false};
    std::size_t landNodes{0};       ///< loaded nodes (x depth layers) that are land, for any of the reasons, each
                                    ///< node counted once, for the first of them that marks it:
    std::size_t fillLandNodes{0};   ///<   u or v a fill value in some record of the trip
    std::size_t maskLandNodes{0};   ///<   land in the mask (in some record of the trip, for a mask with a time axis)
    std::size_t tracerLandNodes{0}; ///<   a tracer's missing value (tracerVariable) in some record of the trip
    std::size_t zeroLandNodes{0};   ///<   u = v = 0 exactly in every record of the trip (zeroVelocityLand)
    std::size_t fileValues{0};      ///< values per component in the file variable (summed over the files read)
    std::size_t loadedValues{0};    ///< values per component loaded
    /// Forecast in several files: records of a file left out because a later file (the newer forecast) starts
    /// at or before their time, counted over all the files given; 0 for one file.
    std::size_t droppedRecords{0};
};

/// @brief Loads u/v from a NetCDF file into a GriddedCurrentField (see GriddedCurrentOptions for what is found
/// automatically and what is loaded).
///
/// Reads: dimensions (time, depth, lat, lon) in any order of the file, depth and time optional; 1-D axes or 2-D
/// curvilinear latitude/longitude (from the `coordinates` attribute, standard_name or units); scale_factor /
/// add_offset packing; _FillValue / missing_value / valid_min / valid_max / valid_range compared on the packed
/// value (plus the netCDF default fill when _FillValue is absent, and NaN); CF time units with the standard,
/// gregorian, proleptic_gregorian, julian, noleap/365_day, all_leap/366_day and 360_day calendars; longitudes
/// in -180..180 or 0..360 and regions across the seam of a global grid; latitude and depth ascending or
/// descending; depth positive="up" negated; velocities, Cartesian axes and depths in any unit UDUNITS-2 reads
/// ("m s-1", "cm/s", "knots", "km/h"; "km", "centimeters": UnitConversion.h). Only the hyperslab covering the
/// region (+ margin), the depth layers down to maxDepth and the time window is read (nc_get_vara).
///
/// Land, per node and depth layer, is the union of every signal the file gives (the more conservative where they
/// disagree), each decided on the trip's records: u or v a fill value in any of them; land in a mask variable
/// (below), in any of them when the mask has the time axis of u; a tracer's missing value (below); and still nodes,
/// u = v = 0 exactly in all of them (GriddedCurrentOptions::zeroVelocityLand, on by default). The trip's records are
/// those from the last at or before the departure to the first at or after departure + horizon (not the stencil
/// margin loaded around them), so a seasonal mask or missing winter data close what is closed during the trip,
/// not all year.
///
/// Still nodes are land where the file marks no other land in the region (POP-like files whose land is all zeros),
/// on a B grid (GriddedCurrents::cornerGrid: the model writes every velocity point touching a land tracer cell as
/// zero, an island's corners too), and elsewhere where their block of still nodes (8-connected in a layer) touches
/// land or an edge of the loaded nodes beyond which the file goes on (the coast's ring of zeros around land marked
/// by fill values, a mask or a tracer). A block of still nodes in open water, away from any land, in a file that
/// marks its land otherwise stays water (a calm patch; nothing in an A-grid file tells it from an island written
/// as zeros, which a tracer or mask then marks). Never when every water node is still (a still field), nor for
/// packed data seen in a single record, where rounding can zero a calm node.
///
/// The tracer (GriddedCurrentOptions::tracerName; "none": none) is found automatically: standard_name
/// sea_water_potential_temperature, sea_water_temperature, sea_water_conservative_temperature, sea_water_salinity,
/// sea_water_practical_salinity or sea_water_absolute_salinity, then the names (case-insensitive) temp, t, salt,
/// theta, thetao, so, votemper, vosaline, water_temp, salinity; only one whose dimensions fit u's grid as a mask's
/// must, and that holds a valid value in the loaded region (a variable never written is all fill values). It is
/// land where it holds its _FillValue, missing_value, NaN or a value outside its valid range (per layer when it has
/// u's depth dimension, else at every layer). Its cells are placed on the velocity points (GriddedCurrents::
/// tracerPlacement): on a B grid a velocity point is land when any of the 4 tracer cells around it is, which is
/// established when the tracer's own coordinates (POP's TLAT/TLONG, MOM's xt_ocean/yt_ocean) lie half a cell
/// south-west (or north-east) of the velocities' (ULAT/ULONG), or when the tracer shares the velocities'
/// coordinates and these are named as a B grid's velocity points (ULAT/ULONG/ULON, xu_ocean/yu_ocean, or
/// "u-grid" in their long_name, as NCL's pop.nc: POP's velocity point (j, i) is the north-east corner of tracer
/// cell (j, i)); else the tracer at the velocity point's own index. On a ROMS C grid the tracer is on the rho
/// points the field is loaded on. Across the seam of a curvilinear grid whose columns wrap, the neighbour cells
/// are read across it.
///
/// The mask variable is found automatically, in this order: a variable
/// with CF flag_values/flag_meanings naming both land and sea/water/ocean (not a quality flag such as
/// "land_contaminated"), standard_name land_binary_mask or sea_binary_mask, then the names
/// (case-insensitive) mask_rho, mask, tmask, landmask, land_mask, lsm, land_sea_mask, seamask, sea_mask, kmu, kmt;
/// only one whose dimensions fit u's grid (its horizontal dimensions are u's, or have their lengths; a time or depth
/// dimension must be u's) is taken. A given name (maskName) must fit. The values mean:
///  - flag_values with flag_meanings: a value whose meaning has the word sea, water or ocean and none of ice, land,
///    shelf, lake, glacier, river ("sea", "open_water"; not "sea_ice") is water, any other value land;
///  - land_binary_mask, or (without standard_name sea_binary_mask) a name containing "land" or "lsm" (ERA5's land
///    fraction, WRF's LANDMASK): >= 0.5 is land;
///  - kmt / KMT, kmu / KMU (POP's number of ocean levels at the tracer / velocity points): depth layer k (file
///    index) is water when k < KMT;
///  - sea_binary_mask and every other name (ROMS mask_rho, NEMO tmask, mask): >= 0.5 is water;
///  - a fill value is land.
///
/// Steady fields: velocities without time dimension, with a single time record, or one record chosen with
/// GriddedCurrentOptions::steadyRecord give a field that is the same at all times (GriddedCurrents::steady,
/// timeEnd() = +inf) and take any departure. A time axis without "since" ("month", "hours", no units) is
/// refused in a geographic file unless GriddedCurrentOptions::timeUnits supplies the units or steadyRecord picks
/// one record.
///
/// Geographic grids (1-D or 2-D) become curvilinear grids of projected nodes (LocalProjection about the
/// reference point) and eastward/northward velocities are rotated into x/y at each node. Between nodes a point is
/// located in the straight-edged cell of the projected nodes (GriddedCurrentField); a parallel bows away from that edge
/// by at most L^2 tan(lat) / (8 R) for a cell of width L: 0.5 m for 6 km cells at 45 degrees, 27 m for 0.5-degree cells
/// at 33 degrees, far below the forecasts' resolution. Velocities are eastward/northward unless an angle variable
/// (angleName) says they run along the grid's i/j directions; then (u, v) at each node is rotated by its angle a: east
/// = u cos a - v sin a, north = u sin a + v cos a (ROMS `angle`, POP `ANGLE`).
///
/// Staggered grids: u and v on grids of their own. An Arakawa C grid as ROMS writes it (u on (eta_u, xi_u) with
/// xi_u = xi_rho - 1, v on (eta_v, xi_v) with eta_v = eta_rho - 1, 2-D longitude/latitude on (eta_rho, xi_rho))
/// is loaded on its interior rho points: u at a rho point is the mean of the u points west and east of it, v the
/// mean of the v points south and north of it, read at their own points. A face that mask_u/mask_v marks as land,
/// or whose value is a fill value, counts as zero flow (no flow through a coast); a rho point whose two u faces or
/// two v faces are both fill values is land, as is a rho point that mask_rho marks as land. A B grid (POP, MOM: u and
/// v together on the velocity points, ULONG/ULAT) is an ordinary curvilinear grid with an angle (its land: the
/// tracer cells around each velocity point, and its still nodes, above). Terrain-following
/// levels of ROMS (CF ocean_s_coordinate_g1/_g2) become depth levels in metres per water column (level depths
/// from formula_terms or ROMS' Cs_r, h, hc, zeta; linear in depth between levels; below the floor h is land; the
/// standard levels 0, 2, 5, 10, ... m down to maxDepth plus two); other sigma coordinates are an Error.
///
/// Bad files are refused rather than loaded wrong: a classic-format (CDF-1/2/5) file shorter than its
/// header declares, a dimension of u/v of length 0, axes holding fill values, NaN or infinities, axes that are not
/// strictly monotonic (longitudes written across one seam, 170, 180, -170 or 350, 0, 10, are allowed), folded
/// curvilinear grids, and a trip region whose hyperslab exceeds the memory limit (checkMemory()).
///
/// @throws Error naming the file, the variable and what was expected when something is missing or wrong.
GriddedCurrents loadGriddedCurrents(const std::string &path, const GriddedCurrentOptions &options = {});

/// @brief Whether loadGriddedCurrents() reads the file's horizontal coordinates as longitude/latitude (true) or as
/// Cartesian x/y (false), by the loader's own detection (the variable names and `coordinates` of the options);
/// reads attributes only. @throws Error as loadGriddedCurrents() does for a file that is not NetCDF or whose
/// velocities or grid cannot be found.
bool netCdfIsGeographic(const std::string &path, const GriddedCurrentOptions &options = {});

/// @brief The extent of the velocities' grid with the loader's own detection (the names of `options`), reading the
/// coordinate variables only: what the command line checks the start and goal against before a forecast's data are
/// read. @throws Error as loadGriddedCurrents() does for a file whose velocities or grid cannot be found.
ForecastExtent readForecastExtent(const std::string &path, const GriddedCurrentOptions &options = {});

/// @brief Finds and reads the time axis of the forecast's velocities with the loader's own detection (the same
/// code): the eastward velocity (GriddedCurrentOptions::uName, else its CF standard_name or usual names), then
/// among its dimensions the one whose 1-D coordinate variable is named by timeName, or else has units
/// "<unit> since <date>", standard_name "time" or axis "T" (or a usual name such as time, time_counter,
/// ocean_time), whatever the variable is called.
///
/// Only the names in `options` (uName, lonName, latName, depthName, timeName, coordinates), timeUnits and
/// steadyRecord are used; vName and the rest of the grid are not checked, so a file this accepts may still fail to
/// load. With steadyRecord: found and steady, size 1, span 0, dated (originSeconds the record's time) when the
/// axis or timeUnits has dates.
/// @returns found = false (and steady) when the velocities have no time dimension.
/// @throws Error naming the file (and the variable) when the file is not NetCDF, a given name is missing or not
/// on a dimension of u, no velocity variable is found, the time units or calendar are not understood, or the
/// times are not finite and strictly increasing; for timeUnits or steadyRecord without time dimension, and a
/// steadyRecord beyond the last record.
ForecastTimeAxis readForecastTimeAxis(const std::string &path, const GriddedCurrentOptions &options);

/// @brief readForecastTimeAxis() with only the names of the time and eastward velocity variables (empty: found
/// automatically).
ForecastTimeAxis readForecastTimeAxis(const std::string &path, const std::string &timeName = "",
                                      const std::string &uName = "");

/// @brief A forecast in several files (daily files of one model, each with its own time axis) loaded as one, with
/// the same options and the same stages as one file (the region, depths, units, land rules of loadGriddedCurrents()).
///
/// - Order: the files are ordered by their first time (a date: each file's "<unit> since <date>" is read on its
///   own, so the files may use different units and origins), whatever the order given; field time 0 is the first
///   time of the earliest file. The calendars must agree.
/// - Overlap: a record of a file at or after the first time of the next file is dropped: the later file (the newer
///   forecast) gives every time from its first on (GriddedCurrents::droppedRecords counts them).
/// - What is read: the records the trip needs are chosen on the joined time axis exactly as in one file
///   (departure to departure + horizon, plus 2 records of stencil margin on each side), and only the files that
///   hold some of them are opened for their velocities (GriddedCurrents::files); the others' time axes only.
/// - Grids: the files read must give the same grid in the trip's region (the same nodes and coordinates, depth
///   layers, longitude/latitude or Cartesian, velocity variable names); velocity units may differ (each file's
///   are converted to m/s).
/// - Gaps: a step between two files' records within the records read longer than twice the forecast's typical
///   step (the median step of the joined axis) is refused, naming both files and the dates: interpolating across
///   a missing day is not what a pilot expects. Gaps outside the trip's records do not matter.
/// - Land: a node is land when it is land in any file's records of the trip (fill values, a mask, a tracer);
///   zero-velocity land (GriddedCurrentOptions::zeroVelocityLand) is decided on all the trip's records of all
///   files, after the others. The files must agree on the mask and tracer variables.
/// One path: exactly loadGriddedCurrents(path, options).
/// @throws Error naming the file(s) for: no file; a file without time dimension or without dated time axis
/// (undated files cannot be ordered or joined); different calendars; two files with the same first time (the
/// same file twice); GriddedCurrentOptions::steadyRecord; a departure outside the joined forecast; a gap; grids
/// that differ (naming both files and what differs); and everything loadGriddedCurrents() refuses in a file.
GriddedCurrents loadGriddedCurrents(const std::vector<std::string> &paths, const GriddedCurrentOptions &options = {});

/// @brief The time axis of a forecast in several files as loadGriddedCurrents(paths) joins it (dated, never steady;
/// originSeconds the first time of the earliest file, size the records after overlaps are dropped, span from the
/// first to the last). One path: readForecastTimeAxis(path, options). @throws Error as the loader does for the
/// time axes (undated files, calendars, equal first times, steadyRecord).
ForecastTimeAxis readForecastTimeAxis(const std::vector<std::string> &paths, const GriddedCurrentOptions &options);

/// @brief netCdfIsGeographic() of every file; @throws Error naming two files that disagree.
bool netCdfIsGeographic(const std::vector<std::string> &paths, const GriddedCurrentOptions &options = {});

/// @brief The NetCDF reader as the registry's gridded source `netcdf` (ForecastSource.h): one file, several files
/// read as one, OPeNDAP URLs, and Zarr stores and GRIB files (through GDAL); its messages name the request's
/// settings in the caller's words (ForecastRequest::optionNames).
std::shared_ptr<const GriddedSource> griddedForecastSource();
} // namespace ompl_glider
