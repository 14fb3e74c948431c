#pragma once
/// @file CampaignControl.h
/// @brief The control-planning part of the benchmark campaign: OMPL's control planners (oc::SST, oc::RRT,
/// oc::KPIECE1) on the heading-control setup of a campaign problem (makeControlSetup(), GliderControl.h), run by
/// ompl::tools::Benchmark's constructor for oc::SimpleSetup into their own log (one more experiment of the database).
///
/// Per run the post-run event records what the geometric runs record, measured on the control path:
///   - "reached goal": an exact solution whose last state lies within the control goal tolerance of the goal;
///   - "travel time" and "best cost": the sum of the path's control durations (its cost under
///     ControlTravelTimeObjective) when it reached the goal and its re-flight is valid;
///   - "plan valid": the path's controls re-flown from the start with flyHeadingRoute() (the one dive integrator)
///     end within the goal tolerance at t0 + travel time, at the path's last state (1e-6), without a grounding, inside
///     the planning box and the time window;
///   - "path motions valid": OMPL's PathControl::check() (every control re-propagated to its next state);
///   - "planner travel time" (last state's time - t0), "waypoints" (states), "controls", "CMC" (current-model calls
///     during solve(); the control planners call no travel-time code, so "CFC" is 0).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <string>

#include "CampaignBenchmark.h"

#include <ompl/control/planners/kpiece/KPIECE1.h>
#include <ompl/control/planners/rrt/RRT.h>
#include <ompl/control/planners/sst/SST.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include "ompl_glider/execution/GliderControl.h"
#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"

#include "CampaignProblems.h"

