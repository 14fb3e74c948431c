/// @file WorkEstimates.cpp
/// @brief Work estimates of the pipeline's own steps made before the work (PlanningInternal.h): a step whose cost a
/// field controls is refused up front, naming the field or flag with the estimate and the limit, as each planner
/// refuses its own (PipelinePlanner::prepare(), reachWork()). Execution: surfacings per flight and in all (the
/// isochrones' count is checked where they are made: Isochrones.cpp, ReachProbability.cpp).

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../../io/NumberText.h"
#include "PlanningInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/ResourceLimits.h"
#include "ompl_glider/mission/MissionProblem.h"

namespace ompl_glider
{
namespace planning_detail
{
void checkExecutionWork(const MissionSpec &m, double interval, double window, std::size_t runs, std::size_t strategies)
{
    const double perFlight = std::ceil(window / interval);
    const double total = perFlight * static_cast<double>(runs) * static_cast<double>(strategies);
    if (perFlight <= kMaxSurfacingsPerFlight && total <= kMaxSurfacings)
        return;
    throw Error(
        m.place("execution.surfacing_interval") +
        text::formatted(": a surfacing interval of %g gives up to %.3g surfacings per flight over %.4g", interval,
                        perFlight, window) +
        text::formatted(" (%.3g in all: %.0f runs x %.0f strategies)", total, static_cast<double>(runs),
                        static_cast<double>(strategies)) +
        text::formatted(", more than the limit of %.3g per flight and %.3g in all: use a longer surfacing interval, "
                        "fewer batch pairs or a shorter execution.duration",
                        kMaxSurfacingsPerFlight, kMaxSurfacings));
}
} // namespace planning_detail
} // namespace ompl_glider
