// An ompl::tools::Benchmark of ZA*TVE against OMPL's RRT* and PRM (geometric, on the time-augmented space) and the
// control planners RRT, SST and KPIECE1 (heading controls flown by the dive integrator) on a crossing of the
// meandering jet past a drifting ice zone. Writes two OMPL benchmark logs; ompl_benchmark_statistics turns them into
// the database Planner Arena (plannerarena.org) reads:
//   demo_benchmark OUTDIR [seconds per run = 1] [runs = 5]
//   ompl_benchmark_statistics OUTDIR/ice_geometric.log OUTDIR/ice_control.log -d ice.db
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include <ompl/control/planners/kpiece/KPIECE1.h>
#include <ompl/control/planners/rrt/RRT.h>
#include <ompl/control/planners/sst/SST.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>

#include "ompl_glider/execution/GliderControl.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/planners/ZAStarTVE.h"

namespace
{
// The problem as a mission (examples/MISSION_FORMAT.md): the library builds the field, the ice zone and the box.
const char *kMission = R"(
name: ice_crossing
current: {type: meandering_jet}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: -3}
goal: {x: 8, y: 3}
vehicle: {speed: 0.5}
forbidden:
  ice:
    - name: drifting floe
      points: [[3.0, -2.0], [5.0, -2.0], [5.0, 0.5], [3.0, 0.5]]
      t_ref: 0.0
      drift: [0.05, -0.02]
      max_submerged_time: 0.5
)";
} // namespace

int main(int argc, char **argv)
{
    if (argc < 2)
    {
        std::cerr << "usage: demo_benchmark OUTDIR [seconds per run] [runs]\n";
        return 2;
    }
    const std::string out = argv[1];
    const double seconds = argc > 2 ? std::atof(argv[2]) : 1.0;
    const unsigned runs = argc > 3 ? static_cast<unsigned>(std::atoi(argv[3])) : 5u;
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);

    const ompl_glider::MissionProblem mission(ompl_glider::parseMission(kMission, "ice_crossing"));
    const ompl_glider::GliderProblem problem = mission.gliderProblem(0.0, mission.getSpec().vehicle.speed);
    const ompl::tools::Benchmark::Request request(seconds, 4096.0, runs, 0.1, false, false, false);

    // Geometric planners on one SimpleSetup: ZA*TVE is an ompl::base::Planner like the others.
    std::shared_ptr<ompl_glider::GliderContext> ctx;
    ompl::geometric::SimpleSetupPtr ss = ompl_glider::makeSimpleSetup(problem, &ctx);
    ompl::tools::Benchmark geometric(*ss, "ice_geometric");
    auto zastar = std::make_shared<ompl_glider::ZAStarTVE>(ss->getSpaceInformation(), ctx, "ZA*TVE");
    zastar->params().setParam("grid_size", "0.5");
    geometric.addPlanner(zastar);
    geometric.addPlanner(std::make_shared<ompl::geometric::RRTstar>(ss->getSpaceInformation()));
    geometric.addPlanner(std::make_shared<ompl::geometric::PRM>(ss->getSpaceInformation()));
    geometric.benchmark(request);
    geometric.saveResultsToFile((out + "/ice_geometric.log").c_str());

    // Control planners on the heading-control setup of the same problem.
    const auto cs = ompl_glider::makeControlSetup(problem);
    ompl::tools::Benchmark control(*cs, "ice_control");
    const auto si = cs->getSpaceInformation();
    control.addPlanner(std::make_shared<ompl::control::RRT>(si));
    control.addPlanner(std::make_shared<ompl::control::SST>(si));
    control.addPlanner(std::make_shared<ompl::control::KPIECE1>(si));
    control.benchmark(request);
    control.saveResultsToFile((out + "/ice_control.log").c_str());

    std::cout << "wrote " << out << "/ice_geometric.log and " << out << "/ice_control.log\n";
    return 0;
}
