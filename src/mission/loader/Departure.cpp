// The `departure` section (a time, or a window of departures searched) and the goal's arrival window.
#include <algorithm>
#include <cmath>

#include "MissionReader.h"
#include "ompl_glider/ompl/Sectors.h"

namespace ompl_glider::mission_loader
{
namespace
{
constexpr double kMaxSupportingPoints = 10000.0; ///< departure-window samples, each a whole search
} // namespace

void readDeparture(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "departure";
    r.checkMap(n, f, {"time", "window"});
    DepartureSpec &d = m.departure;
    if (n["time"] && n["window"])
        r.fail(n, f, "give either a departure time or a departure window, not both");
    if (n["time"])
        d.time = r.time(n["time"], f + ".time", m);
    if (!n["window"])
        return;
    const YAML::Node &w = n["window"];
    const std::string g = f + ".window";
    r.checkMap(w, g, {"begin", "end", "spacing", "tolerance", "coarse_grid_size", "coarse_sectors", "threads"});
    if (!w["begin"] || !w["end"])
        r.fail(w, g, "begin and end are required");
    d.window = true;
    d.begin = r.time(w["begin"], g + ".begin", m);
    d.end = r.time(w["end"], g + ".end", m);
    if (!(d.end >= d.begin))
        r.fail(w["end"], g + ".end", "must not be before begin");
    d.time = d.begin;
    if (w["spacing"])
        d.spacing = r.positive(w["spacing"], g + ".spacing");
    // every supporting point is a whole search: refuse a sample set that could never finish
    const double points = std::floor((d.end - d.begin) / d.spacing) + 1.0;
    if (points > kMaxSupportingPoints)
        r.fail(w["spacing"] ? w["spacing"] : w, g + ".spacing",
               "gives " + std::to_string(static_cast<long long>(std::min(points, 1e18))) +
                   " supporting points (one search each; at most " +
                   std::to_string(static_cast<long>(kMaxSupportingPoints)) + "): use a larger spacing");
    if (w["tolerance"])
        d.tolerance = r.positive(w["tolerance"], g + ".tolerance");
    if (w["coarse_grid_size"])
        d.coarseGridSize = r.positive(w["coarse_grid_size"], g + ".coarse_grid_size");
    if (w["coarse_sectors"])
        d.coarseSectors =
            static_cast<int>(r.integer(w["coarse_sectors"], g + ".coarse_sectors", kMinSectors, kMaxSectors));
    readThreads(r, w, g, d.threads);
}

void readGoalWindow(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string g = "goal.window";
    r.checkMap(n, g, {"begin", "end"});
    if (!n["begin"] || !n["end"])
        r.fail(n, g, std::string("begin and end are required (missing ") + (n["begin"] ? "end" : "begin") + ")");
    GoalWindowSpec &w = m.goalWindow;
    w.set = true;
    w.begin = r.time(n["begin"], g + ".begin", m);
    w.end = r.time(n["end"], g + ".end", m);
    if (!(w.end >= w.begin))
        r.fail(n["end"], g + ".end", "must not be before begin");
    // (a window out of reach of the departure and the planning horizon is refused by runMission())
}
} // namespace ompl_glider::mission_loader
