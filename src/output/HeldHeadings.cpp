/// @file HeldHeadings.cpp
/// @brief The held headings the files write (RouteFiles.h: trueHeadings(), uploadHolds(), trueBearing()): true
/// bearings, each the one whose flight through the current ends where the planner's segment (or the uploads' merged
/// span of segments) ends.
///
/// The planner holds a heading in the plane of its projection (azimuthal equidistant about a centre: its north, +y,
/// is true north only on the centre's meridian, 1-3 degrees off it a few hundred km away). A glider holds a true
/// (compass) heading: its direction in the plane turns along the way with the meridians (and the projection's small
/// angle distortion). So a written heading is not the planner's converted at one point: it is the true heading which,
/// held through the forecast from the segment's start for its duration (the plane direction of that true heading
/// recomputed along the flight), ends nearest the segment's end (Gauss-Newton on the one angle).
#include "ompl_glider/output/RouteFiles.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ompl_glider/Exception.h"
#include "ompl_glider/execution/HeadingRoute.h"
#include "RouteCommon.h"

namespace ompl_glider
{
namespace
{
constexpr double kRad = M_PI / 180.0;

/// Degrees in [0, 360).
double wrap360(double deg)
{
    const double w = std::fmod(deg, 360.0);
    return w < 0.0 ? w + 360.0 : (w >= 360.0 ? 0.0 : w);
}

/// Plane vectors of one metre east and one metre north at a point (planning units per metre of the ground).
struct GroundAxes
{
    Point2 east{1.0, 0.0}, north{0.0, 1.0};
};

/// The ground axes at @p p of a geographic problem: WGS84's radii of curvature turn degrees into metres.
GroundAxes groundAxes(const MissionProblem &problem, Point2 p)
{
    GroundAxes a;
    const LonLat g = problem.toGeographic(p);
    const double d = 1e-5, s = std::sin(g.lat * kRad);
    const double A = 6378137.0, e2 = 6.69437999014e-3, w = 1.0 - e2 * s * s;
    const double M = A * (1.0 - e2) / (w * std::sqrt(w)), N = A / std::sqrt(w);
    const Point2 e1 = problem.toLocal({g.lon + d, g.lat}), e0 = problem.toLocal({g.lon - d, g.lat});
    const Point2 n1 = problem.toLocal({g.lon, g.lat + d}), n0 = problem.toLocal({g.lon, g.lat - d});
    const double me = 2.0 * d * kRad * N * std::cos(g.lat * kRad), mn = 2.0 * d * kRad * M;
    a.east = {(e1.x - e0.x) / me, (e1.y - e0.y) / me};
    a.north = {(n1.x - n0.x) / mn, (n1.y - n0.y) / mn};
    return a;
}

/// The true bearing (degrees in [0, 360)) of the plane's bearing @p grid at @p p, of ground axes @p a.
double trueOfGrid(const GroundAxes &a, double grid)
{
    const Point2 d = bearingVector(grid);
    // d = E east + N north: solve for the ground components
    const double det = a.east.x * a.north.y - a.east.y * a.north.x;
    const double E = (d.x * a.north.y - d.y * a.north.x) / det, N = (a.east.x * d.y - a.east.y * d.x) / det;
    return wrap360(std::atan2(E, N) / kRad);
}

/// The flights of held true headings through a mission's forecast, in its planning frame.
class TrueFlyer
{
public:
    TrueFlyer(const MissionResult &r, const MissionProblem *problem, double speed)
        : r_(r), problem_(problem), speed_(speed), geo_(problem && route_detail::geographic(r))
    {
        if (route_detail::geographic(r) && !problem)
            throw Error(r.spec.file + ": the true bearings of held headings need the problem (its projection)");
        // RK4 steps of a minute with physical time units, else a 500th of the span
        step_ = r.spec.physicalUnits().time ? 60.0 / r.spec.timeUnitSeconds : 0.0;
    }

    /// The ground axes at @p p: WGS84's radii of curvature turn degrees into metres.
    GroundAxes axes(Point2 p) const { return geo_ ? groundAxes(*problem_, p) : GroundAxes{}; }

