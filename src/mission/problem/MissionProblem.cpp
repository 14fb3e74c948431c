#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/SettingRanges.h"
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
GliderProblem gulfStreamProblem()
{
    const MissionSpec m = defaultGulfStreamMission();
    return MissionProblem(m).gliderProblem(m.departure.time, m.vehicle.speed);
}

MissionProblem::~MissionProblem() = default;

MissionProblem::MissionProblem(MissionSpec spec) : MissionProblem(loadProblemInputs(std::move(spec))) {}

MissionProblem::MissionProblem(const ProblemInputs &in)
    : spec_(in.spec), field_(in.field), truth_(in.truth), members_(in.members), runs_(in.runs), run_(in.run),
      runSpread_(in.runSpread), frame_(in.frame), forecastFiles_(in.forecastFiles), forecastNotes_(in.forecastNotes),
      remoteSources_(in.remoteSources), diveBathymetry_(in.diveBathymetry), coastlineNote_(in.coastlineNote)
{
    if (in.wind)
        fieldWord_ = "wind";
    start_ = localPoint(spec_.start, "start");
    goal_ = localPoint(spec_.goal, "goal");
    for (std::size_t i = 0; i < spec_.waypoints.size(); ++i)
        via_.push_back(localPoint(spec_.waypoints[i].position, "waypoints[" + std::to_string(i) + "]"));
    snapEndpoints();
    checkPointsInBox();
    if (in.observations)
        applyObservations(*in.observations);
    buildRegions(in);
    checkViaPoints();
    gridSizeAutomatic_ = !(spec_.planner.gridSize > 0);
    if (gridSizeAutomatic_)
        spec_.planner.gridSize = automaticGridSize(start_, goal_); // (each leg's own: withLeg())
}

void MissionProblem::checkPointsInBox() const
{
    const Region &box = frame_.box;
    std::vector<std::pair<std::string, Point2>> points{{"start", start_}, {"goal", goal_}};
    for (std::size_t i = 0; i < via_.size(); ++i)
        points.emplace_back("waypoints[" + std::to_string(i) + "]", via_[i]);
    for (const auto &[name, p] : points)
        if (!(p.x >= box.xMin && p.x <= box.xMax && p.y >= box.yMin && p.y <= box.yMax))
        {
            char text[160];
            std::snprintf(text, sizeof text, "x %g..%g, y %g..%g", box.xMin, box.xMax, box.yMin, box.yMax);
            char point[80];
            std::snprintf(point, sizeof point, "(%g, %g)", p.x, p.y);
            throw Error(spec_.place(name) + ": " + point + " lies outside the planning region (" + text + ")");
        }
}

bool MissionProblem::isGeographic() const
{
    return frame_.isGeographic();
}

LonLat MissionProblem::toGeographic(Point2 p) const
{
    return frame_.toGeographic(p);
}

Point2 MissionProblem::toLocal(LonLat g) const
{
    return frame_.toLocal(g);
}

std::string MissionProblem::isoTime(double t) const
{
    return spec_.isoTime(t);
}

double MissionProblem::horizon(double tDep, double speed) const
{
    if (spec_.planner.horizon > 0)
        return spec_.planner.horizon;
    const Region &b = frame_.box;
    const double dist = std::hypot(goal_.x - start_.x, goal_.y - start_.y);
    double horizon = 50.0 * (std::hypot(b.xMax - b.xMin, b.yMax - b.yMin) + dist) / speed;
    if (std::isfinite(field_->timeEnd()))
        horizon = std::min(horizon, field_->timeEnd() - tDep);
    return horizon;
}

double MissionProblem::goalTolerance() const
{
    const Region &b = frame_.box;
    return spec_.planner.goalTolerance >= 0 ? spec_.planner.goalTolerance
                                            : 1e-6 * std::max(b.xMax - b.xMin, b.yMax - b.yMin);
}

GliderProblem MissionProblem::gliderProblem(double tDep, double speed) const
{
    const Region &b = frame_.box;
    GliderProblem p;
    p.field = field_;
    p.travel = spec_.travel;
    p.travel.speed = speed; // the vehicle's (MissionSpec::travel holds the integration's settings only)
    p.travel.depth = spec_.vehicle.depth;
    p.environment = environment_;
    p.xMin = b.xMin;
    p.xMax = b.xMax;
    p.yMin = b.yMin;
    p.yMax = b.yMax;
    p.t0 = tDep;
    // a speed so high that the trip takes no time at the planner's time resolution (a typing error: 1e308)
    const double crossing = std::hypot(b.xMax - b.xMin, b.yMax - b.yMin) / speed;
    if (!(crossing >= 1e-9)) // (a departure too large for the time resolution is departureProblem()'s)
        throw Error((speed == spec_.vehicle.speed ? spec_.place("vehicle.speed") : "speed " + text::number(speed)) +
                    ": " + text::number(speed) + " crosses the planning region (diagonal " +
                    text::number(crossing * speed) + ") in " + text::number(crossing) +
                    " time units, below the planner's time resolution: give the vehicle's speed in the mission's "
                    "units");
    p.horizon = horizon(tDep, speed);
    p.start.x = start_.x;
    p.start.y = start_.y;
    p.goal.x = goal_.x;
    p.goal.y = goal_.y;
    if (spec_.goalWindow.set)
    {
        p.arriveNotBefore = spec_.goalWindow.begin;
        p.arriveNotAfter = spec_.goalWindow.end;
    }
    p.goalTolerance = goalTolerance();
    return p;
}

double MissionProblem::minTripDuration(double speed) const
{
    Region r = frame_.box;
    return std::hypot(goal_.x - start_.x, goal_.y - start_.y) / (speed + field_->maxSpeed(r));
}

std::shared_ptr<const DiveProfileTravelTime> MissionProblem::diveProfiles(double speed) const
{
    if (!spec_.dive.enabled)
        return nullptr;
    TravelTimeParams t = spec_.travel;
    t.speed = speed;
    t.depth = spec_.vehicle.depth;
    return std::make_shared<DiveProfileTravelTime>(field_, t, spec_.dive.params, diveBathymetry_, spec_.dive.threads);
}
} // namespace ompl_glider
