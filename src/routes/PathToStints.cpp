// From a timed path to constant-bearing stints; see PathToStints.h.
#include "ompl_glider/routes/PathToStints.h"

#include <algorithm>
#include <cmath>

#include "ompl_glider/Exception.h"
#include "ompl_glider/execution/Execution.h"
#include "StintStep.h"

namespace ompl_glider
{
namespace
{
/// The path's time at the point of the path nearest (x, y) (the glider's progress along it, whatever the clock).
double progressTime(const std::vector<TimedPoint> &path, double x, double y)
{
    double best = INFINITY, tBest = path.front().t;
    for (std::size_t k = 0; k + 1 < path.size(); ++k)
    {
        const TimedPoint &a = path[k], &b = path[k + 1];
        const double ex = b.x - a.x, ey = b.y - a.y, l2 = ex * ex + ey * ey;
        const double q = l2 > 0.0 ? std::clamp(((x - a.x) * ex + (y - a.y) * ey) / l2, 0.0, 1.0) : 0.0;
        const double d = std::hypot(a.x + q * ex - x, a.y + q * ey - y);
        if (d < best)
        {
            best = d;
            tBest = a.t + q * (b.t - a.t);
        }
    }
    return tBest;
}
} // namespace

PathToStintsResult stintsFromPath(const StintSimulator &sim, const std::vector<TimedPoint> &path,
                                  const BearingOptimizerParams &params)
{
    if (path.size() < 2)
        throw Error("stintsFromPath: the path needs at least two points");
    if (!(sim.settings().radius > 0.0))
        throw Error("stintsFromPath: the simulator needs a goal radius");
    PathToStintsResult out;
    out.pathTravelTime = path.back().t - path.front().t;
    const double D = sim.settings().duration;
    // tracking: stint by stint toward the path's position one stint later
    std::vector<double> bearings;
    double x = path.front().x, y = path.front().y, t = path.front().t;
    const std::size_t count = sim.settings().stintCount();
    while (bearings.size() < count && t < sim.endTime())
    {
        // aim one stint ahead of the glider's progress along the path (ahead of the path's clock or behind it)
        const double tau = progressTime(path, x, y);
        const TimedPoint aim = planAt(path, tau + D);
        double dx = aim.x - x, dy = aim.y - y;
        const double len = std::hypot(dx, dy);
        double b0 = sim.bearingToGoal(x, y);
        if (len > 0.0)
        {
            double hx = 0.0, hy = 0.0;
            crabHeading(dx / len, dy / len, sim.field().velocity(x, y, sim.settings().depth, t), sim.speed(), hx, hy);
            b0 = bearingOf(hx, hy);
        }
        // the path ends within this stint: aim at the goal's radius (arriving, the earlier the better; else the
        // closest approach), otherwise at the path's point one stint later
        const bool last = tau + D >= path.back().t;
        auto miss = [&](double b) -> double {
            const DiveEnd e = sim.flyStint(x, y, t, b);
            if (e.grounded)
                return INFINITY;
            if (e.reached)
                return -1e6 * D + (e.arrivalTime - t);
            return last ? e.closestDistance : std::hypot(aim.x - e.x, aim.y - e.y);
        };
        // golden section over b0 +- 45 degrees
        const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
        double a = b0 - 45.0, c = b0 + 45.0;
        double p = c - phi * (c - a), q = a + phi * (c - a);
        double fp = miss(p), fq = miss(q);
        for (int it = 0; it < 18; ++it)
        {
            if (fp <= fq)
            {
                c = q;
                q = p;
                fq = fp;
                p = c - phi * (c - a);
                fp = miss(p);
            }
            else
            {
                a = p;
                p = q;
                fp = fq;
                q = a + phi * (c - a);
                fq = miss(q);
            }
        }
        double b = fp <= fq ? p : q;
        if (!(std::min(fp, fq) <= miss(b0)))
            b = b0;
        bearings.push_back(b);
        if (flyOneStint(sim, x, y, t, b))
            break;
    }
    out.tracking = sim.simulate(bearings);
    const BearingOptimizerResult opt = optimiseBearings(sim, bearings, params);
    out.evaluations = opt.evaluations;
    // the better of the two, a plan that arrives before one that does not
    const bool optBetter =
        opt.plan.reached != out.tracking.reached ? opt.plan.reached : opt.plan.cost <= out.tracking.cost;
    out.plan = optBetter ? opt.plan : out.tracking;
    if (out.plan.reached)
    {
        out.stintTravelTime = out.plan.arrivalTime - path.front().t;
        out.loss = out.stintTravelTime / out.pathTravelTime - 1.0;
    }
    return out;
}
} // namespace ompl_glider
