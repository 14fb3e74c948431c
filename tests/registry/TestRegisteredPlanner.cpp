// A planner that exists only in this test, registered at run time (registerPlanner()): it plans, reports, refuses
// and explains why it found no path through the whole pipeline (mission file, runMission(), the output files)
// without any edit to mission/. It flies the straight leg from start to goal, or says why it cannot.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/ompl/GliderContext.h"
#include "ompl_glider/ompl/PipelinePlanner.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/output/OutputWriter.h"
#include "ompl_glider/registry/PlannerRegistry.h"

using namespace ompl_glider;

namespace
{
/// The straight leg: the start state, then the goal at the time the travel-time code gives for the leg.
class StraightLegPlanner : public ompl::base::Planner, public PipelinePlanner
{
public:
    StraightLegPlanner(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx)
        : ompl::base::Planner(si, "StraightLeg"), ctx_(std::move(ctx))
    {
        declareParam<double>("max_length", this, &StraightLegPlanner::setMaxLength, &StraightLegPlanner::maxLength,
                             "0:1:1000000");
        // the cause it gives when it has no path (NoPathCause; 0: Other), its words the same whatever the cause
        declareParam<int>("cause", this, &StraightLegPlanner::setCause, &StraightLegPlanner::cause, "0:1:13");
    }
    void setMaxLength(double v) { maxLength_ = v; }
    double maxLength() const { return maxLength_; }
    void setCause(int c) { cause_ = c == 0 ? NoPathCause::Other : static_cast<NoPathCause>(c); }
    int cause() const { return cause_ == NoPathCause::Other ? 0 : static_cast<int>(cause_); }

    void prepare(const PipelineSetup &setup) override
    {
        const double d = std::hypot(setup.goal.x - setup.start.x, setup.goal.y - setup.start.y);
        if (maxLength_ > 0.0 && d > maxLength_)
            throw Error(setup.where("planner.parameters.max_length") + ": the leg is " + std::to_string(d) +
                        " long, longer than the test planner's max_length");
    }
    std::uint64_t expandedVertices() const override { return expanded_; }
    NoPath noPathReason(const ompl::base::PlannerStatus &, double) const override
    {
        return {why_.empty() ? NoPathCause::None : cause_, why_};
    }

    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &) override
    {
        checkValidity();
        why_.clear();
        const auto *goal = pdef_->getGoal()->as<PositionGoal>();
        const auto *start = pdef_->getStartState(0)->as<TimeSE2StateSpace::StateType>();
        const double t =
            ctx_->travel->travelTime(start->getX(), start->getY(), goal->getX(), goal->getY(), start->getTime());
        auto path = std::make_shared<ompl::geometric::PathGeometric>(si_);
        path->append(start);
        ompl::base::ScopedState<TimeSE2StateSpace> end(si_->getStateSpace());
        end->setXYT(goal->getX(), goal->getY(), start->getTime() + t);
        end->setYaw(0.0);
        path->append(end.get());
        expanded_ = 2;
        if (!std::isfinite(t) || !si_->checkMotion(start, end.get()))
        {
            why_ = "StraightLeg: the straight leg from the start to the goal cannot be flown (land, a forbidden "
                   "region or a current it cannot stem lies across it)";
            return ompl::base::PlannerStatus::ABORT;
        }
        pdef_->addSolutionPath(path, false, 0.0, getName());
        return ompl::base::PlannerStatus::EXACT_SOLUTION;
    }

private:
    std::shared_ptr<const GliderContext> ctx_;
    double maxLength_{0.0};
    std::uint64_t expanded_{0};
    std::string why_;
    NoPathCause cause_{NoPathCause::Other};
};

void registerOnce()
{
    if (findPlanner("StraightLeg"))
        return;
    PlannerEntry e;
    e.name = "StraightLeg";
    e.aliases = {"straight_leg"};
    e.description = "the straight leg from start to goal (registered by a test)";
    e.family = PlannerFamily::Other;
    e.make = [](const ompl::base::SpaceInformationPtr &si, const std::shared_ptr<const GliderContext> &ctx) {
        return std::make_shared<StraightLegPlanner>(si, ctx);
    };
    registerPlanner(e);
}

std::string mission(const std::string &extra)
{
    return "name: straight\ncurrent: {type: uniform, parameters: {u: 0.1, v: 0}}\n"
           "region: {x_min: -1, x_max: 9, y_min: -4, y_max: 4}\n"
           "start: {x: 0, y: 0}\ngoal: {x: 8, y: 0}\ndeparture: {time: 0}\nvehicle: {speed: 0.5}\n"
           "planner:\n  name: straight_leg\n  horizon: 60\n" +
           extra;
}
} // namespace

