/// @file NoPathReason.cpp
/// @brief Why a search ended without a path, in words for the user: the setup's own check, the outcome of the
/// lattice, wavefront and level-set planners, or OMPL's status; and what bounds the arrival of an exhausted search.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../io/NumberText.h"
#include "PlanningInternal.h"
#include "ompl_glider/planners/IsochronePlanner.h"
#include "ompl_glider/planners/Wavefront.h"
#include "ompl_glider/planners/ZAStarTVE.h"
#include "ompl_glider/reachability/LevelSetPlanner.h"

namespace ompl_glider
{
namespace planning_detail
{
std::string noPathReason(const ompl::base::PlannerStatus &status, const ompl::base::Planner &planner,
                         const GliderSimpleSetup *setup, double timeLimit)
{
    if (setup && !setup->lastCheckMessage().empty())
        return setup->lastCheckMessage();
    if (const auto *z = dynamic_cast<const ZAStarTVE *>(&planner))
    {
        const TveResult &r = z->lastResult();
        switch (r.outcome)
        {
            case TveOutcome::InvalidStart:
                return "invalid start: " + r.message;
            case TveOutcome::InvalidGoal:
                return "invalid goal: " + r.message;
            case TveOutcome::Exhausted:
                return "no path exists on this lattice (" + std::to_string(r.expansions) +
                       " vertices expanded; a finer grid, more sectors or a higher speed may find one)";
            case TveOutcome::Terminated:
                return "the time limit (" + text::number(timeLimit) + " s) ended the search: raise it";
            default:
                break;
        }
    }
    if (const auto *l = dynamic_cast<const LevelSetPlanner *>(&planner);
        l && status == ompl::base::PlannerStatus::ABORT)
        return l->lastReachability().goalReached ? l->lastReason()
               : l->lastReachability().goalWalledOff
                   ? "the reachable front never reaches the goal: no water links it to the start (land or forbidden "
                     "regions wall it in; a flood fill of the level set's grid, before any step)"
                   :
                   "the reachable front never reaches the goal within the time window (the current carries the "
                   "glider off faster than it makes way, or land, forbidden regions or a closure wall it in)";
    if (const auto *iso = dynamic_cast<const IsochronePlanner *>(&planner);
        iso && status == ompl::base::PlannerStatus::ABORT && !iso->lastReason().empty())
        return iso->lastReason();
    if (const auto *w = dynamic_cast<const Wavefront *>(&planner))
    {
        switch (w->lastOutcome())
        {
            case WavefrontOutcome::InvalidStart:
                return "invalid start: " + w->lastMessage();
            case WavefrontOutcome::InvalidGoal:
                return "invalid goal: " + w->lastMessage();
            case WavefrontOutcome::Exhausted:
                return "no path exists on this lattice: " + w->lastMessage();
            case WavefrontOutcome::BadWindow:
                return w->lastMessage();
            case WavefrontOutcome::Terminated:
                return "the time limit (" + text::number(timeLimit) + " s) ended the search: raise it";
            default:
                break;
        }
    }
    if (status == ompl::base::PlannerStatus::APPROXIMATE_SOLUTION)
        return "the planner reached only an approximate solution within the time limit";
    if (status == ompl::base::PlannerStatus::TIMEOUT)
        return "the time limit (" + text::number(timeLimit) + " s) ended the search before a path was found: raise it "
               "(planner.time_limit, --time-limit) or shorten the planning horizon (planner.horizon)";
    return std::string("planner status: ") + status.asString();
}

/// What bounds the arrival of an exhausted search: the end of the forecast or the planning horizon.
std::string horizonNote(const MissionProblem &problem, const GliderProblem &gp)
{
    // in the mission's own units: days and hours where it has a time unit, else the field's number
    const MissionSpec &m = problem.getSpec();
    const std::string span = m.physicalUnits().time ? text::durationText(gp.horizon * m.timeUnitSeconds) :
                                                      text::number(gp.horizon, 6) + " time units";
    const double fieldEnd = problem.getField()->timeEnd();
    if (std::isfinite(fieldEnd) && gp.t0 + gp.horizon >= fieldEnd - 1e-9 * std::max(1.0, std::abs(fieldEnd)))
        return std::string("; the path must arrive before the forecast ends, ") + span +
               " after departure: depart earlier, or hold the last forecast time past its end (current.horizon: hold_last, --beyond hold)";
    return std::string("; the path must arrive within the planning horizon, ") + span +
           " after departure (planner.horizon)";
}
}  // namespace planning_detail
}  // namespace ompl_glider
