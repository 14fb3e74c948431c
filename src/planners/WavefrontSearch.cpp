/// @file WavefrontSearch.cpp
/// @brief One search of the Wavefront planner ([ThompsonICRA] Algorithm 1): Wavefront::search() and its steps
/// (Wavefront::Search) over space-time nodes (lattice vertex, time interval). The planner itself (parameters, limits,
/// solve(), planner data) is in Wavefront.cpp.

#include "ompl_glider/planners/Wavefront.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <queue>
#include <unordered_map>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/GliderStateValidityChecker.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/ompl/TravelTimeMotionValidator.h"
#include "detail/Lattice.h"
#include "SearchSetting.h"
#include "ompl_glider/ResourceLimits.h"
#include "../io/NumberText.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{
using TimeState = TimeSE2StateSpace::StateType;

/// Node (v, k) as one key: the vertex in the high 32 bits (a lattice holds at most 2^31 + 2 vertices), k below.
using NodeKey = std::uint64_t;
constexpr NodeKey kNoNode = std::numeric_limits<NodeKey>::max();
NodeKey nodeKey(Lattice::VertexId v, std::uint64_t k)
{
    return (static_cast<NodeKey>(v) << 32) | k;
}
Lattice::VertexId nodeVertex(NodeKey n)
{
    return static_cast<Lattice::VertexId>(n >> 32);
}
std::uint64_t nodeInterval(NodeKey n)
{
    return n & 0xffffffffULL;
}
/// Interval index of the goal node "arrived in the arrival window" (a move reaching the goal at a time of its
/// window goes there, so that an earlier arrival in the same interval, before the window opens, cannot hide it).
constexpr std::uint64_t kArrived = 0xffffffffULL;

/// Label of a node: earliest valid arrival A, parent node, whether it was reached by holding, closed.
struct NodeLabel
{
    double a{kInf};
    NodeKey parent{kNoNode};
    bool hold{false};
    bool closed{false};
};

/// Queue entry: key = the time the node is occupied, max(A, start of its interval); A (stale-entry test); node.
struct WaveEntry
{
    double key;
    double a;
    NodeKey n;
    bool operator>(const WaveEntry &o) const { return key > o.key || (key == o.key && n > o.n); }
};
} // namespace

/// @brief One search of Wavefront::search(): the lattice, the time intervals, the nodes' labels and the queue, with
/// the steps of [ThompsonICRA] Algorithm 1 as member functions. Writes the planner's message, counters, settled nodes
/// and path.
class Wavefront::Search : private SearchSetting
{
public:
    Search(Wavefront &planner, double startX, double startY, double departure, double goalX, double goalY,
           const ompl::base::PlannerTerminationCondition &stop);
    ~Search();
    Search(const Search &) = delete;
    Search &operator=(const Search &) = delete;
    /// @brief The search from the start at t0 to the goal; the path is stored in the planner on Exact.
    WavefrontOutcome run();

private:
    using Queue = std::priority_queue<WaveEntry, std::vector<WaveEntry>, std::greater<WaveEntry>>;

    std::optional<WavefrontOutcome> checkEndpoints();
    std::optional<WavefrontOutcome> setUpIntervals();
    WavefrontOutcome sweep();
    void recordSettled(NodeKey n, double x, double y, double a, NodeKey parent);
    bool arriveAtGoal(NodeKey n, double x, double y, double tDepart);
    void move(NodeKey from, double vx, double vy, double tDepart, Lattice::VertexId u);
    void storePath();
    std::vector<TimedPoint> mergeHolds(const std::vector<TimedPoint> &wp) const;

    bool validState(double x, double y, double t);
    bool inWater(Lattice::VertexId v);
    bool holdValid(double x, double y, double t1, double t2) const;
    void improve(NodeKey n, double a, NodeKey parent, bool hold);
    /// Start of tau_k.
    double intervalStart(std::uint64_t k) const { return t0 + static_cast<double>(k) * dt; }
    /// The interval holding t (clamped to 0 .. K - 1).
    std::uint64_t intervalOf(double t) const
    {
        const double k = std::floor((t - t0) / dt);
        return k <= 0.0 ? std::uint64_t{0} : std::min(K - 1, static_cast<std::uint64_t>(k));
    }

