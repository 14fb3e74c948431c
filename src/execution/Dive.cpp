// One dive with a held heading: RK4 between surfacings with land, forbidden-region and goal checks (see Dive.h).
#include "ompl_glider/execution/Dive.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
namespace
{
std::string divePointText(double x, double y, double t)
{
    std::ostringstream os;
    os << "(" << x << ", " << y << ") at t = " << t;
    return os.str();
}

/// True when (x, y) lies off a gridded field's grid: the grid's edge, where the field ends, not its land (off the
/// grid itself, not only its bounding box: a lon/lat grid in the planning frame has curved edges).
bool leavesGrid(const CurrentField &field, double x, double y)
{
    const FieldGrid *g = field.grid(); // any gridded source, whatever reads it (CurrentField.h)
    return g && !g->covers(x, y);
}
} // namespace

DiveEnd flyHeading(double x, double y, double t, double hx, double hy, double tEnd, const CurrentField &field,
                   const Environment *forbidden, const DiveSettings &s, std::vector<TimedPoint> *track)
{
    DiveEnd e;
    auto rate = [&](double px, double py, double pt) {
        const Velocity c = field.velocity(px, py, s.depth, pt);
        return Velocity{s.speed * hx + c.u, s.speed * hy + c.v};
    };
    while (t < tEnd - 1e-12 * std::max(1.0, std::abs(tEnd)))
    {
        const double h = std::min(s.step, tEnd - t);
        const Velocity k1 = rate(x, y, t);
        const Velocity k2 = rate(x + 0.5 * h * k1.u, y + 0.5 * h * k1.v, t + 0.5 * h);
        const Velocity k3 = rate(x + 0.5 * h * k2.u, y + 0.5 * h * k2.v, t + 0.5 * h);
        const Velocity k4 = rate(x + h * k3.u, y + h * k3.v, t + h);
        const double nx = x + h / 6.0 * (k1.u + 2.0 * k2.u + 2.0 * k3.u + k4.u);
        const double ny = y + h / 6.0 * (k1.v + 2.0 * k2.v + 2.0 * k3.v + k4.v);
        const double nt = t + h;
        if (!std::isfinite(nx) || !std::isfinite(ny) || !field.segmentInWater(x, y, nx, ny, s.depth))
        {
            e.grounded = true;
            e.why = (leavesGrid(field, nx, ny) ? "the edge of the current field's grid (not land) between "
                                               : "land of the current field between ") +
                    divePointText(x, y, t) + " and " + divePointText(nx, ny, nt);
            break;
        }
        if (forbidden && !forbidden->legFree(x, y, t, nx, ny, nt))
        {
            e.grounded = true;
            e.why = forbidden->whyLegBlocked(x, y, t, nx, ny, nt) + " between " + divePointText(x, y, t) + " and " +
                    divePointText(nx, ny, nt);
            break;
        }
        // the goal reached within this step: the first point of the step within radius (its chord)
        if (s.radius > 0.0)
        {
            const double ex = nx - x, ey = ny - y, fx = x - s.goal.x, fy = y - s.goal.y;
            const double a = ex * ex + ey * ey, b = 2.0 * (ex * fx + ey * fy),
                         c = fx * fx + fy * fy - s.radius * s.radius;
            const double disc = b * b - 4.0 * a * c;
            // closest approach on the chord (for a continuous cost of plans that miss the radius)
            const double q0 = a > 0.0 ? std::clamp(-(ex * fx + ey * fy) / a, 0.0, 1.0) : 0.0;
            const double dq = std::hypot(fx + q0 * ex, fy + q0 * ey);
            if (dq < e.closestDistance)
            {
                e.closestDistance = dq;
                e.closestTime = t + q0 * h;
            }
            if (a > 0.0 && disc >= 0.0)
            {
                const double q = (-b - std::sqrt(disc)) / (2.0 * a);
                if (q >= 0.0 && q <= 1.0)
                {
                    e.reached = true;
                    e.arrivalTime = t + q * h;
                    e.arrival = {x + q * ex, y + q * ey, e.arrivalTime};
                }
            }
        }
        x = nx;
        y = ny;
        t = nt;
        if (track)
            track->push_back({x, y, t});
        if (e.reached)
            break;
    }
    e.x = x;
    e.y = y;
    e.t = t;
    return e;
}
} // namespace ompl_glider
