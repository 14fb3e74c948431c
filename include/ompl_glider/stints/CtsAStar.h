#pragma once
/// @file CtsAStar.h
/// @brief CTS-A*: A* over constant-bearing stints ([IsernObstacles] Sec. II.1 and III.A): the times between two
/// surfacings are fixed, a node is a surfacing (position, time, stint index) and its successors are the stints
/// flown with every bearing of a rose of StintSettings::bearingStep degrees. Two surfacings after the same number
/// of stints in one cell of a spatial grid are duplicates (the first one expanded wins). Nodes are expanded in the
/// order of StintSimulator::lowerBound() (remaining distance / (V + max current) for the earliest arrival), ties
/// broken by the distance to the goal; stints that meet land or a forbidden region are dropped.

#include <cstdint>
#include <functional>

#include "ompl_glider/routes/StintSimulator.h"

namespace ompl_glider
{
/// @brief Parameters of ctsAStar().
struct CtsAStarParams
{
    double cellSize{0.0};                ///< duplicate-detection grid spacing; 0: V * duration / 2
    std::uint64_t maxExpansions{200000}; ///< expansions at most (then the best plan found so far)
    std::function<bool()> stop;          ///< polled between expansions: true ends the search (best so far)
};

/// @brief What ctsAStar() found.
struct CtsAStarResult
{
    StintPlan plan;              ///< the best plan (the optimum of the search graph when `complete`)
    bool complete{false};        ///< the search proved its plan best on its graph (not stopped or capped)
    std::uint64_t expansions{0}; ///< nodes expanded
    std::uint64_t stints{0};     ///< stints flown
};

/// @brief Runs CTS-A* from the simulator's start. Without any complete plan when stopped, the best partial plan
/// (lowest bound) is completed with direct-to-goal bearings.
CtsAStarResult ctsAStar(const StintSimulator &sim, const CtsAStarParams &params = {});
} // namespace ompl_glider
