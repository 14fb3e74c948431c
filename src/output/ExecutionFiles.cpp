#include "ompl_glider/output/ExecutionFiles.h"
#include "ompl_glider/output/RouteFiles.h"
#include "../io/NumberText.h"

#include <cmath>
#include <cstdio>

namespace ompl_glider
{
namespace
{
std::string csvCell(double v)
{
    return std::isfinite(v) ? text::number(v, 10) : "";
}

/// A text cell: the CSV's separators and quotes made ';' (a reason is one cell).
std::string reasonCell(std::string s)
{
    for (char &c : s)
        if (c == ',' || c == '\n' || c == '"')
            c = ';';
    return s;
}

/// "x,y,lon,lat" of a point (lon/lat empty without a projection).
std::string csvPoint(const MissionProblem &problem, Point2 p)
{
    std::string s = csvCell(p.x) + "," + csvCell(p.y) + ",";
    if (problem.isGeographic())
    {
        const LonLat g = problem.toGeographic(p);
        s += csvCell(g.lon) + "," + csvCell(g.lat);
    }
    else
        s += ",";
    return s;
}

/// Heading in degrees clockwise from north (+y) of a heading angle from +x counter-clockwise (radians).
double compassDegrees(double angle)
{
    double d = 90.0 - angle * 180.0 / M_PI;
    d = std::fmod(d, 360.0);
    return d < 0.0 ? d + 360.0 : d;
}
} // namespace

std::string executionCsv(const ExecutionResult &e, const MissionProblem &problem)
{
    std::string s =
        "run,strategy,start_x,start_y,start_lon,start_lat,goal_x,goal_y,goal_lon,goal_lat,departure,"
        "planned_arrival,distance_at_planned_arrival,arrival_time,arrival_iso,reached,grounded,made_good_speed,"
        "surfacings,replans,radius,why_not_reached,stations_reached,windows_missed,oracle_arrival\n";
    for (const ExecutionRun &run : e.runs)
    {
        const std::string head = std::to_string(run.index) + ",";
        const std::string ends =
            csvPoint(problem, run.start) + "," + csvPoint(problem, run.goal) + "," + csvCell(run.departure) + ",";
        // the oracle's arrival (empty without an oracle, or where it did not reach), the same on each strategy's row
        const std::string oracle = "," + csvCell(run.oracleArrival) + "\n";
        if (!run.planned)
        {
            s +=
                head + "none," + ends + ",,,,,,,,," + csvCell(run.radius) + "," +
                reasonCell("not flown: " + (run.reason.empty() ? std::string("no plan on the forecast") : run.reason)) +
                ",," + oracle;
            continue;
        }
        for (std::size_t k = 0; k < e.strategies.size(); ++k)
        {
            const FlownTrack &f = run.flown[k];
            s += head + controlStrategyName(e.strategies[k]) + "," + ends + csvCell(f.plannedArrival) + "," +
                 csvCell(f.finalDistance) + "," + csvCell(f.arrivalTime) + "," +
                 (std::isfinite(f.arrivalTime) ? problem.isoTime(f.arrivalTime) : std::string()) + "," +
                 (f.reached ? "1" : "0") + "," + (f.grounded ? "1" : "0") + "," + csvCell(f.madeGoodSpeed) + "," +
                 std::to_string(f.fixes.empty() ? 0 : f.fixes.size() - 1) + "," + std::to_string(f.replans) + "," +
                 csvCell(run.radius) + "," + reasonCell(f.notReachedWhy) + "," +
                 (e.stops.empty() ? std::string(",")
                                  : std::to_string(f.stationsReached) + "," + std::to_string(f.windowsMissed)) +
                 oracle;
        }
    }
    return s;
}

std::string executionTracksCsv(const ExecutionResult &e, const MissionProblem &problem)
{
    // the glider's heading from true north where the problem has lon/lat (the frame's grid north turned there)
    std::string s = std::string("strategy,index,time,time_iso,x,y,lon,lat,") +
                    (problem.isGeographic() ? "heading_true_deg" : "heading_deg") + "\n";
    const ExecutionRun &run = e.runs.front();
    if (!run.planned)
        return s;
    for (std::size_t i = 0; i < run.plan.size(); ++i)
        s += "plan," + std::to_string(i) + "," + csvCell(run.plan[i].t) + "," + problem.isoTime(run.plan[i].t) + "," +
             csvPoint(problem, {run.plan[i].x, run.plan[i].y}) + ",\n";
    for (std::size_t k = 0; k < e.strategies.size(); ++k)
    {
        const FlownTrack &f = run.flown[k];
        for (std::size_t i = 0; i < f.fixes.size(); ++i)
            s += controlStrategyName(e.strategies[k]) + "," + std::to_string(i) + "," + csvCell(f.fixes[i].t) + "," +
                 problem.isoTime(f.fixes[i].t) + "," + csvPoint(problem, {f.fixes[i].x, f.fixes[i].y}) + "," +
                 (i < f.headings.size()
                      ? csvCell(trueBearing(problem, {f.fixes[i].x, f.fixes[i].y}, compassDegrees(f.headings[i])))
                      : std::string()) +
                 "\n";
    }
    return s;
}
} // namespace ompl_glider
