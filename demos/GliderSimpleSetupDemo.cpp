// ZA*TVE as a drop-in ompl::base::Planner: an application builds its SimpleSetup (here the library's
// makeSimpleSetup() on the Gulf Stream problem: TimeSE2StateSpace, travel-time motion validator and objective),
// sets the planner and calls solve() as with any OMPL planner. Swapping in RRT* is one line (--rrtstar).
//
// Usage: demo_simple_setup [--rrtstar]        exit 0 when ZA*TVE found an exact solution (RRT*: any solution)
#include <iostream>
#include <memory>
#include <string>

#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>

#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/planners/ZAStarTVE.h"

int main(int argc, char **argv)
{
    const bool rrtStar = argc > 1 && std::string(argv[1]) == "--rrtstar";
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);

    // The problem: the meandering jet, x in [0, 10], y in [-4, 4], V = 0.5, from (1, -3) to (8, 3) at t = 0.
    const ompl_glider::GliderProblem problem = ompl_glider::gulfStreamProblem();
    std::shared_ptr<ompl_glider::GliderContext> ctx;
    ompl::geometric::SimpleSetupPtr ss = ompl_glider::makeSimpleSetup(problem, &ctx);

    // The planner: ZA*TVE on a 0.4 lattice, set by its OMPL parameters ...
    auto planner = std::make_shared<ompl_glider::ZAStarTVE>(ss->getSpaceInformation(), ctx, "ZA*TVE");
    planner->params().setParam("grid_size", "0.4");
    ss->setPlanner(planner);
    // ... or RRT* instead, the one line an application changes:
    if (rrtStar)
        ss->setPlanner(std::make_shared<ompl::geometric::RRTstar>(ss->getSpaceInformation()));

    // ZA*TVE runs to its end; RRT* uses all the time it is given (and may end with an approximate solution)
    const ompl::base::PlannerStatus status = ss->solve(rrtStar ? 2.0 : 60.0);
    const bool accepted = status == ompl::base::PlannerStatus::EXACT_SOLUTION ||
                          (rrtStar && status == ompl::base::PlannerStatus::APPROXIMATE_SOLUTION);
    if (!accepted)
    {
        std::cout << ss->getPlanner()->getName() << ": " << status.asString() << "\n";
        return 1;
    }
    ompl::geometric::PathGeometric &path = ss->getSolutionPath();
    const auto *last = path.getStates().back()->as<ompl_glider::TimeSE2StateSpace::StateType>();
    std::cout << ss->getPlanner()->getName() << ": " << status.asString() << ", " << path.getStateCount()
              << " states, travel time " << last->getTime() - problem.t0 << "\n";
    return 0;
}
