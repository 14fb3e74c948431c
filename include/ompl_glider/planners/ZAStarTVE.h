#pragma once
/// @file ZAStarTVE.h
/// @brief TVE, A*TVE, ZTVE and ZA*TVE ([EichhornRAS] Sec. 2.2, Tables 1 and 2) as an ompl::base::Planner.

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <ompl/base/Planner.h>

#include "ompl_glider/ompl/GliderContext.h"
#include "ompl_glider/planners/LatticePlanner.h"
#include "ompl_glider/planners/TveTypes.h"

namespace ompl_glider
{
class TveSearch; // the search (internal to the library)

/// @brief Time-optimal lattice search in a time-varying current with the edge weights computed during the search.
///
/// The configuration picks the acceleration methods of [EichhornRAS] Sec. 2.2: "TVE" (time-dependent Dijkstra),
/// "A*TVE" (+ the heuristic of [EichhornRAS] Eq. 1), "ZTVE" (+ Zermelo pruning, [EichhornRAS] Sec. 2.2.2) and "ZA*TVE"
/// (both, [EichhornRAS] Table 2). The search runs on an implicit rectangular lattice over ctx->region (grid_size,
/// sectors; see LatticePlanner and Lattice) from the exact start to the exact goal position (both joined to the
/// lattice), departing at the time t0 of the (first) start state, which must lie in [ctx->region.tMin,
/// ctx->region.tMax].
///
/// The space must be a TimeSE2StateSpace (or hold one as its state type). Goals: PositionGoal, or any GoalState /
/// GoalSampleableRegion whose (sampled) state gives the goal position. The returned PathGeometric has one
/// TimeSE2 state per waypoint: x, y, yaw = heading of the leg that reaches it (the first leg's at the start),
/// t = arrival time; its cost under TravelTimeObjective is the arrival time minus t0 (the start state's time).
///
/// Outcomes of solve(): EXACT_SOLUTION; APPROXIMATE_SOLUTION when the termination condition stopped the search (the
/// path leads to the reached vertex closest to the goal); TIMEOUT with no path when the search exhausted the lattice
/// without reaching the goal (OMPL 1.5 has no INFEASIBLE status; lastOutcome() says TveOutcome::Exhausted, and this
/// is quick: at most every lattice vertex once per improvement) or when it was stopped before reaching anything
/// closer to the goal than the start; INVALID_START / INVALID_GOAL (with an OMPL_ERROR saying why) when the start
/// or goal is outside the region, on land or in a forbidden region; UNRECOGNIZED_GOAL_TYPE otherwise.
///
/// With the parameters "smooth" and "refine" (both on by default) an exact lattice path is smoothed
/// (PathSmoother) and its waypoints refined (WaypointRefiner) before it is returned, so that OMPL's Benchmark and any
/// OMPL application get the best path; getWaypoints() keeps the lattice path.
///
/// Planner progress properties (logged by ompl::tools::Benchmark): "cost function calls INTEGER",
/// "current model calls INTEGER" (CFC / CMC of the current or last solve, [EichhornRAS] Table 4; CFC includes smoothing
/// and refinement), "best cost REAL".
///
/// @par External documentation
/// M. Eichhorn, "Optimal routing strategies for autonomous underwater vehicles in time-varying environment",
/// Robotics and Autonomous Systems ([EichhornRAS]), Sec. 2.2 and Tables 1, 2, 4.
class ZAStarTVE : public LatticePlanner
{
public:
    /// @brief Planner on space information si for the problem described by ctx; configuration is one of
    /// "TVE", "A*TVE", "ZTVE", "ZA*TVE" (also the planner's name). Throws ompl_glider::Error on an unknown
    /// configuration or a null context.
    ZAStarTVE(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx,
              const std::string &configuration = "ZA*TVE");
    ~ZAStarTVE() override;

    /// @brief An allocator for ompl::tools::Benchmark::addPlannerAllocator() making this configuration.
    static ompl::base::PlannerAllocator allocator(std::shared_ptr<const GliderContext> ctx,
                                                  const std::string &configuration);

    /// @brief Runs the search ([EichhornRAS] Table 2 with the switches of the configuration).
    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
    /// @brief Forgets the last search (labels, tree, counters).
    void clear() override;
    /// @brief Checks the space and the lattice parameters.
    void setup() override;
    /// @brief The explored tree of the last search: every reached vertex (x, y, yaw of its incoming leg,
    /// arrival time) with an edge from its predecessor weighted by the leg's travel time.
    void getPlannerData(ompl::base::PlannerData &data) const override;

    // Parameters (OMPL ParamSet names in quotes; "grid_size" and "sectors" are LatticePlanner's). Each setter with a
    // range throws ompl_glider::Error on a value outside it.

