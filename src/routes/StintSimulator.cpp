// Constant-bearing stints ([IsernObstacles] Sec. II): flying a list of bearings, one per surfacing.
#include "ompl_glider/routes/StintSimulator.h"

#include <algorithm>
#include <cmath>

#include "ompl_glider/Exception.h"
#include "../execution/DiveOutcome.h"

namespace ompl_glider
{
StintSimulator::StintSimulator(std::shared_ptr<const CurrentField> field, std::shared_ptr<const Environment> forbidden,
                               double speed, double maxCurrent, Point2 start, double t0, Point2 goal,
                               StintSettings settings)
    : field_(std::move(field)), forbidden_(std::move(forbidden)), speed_(speed), maxCurrent_(maxCurrent), start_(start),
      t0_(t0), goal_(goal), settings_(settings), flown_(std::make_shared<std::atomic<std::uint64_t>>(0))
{
    if (!field_)
        throw Error("StintSimulator: no current field");
    settings_.check();
    if (!(speed_ > 0.0) || !std::isfinite(speed_))
        throw Error("StintSimulator: the speed must be positive and finite");
    if (!(maxCurrent_ >= 0.0) || !std::isfinite(maxCurrent_))
        throw Error("StintSimulator: the current bound must be >= 0 and finite");
    dive_.speed = speed_;
    dive_.step = settings_.rk4Step();
    dive_.depth = settings_.depth;
    dive_.radius = settings_.radius;
    dive_.goal.x = goal_.x;
    dive_.goal.y = goal_.y;
}

std::uint64_t StintSimulator::stintsFlown() const
{
    return flown_->load(std::memory_order_relaxed);
}

DiveEnd StintSimulator::flyStint(double x, double y, double t, double bearing, std::vector<TimedPoint> *track) const
{
    flown_->fetch_add(1, std::memory_order_relaxed);
    const Point2 h = bearingVector(bearing);
    return flyHeading(x, y, t, h.x, h.y, std::min(t + settings_.duration, endTime()), *field_, forbidden_.get(), dive_,
                      track);
}

double StintSimulator::bearingToGoal(double x, double y) const
{
    return bearingOf(goal_.x - x, goal_.y - y);
}

namespace
{
/// Flies stints from the start, the bearing of each chosen by @p next(k, x, y, t) (k = stint index).
template <class Next> StintPlan fly(const StintSimulator &sim, const Next &next, std::size_t count, bool keepTrack)
{
    StintPlan p;
    double x = sim.start().x, y = sim.start().y, t = sim.t0();
    p.surfacings.push_back({x, y, t});
    if (keepTrack)
        p.track.push_back({x, y, t});
    const double r = sim.settings().radius;
    if (r > 0.0)
    {
        p.closestDistance = std::hypot(sim.goal().x - x, sim.goal().y - y);
        p.closestTime = t;
    }
    if (r > 0.0 && p.closestDistance <= r)
    {
        p.reached = true;
        p.arrivalTime = t;
    }
    const double end = sim.endTime();
    for (std::size_t k = 0; k < count && !p.reached && t < end - 1e-12 * std::max(1.0, std::abs(end)); ++k)
    {
        const double b = next(k, x, y, t);
        p.bearings.push_back(b);
        const DiveEnd e = sim.flyStint(x, y, t, b, keepTrack ? &p.track : nullptr);
        x = e.x;
        y = e.y;
        t = e.t;
        p.surfacings.push_back({x, y, t});
        if (e.closestDistance < p.closestDistance)
        {
            p.closestDistance = e.closestDistance;
            p.closestTime = e.closestTime;
        }
        noteDiveOutcome(e, p);
        if (e.grounded)
            break;
    }
    p.remainingDistance = std::hypot(sim.goal().x - x, sim.goal().y - y);
    p.cost = sim.cost(p);
    return p;
}
} // namespace

StintPlan StintSimulator::simulate(const std::vector<double> &bearings, bool keepTrack) const
{
    return fly(
        *this, [&](std::size_t k, double, double, double) { return bearings[k]; },
        std::min(bearings.size(), settings_.stintCount()), keepTrack);
}

StintPlan StintSimulator::direct() const
{
    return fly(
        *this, [&](std::size_t, double x, double y, double) { return bearingToGoal(x, y); }, settings_.stintCount(),
        true);
}

double StintSimulator::cost(const StintPlan &p) const
{
    const TimedPoint &last = p.surfacings.back();
    const double lost = p.grounded ? std::max(0.0, endTime() - last.t) : 0.0;
    if (settings_.objective == StintObjective::RemainingDistance)
        return p.remainingDistance + maxReach() * lost;
    if (p.reached)
        return p.arrivalTime - t0_;
    if (!std::isfinite(p.closestDistance)) // a plan that has not flown (no radius is checked by the settings)
        return settings_.missionDuration + p.remainingDistance / maxReach() + lost;
    // a miss costs the time of the closest approach plus the distance left to the radius at a tenth of the speed
    // through water: continuous where a plan starts to reach the radius, and steep enough that just missing early
    // never beats reaching a little later
    return p.closestTime - t0_ + std::max(0.0, p.closestDistance - settings_.radius) / (0.1 * speed_) + lost;
}

double StintSimulator::lowerBound(double x, double y, double t) const
{
    const double d = std::hypot(goal_.x - x, goal_.y - y);
    if (settings_.objective == StintObjective::RemainingDistance)
        return std::max(0.0, d - maxReach() * std::max(0.0, endTime() - t));
    return (t - t0_) + std::max(0.0, d - settings_.radius) / maxReach();
}
} // namespace ompl_glider
