// The one planning pipeline (mission/Planning.h) and the one output layer (output/OutputWriter.h): every way in
// gives the same answer, planner parameters by their OMPL names, no path as an outcome with its reason, and output
// directories that change all or nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <unistd.h>

#include <nlohmann/json.hpp>
#include <ompl/geometric/SimpleSetup.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/output/OutputWriter.h"
#include "ompl_glider/output/Report.h"
#include "ompl_glider/output/SlocumGoto.h"
#include "ompl_glider/output/SummaryJson.h"
#include "ompl_glider/routes/PathSmoother.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#include "ompl_glider/planners/Wavefront.h"
#include "ompl_glider/planners/ZAStarTVE.h"

using namespace ompl_glider;
namespace fs = std::filesystem;

namespace
{
/// The built-in Gulf Stream mission written as a mission file.
const std::string kGulfStreamYaml = R"(name: gulf_stream
current: {type: meandering_jet}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: -3}
goal: {x: 8, y: 3}
vehicle: {speed: 0.5}
planner:
  name: zastartve
  horizon: 60
  goal_tolerance: 0.001
)";

std::string errorOf(const std::string &yaml)
{
    try
    {
        const MissionProblem problem(parseMission(yaml, "m.yaml"));
        runMission(problem);
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

#define EXPECT_HAS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

/// A directory that does not exist yet, alone in a parent of its own (so that counting the parent's entries sees
/// only what the writer left there, not other processes' files in the shared temporary directory).
fs::path freshDirectory(const std::string &name)
{
    const fs::path parent = fs::path(::testing::TempDir()) / ("pipeline_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(parent);
    fs::create_directories(parent);
    return parent / "out";
}

/// Every file of a directory with its contents.
std::map<std::string, std::string> snapshot(const fs::path &dir)
{
    std::map<std::string, std::string> out;
    for (const auto &e : fs::directory_iterator(dir))
    {
        std::ifstream in(e.path(), std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        out[e.path().filename().string()] = s.str();
    }
    return out;
}

nlohmann::json readJson(const fs::path &p)
{
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}
} // namespace

TEST(Pipeline, GulfStreamStagesNeverArriveLaterAndApproachTheOptimum)
{
    const MissionProblem problem(defaultGulfStreamMission());
    PlanOptions plain;
    plain.smoothing = false;
    plain.refinement = false;
    const PlannedPath a = planRoute(problem, 0.0, plain);
    ASSERT_TRUE(a.solved) << a.reason;
    EXPECT_EQ(a.status, PlanStatus::ExactSolution);
    EXPECT_EQ(a.planner, "ZA*TVE");
    EXPECT_EQ(a.path.size(), a.raw.size());
    EXPECT_EQ(a.travelTime, a.rawTravelTime);
    EXPECT_EQ(a.postprocessCostFunctionCalls, 0u);
    EXPECT_GT(a.searchCostFunctionCalls, 0u);
    EXPECT_GT(a.currentModelCalls, a.searchCostFunctionCalls); // several current calls per leg
    EXPECT_TRUE(a.pathChecked);

    RunOptions o;
    o.optimum = true;
    const MissionResult r = runMission(problem, o);
    const PlannedPath &b = r.plan;
    ASSERT_TRUE(b.solved);
    EXPECT_EQ(b.rawTravelTime, a.rawTravelTime); // the same search
    EXPECT_EQ(b.searchCostFunctionCalls, a.searchCostFunctionCalls);
    EXPECT_LE(b.smoothed.size(), b.raw.size());
    EXPECT_LE(b.smoothedTravelTime, b.rawTravelTime * (1.0 + 1e-12));
    EXPECT_LE(b.travelTime, b.smoothedTravelTime);
    EXPECT_GT(b.postprocessCostFunctionCalls, 0u);
    EXPECT_NEAR(b.pathLength, pathLength(b.path), 1e-12);
    EXPECT_EQ(b.path.front().x, 1.0);
    EXPECT_EQ(b.path.back().y, 3.0);
    // The final times are the re-flown ones: the last waypoint's arrival is the travel time.
    EXPECT_EQ(r.waypoints.back().time, b.path.back().t);
    ASSERT_TRUE(r.optimum && r.optimum->found);
    EXPECT_LE(b.travelTime, 1.01 * r.optimum->travelTime);
    EXPECT_GE(b.travelTime, 0.999 * r.optimum->travelTime); // no path beats the optimum (integration tolerance)
    // The straight line crosses the jet against the current: impassable.
    EXPECT_FALSE(std::isfinite(b.straightLineTime));
    EXPECT_DOUBLE_EQ(b.straightLineLength, std::hypot(7.0, 6.0));

    std::ostringstream report;
    printReport(report, r);
    EXPECT_HAS(
        report.str(), "Travel time:        " + [&] {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.4f", b.travelTime);
            return std::string(buf);
        }());
    EXPECT_HAS(report.str(), "Optimal control:");
}

TEST(Pipeline, LibraryMissionFileAndOmplBenchmarkGiveIdenticalAnswers)
{
    // The library's built-in mission and the same problem as a mission file.
    const MissionProblem builtIn(defaultGulfStreamMission());
    const MissionProblem fromFile(parseMission(kGulfStreamYaml, "gulf.yaml"));
    const MissionResult a = runMission(builtIn), b = runMission(fromFile);
    ASSERT_TRUE(a.plan.solved);
    EXPECT_EQ(a.plan.status, b.plan.status);
    EXPECT_EQ(a.plan.travelTime, b.plan.travelTime); // bit-identical
    EXPECT_EQ(a.plan.rawTravelTime, b.plan.rawTravelTime);
    EXPECT_EQ(a.plan.searchCostFunctionCalls, b.plan.searchCostFunctionCalls);
    EXPECT_EQ(a.plan.postprocessCostFunctionCalls, b.plan.postprocessCostFunctionCalls);
    EXPECT_EQ(a.plan.currentModelCalls, b.plan.currentModelCalls);

    // ZAStarTVE as any OMPL application (or ompl::tools::Benchmark) runs it: smoothing and refinement are on by
    // default, so it returns the pipeline's final path.
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(gulfStreamProblem(), &ctx);
    auto planner = std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "ZA*TVE");
    ASSERT_TRUE(planner->getSmooth());
    ASSERT_TRUE(planner->getRefine());
    ss->setPlanner(planner);
    ASSERT_EQ(ss->solve(30.0), ompl::base::PlannerStatus::EXACT_SOLUTION);
    const auto path = waypointsFromPath(ss->getSolutionPath());
    // the same path, timed by the planner's integrator; the pipeline reports its accurate re-flight
    EXPECT_EQ(path.back().t - path.front().t, a.plan.plannerTravelTime);
    EXPECT_TRUE(a.plan.reflown);
    EXPECT_EQ(a.plan.reflightFallback, ReflightFallback::None); // the final path flies: no fallback, no note
    EXPECT_TRUE(a.plan.reflightNote.empty());
    EXPECT_NEAR(a.plan.travelTime, a.plan.plannerTravelTime, 1e-3 * a.plan.travelTime);
    EXPECT_EQ(path.size(), a.plan.path.size());
    EXPECT_EQ(planner->getCostFunctionCalls(), a.plan.searchCostFunctionCalls);
    EXPECT_EQ(planner->getPostprocessCostFunctionCalls(), a.plan.postprocessCostFunctionCalls);
}

TEST(Pipeline, RefinementIsOnByDefaultInMissionFiles)
{
    const MissionSpec on = parseMission(kGulfStreamYaml, "gulf.yaml");
    EXPECT_TRUE(on.planner.refinement);
    EXPECT_TRUE(on.planner.smoothing);
    const MissionSpec off = parseMission(kGulfStreamYaml + "  refinement: false\n", "gulf.yaml");
    EXPECT_FALSE(off.planner.refinement);
    const MissionResult a = runMission(MissionProblem(on)), b = runMission(MissionProblem(off));
    EXPECT_LT(a.plan.travelTime, b.plan.travelTime); // refinement gains on this crossing
    EXPECT_EQ(b.plan.path.size(), b.plan.smoothed.size());
}

TEST(Pipeline, DefaultLatticeSpacingScalesWithTheTripOnAnalyticFields)
{
    // The forecasts' rule with 0.4 in place of half a cell: 0.4 within 1/200..1/25 of the start-goal distance.
    auto gridOf = [](Point2 s, Point2 g, double given) {
        MissionSpec m = defaultGulfStreamMission();
        m.start.xy = s;
        m.goal.xy = g;
        m.planner.gridSize = given;
        return MissionProblem(m).getSpec().planner.gridSize;
    };
    EXPECT_DOUBLE_EQ(gridOf({1, 0}, {2, 0}, 0.0), 0.04);         // a 1-unit trip: 25 steps across, not 2.5
    EXPECT_DOUBLE_EQ(gridOf({0.5, -3.5}, {9.5, 3.5}, 0.0), 0.4); // 11.4 units: 0.4 is within the bounds
    EXPECT_DOUBLE_EQ(gridOf({1, -3}, {8, 2.9}, 0.0), 0.37);      // 9.16 units: at most 1/25 of them
    EXPECT_DOUBLE_EQ(gridOf({1, -3}, {8, 3}, 0.0), 0.4);         // the built-in trip keeps the paper's lattice
    EXPECT_DOUBLE_EQ(gridOf({1, 0}, {2, 0}, 0.25), 0.25);        // a size given is kept
    // a mission file without grid_size: the same rule, and the same 0.4 for the built-in trip from a file
    EXPECT_DOUBLE_EQ(MissionProblem(parseMission(kGulfStreamYaml, "gulf.yaml")).getSpec().planner.gridSize, 0.4);
    MissionSpec shortTrip = parseMission(kGulfStreamYaml, "gulf.yaml");
    shortTrip.goal.xy = {2.0, -3.0};
    const MissionProblem problem(shortTrip);
    EXPECT_DOUBLE_EQ(problem.getSpec().planner.gridSize, 0.04);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved);
    // the lattice resolves the trip: its path within 0.1 % of the final one (on 0.4 it was 7.6 % slower)
    const double raw = r.plan.raw.back().t - r.plan.raw.front().t;
    EXPECT_LT(raw, 1.001 * r.plan.travelTime);
}

TEST(Pipeline, PlannerParametersByTheirOmplNames)
{
    // certify_tolerance 0 makes the pruned search return the lattice optimum: TVE's travel time.
    const std::string lattice = "  smoothing: false\n  refinement: false\n";
    const MissionResult tve = runMission(MissionProblem(parseMission(
        std::string(kGulfStreamYaml).replace(kGulfStreamYaml.find("zastartve"), 9, "TVE") + lattice, "gulf.yaml")));
    std::string yaml = kGulfStreamYaml + lattice + "  parameters: {certify_tolerance: 0, delta_phi_max: 20}\n";
    const MissionResult exact = runMission(MissionProblem(parseMission(yaml, "gulf.yaml")));
    ASSERT_TRUE(tve.plan.solved && exact.plan.solved);
    EXPECT_NEAR(exact.plan.rawTravelTime, tve.plan.rawTravelTime, 1e-12 * tve.plan.rawTravelTime);
    EXPECT_LT(exact.plan.searchCostFunctionCalls, tve.plan.searchCostFunctionCalls);

    // Unknown names, values out of range and pipeline settings given as parameters: errors naming file:line.
    std::string msg = errorOf(kGulfStreamYaml + "  parameters: {delta_phi_max_deg: 20}\n");
    EXPECT_HAS(msg, "m.yaml:11"); // the line of the parameter
    EXPECT_HAS(msg, "planner.parameters.delta_phi_max_deg");
    EXPECT_HAS(msg, "delta_phi_max"); // the list of the planner's parameters
    msg = errorOf(kGulfStreamYaml + "  parameters: {zermelo_steps: 1e12}\n");
    EXPECT_HAS(msg, "planner.parameters.zermelo_steps");
    EXPECT_HAS(msg, "rejects");
    msg = errorOf(kGulfStreamYaml + "  parameters: {refiner_max_evaluations: 0.5}\n");
    EXPECT_HAS(msg, "refiner_max_evaluations");
    msg = errorOf(kGulfStreamYaml + "  parameters: {delta_phi_max: 400}\n"); // the planner's own check
    EXPECT_HAS(msg, "m.yaml:11");
    EXPECT_HAS(msg, "planner.parameters.delta_phi_max");
    EXPECT_HAS(msg, "0.1..180");                                           // its one range, declared and checked
    msg = errorOf(kGulfStreamYaml + "  parameters: {heuristic: maybe}\n"); // OMPL would read it as false
    EXPECT_HAS(msg, "planner.parameters.heuristic");
    EXPECT_HAS(msg, "true or false");
    msg = errorOf(kGulfStreamYaml + "  parameters: {grid_size: 0.2}\n");
    EXPECT_HAS(msg, "planner.grid_size");
    msg = errorOf(std::string(kGulfStreamYaml).replace(kGulfStreamYaml.find("zastartve"), 9, "RRTstar") +
                  "  parameters: {certify_tolerance: 0}\n");
    EXPECT_HAS(msg, "has no parameter 'certify_tolerance'");
    EXPECT_HAS(msg, "range"); // RRT*'s own parameters are listed
}

TEST(Pipeline, EveryRegisteredPlannerIsReachableByNameAndAlias)
{
    for (const char *alias : {"zastartve", "ZAStarTVE", "za*tve", "astartve", "RRT*", "prm*", "BIT*", "rrt#"})
        EXPECT_NE(findPlanner(alias), nullptr) << alias;
    EXPECT_EQ(findPlanner("zastartve")->name, "ZA*TVE");
    EXPECT_EQ(findPlanner("dijkstra"), nullptr);
    EXPECT_THROW(plannerEntry("dijkstra"), Error);
    // Every entry makes its planner on the Gulf Stream problem, under the registry's name, and a sampling planner
    // returns either an exact path from start to goal or no path with a reason.
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(gulfStreamProblem(), &ctx);
    for (const PlannerEntry &e : plannerRegistry())
    {
        const auto planner = e.make(ss->getSpaceInformation(), ctx);
        ASSERT_NE(planner, nullptr) << e.name;
        EXPECT_EQ(planner->getName(), e.name);
        EXPECT_EQ(e.lattice(), std::dynamic_pointer_cast<ZAStarTVE>(planner) != nullptr ||
                                   std::dynamic_pointer_cast<Wavefront>(planner) != nullptr)
            << e.name;
    }
    MissionSpec m = defaultGulfStreamMission();
    m.planner.name = "RRTConnect";
    m.planner.timeLimit = 0.5;
    const MissionResult r = runMission(MissionProblem(m));
    EXPECT_EQ(r.plan.planner, "RRTConnect");
    if (r.plan.solved)
    {
        EXPECT_EQ(r.plan.path.front().x, 1.0);
        EXPECT_NEAR(r.plan.path.back().x, 8.0, 1e-3);
        EXPECT_TRUE(std::isfinite(r.plan.travelTime));
    }
    else
        EXPECT_FALSE(r.plan.reason.empty());
}

TEST(Pipeline, NoPathIsAnOutcomeWithItsReason)
{
    MissionSpec m = defaultGulfStreamMission();
    m.planner.horizon = 2.0; // far too short to reach the goal: the lattice is exhausted
    const MissionResult r = runMission(MissionProblem(m));
    EXPECT_FALSE(r.plan.solved);
    EXPECT_FALSE(std::isfinite(r.plan.travelTime));
    EXPECT_HAS(r.plan.reason, "no path exists: the reachable front never reaches the goal"); // the level set proves it
    EXPECT_HAS(r.plan.reason, "within the planning horizon, 2 time units");                  // what bounded the search
    EXPECT_TRUE(r.waypoints.empty());
}

TEST(Registry, AnalyticCurrentKindsWithDefaultsAndErrors)
{
    for (const CurrentFieldKind &k : currentFieldKinds())
    {
        if (k.gridded())
        {
            EXPECT_THROW(makeAnalyticField(k.name), Error);
            continue;
        }
        const auto f = makeAnalyticField(k.name);
        ASSERT_NE(f, nullptr) << k.name;
        const Velocity c = f->velocity(0.3, 0.2, 0.0, 1.0);
        EXPECT_TRUE(std::isfinite(c.u) && std::isfinite(c.v)) << k.name;
    }
    const auto u = makeAnalyticField("uniform", {{"u", 0.25}, {"v", -0.5}});
    EXPECT_EQ(u->velocity(3.0, 4.0, 0.0, 5.0).u, 0.25);
    EXPECT_EQ(u->velocity(3.0, 4.0, 0.0, 5.0).v, -0.5);
    EXPECT_THROW(makeAnalyticField("uniform", {{"w", 1.0}}), Error);
    EXPECT_THROW(makeAnalyticField("vortex"), Error);
}

TEST(Output, SummaryHasOneSchemaAndNoDuplicateKeys)
{
    MissionSpec m = defaultGulfStreamMission();
    m.outputs.directory = freshDirectory("schema").string();
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    const auto files = writeOutputs(r, problem);
    const nlohmann::json s = readJson(fs::path(m.outputs.directory) / "summary.json");
    EXPECT_EQ(s["schema"], kSummarySchema);
    EXPECT_EQ(s["solved"], true);
    EXPECT_EQ(s["status"], "Exact solution");
    EXPECT_EQ(s["travel_time"].get<double>(), r.plan.travelTime);
    EXPECT_EQ(s["cost_function_calls"]["search"].get<std::uint64_t>(), r.plan.searchCostFunctionCalls);
    EXPECT_EQ(s["current_model_calls"].get<std::uint64_t>(), r.plan.currentModelCalls);
    EXPECT_TRUE(s["straight_line"]["travel_time"].is_null());
    EXPECT_EQ(s["straight_line"]["passable"], false);
    EXPECT_EQ(s["start"]["x"], 1.0);
    // Straight legs at V = 0.5: no heading route, no switch
    EXPECT_FALSE(r.plan.headingRoute());
    EXPECT_EQ(s["route_model"], "straight_legs");
    EXPECT_TRUE(s["headings"].is_null());
    EXPECT_TRUE(s["switched_from"].is_null());
    EXPECT_TRUE(s["switch_reason"].is_null());
    // One name per quantity: none of the old duplicates.
    for (const char *old : {"cfc", "cmc", "feasible", "waypoints_raw", "planning_time_s", "straight_line_travel_time"})
        EXPECT_FALSE(s.contains(old)) << old;
    // The JSON text itself has no key twice in any object (nlohmann would keep only the last).
    std::ifstream in(fs::path(m.outputs.directory) / "summary.json");
    std::vector<std::set<std::string>> open;
    bool duplicate = false;
    nlohmann::json::parser_callback_t cb = [&](int, nlohmann::json::parse_event_t event, nlohmann::json &parsed) {
        if (event == nlohmann::json::parse_event_t::object_start)
            open.emplace_back();
        else if (event == nlohmann::json::parse_event_t::object_end)
            open.pop_back();
        else if (event == nlohmann::json::parse_event_t::key)
            duplicate = duplicate || !open.back().insert(parsed.get<std::string>()).second;
        return true;
    };
    const nlohmann::json parsed = nlohmann::json::parse(in, cb);
    EXPECT_TRUE(parsed.is_object());
    EXPECT_FALSE(duplicate);
    // The summary lists exactly the files written.
    std::set<std::string> listed, written;
    for (const auto &f : s["files"])
        listed.insert(f.get<std::string>());
    for (const auto &f : files)
        written.insert(fs::path(f).filename().string());
    EXPECT_EQ(listed, written);
    EXPECT_EQ(written, (std::set<std::string>{"summary.json", "waypoints.csv", "path.csv", "path.geojson", "map.svg",
                                              "map.png", "map.html"}));
}

TEST(Output, NoPathRunRemovesTheEarlierRouteAndSaysWhy)
{
    MissionSpec m = defaultGulfStreamMission();
    m.outputs.directory = freshDirectory("nopath").string();
    {
        const MissionProblem problem(m);
        writeOutputs(runMission(problem), problem);
    }
    const fs::path dir(m.outputs.directory);
    ASSERT_TRUE(fs::exists(dir / "waypoints.csv"));
    std::ofstream(dir / "notes.txt") << "a pilot's own file\n";
    m.planner.horizon = 2.0;
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_FALSE(r.plan.solved);
    writeOutputs(r, problem);
    for (const char *route : {"waypoints.csv", "path.csv", "path.geojson"})
        EXPECT_FALSE(fs::exists(dir / route)) << route;
    EXPECT_TRUE(fs::exists(dir / "map.png"));
    EXPECT_TRUE(fs::exists(dir / "notes.txt")); // only files the earlier run listed are removed
    const nlohmann::json s = readJson(dir / "summary.json");
    EXPECT_EQ(s["solved"], false);
    EXPECT_NE(s["reason"].get<std::string>().find("no path exists: the reachable front"), std::string::npos);
    EXPECT_TRUE(s["travel_time"].is_null());
}

TEST(Output, AFailingWriteLeavesTheDirectoryAsItWas)
{
    MissionSpec m = defaultGulfStreamMission();
    m.outputs.directory = freshDirectory("atomic").string();
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    writeOutputs(r, problem);
    const fs::path dir(m.outputs.directory);
    const auto before = snapshot(dir);
    const auto parentBefore = snapshot(dir.parent_path()).size();

    MissionResult other = r;
    other.spec.name = "changed"; // every file would differ
    std::vector<OutputFile> files = outputFiles(other, problem);
    ASSERT_GE(files.size(), 3u);
    // The map fails half-way (as a full disk or a cairo error would), after other files were written.
    files.push_back({"map2.png", [](const std::string &path) {
                         std::ofstream(path) << "half";
                         throw Error("cannot write '" + path + "': disk full");
                     }});
    EXPECT_THROW(writeOutputFiles(dir.string(), files), Error);
    EXPECT_EQ(snapshot(dir), before);
    EXPECT_EQ(snapshot(dir.parent_path()).size(), parentBefore); // no temporary directory left behind

    // A directory that does not exist yet is not created by a failed write.
    const fs::path fresh = freshDirectory("atomic_new");
    EXPECT_THROW(writeOutputFiles(fresh.string(), files), Error);
    EXPECT_FALSE(fs::exists(fresh));
}

TEST(Output, PrefixAddsCopiesAndSummaryIsAlwaysThere)
{
    MissionSpec m = parseMission(kGulfStreamYaml + "outputs: {files: [csv], prefix: trip1}\n", "gulf.yaml");
    m.outputs.directory = freshDirectory("prefix").string();
    const MissionProblem problem(m);
    writeOutputs(runMission(problem), problem);
    const auto files = snapshot(m.outputs.directory);
    std::set<std::string> names;
    for (const auto &[name, text] : files)
        names.insert(name);
    EXPECT_EQ(names,
              (std::set<std::string>{"summary.json", "waypoints.csv", "trip1_summary.json", "trip1_waypoints.csv"}));
    EXPECT_EQ(files.at("waypoints.csv"), files.at("trip1_waypoints.csv"));
    // A prefix that would leave the directory is refused where it is read.
    for (const char *bad : {"../../x", "a/b", ".."})
    {
        try
        {
            parseMission(kGulfStreamYaml + "outputs: {prefix: \"" + bad + "\"}\n", "gulf.yaml");
            ADD_FAILURE() << bad << " accepted";
        }
        catch (const Error &e)
        {
            EXPECT_HAS(e.what(), "gulf.yaml:11");
            EXPECT_HAS(e.what(), "outputs.prefix");
        }
    }
}

TEST(Output, CheckOutputDirectoryBeforePlanning)
{
    const fs::path file = freshDirectory("not_a_dir");
    std::ofstream(file) << "x";
    EXPECT_THROW(checkOutputDirectory(file.string()), Error);
    EXPECT_THROW(checkOutputDirectory((file / "sub").string()), Error);
    EXPECT_NO_THROW(checkOutputDirectory(freshDirectory("fresh").string()));
    fs::remove(file);
}

namespace
{
/// Cells of a CSV text without quoting (the route files quote nothing), the header first.
std::vector<std::vector<std::string>> csvRows(const std::string &text)
{
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line))
    {
        std::vector<std::string> cells;
        std::size_t from = 0;
        for (std::size_t comma = line.find(','); comma != std::string::npos; comma = line.find(',', from))
        {
            cells.push_back(line.substr(from, comma - from));
            from = comma + 1;
        }
        cells.push_back(line.substr(from));
        rows.push_back(cells);
    }
    return rows;
}

