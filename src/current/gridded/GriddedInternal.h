#pragma once
/// @file GriddedInternal.h
/// @brief Internal pieces of the NetCDF reader (loadGriddedCurrents(), readForecastTimeAxis()); not installed.
///
/// The reader runs in stages, one source file each (all in src/current/gridded/ except the composition and the file
/// access):
///  - ../../io/GriddedDataset.cpp    the open file, attribute/variable queries, errors that name the file
///  (io/GriddedDataset.h)
///  - ../../io/ClassicSize.cpp  the size a classic-format file must have, from its header (refuses truncated files)
///  - AxisChecks.cpp         coordinate values: no fill values or non-finite numbers, strictly monotonic axes
///  - VariableDetection.cpp  velocities and the role of each of their dimensions (CF standard_name, axis, units)
///  - GridLayout.cpp         1-D axes or a 2-D curvilinear grid; geographic or Cartesian
///  - TimeAxis.cpp           the CF time axis and the time window (also readForecastTimeAxis())
///  - DepthAxis.cpp          depth in metres, positive down, and the layers down to maxDepth
///  - RegionOfInterest.cpp   the region of the options, index ranges of an axis, longitude wrapping
///  - RectilinearSubset.cpp  index ranges of 1-D axes for the region, wrapping across the seam of global grids
///  - CurvilinearSubset.cpp  index box of a 2-D grid for the region and its node coordinates
///  - Hyperslab.cpp          contiguous runs per dimension and the scattered nc_get_vara reads
///  - UnitsAndPacking.cpp    velocity and axis units, scale_factor/add_offset and fill/valid-range rules
///  - LandMask.cpp           reading u/v: unpacking, unit conversion; land from fill values, a mask, zero velocity
///  - TracerLand.cpp         land from a tracer's missing values (temperature, salinity), B grid corners
///  - Staggered.cpp          a ROMS C grid's u/v read at their own points onto the rho points; grid angle rotation
///  - SigmaLevels.cpp        terrain-following s-levels (ROMS) interpolated onto depth levels in metres
///  - NodeCoordinates.cpp    projected (and rotated) or Cartesian node coordinates
///  - ../GriddedCurrents.cpp  loadGriddedCurrents(), composing the stages, and the GriddedCurrents members

#include <netcdf.h>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <istream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "../../io/GriddedDataset.h"
#include "../../io/NumberText.h"
#include "../../io/TextUtil.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/current/GriddedCurrentField.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/current/GriddedCurrents.h"
#include "ompl_glider/io/UnitConversion.h"
#include "ompl_glider/Exception.h"
#include "../../core/Numbers.h"