    /// The unit plane direction of the true bearing @p psi (degrees) at @p p.
    Point2 direction(Point2 p, double psi) const
    {
        if (!geo_)
            return bearingVector(psi);
        const GroundAxes a = axes(p);
        const double s = std::sin(psi * kRad), c = std::cos(psi * kRad);
        const Point2 v{s * a.east.x + c * a.north.x, s * a.east.y + c * a.north.y};
        const double n = std::hypot(v.x, v.y);
        return {v.x / n, v.y / n};
    }

    /// The true bearing (degrees in [0, 360)) of the plane's bearing @p grid at @p p.
    double trueOf(Point2 p, double grid) const { return geo_ ? trueOfGrid(axes(p), grid) : wrap360(grid); }

    /// Holds @p psi from @p from for its duration (to @p to's time); the positions at @p times (ascending, in the
    /// span) into @p at, every step's into @p track when given. Returns the end.
    Point2 fly(const TimedPoint &from, double until, double psi, const std::vector<double> &times,
               std::vector<Point2> *at, std::vector<TimedPoint> *track) const
    {
        const CurrentField &f = *problem_->getField();
        const double depth = r_.spec.vehicle.depth, span = until - from.t;
        const int n = std::clamp(step_ > 0.0 ? static_cast<int>(std::ceil(span / step_)) : 500, 8, 20000);
        const double h = span / n;
        Point2 p{from.x, from.y};
        double t = from.t;
        std::size_t next = 0;
        if (track)
            track->push_back({p.x, p.y, t});
        const auto rate = [&](Point2 q, double tq, Point2 dir) {
            const Velocity c = f.velocity(q.x, q.y, depth, tq);
            return Point2{speed_ * dir.x + c.u, speed_ * dir.y + c.v};
        };
        for (int i = 0; i < n; ++i)
        {
            const Point2 dir = direction(p, psi); // the meridians turn slowly: once a step
            const Point2 k1 = rate(p, t, dir);
            const Point2 k2 = rate({p.x + 0.5 * h * k1.x, p.y + 0.5 * h * k1.y}, t + 0.5 * h, dir);
            const Point2 k3 = rate({p.x + 0.5 * h * k2.x, p.y + 0.5 * h * k2.y}, t + 0.5 * h, dir);
            const Point2 k4 = rate({p.x + h * k3.x, p.y + h * k3.y}, t + h, dir);
            const Point2 q{p.x + h / 6.0 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
                           p.y + h / 6.0 * (k1.y + 2 * k2.y + 2 * k3.y + k4.y)};
            // positions at the asked times: linear within the step (steps of a minute)
            while (at && next < times.size() && times[next] <= t + h + 1e-12 * std::abs(t + h))
            {
                const double s = h > 0.0 ? std::clamp((times[next] - t) / h, 0.0, 1.0) : 1.0;
                at->push_back({p.x + s * (q.x - p.x), p.y + s * (q.y - p.y)});
                ++next;
            }
            p = q;
            t = from.t + (i + 1) * h;
            if (track)
                track->push_back({p.x, p.y, t});
        }
        while (at && next++ < times.size())
            at->push_back(p);
        return p;
    }

