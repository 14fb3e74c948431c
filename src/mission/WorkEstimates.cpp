/// @file WorkEstimates.cpp
/// @brief Work estimates made before the work (PlanningInternal.h): a planner or post-processing step whose cost a
/// parameter controls is refused up front, naming the field or flag with the estimate and the limit, as the lattice
/// is refused by its vertex count and memory (checkLatticeSize()). Level set: grid nodes x time steps over the
/// planning window; Wavefront: lattice vertices x time intervals (its space-time nodes); stints: bearings per
/// expansion x expansions; execution: surfacings per flight and in all; isochrones: their count.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "PlanningInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/ResourceLimits.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/planners/Wavefront.h"
#include "ompl_glider/reachability/LevelSetPlanner.h"
#include "ompl_glider/stints/StintPlanner.h"

namespace ompl_glider
{
namespace planning_detail
{
namespace
{
std::string format(const char *fmt, double a, double b = 0.0, double c = 0.0, double d = 0.0, double e = 0.0)
{
    char text[320];
    std::snprintf(text, sizeof text, fmt, a, b, c, d, e);
    return text;
}

/// Where the mission gave the first of @p parameters, else planner.horizon when given, else planner.name.
std::string workPlace(const MissionSpec &m, std::initializer_list<const char *> parameters, bool horizonFirst)
{
    if (horizonFirst && m.marks.count("planner.horizon"))
        return m.place("planner.horizon");
    for (const char *p : parameters)
        if (m.planner.parameters.count(p))
            return parameterPlace(m, p);
    if (m.marks.count("planner.horizon"))
        return m.place("planner.horizon");
    return m.place("planner.name");
}

void checkLevelSet(const MissionSpec &m, const GliderContext &ctx, const LevelSetPlanner &ls, double departure)
{
    const Region &r = ctx.region;
    const double h = ls.getResolution() > 0.0 ? ls.getResolution() : defaultLevelSetResolution(ctx);
    const double nodes = (std::floor((r.xMax - r.xMin) / h + 1e-9) + 1.0) * (std::floor((r.yMax - r.yMin) / h + 1e-9) + 1.0);
    const double dt = ls.getCfl() * h / (ctx.speed() + std::max(ctx.maxCurrent(), 0.0));
    const double tEnd = std::min(r.tMax, ctx.field->timeEnd());
    const double steps = std::isfinite(tEnd) ? std::ceil(std::max(tEnd - departure, 0.0) / dt) : kInf;
    const double work = nodes * steps;
    if (steps <= kMaxLevelSetSteps && work <= kMaxLevelSetWork)
        return;
    const bool horizonFirst = !(steps <= kMaxLevelSetSteps);
    throw Error(workPlace(m, {"resolution", "cfl"}, horizonFirst) +
                format(": the level set would take up to %.3g time steps of %.3g over the planning window of %.4g, on "
                       "%.4g grid nodes (%.3g node updates)",
                       steps, dt, tEnd - departure, nodes, work) +
                format(", more than the limit of %.3g steps and %.3g node updates: use a coarser resolution, a larger "
                       "cfl or a shorter planner.horizon",
                       kMaxLevelSetSteps, kMaxLevelSetWork));
}

void checkWavefront(const MissionProblem &problem, const GliderContext &ctx, const Wavefront &w, double departure)
{
    const MissionSpec &m = problem.getSpec();
    const Point2 start = problem.getStart(), goal = problem.getGoal();
    const Region &r = ctx.region;
    const double grid = w.getGridSize();
    const double vertices =
        (std::floor((r.xMax - r.xMin) / grid + 1e-9) + 1.0) * (std::floor((r.yMax - r.yMin) / grid + 1e-9) + 1.0);
    const double tEnd = std::min(r.tMax, ctx.arriveNotAfter);
    const double intervals = std::floor(std::max(tEnd - departure, 0.0) / w.effectiveTimeStep()) + 1.0;
    // the search ends no earlier than the fastest conceivable arrival: every vertex reachable by then holds into
    // each interval up to it
    const double fastest = std::hypot(goal.x - start.x, goal.y - start.y) /
                           (ctx.speed() + std::max(ctx.maxCurrent(), 0.0));
    const double least = vertices * std::min(intervals, std::max(1.0, fastest / w.effectiveTimeStep()));
    if (least <= kMaxWavefrontNodes)
        return;
    throw Error((m.planner.parameters.count("time_step") ? parameterPlace(m, "time_step")
                                                         : m.place("planner.grid_size")) +
                format(": the Wavefront search settles %.3g lattice vertices in each of its time intervals of %g (at "
                       "least %.3g space-time nodes before the fastest conceivable arrival, %.3g in the window)",
                       vertices, w.effectiveTimeStep(), least, vertices * intervals) +
                format(", more than the limit of %.3g: use a larger planner.grid_size or time_step", kMaxWavefrontNodes));
}

void checkStints(const MissionSpec &m, const StintPlanner &st)
{
    if (st.getMethod() != StintMethod::CtsAStar && st.getMethod() != StintMethod::InitOptim)
        return;  // only CTS-A* flies a rose of bearings
    const double rose = std::max(1.0, std::round(360.0 / m.stints.bearingStep));
    const double expansions = static_cast<double>(st.getMaxExpansions());
    const double flights = rose * expansions;
    if (rose <= kMaxStintBearings && flights <= kMaxStintFlights)
        return;
    const bool byExpansions = rose <= kMaxStintBearings && m.planner.parameters.count("max_expansions");
    throw Error((byExpansions ? parameterPlace(m, "max_expansions") : m.place("stints.bearing_step")) +
                format(": a bearing step of %g degrees flies %.4g stints from every surfacing the search expands, "
                       "up to %.3g stints over its %.3g expansions",
                       m.stints.bearingStep, rose, flights, expansions) +
                format(", more than the limit of %.4g bearings and %.3g stints: use a bearing step of at least %g "
                       "degrees (or fewer max_expansions)",
                       kMaxStintBearings, kMaxStintFlights, 360.0 / kMaxStintBearings));
}
}  // namespace

void checkPlannerWork(const MissionProblem &problem, const GliderContext &ctx, const ompl::base::Planner &planner,
                      double departure)
{
    const MissionSpec &m = problem.getSpec();
    if (const auto *ls = dynamic_cast<const LevelSetPlanner *>(&planner))
        checkLevelSet(m, ctx, *ls, departure);
    else if (const auto *w = dynamic_cast<const Wavefront *>(&planner))
        checkWavefront(problem, ctx, *w, departure);
    else if (const auto *st = dynamic_cast<const StintPlanner *>(&planner))
        checkStints(m, *st);
}

void checkExecutionWork(const MissionSpec &m, double interval, double window, std::size_t runs,
                        std::size_t strategies)
{
    const double perFlight = std::ceil(window / interval);
    const double total = perFlight * static_cast<double>(runs) * static_cast<double>(strategies);
    if (perFlight <= kMaxSurfacingsPerFlight && total <= kMaxSurfacings)
        return;
    throw Error(m.place("execution.surfacing_interval") +
                format(": a surfacing interval of %g gives up to %.3g surfacings per flight over %.4g", interval,
                       perFlight, window) +
                format(" (%.3g in all: %.0f runs x %.0f strategies)", total, static_cast<double>(runs),
                       static_cast<double>(strategies)) +
                format(", more than the limit of %.3g per flight and %.3g in all: use a longer surfacing interval, "
                       "fewer batch pairs or a shorter execution.duration",
                       kMaxSurfacingsPerFlight, kMaxSurfacings));
}
}  // namespace planning_detail
}  // namespace ompl_glider