    Wavefront &wf;
    const ompl::base::PlannerTerminationCondition &ptc;
    Lattice lattice;
    Lattice::VertexId s{Lattice::kNone}, g{Lattice::kNone};
    ompl::base::State *scratch{nullptr};             ///< the state validState() checks
    double tEnd{0.0};                                ///< end of the window: min(region.tMax, arriveNotAfter)
    double dt{0.0};                                  ///< interval length
    std::uint64_t K{0};                              ///< intervals tau_0 .. tau_{K-1}
    double notBefore{0.0};                           ///< the goal window's begin
    std::unordered_map<Lattice::VertexId, bool> wet; ///< land cache of the vertices looked at
    std::unordered_map<NodeKey, NodeLabel> labels;
    Queue queue;
    std::unordered_map<NodeKey, std::int64_t> settledIndex; ///< node -> index in the planner's settled_
    NodeKey goalNode{kNoNode};
    double arrival{kInf};
};

Wavefront::Search::Search(Wavefront &planner, double startX, double startY, double departure, double goalX,
                          double goalY, const ompl::base::PlannerTerminationCondition &stop)
    : SearchSetting(*planner.ctx_, startX, startY, departure, goalX, goalY), wf(planner), ptc(stop),
      lattice(ctx.region.xMin, ctx.region.xMax, ctx.region.yMin, ctx.region.yMax, planner.getGridSize(),
              planner.getSectors())
{
}

Wavefront::Search::~Search()
{
    if (scratch)
        wf.si_->freeState(scratch);
}

WavefrontOutcome Wavefront::search(double sx, double sy, double t0, double gx, double gy,
                                   const ompl::base::PlannerTerminationCondition &ptc)
{
    return Search(*this, sx, sy, t0, gx, gy, ptc).run();
}

WavefrontOutcome Wavefront::Search::run()
{
    // Start and goal (the state checks of OMPL's validity checker, with its reason when it has one).
    s = lattice.setStart(sx, sy);
    g = lattice.setGoal(gx, gy);
    scratch = wf.si_->allocState();
    if (const std::optional<WavefrontOutcome> bad = checkEndpoints())
        return *bad;
    if (const std::optional<WavefrontOutcome> bad = setUpIntervals())
        return *bad;
    notBefore = ctx.arriveNotBefore;

    improve(nodeKey(s, 0), t0, kNoNode, false);
    const WavefrontOutcome outcome = sweep();
    if (outcome == WavefrontOutcome::Terminated)
        return outcome;
    if (goalNode == kNoNode)
    {
        wf.message_ = "no path reaches the goal by t = " + std::to_string(tEnd) + " (" +
                      std::to_string(wf.expansions_) + " nodes expanded)";
        return WavefrontOutcome::Exhausted;
    }
    storePath();
    return WavefrontOutcome::Exact;
}

/// InvalidStart or InvalidGoal (with the planner's message saying why) when the start at t0 or the goal is not
/// valid; nothing otherwise.
std::optional<WavefrontOutcome> Wavefront::Search::checkEndpoints()
{
    if (s == Lattice::kNone)
    {
        wf.message_ = "start " + formatPoint(sx, sy) + " lies outside the planning region";
        return WavefrontOutcome::InvalidStart;
    }
    if (!std::isfinite(t0) || !(t0 >= ctx.region.tMin && t0 <= ctx.region.tMax) || !validState(sx, sy, t0))
    {
        wf.message_ = "start " + formatPoint(sx, sy) + " is not a valid state at t0 = " + std::to_string(t0);
        if (const auto *vc = dynamic_cast<const GliderStateValidityChecker *>(wf.si_->getStateValidityChecker().get()))
        {
            const std::string why = vc->whyInvalid(scratch);
            if (!why.empty())
                wf.message_ += ": " + why;
        }
        return WavefrontOutcome::InvalidStart;
    }
    if (g == Lattice::kNone || !field.inWater(gx, gy, z))
    {
        wf.message_ = "goal " + formatPoint(gx, gy) +
                      (g == Lattice::kNone ? " lies outside the planning region" : " is not in water");
        return WavefrontOutcome::InvalidGoal;
    }
    return std::nullopt;
}