namespace ompl_glider
{
/// @brief A number with 10 significant digits (the logs' values).
inline std::string controlNumber(double v)
{
    std::ostringstream os;
    os << std::setprecision(10) << v;
    return os.str();
}

/// @brief OMPL's control planners the campaign knows, by their OMPL names.
inline const std::set<std::string> &campaignControlPlanners()
{
    static const std::set<std::string> names{"SST", "RRT", "KPIECE1"};
    return names;
}

/// @brief The control planner @p name on @p si. SST's selection and pruning radii (distances of TimeSE2StateSpace)
/// are scaled to the problem: the box diagonal D over 64 and over 128 (OMPL's defaults 0.2 and 0.1 are those of a
/// box of diagonal 12.8, the meandering jet's).
inline ompl::base::PlannerPtr makeControlPlanner(const std::string &name, const ompl::control::SpaceInformationPtr &si,
                                                 double diagonal)
{
    namespace oc = ompl::control;
    if (name == "SST")
    {
        auto p = std::make_shared<oc::SST>(si);
        p->setSelectionRadius(diagonal / 64.0);
        p->setPruningRadius(diagonal / 128.0);
        return p;
    }
    if (name == "RRT")
        return std::make_shared<oc::RRT>(si);
    if (name == "KPIECE1")
        return std::make_shared<oc::KPIECE1>(si);
    return nullptr;
}

/// @brief Records the control path of a finished run into @p run (see the file's documentation).
inline void recordControlRun(const ompl::base::PlannerPtr &planner, ompl::tools::Benchmark::RunProperties &run,
                             const GliderContext &ctx, const GliderProblem &pr, const GliderStatePropagator &prop,
                             double tolerance)
{
    namespace oc = ompl::control;
    run["CFC INTEGER"] = "0";
    run["CMC INTEGER"] = std::to_string(ctx.field->callCount());
    const ompl::base::ProblemDefinitionPtr pdef = planner->getProblemDefinition();
    if (!pdef || !pdef->hasSolution())
        return;
    auto path = std::dynamic_pointer_cast<oc::PathControl>(pdef->getSolutionPath());
    if (!path || path->getStateCount() == 0)
        return;
    const auto *last = path->getState(path->getStateCount() - 1)->as<TimeSE2StateSpace::StateType>();
    const bool reached =
        !pdef->hasApproximateSolution() && std::hypot(last->getX() - pr.goal.x, last->getY() - pr.goal.y) <= tolerance;
    const double duration = path->length(); // the sum of the control durations
    const HeadingFlight f =
        flyHeadingRoute(controlPathToHeadingRoute(*path), *ctx.field, ctx.environment.get(), prop.diveSettings(), true);
    const Region &box = ctx.region;
    bool valid = !f.grounded && !f.ends.empty();
    for (const TimedPoint &q : f.track)
        valid = valid && q.x >= box.xMin && q.x <= box.xMax && q.y >= box.yMin && q.y <= box.yMax && q.t <= box.tMax;
    if (valid)
    {
        const TimedPoint &e = f.ends.back();
        valid = std::hypot(e.x - pr.goal.x, e.y - pr.goal.y) <= tolerance &&
                std::hypot(e.x - last->getX(), e.y - last->getY()) <= 1e-6 &&
                std::abs(e.t - pr.t0 - duration) <= 1e-9 * std::max(1.0, duration);
    }
    run["reached goal BOOLEAN"] = reached ? "1" : "0";
    run["plan valid BOOLEAN"] = (reached && valid) ? "1" : "0";
    if (reached && valid)
    {
        run["travel time REAL"] = controlNumber(duration);
        run["best cost REAL"] = controlNumber(duration);
    }
    run["planner travel time REAL"] = controlNumber(last->getTime() - pr.t0);
    run["waypoints INTEGER"] = std::to_string(path->getStateCount());
    run["controls INTEGER"] = std::to_string(path->getControlCount());
    run["path motions valid BOOLEAN"] = path->check() ? "1" : "0";
    if (reached && !valid)
        std::cerr << "warning: " << planner->getName() << ": the re-flown controls do not reproduce the path"
                  << (f.grounded ? " (" + f.why + ")" : "") << "\n";
}

/// @brief Benchmarks the control planners @p names on the heading-control setup of @p p: @p runs runs of
/// @p seconds each; writes OUTDIR/<problem>_control.log. Experiment parameters as the geometric experiment's, plus the
/// control discretisation (propagation step, control durations, RK4 substeps, goal tolerance).
inline std::unique_ptr<BuiltBenchmark> buildControlBenchmark(const CampaignProblem &p,
                                                             const std::set<std::string> &names, unsigned runs,
                                                             double seconds, std::uint32_t seed,
                                                             const std::string &outdir)
{
    namespace ob = ompl::base;
    namespace ot = ompl::tools;
    std::shared_ptr<GliderContext> ctx;
    const std::shared_ptr<GliderControlSetup> css = makeControlSetup(p.problem, ControlSettings(), &ctx);
    css->setup();
    const ompl::control::SpaceInformationPtr si = css->getSpaceInformation();
    const auto prop = std::dynamic_pointer_cast<GliderStatePropagator>(si->getStatePropagator());
    const ControlSettings &cs = css->settings();
    const Region &r = ctx->region;
    const double diagonal = std::hypot(r.xMax - r.xMin, r.yMax - r.yMin);
    const auto str = controlNumber;

    auto built = std::make_unique<BuiltBenchmark>();
    built->setup = css;
    built->benchmark = std::make_unique<ot::Benchmark>(*css, "glider " + p.name + "_control"); // the statistics
    ot::Benchmark &b = *built->benchmark; // script keeps the last word
    b.addExperimentParameter("problem", "VARCHAR(64)", p.name);
    b.addExperimentParameter("description", "VARCHAR(256)", p.description);
    b.addExperimentParameter("field", "VARCHAR(64)", p.problem.field->name());
    b.addExperimentParameter("speed", "REAL", str(p.problem.travel.speed));
    b.addExperimentParameter("t0", "REAL", str(p.problem.t0));
    b.addExperimentParameter("horizon", "REAL", str(p.problem.horizon));
    b.addExperimentParameter("start_x", "REAL", str(p.problem.start.x));
    b.addExperimentParameter("start_y", "REAL", str(p.problem.start.y));
    b.addExperimentParameter("goal_x", "REAL", str(p.problem.goal.x));
    b.addExperimentParameter("goal_y", "REAL", str(p.problem.goal.y));
    b.addExperimentParameter("regions", "INTEGER", std::to_string(p.environment ? p.environment->size() : 0));
    b.addExperimentParameter("campaign_seed", "INTEGER", std::to_string(seed));
    b.addExperimentParameter("propagation_step", "REAL", str(cs.propagationStep));
    b.addExperimentParameter("control_steps_min", "INTEGER", std::to_string(cs.minSteps));
    b.addExperimentParameter("control_steps_max", "INTEGER", std::to_string(cs.maxSteps));
    b.addExperimentParameter("dive_substeps", "INTEGER", std::to_string(cs.diveSubsteps));
    b.addExperimentParameter("control_goal_tolerance", "REAL", str(cs.goalTolerance));

    std::size_t n = 0;
    for (const std::string &name : names)
        if (const ob::PlannerPtr planner = makeControlPlanner(name, si, diagonal))
        {
            b.addPlanner(planner);
            ++n;
        }
    if (n == 0)
        return nullptr;
    b.setPreRunEvent([ctx](const ob::PlannerPtr &) { ctx->field->resetCallCount(); });
    b.setPostRunEvent([ctx, pr = p.problem, prop, tol = cs.goalTolerance](const ob::PlannerPtr &planner,
                                                                          ot::Benchmark::RunProperties &run) {
        recordControlRun(planner, run, *ctx, pr, *prop, tol);
    });
    built->request = ot::Benchmark::Request(seconds, 4096.0, runs, 0.1, false, false, false);
    std::ostringstream banner;
    banner << "problem " << p.name << " (control): " << runs << " runs x " << n << " planners, " << seconds
           << " s each; propagation step " << cs.propagationStep << ", controls of " << cs.minSteps << "-"
           << cs.maxSteps << " steps, goal tolerance " << cs.goalTolerance;
    built->banner = banner.str();
    built->log = outdir + "/" + p.name + "_control.log";
    return built;
}
} // namespace ompl_glider
