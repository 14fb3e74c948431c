#include "ompl_glider/mission/Isochrones.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "PlanningInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/reachability/LevelSet.h"

namespace ompl_glider
{
IsochroneSet computeIsochrones(const MissionProblem &problem, const PlannedPath &plan, double departure,
                               double interval)
{
    const MissionSpec &m = problem.getSpec();
    const double speed = plan.speed > 0.0 ? plan.speed : m.vehicle.speed;
    const GliderProblem gp = problem.gliderProblem(departure, speed);
    const auto ctx = makeGliderContext(gp);
    const double horizon = std::min(gp.horizon, ctx->field->timeEnd() - departure);
    const double span = plan.solved && std::isfinite(plan.travelTime) ? std::min(plan.travelTime, horizon) : horizon;
    std::vector<double> times;
    if (std::isfinite(interval) && interval > 0.0)
    {
        const double count = std::floor(span * (1 + 1e-9) / interval);
        if (count > static_cast<double>(planning_detail::kMaxIsochrones))
        {
            char text[200];
            std::snprintf(text, sizeof text,
                          ": an interval of %g gives %.4g isochrones over the %.4g the plan takes, more than the "
                          "limit of %zu: use a longer interval",
                          interval, count, span, planning_detail::kMaxIsochrones);
            throw Error(m.place("outputs.isochrone_interval") + text);
        }
        for (double t = interval; t <= span * (1 + 1e-9); t += interval)
            times.push_back(t);
    }
    else
        for (int k = 1; k <= 8; ++k)
            times.push_back(span * k / 8.0);

    IsochroneSet out;
    LevelSetParams lp;
    // Contours for a pilot's map: a cell of 1/100 of the region's larger side (the planner's default is 1/200; this
    // is eight times less work, about 1 % of the region's size in position)
    lp.cellSize = 2.0 * defaultLevelSetResolution(*ctx);
    out.resolution = lp.cellSize;
    const LevelSetSolver solver(ctx, lp);
    const Point2 s = problem.getStart();
    const Reachability r = solver.solve(s.x, s.y, departure, departure + (times.empty() ? 0.0 : times.back()),
                                        std::nullopt);
    out.seconds = r.stats.seconds;
    out.x0 = r.x0;
    out.y0 = r.y0;
    out.h = r.h;
    out.nx = r.nx;
    out.ny = r.ny;
    out.arrival = r.arrival;
    for (double dt : times)
    {
        Isochrone c;
        c.time = departure + dt;
        c.lines = r.isochrone(c.time);
        c.iso = problem.isoTime(c.time);  // empty without dates
        if (problem.isGeographic())
        {
            for (const auto &line : c.lines)
            {
                std::vector<LonLat> g;
                g.reserve(line.size());
                for (const Point2 &p : line)
                    g.push_back(problem.toGeographic(p));
                c.lonLat.push_back(std::move(g));
            }
        }
        out.contours.push_back(std::move(c));
    }
    return out;
}
}  // namespace ompl_glider