/// Time intervals tau_k = [t0 + k dt, t0 + (k + 1) dt), k = 0 .. K - 1, up to the end of the window; BadWindow or
/// Exhausted (with the planner's message) when there are none. Throws ompl_glider::Error on more than
/// kMaxIntervals.
std::optional<WavefrontOutcome> Wavefront::Search::setUpIntervals()
{
    tEnd = std::min(ctx.region.tMax, ctx.arriveNotAfter);
    if (!std::isfinite(tEnd))
    {
        wf.message_ = "the planning window has no finite end (region.tMax and the goal's arrival window are unbounded)";
        return WavefrontOutcome::BadWindow;
    }
    dt = wf.effectiveTimeStep();
    const double intervals = std::floor((tEnd - t0) / dt) + 1.0;
    if (!(intervals <= kMaxIntervals)) // (also keeps k below kArrived)
    {
        char text[200];
        std::snprintf(text, sizeof text,
                      "Wavefront: time_step %g gives %.4g time intervals over the planning window [%g, %g] (at most "
                      "1e6): use a larger time_step",
                      dt, intervals, t0, tEnd);
        throw Error(text);
    }
    if (!(intervals >= 1.0))
    {
        wf.message_ = "the planning window ends (t = " + std::to_string(tEnd) + ") before the departure";
        return WavefrontOutcome::Exhausted;
    }
    K = static_cast<std::uint64_t>(intervals);
    return std::nullopt;
}

/// The validity checker's verdict on (x, y, t) (yaw 0).
bool Wavefront::Search::validState(double x, double y, double t)
{
    scratch->as<TimeState>()->setXYT(x, y, t);
    scratch->as<TimeState>()->setYaw(0.0);
    return wf.si_->isValid(scratch);
}

/// Land test of a vertex (cached).
bool Wavefront::Search::inWater(Lattice::VertexId v)
{
    const auto [it, inserted] = wet.try_emplace(v, false);
    if (inserted)
        it->second = field.inWater(lattice.x(v), lattice.y(v), z);
    return it->second;
}

/// A hold at (x, y) over [t1, t2]: the motion validator's verdict (canHold(): |c| < V; the environment).
bool Wavefront::Search::holdValid(double x, double y, double t1, double t2) const
{
    return t2 == t1 || wf.validator_->classify(x, y, t1, x, y, t2) == MotionVerdict::Valid;
}

/// Node n reached at a from parent (by a hold or a move): queued when it improves n's label and n is open.
void Wavefront::Search::improve(NodeKey n, double a, NodeKey parent, bool hold)
{
    NodeLabel &l = labels[n];
    if (l.closed || !(a < l.a))
        return;
    l.a = a;
    l.parent = parent;
    l.hold = hold;
    const std::uint64_t k = nodeInterval(n);
    queue.push({k == kArrived ? a : std::max(a, intervalStart(k)), a, n});
}

/// The wavefront: settles nodes in increasing departure time until a goal node is settled (Exact, goalNode and
/// arrival set), the queue runs empty (Exhausted) or the termination condition fires (Terminated).
WavefrontOutcome Wavefront::Search::sweep()
{
    while (!queue.empty())
    {
        const WaveEntry e = queue.top();
        queue.pop();
        NodeLabel &label = labels[e.n];
        if (label.closed || e.a != label.a)
            continue; // stale entry
        label.closed = true;
        if ((++wf.expansions_ & 63u) == 0 && ptc())
            return WavefrontOutcome::Terminated;
        const Lattice::VertexId v = nodeVertex(e.n);
        const std::uint64_t k = nodeInterval(e.n);
        const double vx = lattice.x(v), vy = lattice.y(v);
        recordSettled(e.n, vx, vy, e.a, label.parent);
        // Earliest possible departure ([ThompsonICRA] Algorithm 1, lines 13-16).
        const double tDepart = e.key; // = max(A, start of tau_k)

        if (k == kArrived)
        {
            goalNode = e.n; // the earliest arrival inside the window
            arrival = e.a;
            return WavefrontOutcome::Exact;
        }
        if (v == g && arriveAtGoal(e.n, vx, vy, tDepart))
            return WavefrontOutcome::Exact;
        // Hold position into the next interval ([ThompsonICRA] Algorithm 1, lines 6-10).
        if (k + 1 < K && holdValid(vx, vy, tDepart, intervalStart(k + 1)))
            improve(nodeKey(v, k + 1), e.a, e.n, true);
        // Move to each lattice neighbour ([ThompsonICRA] Algorithm 1, lines 11-22).
        lattice.forEachSuccessor(v, [&](Lattice::VertexId u) { move(e.n, vx, vy, tDepart, u); });
    }
    return WavefrontOutcome::Exhausted;
}