    /// @brief A* heuristic on/off (param "heuristic").
    void setHeuristic(bool on) { options_.heuristic = on; }
    bool getHeuristic() const { return options_.heuristic; }
    /// @brief Zermelo pruning on/off (param "zermelo").
    void setZermelo(bool on) { options_.zermelo = on; }
    bool getZermelo() const { return options_.zermelo; }
    /// @brief Half-width of the accepted course range, degrees in 0.1..180 (param "delta_phi_max", default 18).
    /// Every numeric parameter's range is stated once: declareParam's suggestion is what its setter accepts.
    void setDeltaPhiMax(double degrees);
    double getDeltaPhiMax() const;
    /// @brief Extrapolation k of the predicted course (param "course_extrapolation", default 1; 0 = [EichhornRAS]
    /// Table 2).
    void setCourseExtrapolation(double k);
    double getCourseExtrapolation() const { return options_.courseExtrapolation; }
    /// @brief Cone widening w in 0..5 with the predicted turn (param "turn_widening", default 1.5; 0 = [EichhornRAS]
    /// Table 2).
    void setTurnWidening(double w);
    double getTurnWidening() const { return options_.turnWidening; }
    /// @brief Lower bounds from LatticeHeuristic for the heuristic, the certificate and skipped CFC (param
    /// "tight_bounds", default on; TveOptions::tightBounds). Off: [EichhornRAS] Eq. 1 only.
    void setTightBounds(bool on) { options_.tightBounds = on; }
    bool getTightBounds() const { return options_.tightBounds; }
    /// @brief Coarse-to-fine search (param "coarse_factor", 0..64, TveOptions::coarseFactor): spacing factor of the
    /// coarse lattice (0 = automatic: 8 above 2^19 lattice vertices; 1 = off).
    void setCoarseFactor(unsigned f);
    unsigned getCoarseFactor() const { return options_.coarseFactor; }
    /// @brief First half-width of the coarse-to-fine corridor in blocks (param "corridor_blocks", 1..1000).
    void setCorridorBlocks(unsigned b);
    unsigned getCorridorBlocks() const { return options_.corridorBlocks; }
    /// @brief Certification tolerance of the pruned search (param "certify_tolerance", finite, default 0, the lattice
    /// optimum as TVE; < 0 = off, the paper's rule). See TveOptions::certifyTolerance.
    void setCertifyTolerance(double tol);
    double getCertifyTolerance() const { return options_.certifyTolerance; }
    /// @brief Steps of the Zermelo course integration per edge (param "zermelo_steps", 1..10000, default 1).
    void setZermeloSteps(unsigned n);
    unsigned getZermeloSteps() const { return options_.zermeloSteps; }
    /// @brief Smooth the lattice path in the time-varying field before returning it (param "smooth", default on;
    /// PathSmoother, [EichhornRAS] Table 3).
    void setSmooth(bool on) { smooth_ = on; }
    bool getSmooth() const { return smooth_; }
    /// @brief Refine the (smoothed) path's waypoints before returning it (param "refine", default on;
    /// WaypointRefiner). With both on, OMPL's Benchmark and any OMPL application record the refined path.
    void setRefine(bool on) { refine_ = on; }
    bool getRefine() const { return refine_; }
    /// @brief Budget of path re-simulations of the refiner (param "refiner_max_evaluations", 1..10^8).
    void setRefinerMaxEvaluations(unsigned n);
    unsigned getRefinerMaxEvaluations() const { return refinerMaxEvaluations_; }
    /// @brief All search options (Zermelo steps, fallback, ...); the params above set the same fields.
    TveOptions &options() { return options_; }

    /// @brief Cost-function calls (CFC, [EichhornRAS] Table 4) of the last solve's search (without post-processing).
    std::uint64_t getCostFunctionCalls() const { return last_.costFunctionCalls; }
    /// @brief Cost-function calls of the last solve's smoothing and refinement (0 when both are off).
    std::uint64_t getPostprocessCostFunctionCalls() const { return postprocessCfc_; }
    /// @brief Current-model calls (CMC, [EichhornRAS] Table 4) of the last solve, CALC-OPTDIR included.
    std::uint64_t getCurrentModelCalls() const { return last_.currentModelCalls; }
    /// @brief Vertices expanded (extracted from the queue) in the last solve.
    std::uint64_t getExpandedVertices() const { return last_.expansions; }
    /// @brief PipelinePlanner: getExpandedVertices().
    std::uint64_t expandedVertices() const override { return last_.expansions; }
    /// @brief PipelinePlanner: the last search's outcome in words (invalid start or goal, an exhausted lattice,
    /// the time limit).
    NoPath noPathReason(const ompl::base::PlannerStatus &status, double timeLimit) const override;
    /// @brief Waypoints (x, y, arrival time) of the last solve's lattice path, before smoothing and refinement
    /// (empty when none).
    const std::vector<TimedPoint> &getWaypoints() const { return last_.waypoints; }
    /// @brief Waypoints of the path the last solve returned (after smoothing and refinement when they are on).
    const std::vector<TimedPoint> &getSolutionWaypoints() const { return solution_; }
    /// @brief Travel time (arrival - start state's time) of the last exact lattice path (before post-processing);
    /// +inf otherwise.
    double getTravelTime() const { return last_.travelTime; }
    /// @brief Everything the last search reported.
    const TveResult &lastResult() const { return last_; }
    /// @brief How the last search ended.
    TveOutcome lastOutcome() const { return last_.outcome; }

private:
    /// Forgets the search (its lattice) when grid_size or sectors change.
    void latticeChanged() override;

    std::shared_ptr<const GliderContext> ctx_;
    TveOptions options_;
    bool smooth_{true};
    bool refine_{true};
    unsigned refinerMaxEvaluations_{40000};
    std::uint64_t postprocessCfc_{0};
    std::vector<TimedPoint> solution_;
    std::unique_ptr<TveSearch> search_;
    TveResult last_;
    std::vector<TveTreeVertex> tree_;
    mutable std::vector<ompl::base::State *> dataStates_;
    std::atomic<bool> solving_{false};
    std::atomic<std::uint64_t> cfcBase_{0}, cmcBase_{0};
    std::atomic<double> bestCost_{std::numeric_limits<double>::infinity()};
    void freeDataStates() const;
};
} // namespace ompl_glider