    /// The true heading held from @p from until @p to.t whose flight ends nearest @p to, from the guess @p psi.
    double fit(const TimedPoint &from, const TimedPoint &to, double psi) const
    {
        const std::vector<double> none;
        Point2 e = fly(from, to.t, psi, none, nullptr, nullptr);
        for (int it = 0; it < 8; ++it)
        {
            const double dh = 1e-3; // degrees
            const Point2 e2 = fly(from, to.t, psi + dh, none, nullptr, nullptr);
            const Point2 de{(e2.x - e.x) / dh, (e2.y - e.y) / dh}, m{e.x - to.x, e.y - to.y};
            const double dd = de.x * de.x + de.y * de.y;
            if (!(dd > 0.0))
                break;
            const double step = std::clamp(-(de.x * m.x + de.y * m.y) / dd, -10.0, 10.0);
            const Point2 e3 = fly(from, to.t, psi + step, none, nullptr, nullptr);
            if (std::hypot(e3.x - to.x, e3.y - to.y) > std::hypot(m.x, m.y))
                break; // no better: the miss is along the track (the duration's), not the heading's
            psi += step;
            e = e3;
            if (std::abs(step) < 1e-7)
                break;
        }
        return wrap360(psi);
    }

private:
    const MissionResult &r_;
    const MissionProblem *problem_;
    double speed_;
    bool geo_;
    double step_{0.0};
};

TimedPoint at(const MissionWaypoint &w)
{
    return {w.position.x, w.position.y, w.time};
}

/// The speed the heading held from waypoint @p i is flown at: its leg's.
double speedFrom(const MissionResult &r, std::size_t i)
{
    if (!r.legs.empty() && i + 1 < r.waypoints.size())
    {
        const int leg = r.waypoints[i + 1].missionLeg;
        if (leg >= 0 && static_cast<std::size_t>(leg) < r.legs.size() && r.legs[leg].plan.speed > 0.0)
            return r.legs[leg].plan.speed;
    }
    return r.plan.speed > 0.0 ? r.plan.speed : r.spec.vehicle.speed;
}

/// The run of held headings begun at waypoint @p a (its heading finite) ends at the returned waypoint: the first
/// without a heading, the end of the leg (a via point), or the last waypoint.
std::size_t runEnd(const MissionResult &r, std::size_t a)
{
    const auto viaArrival = [&](std::size_t i) {
        for (std::size_t k = 0; k + 1 < r.legs.size(); ++k)
            if (r.legs[k].lastPoint == i)
                return true;
        return false;
    };
    std::size_t b = a + 1;
    while (b + 1 < r.waypoints.size() && std::isfinite(r.waypoints[b].heading) && !viaArrival(b) &&
           r.waypoints[b + 1].missionLeg == r.waypoints[a + 1].missionLeg)
        ++b;
    return b;
}

/// The guess of a span's true heading: the duration-weighted mean direction of its segments' true bearings.
double meanTrue(const TrueFlyer &f, const MissionResult &r, std::size_t a, std::size_t b)
{
    double sx = 0.0, sy = 0.0;
    for (std::size_t i = a; i < b; ++i)
    {
        const Point2 v = bearingVector(f.trueOf(r.waypoints[i].position, r.waypoints[i].heading));
        sx += r.waypoints[i].headingDuration * v.x;
        sy += r.waypoints[i].headingDuration * v.y;
    }
    return wrap360(std::atan2(sx, sy) / kRad);
}

/// One hold from waypoint @p a to @p b, fitted; its largest distance (m) from the planned segment ends it passes
/// (at their times) in @p worst.
HeldHeading fitHold(const TrueFlyer &f, const MissionResult &r, std::size_t a, std::size_t b, double &worst)
{
    HeldHeading h;
    h.from = a;
    h.to = b;
    h.duration = r.waypoints[b].time - r.waypoints[a].time;
    h.bearing = f.fit(at(r.waypoints[a]), at(r.waypoints[b]), meanTrue(f, r, a, b));
    std::vector<double> times;
    for (std::size_t k = a + 1; k <= b; ++k)
        times.push_back(r.waypoints[k].time);
    std::vector<Point2> flown;
    f.fly(at(r.waypoints[a]), r.waypoints[b].time, h.bearing, times, &flown, nullptr);
    worst = 0.0;
    for (std::size_t k = a + 1; k <= b; ++k)
    {
        const Point2 q = flown[k - a - 1], w = r.waypoints[k].position;
        worst = std::max(worst, std::hypot(q.x - w.x, q.y - w.y) * r.spec.metresPerUnit());
    }
    const Point2 e = flown.back(), w = r.waypoints[b].position;
    h.miss = std::hypot(e.x - w.x, e.y - w.y) * r.spec.metresPerUnit();
    return h;
}

/// The merged hold's flight keeps to water and out of the forbidden regions (nothing to check without the problem).
bool holdAllowed(const TrueFlyer &f, const MissionResult &r, const MissionProblem *problem, const HeldHeading &h)
{
    if (!problem)
        return true;
    std::vector<TimedPoint> track;
    f.fly(at(r.waypoints[h.from]), r.waypoints[h.to].time, h.bearing, {}, nullptr, &track);
    const auto &env = problem->getEnvironment();
    for (std::size_t k = 1; k < track.size(); ++k)
    {
        const TimedPoint &p = track[k - 1], &q = track[k];
        if (!problem->getField()->segmentInWater(p.x, p.y, q.x, q.y, r.spec.vehicle.depth))
            return false;
        if (env && !env->legFree(p.x, p.y, p.t, q.x, q.y, q.t))
            return false;
    }
    return true;
}
} // namespace

double trueBearing(const MissionResult &r, const MissionProblem *problem, Point2 at, double gridDeg)
{
    if (!std::isfinite(gridDeg))
        return gridDeg;
    return TrueFlyer(r, problem, r.spec.vehicle.speed).trueOf(at, gridDeg);
}

double trueBearing(const MissionProblem &problem, Point2 at, double gridDeg)
{
    if (!std::isfinite(gridDeg))
        return gridDeg;
    return problem.isGeographic() ? trueOfGrid(groundAxes(problem, at), gridDeg) : wrap360(gridDeg);
}

double trueBearingOfFlight(const MissionResult &r, const MissionProblem *problem, const TimedPoint &from,
                           const TimedPoint &to, double gridDeg, double speed)
{
    if (!std::isfinite(gridDeg) || !problem || !route_detail::geographic(r) || !(to.t > from.t))
        return trueBearing(r, problem, {from.x, from.y}, gridDeg);
    const TrueFlyer f(r, problem, speed);
    return f.fit(from, to, f.trueOf({from.x, from.y}, gridDeg));
}

std::vector<double> trueHeadings(const MissionResult &r, const MissionProblem *problem)
{
    std::vector<double> out(r.waypoints.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i + 1 < r.waypoints.size(); ++i)
        if (std::isfinite(r.waypoints[i].heading))
            out[i] = trueBearingOfFlight(r, problem, at(r.waypoints[i]), at(r.waypoints[i + 1]), r.waypoints[i].heading,
                                         speedFrom(r, i));
    return out;
}

std::vector<double> trueStintBearings(const MissionResult &r, const MissionProblem *problem)
{
    std::vector<double> out;
    if (!r.plan.stints)
        return out;
    const StintPlan &sp = r.plan.stints->plan;
    for (std::size_t k = 0; k < sp.bearings.size(); ++k)
        out.push_back(
            k + 1 < sp.surfacings.size()
                ? trueBearingOfFlight(r, problem, sp.surfacings[k], sp.surfacings[k + 1], sp.bearings[k], r.plan.speed)
                : trueBearing(r, problem, {sp.surfacings[k].x, sp.surfacings[k].y}, sp.bearings[k]));
    return out;
}

std::vector<HeldHeading> uploadHolds(const MissionResult &r, const MissionProblem *problem)
{
    std::vector<HeldHeading> holds;
    const double tolerance = r.spec.outputs.holdTolerance;
    std::size_t a = 0;
    while (a + 1 < r.waypoints.size())
    {
        if (!std::isfinite(r.waypoints[a].heading))
        {
            ++a;
            continue;
        }
        const TrueFlyer f(r, problem, speedFrom(r, a));
        const std::size_t end = runEnd(r, a);
        double worst = 0.0;
        HeldHeading best = fitHold(f, r, a, a + 1, worst); // one segment: the planner's own, always kept
        // the farthest end within the tolerance: doubling, then halving between the last good and the first bad
        std::size_t good = a + 1, bad = end + 1;
        for (std::size_t span = 2; tolerance > 0.0 && a + span <= end && bad == end + 1; span *= 2)
        {
            const HeldHeading h = fitHold(f, r, a, a + span, worst);
            if (worst <= tolerance && holdAllowed(f, r, problem, h))
            {
                good = a + span;
                best = h;
            }
            else
                bad = a + span;
        }
        if (tolerance > 0.0 && bad == end + 1 && good < end)
        {
            const HeldHeading h = fitHold(f, r, a, end, worst);
            if (worst <= tolerance && holdAllowed(f, r, problem, h))
                good = end, best = h;
            else
                bad = end;
        }
        while (tolerance > 0.0 && bad - good > 1 && good < end)
        {
            const std::size_t mid = good + (bad - good) / 2;
            const HeldHeading h = fitHold(f, r, a, mid, worst);
            if (worst <= tolerance && holdAllowed(f, r, problem, h))
                good = mid, best = h;
            else
                bad = mid;
        }
        holds.push_back(best);
        a = good;
    }
    return holds;
}
} // namespace ompl_glider
