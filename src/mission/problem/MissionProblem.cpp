#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/SettingRanges.h"
#include "ProblemParts.h"
#include "../../io/NumberText.h"
#include "ompl_glider/current/EnsembleField.h"
#include "ompl_glider/current/ShiftedTimeField.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/io/Coastline.h"
#include "ompl_glider/io/GeoBox.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/current/Interpolation.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/io/Bathymetry.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/IceZone.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/TimeWindowedZone.h"
#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/io/GliderObservations.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/mission/Observations.h"
#endif
#include "../../core/Numbers.h"

namespace ompl_glider
{
std::string sourcePlace(const MissionSpec &m, const SourceMark &mark)
{
    if (!mark.file.empty() && mark.line > 0)
        return mark.file + ":" + std::to_string(mark.line) + ": ";
    return m.file + ": ";
}

double tripMarginKm(LonLat start, LonLat goal)
{
    return std::max(kMinTripMarginKm, 0.5 * greatCircleKm(start, goal));
}

std::map<ForecastOption, std::string> forecastFieldNames(const std::string &section)
{
    const std::string v = section + ".variables.";
    return {{ForecastOption::U, v + "u"},
            {ForecastOption::V, v + "v"},
            {ForecastOption::Lon, v + "lon"},
            {ForecastOption::Lat, v + "lat"},
            {ForecastOption::Depth, v + "depth"},
            {ForecastOption::Time, v + "time"},
            {ForecastOption::VelocityUnits, section + ".velocity_units"},
            {ForecastOption::TimeUnits, section + ".time_units"},
            {ForecastOption::SteadyRecord, section + ".steady_record"},
            {ForecastOption::ZeroVelocityLand, section + ".zero_velocity_land"},
            {ForecastOption::Angle, v + "angle"},
            {ForecastOption::Mask, v + "mask"},
            {ForecastOption::DepthAverage, section + ".depth_average"},
            {ForecastOption::MaxSpeed, section + ".max_speed"}};
}

ForecastRequest forecastRequest(const MissionSpec &m)
{
    const CurrentSpec &c = m.current;
    ForecastRequest o;
    o.files = c.forecastFiles();
    o.variables = c.variables;
    o.optionNames = forecastFieldNames("current");
    o.zeroVelocityLand = c.zeroVelocityLand;
    o.depthAverage = c.depthAverage;
    // the trip's records (land is decided on them): from the departure (or the window's first) to the horizon
    // (only under the 'refuse' policy: with hold_last a departure may lie after the forecast, and then every
    // record counts, which errs towards land)
    const double departure = m.departure.window ? m.departure.begin : m.departure.time;
    if (std::isfinite(departure) && departure >= 0.0 && c.horizonPolicy == BeyondForecast::Refuse &&
        !(m.observations && m.observations->hasFiles())) // (a glider's DAC lie before the departure: every record)
    {
        if (departure > 0.0)
            o.departure = text::number(departure, 17);
        if (m.planner.horizon > 0.0)
            o.horizon = std::max(m.planner.horizon, m.stints.set ? m.stints.missionDuration : 0.0) +
                        (m.departure.window ? m.departure.end - m.departure.begin : 0.0);
    }
    o.velocityUnits = c.velocityUnits;
    o.maxSpeed = c.maxSpeed;
    o.timeUnits = c.timeUnits;
    o.steadyRecord = c.steadyRecord;
    o.xy = c.xyInterpolation;
    o.depth = c.depthInterpolation;
    o.time = c.timeInterpolation;
    o.beyond = c.horizonPolicy;
    o.name = c.type + ":" + withoutCredentials(c.file); // shown in maps and messages: no URL's password
    for (std::size_t k = 1; k < c.files.size(); ++k)
        o.name += "," + withoutCredentials(c.files[k]);
    o.maxDepth = m.dive.enabled ? m.dive.params.zMax : m.vehicle.depth;
    if (m.projection.set)
    {
        o.refLon = m.projection.lon0;
        o.refLat = m.projection.lat0;
    }
    if (m.region.set && m.region.geographic)
    {
        // as loaded: lon_min in -180..180, lon_max = lon_min + width (beyond 180 across the antimeridian)
        o.lonMin = m.region.lonLat.lonMin;
        o.lonMax = m.region.lonLat.lonMax;
        o.latMin = m.region.lonLat.latMin;
        o.latMax = m.region.lonLat.latMax;
    }
    else if (m.region.set)
        ; // an x/y region is in the planning frame, not the file's coordinates: the whole file is loaded
    else if (m.start.geographic && m.goal.geographic &&
             std::all_of(m.waypoints.begin(), m.waypoints.end(),
                         [](const ViaPointSpec &v) { return v.position.geographic; }))
    {
        // The trip's region in geographic terms (never from projected corners): the lon/lat box of start, via points
        // and goal across the shorter way round, widened by a geodesic margin (half the longest distance between two
        // of them, at least kMinTripMarginKm).
        const LonLat a = m.start.lonLat, b = m.goal.lonLat;
        std::vector<std::pair<std::string, LonLat>> points{{"start", a}, {"goal", b}};
        for (std::size_t i = 0; i < m.waypoints.size(); ++i)
            points.emplace_back("waypoints[" + std::to_string(i) + "]", m.waypoints[i].position.lonLat);
        std::vector<LonLat> corners;
        double margin = kMinTripMarginKm;
        for (const auto &[field, p] : points)
        {
            if (std::abs(p.lat) > kMaxGridLatitude && std::abs(p.lat) <= 90.0)
                throw Error(m.place(field) + ": latitude " + text::number(p.lat) + " is within " +
                            text::number(90.0 - kMaxGridLatitude) +
                            " degrees of a pole, where a longitude/latitude grid degenerates (|lat| <= " +
                            text::number(kMaxGridLatitude) + " can be planned)");
            for (const LonLat &q : corners)
                margin = std::max(margin, tripMarginKm(p, q));
            corners.push_back(p);
        }
        const GeoBox box = tripBox(corners, margin);
        o.lonMin = box.lonMin;
        o.lonMax = box.lonMax;
        o.latMin = box.latMin;
        o.latMax = box.latMax;
    }
    else if (!m.start.geographic && !m.goal.geographic)
    {
        // A Cartesian file: the box of start, via points and goal plus half its larger side (at least 0.2 units)
        // on each side.
        Box b{m.start.xy.x, m.start.xy.x, m.start.xy.y, m.start.xy.y};
        std::vector<Point2> points{m.goal.xy};
        for (const ViaPointSpec &v : m.waypoints)
            points.push_back(v.position.xy);
        for (const Point2 &p : points)
        {
            b.xMin = std::min(b.xMin, p.x);
            b.xMax = std::max(b.xMax, p.x);
            b.yMin = std::min(b.yMin, p.y);
            b.yMax = std::max(b.yMax, p.y);
        }
        const double pad = std::max(0.5 * std::max(b.xMax - b.xMin, b.yMax - b.yMin), 0.2);
        o.lonMin = b.xMin - pad;
        o.lonMax = b.xMax + pad;
        o.latMin = b.yMin - pad;
        o.latMax = b.yMax + pad;
    }
    return o;
}

GliderProblem gulfStreamProblem()
{
    const MissionSpec m = defaultGulfStreamMission();
    return MissionProblem(m).gliderProblem(m.departure.time, m.vehicle.speed);
}

MissionProblem::~MissionProblem() = default;

MissionProblem::MissionProblem(MissionSpec spec) : spec_(std::move(spec))
{
    std::optional<GliderObservations> read; // what resuming read: corrected with below, a URL fetched once
#if OMPL_GLIDER_WITH_NETCDF
    try
    {
        read = resumeAtLastFix(spec_); // replanning at sea: from the glider's last fix, through the stations left
    }
    catch (const Error &e)
    {
        throw Error(spec_.place("observations") + ": " + e.what());
    }
#endif
    checkDatesInRange(spec_); // a time setting past the ISO years is refused naming it, before any field is read
    buildField();
    checkLastFixInForecast(); // (before the stations' windows are judged against a departure past the forecast)
    buildMembers();
    buildTruth();
    start_ = localPoint(spec_.start, "start");
    goal_ = localPoint(spec_.goal, "goal");
    for (std::size_t i = 0; i < spec_.waypoints.size(); ++i)
        via_.push_back(localPoint(spec_.waypoints[i].position, "waypoints[" + std::to_string(i) + "]"));
    snapEndpoints();
    buildBox();
    checkAnalyticFields();
    applyObservations(read ? &*read
                           : nullptr); // (after the box: analytic flows' default length scale; nothing without NetCDF)
    buildRegions();
    const FieldGrid *grid = (members_.empty() ? field_ : members_.front())->grid();
    if (grid)
        spec_.travel.maxStep = 0.5 * grid->minCellSize(); // no travel-time step passes over a grid node
    checkViaPoints();
    gridSizeAutomatic_ = !(spec_.planner.gridSize > 0);
    if (gridSizeAutomatic_)
        spec_.planner.gridSize = automaticGridSize(start_, goal_); // (each leg's own: withLeg())
}

void MissionProblem::buildBox()
{
    const MissionSpec &m = spec_;
    if (m.region.set && !m.region.geographic)
    {
        box_.xMin = m.region.xy.xMin * xyScale_; // a Cartesian forecast's region in its own x/y units
        box_.xMax = m.region.xy.xMax * xyScale_;
        box_.yMin = m.region.xy.yMin * xyScale_;
        box_.yMax = m.region.xy.yMax * xyScale_;
    }
    else if (m.region.set)
    {
        // Start and goal in the region, in geographic terms (longitudes in either convention).
        const GeoBox &region = m.region.lonLat;
        for (const auto &[name, p] : {std::pair<const char *, const PointSpec *>{"start", &m.start}, {"goal", &m.goal}})
            if (p->geographic && !region.contains(p->lonLat))
                throw Error(m.place(name) + ": lon,lat " + text::number(p->lonLat.lon) + "," +
                            text::number(p->lonLat.lat) + " lies outside the region (" + m.place("region") + ": " +
                            region.text() + ")");
        // The planning box: the projected bounding box of the region's outline, sampled along its four edges at
        // least every degree (a parallel bows in the plane).
        box_.xMin = box_.yMin = kInf;
        box_.xMax = box_.yMax = -kInf;
        const int n = std::max(
            8, static_cast<int>(std::ceil(std::max(region.lonMax - region.lonMin, region.latMax - region.latMin))));
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
            {
                if (i != 0 && i != n && j != 0 && j != n)
                    continue;
                const Point2 q = toLocal({region.lonMin + (region.lonMax - region.lonMin) * i / double(n),
                                          region.latMin + (region.latMax - region.latMin) * j / double(n)});
                box_.xMin = std::min(box_.xMin, q.x);
                box_.xMax = std::max(box_.xMax, q.x);
                box_.yMin = std::min(box_.yMin, q.y);
                box_.yMax = std::max(box_.yMax, q.y);
            }
    }
    else if (const FieldGrid *g = (members_.empty() ? field_ : members_.front())->grid())
    {
        const Region e = g->extent();
        box_.xMin = e.xMin;
        box_.xMax = e.xMax;
        box_.yMin = e.yMin;
        box_.yMax = e.yMax;
    }
    else
        throw Error(sourcePlace(m) + "field 'region': missing");
    box_.tMin = field_->timeBegin();
    box_.tMax = field_->timeEnd();
    box_.zMin = 0.0;
    box_.zMax = m.dive.enabled ? m.dive.params.zMax : m.vehicle.depth;
    std::vector<std::pair<std::string, Point2>> points{{"start", start_}, {"goal", goal_}};
    for (std::size_t i = 0; i < via_.size(); ++i)
        points.emplace_back("waypoints[" + std::to_string(i) + "]", via_[i]);
    for (const auto &[name, p] : points)
        if (!(p.x >= box_.xMin && p.x <= box_.xMax && p.y >= box_.yMin && p.y <= box_.yMax))
        {
            char box[160];
            std::snprintf(box, sizeof box, "x %g..%g, y %g..%g", box_.xMin, box_.xMax, box_.yMin, box_.yMax);
            char point[80];
            std::snprintf(point, sizeof point, "(%g, %g)", p.x, p.y);
            throw Error(m.place(name) + ": " + point + " lies outside the planning region (" + box + ")");
        }
}

bool MissionProblem::isGeographic() const
{
    return static_cast<bool>(projection_);
}

LonLat MissionProblem::toGeographic(Point2 p) const
{
    if (!projection_)
        throw Error(spec_.file + ": no projection: longitudes and latitudes are unknown");
    return projection_->inverse(p.x * projectionScale_, p.y * projectionScale_); // longitude in -180..180
}

Point2 MissionProblem::toLocal(LonLat g) const
{
    if (!projection_)
        throw Error(spec_.file + ": no projection: longitudes and latitudes cannot be used");
    Point2 p = projection_->forward(g.lon, g.lat);
    p.x /= projectionScale_;
    p.y /= projectionScale_;
    return p;
}

std::string MissionProblem::isoTime(double t) const
{
    return spec_.isoTime(t);
}

std::string MissionSpec::isoTime(double t) const
{
    if (!epoch || !std::isfinite(t))
        return "";
    const double s = (fileCalendar ? fileCalendar->originSeconds : *epoch) + t * timeUnitSeconds;
    if (fileCalendar) // a dated forecast's own calendar: a climatology's year 0, a noleap or 360_day year
        return formatCalendarTime(s, fileCalendar->calendar);
    if (!isoYearInRange(s))
        throw Error(place("epoch") + ": t = " + text::number(t) +
                    " falls outside the years 0000-9999, which "
                    "ISO 8601 dates are written in (choose an earlier epoch or a shorter horizon)");
    return formatIsoTime(s);
}

GliderProblem MissionProblem::gliderProblem(double tDep, double speed) const
{
    GliderProblem p;
    p.field = field_;
    p.travel = spec_.travel;
    p.travel.speed = speed; // the vehicle's (MissionSpec::travel holds the integration's settings only)
    p.travel.depth = spec_.vehicle.depth;
    p.environment = environment_;
    p.xMin = box_.xMin;
    p.xMax = box_.xMax;
    p.yMin = box_.yMin;
    p.yMax = box_.yMax;
    p.t0 = tDep;
    const double dist = std::hypot(goal_.x - start_.x, goal_.y - start_.y);
    double horizon = spec_.planner.horizon;
    if (!(horizon > 0))
    {
        horizon = 50.0 * (std::hypot(box_.xMax - box_.xMin, box_.yMax - box_.yMin) + dist) / speed;
        if (std::isfinite(field_->timeEnd()))
            horizon = std::min(horizon, field_->timeEnd() - tDep);
    }
    // a speed so high that the trip takes no time at the planner's time resolution (a typing error: 1e308)
    const double crossing = std::hypot(box_.xMax - box_.xMin, box_.yMax - box_.yMin) / speed;
    if (!(crossing >= 1e-9)) // (a departure too large for the time resolution is departureProblem()'s)
        throw Error((speed == spec_.vehicle.speed ? spec_.place("vehicle.speed") : "speed " + text::number(speed)) +
                    ": " + text::number(speed) + " crosses the planning region (diagonal " +
                    text::number(crossing * speed) + ") in " + text::number(crossing) +
                    " time units, below the planner's time resolution: give the vehicle's speed in the mission's "
                    "units");
    p.horizon = horizon;
    p.start.x = start_.x;
    p.start.y = start_.y;
    p.goal.x = goal_.x;
    p.goal.y = goal_.y;
    if (spec_.goalWindow.set)
    {
        p.arriveNotBefore = spec_.goalWindow.begin;
        p.arriveNotAfter = spec_.goalWindow.end;
    }
    p.goalTolerance = spec_.planner.goalTolerance >= 0 ? spec_.planner.goalTolerance
                                                       : 1e-6 * std::max(box_.xMax - box_.xMin, box_.yMax - box_.yMin);
    return p;
}

double MissionProblem::minTripDuration(double speed) const
{
    Region r = box_;
    return std::hypot(goal_.x - start_.x, goal_.y - start_.y) / (speed + field_->maxSpeed(r));
}

std::shared_ptr<const DiveProfileTravelTime> MissionProblem::diveProfiles(double speed) const
{
    if (!spec_.dive.enabled)
        return nullptr;
    std::shared_ptr<const Bathymetry> bathymetry;
    if (spec_.dive.bathymetry == DiveSpec::Bathymetry::Constant)
    {
        const double d = spec_.dive.bathymetryDepth;
        bathymetry = std::make_shared<FunctionBathymetry>([d](double, double) { return d; });
    }
    else if (spec_.dive.bathymetry == DiveSpec::Bathymetry::File)
    {
#if !OMPL_GLIDER_WITH_NETCDF
        throw Error(spec_.file + ": field 'dive_profile.bathymetry': this build has no NetCDF support");
#else
        std::function<LonLat(double, double)> geo;
        if (projection_)
            geo = [this](double x, double y) { return toGeographic({x, y}); };
        try
        {
            bathymetry =
                readBathymetry(spec_.dive.bathymetryFile, spec_.dive.bathymetryVariable, geo, bathymetryRegion());
        }
        catch (const Error &e)
        {
            throw Error(spec_.file + ": field 'dive_profile.bathymetry': " + e.what());
        }
#endif
    }
    TravelTimeParams t = spec_.travel;
    t.speed = speed;
    t.depth = spec_.vehicle.depth;
    return std::make_shared<DiveProfileTravelTime>(field_, t, spec_.dive.params, bathymetry, spec_.dive.threads);
}
} // namespace ompl_glider
