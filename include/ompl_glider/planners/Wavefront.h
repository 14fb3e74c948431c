#pragma once
/// @file Wavefront.h
/// @brief The spatiotemporal wavefront planner with hold-position actions and "earliest valid arrival"
/// ([ThompsonICRA] Sec. III, Algorithm 1) as an ompl::base::Planner.

#include <atomic>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <ompl/base/Planner.h>

#include "ompl_glider/ompl/GliderContext.h"
#include "ompl_glider/planners/LatticePlanner.h"

namespace ompl_glider
{
class TravelTimeMotionValidator;

/// @brief How the last Wavefront search ended.
enum class WavefrontOutcome
{
    None,         ///< no search yet
    Exact,        ///< the goal was reached at a time of its arrival window
    Exhausted,    ///< every node reachable by the end of the window was expanded: no path on this lattice
    Terminated,   ///< the termination condition stopped the search
    InvalidStart, ///< start outside the region, invalid at t0, or t0 outside the planning window
    InvalidGoal,  ///< goal outside the region or not in water
    BadWindow     ///< the planning window has no finite end (the hold actions would never end)
};

/// @brief Earliest valid arrival by a Dijkstra wavefront over (lattice vertex, time interval) nodes, with holding.
///
/// [ThompsonICRA] Sec. III, Algorithm 1: the nodes are pairs (v, k) of a vertex v of the lattice of ZAStarTVE
/// (Lattice: grid_size, sectors of LatticePlanner, where sectors 1 gives the 8 compass directions of [ThompsonICRA]
/// Sec. III; exact start and goal joined to it) and a time interval
/// tau_k = [t0 + k dt, t0 + (k + 1) dt) (dt = time_step, t0 the start state's time). Each node carries A(v, k), its
/// earliest valid arrival: the earliest time at which the glider can be at v and stay there into tau_k (A may lie
/// before tau_k when the glider arrived earlier and held). From (v, k) the glider departs at
/// t_d = max(A, start of tau_k) ([ThompsonICRA] Algorithm 1, lines 13-16). Nodes leave the queue in increasing t_d,
/// the time the node is occupied, and are closed (settled) then. (Algorithm 1 orders by A; since a hold keeps A, that
/// order would expand every hold chain to the end of the window before the goal is settled. Both keys grow along
/// every action, so either order settles each node with its least t_d, and a node's least A is kept among equal
/// t_d.) From (v, k) the glider
///   - holds position into (v, k + 1), keeping A (lines 6-10), where TravelTimeMotionValidator::classify() accepts
///     the zero-length motion (v, t_d) -> (v, start of tau_{k+1}): |c| < V there (canHold()) and the environment
///     allows it;
///   - moves to every lattice successor u: arrival t_a = t_d + TravelTimeCalculator::travelTime(v -> u, t_d) (the
///     fastest pace, one CFC; lines 11-22), kept when finite, not after the end of the window, the leg is
///     Environment::legFree at those times and (u, t_a) is a valid state; it improves node (u, k(t_a)).
///
/// Goals in time: the goal counts as reached at a time in [GliderContext::arriveNotBefore, arriveNotAfter]. A move
/// reaching the goal at a time of the window leads to one extra node "arrived" (so that an earlier arrival in the
/// same interval cannot hide it); settling it ends the search with that arrival. When a goal node (g, k) reached
/// before the window opens is settled, the arrival is T = max(t_d, arriveNotBefore) provided T <= arriveNotAfter
/// and the glider can hold at g from t_d to T ([ThompsonICRA] Sec. III: arrive early, then hold). Either is the
/// earliest valid arrival, since no later-settled node is occupied earlier. Where the goal cannot be held the search
/// goes on: the window is then met by holding elsewhere or by a longer way (timing the arrival). The search ends
/// with no path when no node can still arrive by min(region.tMax, arriveNotAfter).
///
/// Discretisation: departures are at arrival times or at interval starts, so holds are in whole intervals except the
/// last one at the goal. Without holds the wavefront's moves are those of TVE (departure at the earliest arrival),
/// so on the same lattice its arrival is never later than TVE's (ZAStarTVE configuration "TVE"), and equal to it
/// where every leg's arrival is non-decreasing in its departure and holding gains nothing.
///
/// The returned PathGeometric (TimeSE2 states: x, y, yaw of the leg reaching the state, t) has one state per
/// waypoint: the start at t0, each vertex at its arrival time, the end of every hold (consecutive holds at one place
/// merged into one motion where the motion validator accepts the merged hold), and the goal at the arrival T. Every
/// motion is valid under TravelTimeMotionValidator (moves arrive exactly at the fastest travel time). Its cost
/// under TravelTimeObjective is T - t0.
///
/// Outcomes of solve(): EXACT_SOLUTION; ABORT with no path when the search exhausted (OMPL 1.5 has no "infeasible"
/// status) or the window has no finite end; TIMEOUT when the termination condition fired first; INVALID_START /
/// INVALID_GOAL; UNRECOGNIZED_GOAL_TYPE. lastOutcome() says which.
///
/// Planner progress properties: "cost function calls INTEGER", "current model calls INTEGER", "best cost REAL".
///
/// @par External documentation
/// D. R. Thompson, S. Chien, Y. Chao, P. Li, B. Cahill, J. Levin, O. Schofield, A. Balasuriya, S. Petillo,
/// M. Arrott, M. Meisinger, "Spatiotemporal path planning in strong, dynamic, uncertain currents", ICRA 2010
/// ([ThompsonICRA]), Sec. III and Algorithm 1.
class Wavefront : public LatticePlanner
{
public:
    /// @brief Planner on space information si (a TimeSE2StateSpace) for the problem ctx.
    /// @throws ompl_glider::Error when ctx is null or lacks a field or travel-time calculator.
    Wavefront(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx);
    ~Wavefront() override;

