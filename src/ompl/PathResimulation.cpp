#include "ompl_glider/ompl/PathResimulation.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "ompl_glider/ompl/TimeSE2StateSpace.h"

namespace ompl_glider
{
namespace
{
/// Empty when (x, y, t) is a valid point of the context, else why not.
std::string pointProblem(const GliderContext &ctx, double x, double y, double t)
{
    std::ostringstream os;
    const Region &r = ctx.region;
    if (!(x >= r.xMin && x <= r.xMax && y >= r.yMin && y <= r.yMax))
        os << "(" << x << ", " << y << ") outside the region";
    else if (!(t >= r.tMin && t <= r.tMax))
        os << "time " << t << " outside the window [" << r.tMin << ", " << r.tMax << "]";
    else if (!ctx.field->inWater(x, y, ctx.travel->params().depth))
        os << "(" << x << ", " << y << ") not in water";
    else if (ctx.environment && !ctx.environment->pointFree(x, y, t))
        os << "(" << x << ", " << y << ") at time " << t << " in a forbidden region: "
           << ctx.environment->whyBlocked(x, y, t);
    return os.str();
}
}  // namespace

PathResimulation resimulatePath(const GliderContext &ctx, const std::vector<std::array<double, 2>> &wp, double t0)
{
    PathResimulation r;
    r.departureTime = t0;
    r.arrivalTime = t0;
    if (wp.empty())
        return r;
    r.times.assign(wp.size(), std::numeric_limits<double>::infinity());
    r.times[0] = t0;
    auto fail = [&r](int leg, const std::string &why) {
        if (r.valid)
        {
            r.valid = false;
            r.firstBadLeg = leg;
            r.reason = why;
        }
    };
    std::string why = pointProblem(ctx, wp[0][0], wp[0][1], t0);
    if (!why.empty())
        fail(wp.size() > 1 ? 0 : -1, "start: " + why);
    double t = t0;
    for (std::size_t i = 0; i + 1 < wp.size(); ++i)
    {
        const auto &a = wp[i];
        const auto &b = wp[i + 1];
        const double tt = ctx.travel->travelTime(a[0], a[1], b[0], b[1], t);
        const int leg = static_cast<int>(i);
        if (!std::isfinite(tt))
        {
            r.finite = false;
            fail(leg, "leg " + std::to_string(i) + " is infeasible (travel time +inf)");
            t = std::numeric_limits<double>::infinity();
            break;
        }
        const double t2 = t + tt;
        r.times[i + 1] = t2;
        why = pointProblem(ctx, b[0], b[1], t2);
        if (!why.empty())
            fail(leg, "leg " + std::to_string(i) + " ends at " + why);
        else if (ctx.environment && !ctx.environment->legFree(a[0], a[1], t, b[0], b[1], t2))
            fail(leg, "leg " + std::to_string(i) + " crosses a forbidden region");
        t = t2;
    }
    r.arrivalTime = t;
    r.travelTime = t - t0;
    return r;
}

PathResimulation resimulatePath(const GliderContext &ctx, const ompl::geometric::PathGeometric &path, double t0)
{
    std::vector<std::array<double, 2>> wp;
    wp.reserve(path.getStateCount());
    for (std::size_t i = 0; i < path.getStateCount(); ++i)
    {
        const auto *st = path.getState(i)->as<TimeSE2StateSpace::StateType>();
        wp.push_back({st->getX(), st->getY()});
    }
    return resimulatePath(ctx, wp, t0);
}
}  // namespace ompl_glider