namespace ompl_glider
{
namespace gridded_detail
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---- strings (io/TextUtil.h) and the open file (io/GriddedDataset.h: GriddedDataset, ClassicExtent,
// classicTruncation()) ----

using text::inList;
using text::joinNames;
using text::lower;
using text::trim;

// ---- what a variable is (VariableDetection.cpp) ----

/// The standard_name attribute, lower case ("" when absent).
std::string stdName(const GriddedDataset &f, int var);
/// The units attribute as written ("" when absent).
std::string unitsOf(const GriddedDataset &f, int var);
/// Longitude: units degrees_east (and variants), standard_name longitude, or a usual name (lon, nav_lon, ...).
bool isLonVar(const GriddedDataset &f, int var);
/// Latitude: units degrees_north (and variants), standard_name latitude, or a usual name (lat, nav_lat, ...).
bool isLatVar(const GriddedDataset &f, int var);
/// Cartesian x: standard_name projection_x_coordinate, axis = "X", or a usual name (x, xc, easting, ...).
bool isXVar(const GriddedDataset &f, int var);
/// Cartesian y: standard_name projection_y_coordinate, axis = "Y", or a usual name (y, yc, northing, ...).
bool isYVar(const GriddedDataset &f, int var);
/// Time: units "<unit> since <date>", standard_name time, axis = "T", or a usual name (time, time_counter, ...).
bool isTimeVar(const GriddedDataset &f, int var);
/// Depth: standard_name depth, axis = "Z", a positive attribute, or a usual name (depth, deptht, lev, ...).
bool isDepthVar(const GriddedDataset &f, int var);
/// The runs of a forecast model run collection (a THREDDS FMRC): standard_name forecast_reference_time,
/// _CoordinateAxisType RunTime, or a usual name (run, reftime, reftime1, ..., runtime, forecast_reference_time).
bool isRunVar(const GriddedDataset &f, int var);

/// The eastward (east = true) or northward velocity variable: the given name, else the first CF standard_name
/// of the known list found, else the first usual name found. @throws Error listing what was looked for.
int findVelocity(const GriddedDataset &f, const std::string &given, bool east, const std::string &optionName);

/// What a dimension of the velocity variables is.
enum class Role
{
    None,
    Run, ///< the runs of a file of several forecast runs (a THREDDS FMRC); one is read (Layout::run)
    Time,
    Depth,
    X,
    Y
};

/// The dimensions of u classified by their 1-D coordinate variables (names given in the options first, then
/// isRunVar / isTimeVar / isLonVar / isLatVar / isDepthVar / isXVar / isYVar in this order). Dimensions without a
/// 1-D coordinate variable stay Role::None (a curvilinear grid's (j, i)). A file of several forecast runs (a
/// THREDDS FMRC) has time as a 2-D coordinate time(run, time) on u's run and time dimensions: its time dimension
/// gets Role::Time and that variable.
struct DimensionRoles
{
    std::vector<int> dims;     ///< dimension ids of u, in file order
    std::vector<Role> role;    ///< per dimension
    std::vector<int> coordVar; ///< 1-D coordinate variable per dimension, -1 if none
    bool geoAxes{false};       ///< a horizontal axis was recognised as longitude/latitude
    bool cartAxes{false};      ///< a horizontal axis was recognised as Cartesian x/y

    /// Index (in dims) of the dimension with role r, -1 if none.
    int find(Role r) const;
};

/// Classifies the dimensions of the variable uVar. @throws Error when a given coordinate name is missing or not
/// on a dimension of u, a dimension named like time has no coordinate variable, or two dimensions have the
/// same role.
DimensionRoles classifyDimensions(const GriddedDataset &f, const GriddedCurrentOptions &opt, int uVar);

// ---- the grid (GridLayout.cpp) ----

/// The velocity variables and the grid they are on.
struct Layout
{
    int uVar{-1}, vVar{-1};
    std::string uName, vName;
    std::vector<int> dims;                      ///< dimension ids of u and v, file order
    std::vector<Role> role;                     ///< per dimension
    std::vector<int> coordVar;                  ///< 1-D coordinate variable per dimension, -1 if none
    int dimT{-1}, dimZ{-1}, dimX{-1}, dimY{-1}; ///< index in dims, -1 if absent (x/y always present)
    int dimRun{-1};          ///< index in dims of the runs of a file of several forecast runs, -1 if absent
    std::size_t run{0};      ///< the run read along it (GriddedCurrentOptions::runIndex)
    int runVar{-1};          ///< its coordinate variable (the runs' reference times), -1 if none
    bool curvilinear{false}; ///< x/y from 2-D coordinate variables lon2D/lat2D
    int lon2D{-1}, lat2D{-1};
    bool geographic{false};   ///< longitude/latitude (projected), else Cartesian
    std::string xName, yName; ///< the horizontal coordinate variables (1-D or 2-D)
    /// Arakawa C grid (ROMS): u and v on their own dimensions; dims[dimY], dims[dimX] are then the rho (cell
    /// centre) dimensions the grid is loaded on, uDims/vDims the variables' own (file order)
    bool staggered{false};
    std::vector<int> uDims, vDims;
    int angleVar{-1};           ///< grid angle (velocities along the grid's i/j directions), -1 if none
    double angleToRadians{1.0}; ///< its unit
    /// a curvilinear grid without angle variable whose velocities do not say they are eastward: the angle is
    /// derived from the nodes' coordinates (deriveGridAngle())
    bool deriveAngle{false};
};

/// Finds u and v and the grid they are on. @throws Error naming the file, the variable and what was expected.
Layout detectLayout(const GriddedDataset &f, const GriddedCurrentOptions &opt);

// ---- time (TimeAxis.cpp) and depth (DepthAxis.cpp) ----

/// A time axis as read: dated ("<unit> since <date>") or raw values.
struct TimeValues
{
    std::string name; ///< the variable
    bool dated{false};
    Calendar calendar{Calendar::Standard}; ///< dated axes
    double originSeconds{0.0};             ///< first time, seconds since the calendar epoch (dated axes)
    std::vector<double> times;             ///< per record: seconds after the first time, or raw values
    /// per record its index along the time dimension when some were dropped (a 2-D time(run, time)'s fill values:
    /// a run shorter than the others); empty: record k is index k
    std::vector<std::size_t> fileIdx;
    /// The index along the time dimension of record k.
    std::size_t fileIndex(std::size_t k) const { return fileIdx.empty() ? k : fileIdx.at(k); }
};

/// Reads the time coordinate variable tv, with unitsOverride (GriddedCurrentOptions::timeUnits) in place of its
/// units attribute when given. @throws Error when the override is not "<unit> since <date>", when the units are
/// not "<unit> since <date>" and allowUndated is false (naming GriddedCurrentOptions::timeUnits and steadyRecord),
/// when the units or calendar are not understood, or when the variable has no values, holds fill values or
/// non-finite numbers, or is not strictly increasing.
/// A 2-D time(run, time) is read at row @p run, its fill values and NaN dropped (TimeValues::fileIdx).
TimeValues readTimeValues(const GriddedDataset &f, int tv, bool allowUndated, const std::string &unitsOverride = "",
                          std::size_t run = 0);
/// A forecast run's reference time into @p axis (dated): ForecastTimeAxis::referenceSeconds and referenceFrom. In a
/// file of several runs, the value at @p run of the runs' coordinate @p runVar (>= 0); else CF
/// forecast_reference_time, else HYCOM's `tau` (hours since analysis) subtracted from the first time, else the first
/// time. @throws Error for a reference-time variable of more or fewer than one value, or a date not understood.
void readReferenceTime(const GriddedDataset &f, ForecastTimeAxis &axis, int runVar = -1, std::size_t run = 0);
/// The run read of a file of several runs (Layout::run from GriddedCurrentOptions::runIndex). @throws Error when
/// the file holds more than one run and none is given, or the one given is out of range.
void checkRunIndex(const GriddedDataset &f, const Layout &l, const GriddedCurrentOptions &opt);

/// The one record of GriddedCurrentOptions::steadyRecord and its date.
struct SteadyRecord
{
    std::size_t index{0}; ///< file index along the time dimension
    bool dated{false};    ///< the axis (or GriddedCurrentOptions::timeUnits) has dates
    Calendar calendar{Calendar::Standard};
    double originSeconds{0.0}; ///< the record's time, seconds since the calendar epoch (dated)
};

/// nullopt without GriddedCurrentOptions::steadyRecord; else the record on time dimension timeDim (coordinate
/// variable tv, -1 if none), dated when its units (or the options' timeUnits) are "<unit> since <date>" (an
/// undated axis is not read). @throws Error when the index is not below the number of records, or the dated axis
/// is bad (readTimeValues()).
std::optional<SteadyRecord> steadyRecordOf(const GriddedDataset &f, int timeDim, int tv,
                                           const GriddedCurrentOptions &opt);

/// File indices and coordinate values chosen along one dimension.
struct AxisSelection
{
    std::vector<std::size_t> idx{0};
    std::vector<double> values{0.0};
    /// time: positions in idx of the records bracketing the trip (the last at or before the departure to the first
    /// at or after departure + horizon); land is decided on these only, not on the stencil margin around them
    std::size_t tripBegin{0}, tripEnd{0};
    /// depth: terrain-following s-levels (values are s, not metres; remapSigmaToDepths() makes depths of them)
    bool sigma{false};
    /// True when position q counts for land.
    bool inTrip(std::size_t q) const { return q >= tripBegin && q <= tripEnd; }
};

/// The forecast times the mission needs (departure to departure + horizon, plus 2 steps each side); sets the
/// time fields of out (dated, steady, calendar, origin, forecast begin/end, departure). {0}/{0} without time axis
/// or with a single record; {steadyRecord}/{0} with GriddedCurrentOptions::steadyRecord. @throws Error for
/// timeUnits or steadyRecord given for a file without time dimension.
AxisSelection selectTimes(const GriddedDataset &f, const Layout &l, const GriddedCurrentOptions &opt,
                          GriddedCurrents &out);

/// The depth layers (metres, positive down, ascending) down to the first at or below maxDepth plus 2;
/// {0}/{0} without depth axis; every level, with sigma set, for a terrain-following coordinate.
AxisSelection selectDepths(const GriddedDataset &f, const Layout &l, double maxDepth);

// ---- horizontal subset (RegionOfInterest.cpp, RectilinearSubset.cpp, CurvilinearSubset.cpp) ----

/// The region of interest of the options.
struct RegionOfInterest
{
    bool given{false};
    double lonMin{kNaN}, lonMax{kNaN}; ///< as given (for messages)
    double lon0{kNaN}, lon1{kNaN};     ///< lon1 >= lon0: +360 across the antimeridian (geographic)
    double latMin{kNaN}, latMax{kNaN};
    double margin{0.0};
    int marginNodes{2};
};

/// @throws Error when only some bounds are given, latMin > latMax, or lonMin > lonMax in Cartesian mode.
RegionOfInterest regionOfInterest(const GriddedCurrentOptions &opt, bool geographic);

/// The horizontal nodes loaded: file index per internal i / j and their coordinates.
struct HorizontalSubset
{
    std::vector<std::size_t> xIdx, yIdx;
    std::vector<double> lon1D, lat1D;     ///< rectilinear: coordinate per internal i / j
    std::vector<double> nodeLon, nodeLat; ///< curvilinear: coordinates per internal j * nx + i
    double centreLon{kNaN}, centreLat{kNaN};
    double lonLo{kNaN}, lonHi{kNaN}, latLo{kNaN}, latHi{kNaN}; ///< bounds of the nodes (longitudes unwrapped)
    /// curvilinear grids: the period of the file's columns when they wrap round the globe (column P is column 0
    /// again: a displaced-pole or tripolar grid's seam), else 0; the tracer stage reads across it
    std::size_t xPeriod{0};
};

/// Indices [a, b] (inclusive) of an axis (ascending or descending) whose values lie in [lo, hi], widened by
/// `extra` nodes; the bracketing pair when the interval falls between two nodes; nullopt when none.
std::optional<std::pair<std::size_t, std::size_t>> indexRange(const std::vector<double> &ax, double lo, double hi,
                                                              int extra);
/// lon shifted by whole turns into [centre - 180, centre + 180).
double wrapTo(double lon, double centre);

/// 1-D axes: latitude stored ascending, rows beyond +-kMaxGridLatitude left out (geographic); longitude
/// ascending, unwrapped across the seam of a global axis (or of a regional axis written across one), a global
/// axis's repeated seam column (-180 and 180, 0 and 360) read once. The nodes x the times t and depths z must fit
/// the memory limit (checkTripMemory()). @throws Error for axes with fill values or non-finite numbers, axes that
/// are not strictly monotonic, a region outside the axes or a trip too large for the memory.
HorizontalSubset rectilinearSubset(const GriddedDataset &f, const Layout &l, const RegionOfInterest &r,
                                   const AxisSelection &z, const AxisSelection &t);
/// 2-D coordinates: the index box of the nodes in the region (+ margin nodes) and their coordinates; the memory
/// is checked (checkTripMemory()) before they are read. @throws Error also for coordinates with fill values or
/// non-finite numbers, and for coinciding neighbours or folded cells (checkCurvilinearNodes()).
HorizontalSubset curvilinearSubset(const GriddedDataset &f, const Layout &l, const RegionOfInterest &r,
                                   const AxisSelection &z, const AxisSelection &t);

// ---- coordinate values (AxisChecks.cpp) ----

/// A number for messages: up to 10 significant digits ("47.4", "9.969209968e+36").

/// Index of the first value that is NaN, infinite or a fill value of var (packingOf(): _FillValue or the netCDF
/// default fill, missing_value, outside valid_min/valid_max/valid_range); values.size() when there is none.
std::size_t firstFillOrNonFinite(const GriddedDataset &f, int var, const std::vector<double> &values);
/// @throws Error "<kind> '<var>' holds fill values or non-finite numbers (<value> at index k); expected finite
/// coordinates" (kind: "coordinate", "time variable", "depth").
void checkAxisValues(const GriddedDataset &f, int var, const std::vector<double> &values, const std::string &kind);
/// Index k of the first value that breaks strict monotony (v[k] not beyond v[k - 1] in the direction of v[0] to
/// v[1]); values.size() when strictly increasing or strictly decreasing.
std::size_t monotonicBreak(const std::vector<double> &values);
/// @throws Error "<kind> '<name>' is not strictly monotonic: <a> at index k - 1, then <b> at index k" unless values
/// are strictly monotonic; the numbers shown are those of `shown` (the file's, when values were unwrapped).
void checkStrictlyMonotonic(const GriddedDataset &f, const std::vector<double> &values,
                            const std::vector<double> &shown, const std::string &kind, const std::string &name);
/// Longitudes that are not monotonic as written but are across one seam (170, 180, -170 or 350, 0, 10): the
/// values after each jump of more than 180 degrees shifted by a whole turn, when that makes them strictly
/// monotonic within less than a turn; else (and for monotonic axes) the values unchanged.
std::vector<double> unwrapLongitudes(const std::vector<double> &lon);
/// @throws Error "curvilinear coordinates '<lon>'/'<lat>' are not strictly monotonic: ..." when two neighbouring
/// nodes of h coincide or a cell's orientation differs from the first cell's (a fold or a degenerate cell).
void checkCurvilinearNodes(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h);

// ---- reading (Hyperslab.cpp, UnitsAndPacking.cpp, LandMask.cpp) ----

/// Contiguous runs of file indices along one dimension and the internal position of each index read.
struct DimRead
{
    std::vector<std::pair<std::size_t, std::size_t>> runs; ///< (start, count) in the file
    std::vector<std::vector<std::size_t>> pos;             ///< per run, internal position of each element
};

/// Builds the runs from the list "internal position p -> file index fileIdx[p]".
DimRead makeDimRead(const std::vector<std::size_t> &fileIdx);

/// Reads `var` restricted to the per-dimension reads, scattering into `out` at internal offsets
/// sum_d pos * stride[d]. Values are raw (packed) doubles.
void readScatter(const GriddedDataset &f, int var, const std::vector<DimRead> &dims,
                 const std::vector<std::size_t> &stride, std::vector<double> &out);

/// The reads of u/v: per file dimension the runs and the internal stride (internal order t, z, y, x).
struct HyperslabPlan
{
    std::vector<DimRead> reads;
    std::vector<std::size_t> stride;
    std::size_t fileValues{1}; ///< values per component in the file variable
};

/// The bytes loadGriddedCurrents() allocates at its peak for ni x nj nodes, nt times and nz depths: 20 per value of
/// each of u and v while the GriddedCurrentField is built (the loaded float, the field's copy, its stencil maximum
/// and minimum and their scratch copy; more than the reading's raw double and read buffer), plus per node the
/// coordinates, the field's cell index and the land masks.
double tripBytes(std::size_t ni, std::size_t nj, std::size_t nt, std::size_t nz);
/// checkMemory() of tripBytes(): @throws Error "NetCDF file '<path>': the trip's region (I x J nodes, T times,
/// K depths) needs about ..." with a hint to restrict the region or the time window, or use a coarser file.
void checkTripMemory(const GriddedDataset &f, std::size_t ni, std::size_t nj, std::size_t nt, std::size_t nz);

HyperslabPlan planHyperslab(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, const AxisSelection &z,
                            const AxisSelection &t);

/// The conversion to m/s of u and v (UDUNITS-2, velocityToMetresPerSecond()): the options' velocityUnits, else
/// their units attributes; the identity for velocities without units ("" or "1") in a Cartesian file.
/// @throws Error naming the file, the variable (or GriddedCurrentOptions::velocityUnits) and the units when they
/// are missing, not understood, not a velocity, or different for u and v.
LinearConversion velocityConversionOf(const GriddedDataset &f, const Layout &l, const GriddedCurrentOptions &opt);
/// Refuses a velocity no current or wind reaches at a water node of any record loaded (g.u/g.v in m/s: more than
/// 300 m/s, or not finite in single precision; in a Cartesian file's units without units, more than 1e6), naming
/// the variable, the value, the node (file indices, coordinates) and the record: values read as fill values, a
/// scale_factor or units that are wrong, never planned on.
void checkVelocityMagnitudes(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h,
                             const AxisSelection &t, const GriddedCurrentOptions &opt, const GriddedData &g);
/// The conversion to metres of a Cartesian axis' units (UDUNITS-2, lengthToMetres()); the identity without
/// units or for dimensionless ones (degrees included). @throws Error naming the file, the variable and the units
/// when they are not a length.
LinearConversion axisConversion(const GriddedDataset &f, int var);

/// Packing and missing-value rules of a variable (compared on the packed value).
struct Packing
{
    double scale{1.0}, offset{0.0};
    std::vector<double> fills;
    double validMin{-kInf}, validMax{kInf};
    bool isFill(double raw) const;
};

/// scale_factor / add_offset, _FillValue (else the netCDF default fill of the type), missing_value,
/// valid_range / valid_min / valid_max. @throws Error for a zero or non-finite scale or offset.
Packing packingOf(const GriddedDataset &f, int var);
/// Coordinates as CF packs them (int16 lon/lat with scale_factor / add_offset): @p values, read raw and checked
/// for fill values, unpacked in place.
void unpackCoordinates(const GriddedDataset &f, int var, std::vector<double> &values);

/// Unpacks raw u/v (internal order t, z, y, x; packings pu/pv, converted to m/s by vel) into g.u / g.v and marks
/// land in g.water (per z, y, x) where u or v is a fill value (or NaN, or outside the valid range) in any of the
/// trip's records (t.inTrip()), counted in out.fillLandNodes; with zeroIsLand also where u = v = 0 exactly in all
/// of them (counted in out.zeroLandNodes; not when every water node is zero). The loader passes zeroIsLand = false
/// and decides zero-velocity land after every other stage (zeroVelocityLand()).
void unpackAndMask(const std::vector<double> &ru, const std::vector<double> &rv, const Packing &pu, const Packing &pv,
                   const LinearConversion &vel, bool zeroIsLand, const AxisSelection &t, GriddedData &g,
                   GriddedCurrents &out);
/// Reads u and v over the plan into g.u / g.v (unpacked, converted to m/s by vel) and g.water (unpackAndMask()
/// with opt.zeroVelocityLand). g.nx, g.ny, g.depth and g.time must be set.
void readVelocities(const GriddedDataset &f, const Layout &l, const HyperslabPlan &plan, const AxisSelection &t,
                    const LinearConversion &vel, const GriddedCurrentOptions &opt, GriddedData &g,
                    GriddedCurrents &out);

/// How zero velocity becomes land (GriddedCurrentOptions::zeroVelocityLand), decided after the fill values, the
/// mask and the tracer.
struct ZeroLandRule
{
    /// every still node is land: the file marks no other land in the region, or the velocities are a B grid's
    /// (cornerVelocities(): a model such as POP writes every velocity point that touches a land tracer cell as
    /// zero, an island's too)
    bool everyStillNode{false};
    /// the file has nodes beyond this edge of the loaded ones (west, east, south, north in internal order): a
    /// still block reaching it may belong to land beyond the region
    bool openEdge[4]{false, false, false, false};
};

/// The ZeroLandRule of a loaded subset: everyStillNode when `otherLand` is false (no fill, mask or tracer land in
/// the region) or cornerGrid; openEdge from the subset's file indices (an edge is open unless its row or column is
/// the first or last of the file).
ZeroLandRule zeroLandRule(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, bool otherLand,
                          bool cornerGrid);

/// Zero velocity as land: a water node (per z, y, x) whose u and v are exactly 0 in every record of the trip
/// (t.inTrip()) is "still". Still nodes become land in g.water where rule.everyStillNode; else a still node is land
/// when its block of still nodes (8-connected in its layer) touches a land node (8 neighbours: the coast's ring of
/// zero velocities around land marked by fill values, a mask or a tracer) or an open edge of the loaded nodes, and
/// calm water when the block lies in open water away from any land. Never when every water node is still (a still
/// field is water), nor for packed data seen in a single record (rounding can zero a calm node). Returns the nodes
/// it made land.
std::size_t zeroVelocityLand(GriddedData &g, const AxisSelection &t, bool packed, const ZeroLandRule &rule);
/// Sets the velocities of every land node of g (g.water 0) to 0 in every record: the field treats land as zero
/// current (a no-slip coast).
void zeroLandVelocities(GriddedData &g);

/// readVelocities() for a staggered (C) grid (Layout::staggered): u read at the u points west and east of each
/// loaded rho point and averaged, v at the v points south and north of it; faces marked land by mask_u/mask_v or
/// holding fill values count as zero flow, a rho point with both faces of a component fill values is land.
/// @throws Error when the loaded rho points are not one contiguous, interior block.
void readStaggeredVelocities(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h,
                             const AxisSelection &z, const AxisSelection &t, const LinearConversion &vel,
                             const GriddedCurrentOptions &opt, GriddedData &g, GriddedCurrents &out);
/// True when the depth variable zv is terrain-following (standard_name ocean_s_*, ocean_sigma_*,
/// ocean_double_sigma_*).
bool isSigmaCoordinate(const GriddedDataset &f, int zv);
/// Turns the s-levels of g (all of them, read by selectDepths() with AxisSelection::sigma) into fixed depth levels
/// in metres down to `deepest` (plus the depths `requested`): the depth of each s-level per node and record from
/// the CF formula of ocean_s_coordinate_g1/_g2 (formula_terms, else ROMS' Cs_r, h, hc, zeta; zeta 0 without it),
/// each column interpolated linearly in depth; a level below the node's floor (h) is land there, one above the top
/// s-level takes its value. @throws Error for other terrain-following coordinates or missing formula terms.
void remapSigmaToDepths(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, const AxisSelection &z,
                        const AxisSelection &t, double deepest, const std::vector<double> &requested, GriddedData &g);
/// Rotates grid-relative velocities (Layout::angleVar, or the angle derived from the nodes' coordinates with
/// Layout::deriveAngle) into eastward/northward at every loaded node; says how in out.gridAngle.
/// @throws Error when the angle holds fill values or non-finite numbers, or a derived angle is ambiguous (naming the
/// node, the coordinates and what to give instead).
void rotateGridToEastNorth(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, GriddedData &g,
                           GriddedCurrents &out);

// ---- the grid angle from the coordinates (GridAngle.cpp) ----

/// A grid whose i direction is more than this many degrees from east somewhere is rotated.
constexpr double kGridRotatedDegrees = 0.01;
/// Ambiguous grids: j more than this many degrees off 90 degrees counter-clockwise of i ...
constexpr double kGridSkewDegrees = 30.0;
/// ... or i turning by more than this many degrees between neighbouring nodes.
constexpr double kGridTurnDegrees = 30.0;

/// The angle of a grid's i direction at every node.
struct DerivedGridAngle
{
    std::vector<double> radians; ///< per node j * nx + i, counter-clockwise from east (x)
    double maxAbsDegrees{0.0};
    double minDegrees{kInf}, maxDegrees{-kInf};
    bool rotated{false}; ///< maxAbsDegrees > kGridRotatedDegrees
    std::string fault;   ///< non-empty when the angle is ambiguous: what is wrong, at node (faultJ, faultI)
    std::size_t faultJ{0}, faultI{0};
};

/// The angle of the i direction of a curvilinear grid of nx x ny nodes (x = longitude, y = latitude in degrees when
/// geographic, else Cartesian x/y in one unit) at every node, as ROMS' grid tools derive `angle`: the direction of
/// the neighbouring nodes along i (central differences, second-order one-sided ones at the edges), a longitude
/// difference scaled by cos(lat) (and by the WGS84 ellipsoid's ratio of meridian to parallel radius). When the grid
/// is rotated, fault says why the angle would be ambiguous: j not about 90 degrees counter-clockwise of i
/// (kGridSkewDegrees), or i turning sharply between neighbours (kGridTurnDegrees), or a single node along i or j.
DerivedGridAngle deriveGridAngle(const std::vector<double> &x, const std::vector<double> &y, std::size_t nx,
                                 std::size_t ny, bool geographic);
/// "derived from <coordinates>: the grid's i direction a..b degrees counter-clockwise from east".
std::string gridAngleNote(const DerivedGridAngle &a, const std::string &coordinates);
/// Collapses the depth layers of g into one: the depth average over [top, bottom] (trapezoid rule on the
/// piecewise-linear profile, constant outside the layers; GriddedCurrentOptions::depthAverage); a node is land when
/// it is land at a layer that carries weight. g.depth becomes {top}.
void averageOverDepth(double top, double bottom, GriddedData &g);

// ---- land variables on the velocities' grid (LandMask.cpp, TracerLand.cpp) ----

/// How a variable on the velocities' horizontal grid (a mask, a tracer) is read onto the loaded nodes: per
/// dimension of the variable its role among u's (a dimension of its own whose length is u's y or x stands for it),
/// the reads and the strides into an array (t, z, y, x) with only the variable's own axes.
struct GridFit
{
    std::vector<Role> role; ///< per dimension of the variable
    std::vector<DimRead> reads;
    std::vector<std::size_t> stride;
    bool hasTime{false}, hasDepth{false};
    /// The reads for rows yIdx and columns xIdx (file indices, one per loaded node; the tracer's neighbours) in
    /// place of the loaded ones.
    void setHorizontal(const std::vector<std::size_t> &yIdx, const std::vector<std::size_t> &xIdx);
};

/// Where each dimension of `var` sits on u's loaded grid (nodes h, depths z, times t), or nullopt with the reason
/// in `why` when it does not fit: at least (y, x), u's own horizontal dimensions or dimensions of their lengths; a
/// time or depth dimension must be u's; any other dimension must have length 1.
std::optional<GridFit> fitToGrid(const GriddedDataset &f, const Layout &l, int var, const HorizontalSubset &h,
                                 const AxisSelection &z, const AxisSelection &t, std::string &why);

/// The land/sea mask variable (the given one, or one found automatically: rules at loadGriddedCurrents()) applied
/// to g.water over the loaded nodes, depths and times; sets out.maskVariable and out.maskLandNodes.
/// @throws Error when a given mask is missing or does not fit u's grid.
void applyLandMask(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, const AxisSelection &z,
                   const AxisSelection &t, const GriddedCurrentOptions &opt, GriddedData &g, GriddedCurrents &out);

/// True when the velocities' coordinates say they are a B grid's velocity points (the corners of the tracer
/// cells): named ULAT/ULONG/ULON (POP) or xu_ocean/yu_ocean (MOM), or described as the "u-grid" in their
/// long_name (NCL's POP files: "array of u-grid latitudes"). Not for a staggered (C) layout.
bool cornerVelocities(const GriddedDataset &f, const Layout &l);

/// The tracer stage: a tracer variable on the velocities' grid (the given GriddedCurrentOptions::tracerName, else
/// found automatically: standard_name sea_water_temperature, sea_water_potential_temperature,
/// sea_water_conservative_temperature, sea_water_salinity, sea_water_practical_salinity or
/// sea_water_absolute_salinity, then the names temp, t, salt, theta, thetao, so, votemper, vosaline, water_temp,
/// salinity in any case) is land where it holds a fill value, missing_value, NaN or a value outside its valid
/// range, in any of the trip's records (a tracer with a depth dimension per layer, else at every layer). On a B
/// grid (the tracer's coordinates offset half a cell from the velocities', or shared with velocities that
/// cornerVelocities() says are a B grid's) a velocity point is land when any of the 4 tracer cells around it is;
/// else the tracer cell at the same index. A tracer holding no valid value in the loaded region is not read (a
/// variable never written). Sets out.tracerVariable, out.tracerPlacement, out.tracerLandNodes, out.cornerGrid.
/// @throws Error when a given tracer is missing or does not fit u's grid.
void applyTracerLand(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, const AxisSelection &z,
                     const AxisSelection &t, const GriddedCurrentOptions &opt, GriddedData &g, GriddedCurrents &out);

// ---- coordinates (NodeCoordinates.cpp) ----

/// Sets the node coordinates of g: geographic grids are projected about the reference point (options, else the
/// region's centre, else the grid's) and their velocities rotated into x/y; Cartesian axes are scaled to
/// metres. Returns the projection (null in Cartesian mode).
std::shared_ptr<const LocalProjection> setNodeCoordinates(const GriddedDataset &f, const Layout &l,
                                                          const HorizontalSubset &h, const RegionOfInterest &r,
                                                          const GriddedCurrentOptions &opt, GriddedData &g);
} // namespace gridded_detail
} // namespace ompl_glider
