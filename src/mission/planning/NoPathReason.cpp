/// @file NoPathReason.cpp
/// @brief Why a search ended without a path, in words for the user: the setup's own check, the planner's own words
/// (PipelinePlanner::noPathReason()), or OMPL's status; and what bounds the arrival of an exhausted search.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../../io/NumberText.h"
#include "PlanningInternal.h"
#include "ompl_glider/ompl/PipelinePlanner.h"

namespace ompl_glider
{
namespace planning_detail
{
NoPath noPathReason(const ompl::base::PlannerStatus &status, const ompl::base::Planner &planner,
                    const GliderSimpleSetup &setup, double timeLimit, const MissionSpec &m)
{
    if (!setup.lastCheckMessage().empty())
        return {NoPathCause::BadInput, setup.lastCheckMessage()};
    if (NoPath own = pipelineView(planner).noPathReason(status, timeLimit); own.cause != NoPathCause::None)
        return own;
    if (status == ompl::base::PlannerStatus::APPROXIMATE_SOLUTION)
        return {NoPathCause::Approximate, "the planner reached only an approximate solution within the time limit"};
    if (status == ompl::base::PlannerStatus::TIMEOUT)
    {
        NoPath n{NoPathCause::TimeLimit, "the time limit (" + text::number(timeLimit) +
                                             " s) ended the search before "
                                             "a path was found: raise it (" +
                                             m.term("planner.time_limit") + ") or shorten the planning horizon (" +
                                             m.term("planner.horizon") + ")"};
        n.timeLimit = timeLimit;
        return n;
    }
    const bool bad =
        status == ompl::base::PlannerStatus::INVALID_START || status == ompl::base::PlannerStatus::INVALID_GOAL;
    return {bad ? NoPathCause::BadInput : NoPathCause::Other, std::string("planner status: ") + status.asString()};
}

/// What bounds the arrival of an exhausted search: the end of the forecast or the planning horizon.
void boundArrival(const MissionProblem &problem, const GliderProblem &gp, NoPath &n)
{
    // in the mission's own units: days and hours where it has a time unit, else the field's number
    const MissionSpec &m = problem.getSpec();
    const std::string span = m.physicalUnits().time ? text::durationText(gp.horizon * m.timeUnitSeconds)
                                                    : text::number(gp.horizon, 6) + " time units";
    const double fieldEnd = problem.getField()->timeEnd();
    n.boundSpan = gp.horizon;
    if (std::isfinite(fieldEnd) && gp.t0 + gp.horizon >= fieldEnd - 1e-9 * std::max(1.0, std::abs(fieldEnd)))
    {
        n.bound = ArrivalBound::ForecastEnd;
        n.boundText = "; the path must arrive before the forecast ends, " + span +
                      " after departure: depart earlier, or hold the last forecast time past its end (" +
                      m.term("current.horizon: hold_last") + ")";
        return;
    }
    n.bound = ArrivalBound::PlanningHorizon;
    n.boundText = "; the path must arrive within the planning horizon, " + span + " after departure (" +
                  m.term("planner.horizon") + ")";
}
} // namespace planning_detail
} // namespace ompl_glider