    /// @brief Most time intervals a search may have over its window (more: solve() throws ompl_glider::Error naming
    /// time_step).
    static constexpr double kMaxIntervals = 1e6;

    /// @brief An allocator for ompl::tools::Benchmark::addPlannerAllocator().
    static ompl::base::PlannerAllocator allocator(std::shared_ptr<const GliderContext> ctx);

    /// @brief Runs the wavefront search ([ThompsonICRA] Algorithm 1) and adds the path to the problem definition.
    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
    /// @brief Forgets the last search.
    void clear() override;
    /// @brief Checks the state space and finds the motion validator.
    void setup() override;
    /// @brief PipelinePlanner: the lattice's size (LatticePlanner::prepare()), then the time intervals over the
    /// window (at most kMaxIntervals) and the space-time nodes the search must settle before the fastest
    /// conceivable arrival (at most kMaxWavefrontNodes, ResourceLimits.h), refused naming time_step or grid_size.
    void prepare(const PipelineSetup &setup) override;
    /// @brief PipelinePlanner: lastOutcome() and lastMessage() in words.
    NoPath noPathReason(const ompl::base::PlannerStatus &status, double timeLimit) const override;
    /// @brief The settled nodes of the last search: (x, y, yaw 0, A) with an edge from each node's parent weighted
    /// by the difference of their arrival times (0 for a hold).
    void getPlannerData(ompl::base::PlannerData &data) const override;

    /// @brief Length dt of the time intervals (param "time_step", default 0 = automatic: grid_size / V, the time to
    /// cross one cell in still water). Must be finite and >= 0.
    void setTimeStep(double dt);
    /// @brief Length of the time intervals as set (0 = automatic).
    double getTimeStep() const { return timeStep_; }
    /// @brief The interval length a search uses (time_step, or grid_size / V when it is 0).
    double effectiveTimeStep() const;

    /// @brief How the last search ended.
    WavefrontOutcome lastOutcome() const { return outcome_; }
    /// @brief Why the last search found no path or refused its start or goal (empty otherwise).
    const std::string &lastMessage() const { return message_; }
    /// @brief Waypoints of the last path (x, y, time; holds as repeated positions); empty when none.
    const std::vector<TimedPoint> &getWaypoints() const { return waypoints_; }
    /// @brief Arrival at the goal (a time of its window) minus t0 of the last search; +inf when none.
    double getTravelTime() const { return travelTime_; }
    /// @brief Total time the last path holds position (its zero-length motions).
    double getHoldTime() const;
    /// @brief Nodes settled (taken from the queue) by the last search.
    std::uint64_t getExpandedNodes() const { return expansions_; }
    /// @brief Cost-function calls (CFC, [EichhornRAS] Table 4) of the last search.
    std::uint64_t getCostFunctionCalls() const { return cfc_; }
    /// @brief Current-model calls (CMC) of the last search.
    std::uint64_t getCurrentModelCalls() const { return cmc_; }

private:
    /// One search of search() with its steps ([ThompsonICRA] Algorithm 1; WavefrontSearch.cpp).
    class Search;

    /// One settled node of the last search (for getPlannerData()).
    struct SettledNode
    {
        double x, y, a;
        std::int64_t parent; ///< index in settled_, -1 for the start
    };

    std::shared_ptr<const GliderContext> ctx_;
    std::shared_ptr<const TravelTimeMotionValidator> validator_;
    double timeStep_{0.0};

    WavefrontOutcome outcome_{WavefrontOutcome::None};
    std::string message_;
    std::vector<TimedPoint> waypoints_;
    double travelTime_{std::numeric_limits<double>::infinity()};
    std::uint64_t expansions_{0}, cfc_{0}, cmc_{0};
    std::vector<SettledNode> settled_;
    mutable std::vector<ompl::base::State *> dataStates_;
    std::atomic<bool> solving_{false};
    std::atomic<std::uint64_t> cfcBase_{0}, cmcBase_{0};
    std::atomic<double> bestCost_{std::numeric_limits<double>::infinity()};

    WavefrontOutcome search(double sx, double sy, double t0, double gx, double gy,
                            const ompl::base::PlannerTerminationCondition &ptc);
    void freeDataStates() const;
};
} // namespace ompl_glider
