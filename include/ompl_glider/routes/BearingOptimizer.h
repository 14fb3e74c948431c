#pragma once
/// @file BearingOptimizer.h
/// @brief The continuous bearing optimisation of [IsernObstacles] Sec. II.2 ("Optim", and "Init-Optim" when seeded
/// by CTS-A*): the vector of bearings, one per stint, minimises StintSimulator::cost() (the remaining distance
/// after the mission, or the arrival time) through full stint simulations.
///
/// Algorithm: NLopt's Subplex (NLOPT_LN_SBPLX, Rowan's subspace-searching simplex), derivative-free. Chosen over
/// BOBYQA because the cost is not smooth: a stint that starts to graze an island jumps to the grounding penalty,
/// reaching the goal radius one stint earlier is a kink, and the RK4 track in a gridded forecast is only piecewise
/// smooth; BOBYQA's quadratic models assume smoothness and stall on such steps, while Subplex's Nelder-Mead
/// simplices on small subspaces only compare values. Subplex is deterministic (no random restarts), so identical
/// inputs give identical bearings.

#include <cstdint>
#include <functional>
#include <vector>

#include "ompl_glider/routes/StintSimulator.h"

namespace ompl_glider
{
/// @brief Parameters of optimiseBearings().
struct BearingOptimizerParams
{
    unsigned maxEvaluations{1500}; ///< stint-plan simulations at most
    double initialStep{20.0};      ///< initial simplex step of every bearing (degrees)
    double bearingTolerance{0.05}; ///< stop when every bearing moves less than this (degrees)
    std::function<bool()> stop;    ///< polled at every evaluation: true ends the optimisation (best so far)
};

/// @brief What optimiseBearings() found.
struct BearingOptimizerResult
{
    StintPlan plan;          ///< the best plan evaluated (never worse than the initial bearings)
    StintPlan initial;       ///< the plan of the initial bearings
    unsigned evaluations{0}; ///< plans simulated
};

/// @brief Minimises the plan cost over the bearings, starting from @p initial (padded to the stint count with its
/// last bearing, or with direct-to-goal bearings when empty). Every bearing is bounded to +-180 degrees around its
/// start value (the whole circle).
BearingOptimizerResult optimiseBearings(const StintSimulator &sim, std::vector<double> initial,
                                        const BearingOptimizerParams &params = {});
} // namespace ompl_glider