TEST(RegisteredPlanner, PlansThroughTheWholePipelineLikeABuiltInOne)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    registerOnce();
    EXPECT_NE(plannerNameList().find("StraightLeg"), std::string::npos);
    // a name or alias once taken is refused
    PlannerEntry twin = *findPlanner("StraightLeg");
    EXPECT_THROW(registerPlanner(twin), Error);
    twin.name = "Another";
    twin.aliases = {"zastartve"};
    EXPECT_THROW(registerPlanner(twin), Error);

    const std::filesystem::path out = std::filesystem::temp_directory_path() / "ompl_glider_registered_planner";
    std::filesystem::remove_all(out);
    const MissionProblem problem(
        parseMission(mission("outputs: {directory: " + out.string() + ", files: [summary, csv]}\n"), "s.yaml"));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    EXPECT_EQ(r.plan.planner, "StraightLeg");
    EXPECT_EQ(r.plan.expandedVertices, 2u);
    // along a uniform current the leg's ground speed is V + u: the closed form, as flown by the pipeline's re-flight
    EXPECT_NEAR(r.plan.travelTime, 8.0 / 0.6, 1e-6 * 8.0 / 0.6);
    const std::vector<std::string> written = writeOutputs(r, problem);
    EXPECT_FALSE(written.empty());
    ASSERT_TRUE(std::filesystem::exists(out / "summary.json"));
    std::ifstream summary(out / "summary.json");
    const std::string json((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
    EXPECT_NE(json.find("StraightLeg"), std::string::npos);
    std::filesystem::remove_all(out);
}

TEST(RegisteredPlanner, ItsNoPathReasonReachesTheResult)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    registerOnce();
    const MissionProblem problem(parseMission(
        mission("forbidden:\n  obstacles:\n    - {name: rock, points: [[3, -1], [5, -1], [5, 1], [3, 1]]}\n"),
        "s.yaml"));
    const MissionResult r = runMission(problem);
    EXPECT_FALSE(r.plan.solved);
    EXPECT_NE(r.plan.reason.find("StraightLeg: the straight leg from the start to the goal cannot be flown"),
              std::string::npos)
        << r.plan.reason;
}

TEST(RegisteredPlanner, ThePipelineActsOnItsCauseNotItsWords)
{
    // the same words under three causes; the pipeline's handling follows the cause alone
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    registerOnce();
    const std::string rock =
        "forbidden:\n  obstacles:\n    - {name: rock, points: [[3, -1], [5, -1], [5, 1], [3, 1]]}\n";
    const auto run = [&](NoPathCause c, const std::string &current) {
        std::string text = mission("  parameters: {cause: " + std::to_string(static_cast<int>(c)) + "}\n" + rock);
        if (!current.empty())
            text.replace(text.find("u: 0.1"), 6, current);
        return runMission(MissionProblem(parseMission(text, "s.yaml"))).plan;
    };
    // an exhausted search: "No path" and what bounds the arrival (the planning horizon of 60), after the words
    const PlannedPath exhausted = run(NoPathCause::LatticeExhausted, "");
    ASSERT_FALSE(exhausted.solved);
    EXPECT_EQ(exhausted.status, PlanStatus::NoPath);
    EXPECT_EQ(exhausted.noPath.cause, NoPathCause::LatticeExhausted);
    EXPECT_EQ(exhausted.noPath.bound, ArrivalBound::PlanningHorizon);
    EXPECT_DOUBLE_EQ(exhausted.noPath.boundSpan, 60.0);
    EXPECT_EQ(exhausted.reason.rfind("StraightLeg: the straight leg", 0), 0u) << exhausted.reason;
    EXPECT_NE(exhausted.reason.find("; the path must arrive within the planning horizon"), std::string::npos);
    // another cause: OMPL's status stands (Abort), no bound
    const PlannedPath other = run(NoPathCause::SearchEnded, "");
    EXPECT_EQ(other.status, PlanStatus::Abort);
    EXPECT_EQ(other.noPath.bound, ArrivalBound::None);
    EXPECT_EQ(other.noPath.cause, NoPathCause::SearchEnded);
    // a current of 1 against the glider's 0.5: the diagnosis names it, unless the cause is the time limit (more
    // time is then the advice) although the words do not say "time limit"
    const PlannedPath diagnosed = run(NoPathCause::SearchEnded, "u: -1.0");
    EXPECT_NE(diagnosed.reason.find("the current reaches up to"), std::string::npos) << diagnosed.reason;
    const PlannedPath timed = run(NoPathCause::TimeLimit, "u: -1.0");
    EXPECT_EQ(timed.reason.find("the current reaches up to"), std::string::npos) << timed.reason;
    EXPECT_EQ(timed.noPath.cause, NoPathCause::TimeLimit);
    for (const PlannedPath *p : {&exhausted, &other, &diagnosed, &timed})
        EXPECT_EQ(p->reason, p->noPath.text());
}

TEST(RegisteredPlanner, ItsRefusalNamesTheMissionField)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    registerOnce();
    const MissionProblem problem(parseMission(mission("  parameters: {max_length: 5}\n"), "s.yaml"));
    try
    {
        runMission(problem);
        FAIL() << "a leg longer than max_length must be refused";
    }
    catch (const Error &e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("s.yaml:"), std::string::npos) << what;
        EXPECT_NE(what.find("planner.parameters.max_length"), std::string::npos) << what;
    }
    // a parameter the planner does not declare is refused by the pipeline, naming what it has
    const MissionProblem other(parseMission(mission("  parameters: {resolution: 5}\n"), "s.yaml"));
    try
    {
        runMission(other);
        FAIL() << "an undeclared parameter must be refused";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("max_length"), std::string::npos) << e.what();
    }
}
