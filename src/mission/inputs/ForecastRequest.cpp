// What a mission asks of its gridded source (ProblemInputs.h, forecastRequest()): the files, names, schemes and
// the region to load, shared by the mission's inputs and forecastMission().
#include "ompl_glider/mission/ProblemInputs.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../../io/NumberText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/GeoBox.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
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
            {ForecastOption::MaxSpeed, section + ".max_speed"},
            {ForecastOption::Run, section + ".runs"}};
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
    o.run = c.runIndex;
    o.xy = c.xyInterpolation;
    o.depth = c.depthInterpolation;
    o.time = c.timeInterpolation;
    o.beyond = c.horizonPolicy;
    o.name = c.type + ":" + withoutCredentials(c.file); // shown in maps and messages: no URL's password
    for (std::size_t k = 1; k < c.files.size(); ++k)
        o.name += "," + withoutCredentials(c.files[k]);
    if (c.runIndex) // a run of a file of several (a THREDDS FMRC)
        o.name += " run " + std::to_string(*c.runIndex + 1);
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

} // namespace ompl_glider
