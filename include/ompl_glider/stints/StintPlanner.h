#pragma once
/// @file StintPlanner.h
/// @brief The planners on constant-bearing stints ([IsernObstacles]) as one ompl::base::Planner with four methods:
/// direct to goal, CTS-A*, Optim (bearings optimised from the direct bearings) and Init-Optim (optimised from the
/// CTS-A* bearings). The solution path holds the surfacing states (x, y, time; yaw = the heading held from there,
/// radians from +x); it is exact when the goal is reached within StintSettings::radius, else approximate with the
/// remaining distance as its difference. lastPlan() has the bearings and the flown track.
///
/// @par External documentation
/// J. Isern-González, D. Hernández-Sosa, E. Fernández-Perdomo, J. Cabrera-Gámez, A. C. Domínguez-Brito,
/// V. Prieto-Marañón, "Obstacle avoidance in underwater glider path planning", Journal of Physical Agents 6 (1)
/// (2012), doi:10.14198/JoPha.2012.6.1.03 ([IsernObstacles]).

#include <memory>
#include <string>

#include <ompl/base/Planner.h>

#include "ompl_glider/ompl/GliderContext.h"
#include "ompl_glider/ompl/PipelinePlanner.h"
#include "ompl_glider/stints/CtsAStar.h"
#include "ompl_glider/routes/StintSimulator.h"

namespace ompl_glider
{
/// @brief The stint planning methods ([IsernObstacles] Sec. III.A).
enum class StintMethod
{
    Direct,   ///< "direct": the bearing to the goal at every surfacing
    CtsAStar, ///< "cts_astar": A* over a bearing rose per stint (ctsAStar())
    Optim,    ///< "optim": optimiseBearings() from the direct bearings
    InitOptim ///< "init_optim": optimiseBearings() from the CTS-A* bearings
};

/// @brief The registry name of a method ("direct", "cts_astar", "optim", "init_optim").
std::string stintMethodName(StintMethod m);

/// @brief Constant-bearing stint planner. Parameters (declareParam): cell_size (CTS-A* duplicate grid, 0: auto),
/// max_expansions (CTS-A*), max_evaluations (optimisation). The stint settings (duration, mission duration,
/// bearing step, objective, radius) come from setStintSettings() (a mission's `stints` section).
class StintPlanner : public ompl::base::Planner, public PipelinePlanner
{
public:
    /// @brief Planner on @p si for the problem of @p ctx with @p method.
    StintPlanner(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx,
                 StintMethod method);

    /// @brief Plans from the problem definition's start state (position and time) toward its PositionGoal.
    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
    /// @brief Forgets the last plan.
    void clear() override;
    /// @brief Planner::getPlannerData() (progress properties); the surfacings are in lastPlan().
    void getPlannerData(ompl::base::PlannerData &data) const override;

    /// @brief PipelinePlanner: takes the mission's stint settings (refusing a mission without a `stints` section)
    /// and refuses a CTS-A* search that would fly more than kMaxStintBearings bearings per expansion or
    /// kMaxStintFlights stints in all (ResourceLimits.h), naming stints.bearing_step or max_expansions.
    void prepare(const PipelineSetup &setup) override;
    /// @brief PipelinePlanner: lastPlan() when the last solve flew one, else null.
    const StintPlan *lastStintPlan() const override { return plan_.surfacings.empty() ? nullptr : &plan_; }
    /// @brief Stint settings. @throws Error naming the bad setting.
    void setStintSettings(const StintSettings &s);
    /// @brief The stint settings.
    const StintSettings &getStintSettings() const { return settings_; }
    /// @brief The method.
    StintMethod getMethod() const { return method_; }
    /// @brief The last plan (bearings, surfacings, track, remaining distance).
    const StintPlan &lastPlan() const { return plan_; }
    /// @brief The plan the last optimisation started from (Optim: direct; Init-Optim: CTS-A*; else the plan).
    const StintPlan &lastInitialPlan() const { return initial_; }

    void setCellSize(double v) { cellSize_ = v; }                  ///< CTS-A* grid spacing (0: auto)
    double getCellSize() const { return cellSize_; }               ///< CTS-A* grid spacing
    void setMaxExpansions(unsigned v) { maxExpansions_ = v; }      ///< CTS-A* expansion cap
    unsigned getMaxExpansions() const { return maxExpansions_; }   ///< CTS-A* expansion cap
    void setMaxEvaluations(unsigned v) { maxEvaluations_ = v; }    ///< optimisation evaluation cap
    unsigned getMaxEvaluations() const { return maxEvaluations_; } ///< optimisation evaluation cap

private:
    std::shared_ptr<const GliderContext> ctx_;
    StintMethod method_;
    StintSettings settings_;
    StintPlan plan_, initial_;
    double cellSize_{0.0};
    unsigned maxExpansions_{200000};
    unsigned maxEvaluations_{1500};
};
} // namespace ompl_glider
