// runPlan (the library behind glider_plan): the Gulf Stream plan with and without post-processing, the outputs'
// contents, no-path outcomes and bad requests.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/PlanRun.h"
#include "ompl_glider/planners/PathSmoother.h"

using namespace ompl_glider;

TEST(PlanRun, GulfStreamWithAndWithoutPostprocessing)
{
    PlanRequest req;
    req.problem = gulfStreamProblem();
    req.smooth = false;
    req.refine = false;
    const PlanRunResult plain = runPlan(req);
    ASSERT_TRUE(plain.feasible);
    EXPECT_EQ(plain.smoothed.size(), plain.raw.size());
    EXPECT_EQ(plain.path.size(), plain.raw.size());
    EXPECT_EQ(plain.travelTime, plain.travelTimeRaw);
    EXPECT_GT(plain.costFunctionCalls, 0u);
    EXPECT_GT(plain.currentModelCalls, 0u);
    EXPECT_EQ(plain.postprocessCostFunctionCalls, 0u);
    EXPECT_TRUE(plain.pathChecked);

    req.smooth = true;
    req.refine = true;
    req.optimum = true;
    const PlanRunResult full = runPlan(req);
    ASSERT_TRUE(full.feasible);
    EXPECT_EQ(full.travelTimeRaw, plain.travelTimeRaw);  // same search
    EXPECT_LE(full.smoothed.size(), full.raw.size());
    // "never later" up to the smoother's documented tie tolerance (1e-12 relative)
    EXPECT_LE(full.travelTimeSmoothed, full.travelTimeRaw * (1.0 + 1e-12));
    EXPECT_LE(full.travelTime, full.travelTimeSmoothed);
    EXPECT_TRUE(full.pathChecked);
    EXPECT_NEAR(full.pathLength, pathLength(full.path), 1e-12);
    EXPECT_EQ(full.path.front().x, 1.0);
    EXPECT_EQ(full.path.back().y, 3.0);
    ASSERT_TRUE(std::isfinite(full.optimumTime));
    EXPECT_LE(full.travelTime, 1.01 * full.optimumTime);
    EXPECT_GE(full.travelTime, 0.997 * full.optimumTime);

    const std::string json = planSummaryJson(req, full);
    for (const char *k : {"\"travel_time\": ", "\"path_length\": ", "\"waypoints_raw\": ", "\"waypoints_smoothed\": ",
                          "\"cost_function_calls\": ", "\"current_model_calls\": ", "\"planning_time_s\": ",
                          "\"feasible\": true", "\"optimal_control_time\": "})
        EXPECT_NE(json.find(k), std::string::npos) << k;
    const std::string csv = planPathCsv(full);
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "t,x,y");
    std::size_t rows = 0;
    while (std::getline(in, line))
        ++rows;
    EXPECT_EQ(rows, full.path.size());

    std::ostringstream report;
    printPlanReport(report, req, full);
    EXPECT_NE(report.str().find("Travel time"), std::string::npos);
    EXPECT_NE(report.str().find("CMC"), std::string::npos);
}

TEST(PlanRun, NoPathIsAnOutcome)
{
    // Horizon too short to reach the goal: the lattice search exhausts (arrivals after the window are invalid).
    PlanRequest req;
    req.problem = gulfStreamProblem();
    req.problem.horizon = 2.0;
    const PlanRunResult r = runPlan(req);
    EXPECT_FALSE(r.feasible);
    EXPECT_FALSE(std::isfinite(r.travelTime));
    const std::string json = planSummaryJson(req, r);
    EXPECT_NE(json.find("\"feasible\": false"), std::string::npos);
    EXPECT_NE(json.find("\"travel_time\": null"), std::string::npos);
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("ompl_glider_planrun_" + std::to_string(::getpid()));
    const auto files = writePlanOutputs(req, r, dir.string());
    ASSERT_EQ(files.size(), 4u);
    for (const auto &f : files)
        EXPECT_GT(std::filesystem::file_size(f), 0u) << f;
    std::filesystem::remove_all(dir);
}

TEST(PlanRun, BadRequests)
{
    PlanRequest req;
    req.problem = gulfStreamProblem();
    req.planner = "Dijkstra";
    EXPECT_THROW(runPlan(req), Error);
    req.planner = "ZA*TVE";
    req.problem.goalX = 42.0;
    EXPECT_THROW(runPlan(req), Error);
    req.problem = gulfStreamProblem();
    EXPECT_THROW(writePlanOutputs(req, PlanRunResult{}, "/proc/ompl_glider_cannot_write_here"), Error);
}