std::string readText(const fs::path &p)
{
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}
} // namespace

TEST(Output, HeadingRouteFilesCarryTheHeadingsAndTheSwitch)
{
    // The Gulf Stream crossing at V = 0.2, a fifth of the jet's core speed: ZA*TVE finds no path of
    // straight legs, the pipeline switches to Isochrone, whose plan is a route of held headings. Geographic (50 km,
    // one day per unit) so that every file has lon/lat, ISO times and hours.
    MissionSpec m = parseMission(R"(name: jet_headings
units: {length_m: 50000, time_s: 86400}
epoch: "2026-06-01T00:00:00Z"
projection: {lon0: -70.0, lat0: 36.0}
current: {type: meandering_jet}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: -3}
goal: {x: 8, y: 3}
vehicle: {speed: 0.2}
planner: {horizon: 60, goal_tolerance: 0.001}
outputs: {files: [csv, geojson, goto, stints, summary, map], goto_number: 5}
)",
                                 "jet_headings.yaml");
    m.outputs.directory = freshDirectory("headings").string();
    m.outputs.holdTolerance = 0.0; // the uploads too: one hold per segment
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    const PlannedPath &p = r.plan;
    ASSERT_TRUE(p.solved) << p.reason;
    ASSERT_TRUE(p.headingRoute());
    EXPECT_EQ(p.switchedFrom, "ZA*TVE");
    EXPECT_EQ(p.planner, "Isochrone");
    // the route's segments, their bearings in [0, 360) as written for the pilot
    std::vector<HeadingSegment> seg = p.headings->segments;
    for (HeadingSegment &h : seg)
        h.bearing = std::fmod(std::fmod(h.bearing, 360.0) + 360.0, 360.0);
    const std::size_t n = r.waypoints.size();
    ASSERT_EQ(n, p.path.size());
    ASSERT_GE(n, 2u);
    ASSERT_LE(n - 1, seg.size()); // a segment per leg (the arrival may come before the last segment is begun)
    // The waypoints: leg i is flown with segment i for as long as it lasts; the last is cut at the arrival.
    for (std::size_t i = 0; i + 1 < n; ++i)
    {
        EXPECT_NEAR(r.waypoints[i].heading, seg[i].bearing, 1e-12) << i;
        EXPECT_GE(r.waypoints[i].heading, 0.0);
        EXPECT_LT(r.waypoints[i].heading, 360.0);
        EXPECT_EQ(r.waypoints[i].headingDuration, p.path[i + 1].t - p.path[i].t) << i;
        if (i + 2 < n)
            EXPECT_NEAR(r.waypoints[i].headingDuration, seg[i].duration, 1e-9) << i;
        else
            EXPECT_LE(r.waypoints[i].headingDuration, seg[i].duration + 1e-9);
    }
    EXPECT_TRUE(std::isnan(r.waypoints.back().heading));

    const auto files = writeOutputs(r, problem);
    const fs::path dir = m.outputs.directory;
    std::set<std::string> written;
    for (const auto &f : files)
        written.insert(fs::path(f).filename().string());
    EXPECT_EQ(written,
              (std::set<std::string>{"summary.json", "waypoints.csv", "path.geojson", "route.kml", "goto_l05.ma",
                                     "targets", "stints.csv", "map.svg", "map.png", "map.html"}));

    // Every file writes the same TRUE bearings (TestTrueBearings.cpp re-flies them in lon/lat): a degree or two off the
    // projection's grid north here, 300-400 km east of its centre.
    const std::vector<double> truth = trueHeadings(r, &problem);
    const std::vector<HeadingSegment> planned = seg; // the plane's (the drift is the planner's)
    double turned = 0.0;
    for (std::size_t i = 0; i + 1 < n; ++i)
    {
        turned = std::max(turned, std::abs(std::remainder(truth[i] - seg[i].bearing, 360.0)));
        EXPECT_LT(std::abs(std::remainder(truth[i] - seg[i].bearing, 360.0)), 3.0) << i;
        seg[i].bearing = truth[i];
    }
    EXPECT_GT(turned, 0.1);
    // waypoints.csv: the heading held from each waypoint and its duration, empty at the last one.
    const auto w = csvRows(readText(dir / "waypoints.csv"));
    ASSERT_EQ(w.size(), n + 1);
    ASSERT_EQ(w[0].size(), 14u);
    EXPECT_EQ(w[0][12], "heading_true_deg");
    EXPECT_EQ(w[0][13], "segment_duration");
    for (std::size_t i = 0; i + 1 < n; ++i)
    {
        EXPECT_NEAR(std::stod(w[i + 1][12]), seg[i].bearing, 1e-7 * 360.0) << i;
        EXPECT_NEAR(std::stod(w[i + 1][13]), p.path[i + 1].t - p.path[i].t, 1e-8) << i;
    }
    EXPECT_EQ(w[n][12], "");
    EXPECT_EQ(w[n][13], "");

    // stints.csv: one row per segment flown; the drift is the displacement less V dt (sin b, cos b).
    const auto st = csvRows(readText(dir / "stints.csv"));
    ASSERT_EQ(st.size(), n); // header + n - 1 segments
    for (std::size_t i = 0; i + 1 < n; ++i)
    {
        const auto &row = st[i + 1];
        const TimedPoint &a = p.path[i], &b = p.path[i + 1];
        EXPECT_EQ(row[0], std::to_string(i));
        EXPECT_NEAR(std::stod(row[1]), a.t, 1e-8);
        EXPECT_EQ(row[3], problem.isoTime(a.t));
        EXPECT_NEAR(std::stod(row[8]), seg[i].bearing, 1e-7 * 360.0);
        EXPECT_NEAR(std::stod(row[9]), b.t, 1e-8);
        const double b0 = planned[i].bearing * M_PI / 180.0, dt = b.t - a.t;
        EXPECT_NEAR(std::stod(row[12]), b.x - a.x - 0.2 * dt * std::sin(b0), 1e-8);
        EXPECT_NEAR(std::stod(row[13]), b.y - a.y - 0.2 * dt * std::cos(b0), 1e-8);
    }

    // summary.json: the route model, the segments (one day is 24 h) and the switch.
    const nlohmann::json s = readJson(dir / "summary.json");
    EXPECT_EQ(s["route_model"], "headings");
    EXPECT_EQ(s["switched_from"], "ZA*TVE");
    EXPECT_HAS(s["switch_reason"].get<std::string>(), "ZA*TVE found no path");
    EXPECT_EQ(s["switch_cause"], causeName(p.switchCause));
    EXPECT_NE(p.switchCause, NoPathCause::None);
    EXPECT_TRUE(s["no_path_cause"].is_null());
    ASSERT_EQ(s["headings"].size(), n - 1);
    double total = 0.0;
    for (std::size_t i = 0; i + 1 < n; ++i)
    {
        const nlohmann::json &h = s["headings"][i];
        EXPECT_NEAR(h["bearing_true_deg"].get<double>(), seg[i].bearing, 1e-12);
        EXPECT_EQ(h["duration"].get<double>(), p.path[i + 1].t - p.path[i].t);
        EXPECT_NEAR(h["duration_h"].get<double>(), 24.0 * h["duration"].get<double>(), 1e-9);
        EXPECT_EQ(h["start"]["x"].get<double>(), p.path[i].x);
        EXPECT_EQ(h["start"]["time"].get<double>(), p.path[i].t);
        EXPECT_EQ(h["start"]["lat"].get<double>(), r.waypoints[i].lonLat.lat);
        EXPECT_EQ(h["start"]["iso"], r.waypoints[i].iso);
        total += h["duration"].get<double>();
    }
    EXPECT_NEAR(total, s["travel_time"].get<double>(), 1e-9); // no holds: the segments make the whole trip

    // path.geojson: the line is the flown track (lon/lat) through every segment end; the points carry the headings.
    const nlohmann::json g = readJson(dir / "path.geojson");
    const nlohmann::json &line = g["features"][0]["geometry"];
    ASSERT_EQ(line["type"], "LineString");
    ASSERT_EQ(line["coordinates"].size(), p.track.size());
    ASSERT_GT(p.track.size(), n); // curved: more points than segment ends
    for (std::size_t k = 0; k < p.track.size(); k += p.track.size() / 7)
    {
        const LonLat q = problem.toGeographic({p.track[k].x, p.track[k].y});
        EXPECT_EQ(line["coordinates"][k][0].get<double>(), q.lon);
        EXPECT_EQ(line["coordinates"][k][1].get<double>(), q.lat);
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        bool onLine = false;
        for (const auto &c : line["coordinates"])
            onLine = onLine || (std::abs(c[0].get<double>() - r.waypoints[i].lonLat.lon) < 1e-9 &&
                                std::abs(c[1].get<double>() - r.waypoints[i].lonLat.lat) < 1e-9);
        EXPECT_TRUE(onLine) << "segment end " << i << " is not on the line";
        const nlohmann::json &props = g["features"][i + 1]["properties"];
        if (i + 1 < n)
        {
            EXPECT_NEAR(props["heading_true_deg"].get<double>(), seg[i].bearing, 1e-12);
            EXPECT_EQ(props["segment_duration"].get<double>(), p.path[i + 1].t - p.path[i].t);
        }
        else
            EXPECT_TRUE(props["heading_true_deg"].is_null());
    }
    EXPECT_EQ(g["features"][0]["properties"]["route_model"], "headings");

    // The goto list: the segment ends after the start, each after a comment with the heading held to reach it.
    const std::string gotoText = readText(dir / "goto_l05.ma");
    const GotoList back = readGotoFile((dir / "goto_l05.ma").string());
    ASSERT_EQ(back.waypoints.size(), n - 1);
    std::istringstream gl(gotoText);
    std::string gline, previous;
    std::size_t k = 0;
    bool inList = false;
    while (std::getline(gl, gline))
    {
        if (gline == "<start:waypoints>")
            inList = true;
        else if (gline == "<end:waypoints>")
            inList = false;
        else if (inList && gline[0] != '#')
        {
            char want[64];
            std::snprintf(want, sizeof want, "# to here: hold heading %05.1f deg true for %.4f h", seg[k].bearing,
                          24.0 * (p.path[k + 1].t - p.path[k].t));
            EXPECT_EQ(previous, want) << "waypoint " << k;
            ++k;
        }
        previous = gline;
    }
    EXPECT_EQ(k, n - 1);

    // The report: the switch, the route model, the heading column, and no lattice grid for Isochrone.
    std::ostringstream out;
    printReport(out, r);
    const std::string report = out.str();
    EXPECT_HAS(report, "Switched:           ZA*TVE found no path");
    EXPECT_HAS(report, "; planned with Isochrone\n");
    EXPECT_HAS(report, "Route:              held headings (" + std::to_string(seg.size()) + " segments)\n");
    EXPECT_HAS(report, "held for");
    EXPECT_HAS(report, "Planner:            Isochrone, V = 0.2\n");
}
