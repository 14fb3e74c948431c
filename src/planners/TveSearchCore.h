#pragma once
/// @file TveSearchCore.h
/// @brief Internal to the library (not installed): TveSearch::Core, one search of TveSearch::runCore(), and the
/// entries of its queues. Its steps are split by concern:
///  - TveSearchCore.cpp       set-up and result: start and goal checked, the bounds and heuristic (LatticeHeuristic),
///                            the path or the reason returned with the search's counters
///  - TveSearchExpansion.cpp  the queue loop ([EichhornRAS] Table 2): the expansion of a vertex with Zermelo pruning
///                            and certification, and the examination of an edge (holds before the goal window,
///                            departures after a release)

#include <functional>
#include <optional>
#include <queue>
#include <string>
#include <vector>

#include "SearchSetting.h"
#include "TveSearch.h"

namespace ompl_glider
{
namespace tve_detail
{
/// Queue entry: key (d or d + h), the d it was pushed with (stale-entry test), vertex.
struct QueueEntry
{
    double key;
    double d;
    Lattice::VertexId v;
    bool operator>(const QueueEntry &o) const { return key > o.key || (key == o.key && v > o.v); }
};
/// An edge (u, v) pruned by the Zermelo cone, kept for the certification phase (TveOptions::certifyTolerance).
struct DeferredEdge
{
    double key; ///< d[u] + |uv| / (V + max|c|) + |v - goal| / (V + max|c|): a lower bound of any arrival via it
    double du;  ///< d[u] when it was pruned (stale when d[u] changed since)
    Lattice::VertexId u, v;
    bool operator>(const DeferredEdge &o) const
    {
        return key > o.key || (key == o.key && (u > o.u || (u == o.u && v > o.v)));
    }
};

/// The predicted course at a vertex and the half-width of the accepted range around it (Zermelo pruning); no
/// course: every successor is examined.
struct Cone
{
    std::optional<double> phiOpt;
    double halfWidth;
};
} // namespace tve_detail

/// @brief One search of runCore(): the state its steps share (start s, goal g, queue Q, deadline tEnd, ...; the
/// arrival d[v] through dist()) and the steps as member functions. Lives for one call of runCore(); the labels, the
/// reached vertices, the bounds and the edge cache stay in the TveSearch.
class TveSearch::Core : private SearchSetting
{
public:
    /// @brief A search of @p search from (startX, startY), departing at @p departure, to (goalX, goalY).
    Core(TveSearch &search, double startX, double startY, double departure, double goalX, double goalY,
         const TveOptions &opts, const std::function<bool()> &stop);
    /// @brief Checks start and goal, sets up the bounds and the queue, runs the queue loop and returns the result
    /// with the CFC and CMC of this search.
    TveResult run();

private:
    using QueueEntry = tve_detail::QueueEntry;
    using DeferredEdge = tve_detail::DeferredEdge;
    using Cone = tve_detail::Cone;
    using Queue = std::priority_queue<QueueEntry, std::vector<QueueEntry>, std::greater<QueueEntry>>;
    using DeferredQueue = std::priority_queue<DeferredEdge, std::vector<DeferredEdge>, std::greater<DeferredEdge>>;

    // --- set-up and result
    TveResult finish();
    bool invalid(TveOutcome outcome, std::string message);
    bool placed(const std::string &what, Lattice::VertexId v, double x, double y, TveOutcome bad);
    bool validEndpoints();
    void setUpBounds();
    TveResult result(Lattice::VertexId found);
    // --- land, bounds and heuristic
    bool inWater(Lattice::VertexId v);
    double hEuclid(Lattice::VertexId v) const;
    double h(Lattice::VertexId v);
    double edgeBound(Lattice::VertexId u, Lattice::VertexId v) const;
    bool boundSkip(Lattice::VertexId u, double du, Lattice::VertexId v);
    bool terminated() const;
    // --- edges
    double edgeTime(Lattice::VertexId u, double ux, double uy, Lattice::VertexId v, double vx, double vy, double dep);
    void label(Lattice::VertexId u, Lattice::VertexId v, double dv, double dep);
    bool canWait(double ux, double uy, double du, double tw) const;
    bool relax(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v);
    void holdBeforeGoal(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v, double vx,
                        double vy);
    void departAfterRelease(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v, double vx,
                            double vy);
    // --- the queue loop
    Lattice::VertexId search();
    void examineDeferred();
    bool restartUnpruned();
    Cone predictCone(Lattice::VertexId u, double ux, double uy, double du);
    void expand(Lattice::VertexId u);

    double dist(Lattice::VertexId v) const { return ts.dist(v); }
    Lattice::VertexId parent(Lattice::VertexId v) const { return ts.parent(v); }

    TveSearch &ts;
    Lattice &lattice;
    const TveOptions &options;
    const std::function<bool()> &terminate;
    const std::uint64_t cfc0; ///< CFC before the search
    const std::uint64_t cmc0; ///< CMC before the search
    TveResult res;
    LatticeHeuristic *bounds{nullptr}; ///< set by setUpBounds() when TveOptions::tightBounds applies
    Lattice::VertexId s{Lattice::kNone}, g{Lattice::kNone};
    VertexPages<unsigned char> wet; ///< land cache: 0 unknown, 1 water, 2 land (only the pages looked at)
    double tEnd{0.0};               ///< arrival deadline of this search (TveOptions::deadline)
    double vmax{0.0};               ///< speed bound of [EichhornRAS] Eq. 1: V + max|c| with the heuristic, else V
    Queue Q;
    std::vector<Lattice::VertexId> prunedAt; ///< vertices whose expansion pruned edges (for the fallback)
    bool pruning{false};
    std::vector<double> releases; ///< the environment's release times (TveOptions::waiting)
    double holdStep{0.0};
    bool goalWindow{false};
    bool certify{false}; ///< TveOptions::certifyTolerance applies
    double vAll{0.0};    ///< V + max|c|: the edge bound without LatticeHeuristic
    DeferredQueue deferred;
    unsigned checkEvery{1};
};
} // namespace ompl_glider