/// Appends the settled node n (arrival a) to the planner's settled nodes, linked to its parent's entry.
void Wavefront::Search::recordSettled(NodeKey n, double x, double y, double a, NodeKey parent)
{
    const auto parentIt = settledIndex.find(parent);
    const std::int64_t parentIndex = parentIt == settledIndex.end() ? -1 : parentIt->second;
    settledIndex[n] = static_cast<std::int64_t>(wf.settled_.size());
    wf.settled_.push_back({x, y, a, parentIndex});
}

/// The goal node n at (x, y) is settled: the earliest valid arrival in the goal's window, holding at the goal until
/// the window opens when needed. True (goalNode and arrival set) when that hold is valid and ends in the window.
bool Wavefront::Search::arriveAtGoal(NodeKey n, double x, double y, double tDepart)
{
    const double t = std::max(tDepart, notBefore);
    if (!(t <= tEnd && holdValid(x, y, tDepart, t)))
        return false;
    goalNode = n;
    arrival = t;
    return true;
}

/// The move from node `from` at (vx, vy), departing at tDepart, to the lattice successor u (one CFC): improves the
/// node of its arrival when it is finite, by the end of the window, the leg is free and the arrival state valid.
void Wavefront::Search::move(NodeKey from, double vx, double vy, double tDepart, Lattice::VertexId u)
{
    if (u == Lattice::kNone || !inWater(u))
        return;
    const double ux = lattice.x(u), uy = lattice.y(u);
    const double w = travel.travelTime(vx, vy, ux, uy, tDepart);
    if (!std::isfinite(w))
        return;
    const double ta = tDepart + w;
    if (!(ta <= tEnd))
        return;
    const NodeKey child = nodeKey(u, u == g && ta >= notBefore ? kArrived : intervalOf(ta));
    const auto it = labels.find(child);
    if (it != labels.end() && (it->second.closed || !(ta < it->second.a)))
        return;
    if (env && !env->legFree(vx, vy, tDepart, ux, uy, ta))
        return;
    if (!validState(ux, uy, ta))
        return;
    improve(child, ta, from, false);
}

/// The path ([ThompsonICRA] Algorithm 1, lines 24-29): parents from the goal node back to the start, the final hold
/// at the goal, holds merged; stored with the travel time in the planner.
void Wavefront::Search::storePath()
{
    std::vector<NodeKey> chain;
    for (NodeKey n = goalNode; n != kNoNode; n = labels[n].parent)
        chain.push_back(n);
    std::vector<TimedPoint> wp;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it)
    {
        const NodeLabel &l = labels[*it];
        const Lattice::VertexId v = nodeVertex(*it);
        // a hold ends at the start of the node's interval; a move arrives at A
        wp.push_back({lattice.x(v), lattice.y(v), l.hold ? intervalStart(nodeInterval(*it)) : l.a});
    }
    if (arrival > wp.back().t)
        wp.push_back({wp.back().x, wp.back().y, arrival}); // the final hold at the goal until its window opens
    wf.waypoints_ = mergeHolds(wp);
    wf.travelTime_ = arrival - t0;
}

/// Merges each run of holds at one place into one motion where the validator accepts it.
std::vector<TimedPoint> Wavefront::Search::mergeHolds(const std::vector<TimedPoint> &wp) const
{
    std::vector<TimedPoint> merged;
    for (std::size_t i = 0; i < wp.size();)
    {
        std::size_t j = i;
        while (j + 1 < wp.size() && wp[j + 1].x == wp[i].x && wp[j + 1].y == wp[i].y)
            ++j;
        merged.push_back(wp[i]);
        if (j > i)
        {
            if (holdValid(wp[i].x, wp[i].y, wp[i].t, wp[j].t))
                merged.push_back(wp[j]);
            else
                merged.insert(merged.end(), wp.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                              wp.begin() + static_cast<std::ptrdiff_t>(j) + 1);
        }
        i = j + 1;
    }
    return merged;
}
} // namespace ompl_glider
