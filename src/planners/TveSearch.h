#pragma once
/// @file TveSearch.h
/// @brief Internal to the library (not installed): the graph search of TVE / A*TVE / ZTVE / ZA*TVE on an implicit
/// lattice, independent of OMPL types ([EichhornRAS] Sec. 2.2, Tables 1 and 2). ZAStarTVE wraps it as an
/// ompl::base::Planner; its options and result are in TveTypes.h.

#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "detail/Lattice.h"
#include "detail/SearchHeuristic.h"
#include "detail/VertexPages.h"
#include "ompl_glider/ompl/GliderContext.h"
#include "ompl_glider/planners/TveTypes.h"

namespace ompl_glider
{
/// @brief Time-dependent Dijkstra / A* on an implicit lattice with the edge weights computed during the search.
///
/// Per [EichhornRAS] Table 2 (ZA*TVE; TVE, A*TVE and ZTVE switch parts off): d[s] = t0; the queue key is d[v] (+ h(v)
/// with the A* heuristic); when u is extracted, each successor v with d[u] < d[v] is examined (edges with
/// d[u] >= d[v] cannot improve v and are skipped without a cost-function call); the edge weight is
/// travel->travelTime(u, v, d[u]); an improved vertex is inserted again even when it was already expanded
/// ("discover or reopen"). With Zermelo pruning, for u != s the optimal course phi_opt at u is predicted by
/// CALC-OPTDIR (calcOptimalCourse()) and only successors whose edge direction lies within +-deltaPhiMax of it are
/// examined. The search stops when the goal vertex is extracted.
///
/// Arrivals after ctx->region.tMax (the end of the planning window) are dropped.
/// Forbidden regions: vertices with inWater() false are never entered; with an Environment, a vertex must be
/// pointFree() at its arrival time and the edge legFree() for its times, both checked only when the edge is about
/// to improve the vertex (lazily, after its travel time is known).
class TveSearch
{
public:
    /// @brief Search over ctx->region's x/y bounds with the given lattice spacing and sectors.
    /// Throws ompl_glider::Error on a null context, field or travel, or bad lattice parameters.
    TveSearch(std::shared_ptr<const GliderContext> ctx, double gridSize, unsigned sectors);
    TveSearch(const TveSearch &) = delete;
    TveSearch &operator=(const TveSearch &) = delete;

    /// @brief Runs the search from (sx, sy), departing at t0 (the start state's time, d[s] = t0), to (gx, gy).
    /// terminate() is called every options.checkEvery expansions (and once before the first); when it returns true
    /// the search stops.
    TveResult run(double sx, double sy, double t0, double gx, double gy, const TveOptions &options,
                  const std::function<bool()> &terminate = {});

    /// @brief CALC-OPTDIR ([EichhornRAS] Sec. 2.2.2, Table 2): the optimal course over ground at u predicted by
    /// Zermelo's law. Starts at the middle of the edge p -> u at the mid time (tp + tu) / 2 with the heading that keeps
    /// the course along the edge (upper root of [EichhornRAS] Eq. 5-6), integrates Zermelo's law ([EichhornRAS] Eq. 2,
    /// with the field's Jacobian) together with the motion ([EichhornRAS] Eq. 10) by `steps` midpoint steps up to tu,
    /// and returns the direction of the velocity over ground there. Empty when the edge cannot be held at its middle or
    /// the ground speed vanishes. Costs 4 steps + 1 CMC.
    std::optional<double> calcOptimalCourse(double px, double py, double tp, double ux, double uy, double tu,
                                            unsigned steps) const;

    /// @brief The lattice of the last run (start/goal joined).
    const Lattice &lattice() const { return lattice_; }
    /// @brief Vertices reached by the last run with their predecessor and arrival time.
    std::vector<TveTreeVertex> tree() const;

private:
    /// One search of runCore() with its steps ([EichhornRAS] Table 2; TveSearchCore.cpp).
    class Core;

    std::vector<TimedPoint> pathTo(Lattice::VertexId v) const;
    TveResult runCoarseToFine(double sx, double sy, double t0, double gx, double gy, const TveOptions &options,
                              const std::function<bool()> &terminate);
    TveResult runPhases(double sx, double sy, double t0, double gx, double gy, const TveOptions &options,
                        const std::function<bool()> &terminate);
    TveResult runCore(double sx, double sy, double t0, double gx, double gy, const TveOptions &options,
                      const std::function<bool()> &terminate);

    /// Travel times of edges by (u, v, departure time), kept between the phases of one run (greedyDeadline).
    struct EdgeKey
    {
        Lattice::VertexId u, v;
        double t;
        bool operator==(const EdgeKey &o) const { return u == o.u && v == o.v && t == o.t; }
    };
    struct EdgeKeyHash
    {
        std::size_t operator()(const EdgeKey &k) const
        {
            std::uint64_t b;
            static_assert(sizeof b == sizeof k.t);
            std::memcpy(&b, &k.t, sizeof b);
            std::uint64_t h = k.u * 0x9E3779B97F4A7C15ULL ^ (k.v + 0x632BE59BD9B4E019ULL) * 0xC2B2AE3D27D4EB4FULL;
            h ^= b + 0x165667B19E3779F9ULL + (h << 6) + (h >> 2);
            return static_cast<std::size_t>(h);
        }
    };
    std::unordered_map<EdgeKey, double, EdgeKeyHash> *edgeCache_{nullptr};

    std::shared_ptr<const GliderContext> ctx_;
    Lattice lattice_;
    /// Arrival time d[v] and predecessor pi[v] of a reached vertex (hash map: memory grows with the vertices
    /// reached, not with the lattice).
    struct Label
    {
        double d{std::numeric_limits<double>::infinity()};
        Lattice::VertexId pi{Lattice::kNone};
        /// Departure from pi[v] when the glider held position there first (a waiting edge, TveOptions::waiting);
        /// -inf when it left on arrival
        double dep{-std::numeric_limits<double>::infinity()};
        bool expanded{false}; ///< expanded once (TveOptions::reopen off)
    };
    bool ignoreGoalWindow_{false}; ///< the fallback run of run() (TveOptions::goalWindowFallback)
    /// Hold at the goal after the arrival d[goal] up to this time (the goal window opens then); -inf: none
    double goalHoldUntil_{-std::numeric_limits<double>::infinity()};
    VertexPages<Label> labels_; // pages of vertices: memory grows with the area the search visits
    double dist(Lattice::VertexId v) const { return labels_.get(v).d; }
    Lattice::VertexId parent(Lattice::VertexId v) const { return labels_.get(v).pi; }
    std::vector<Lattice::VertexId> reached_;
    std::unique_ptr<LatticeHeuristic> bounds_; ///< kept while the time window and cell factor stay the same
    bool boundsRefined_{false};                ///< bounds_ was narrowed to one run's corridor
    std::shared_ptr<CellBoxCache> boxCache_;   ///< velocity boxes per cell and unit time slice (CellBoxCache::shared)
    /// Coarse-to-fine (TveOptions::coarseFactor): the coarse search, and the corridor of the fine one (per block of
    /// corridorFactor_ x corridorFactor_ cells, 1 = inside; empty = no corridor)
    std::unique_ptr<TveSearch> coarse_;
    std::vector<unsigned char> corridor_;
    long corridorFactor_{1}, corridorNX_{0};
    bool inCorridor(Lattice::VertexId v) const
    {
        if (corridor_.empty() || v >= lattice_.numGridVertices())
            return true;
        const long I = lattice_.columnOf(v) / corridorFactor_, J = lattice_.rowOf(v) / corridorFactor_;
        return corridor_[static_cast<std::size_t>(I + J * corridorNX_)] != 0;
    }
};
} // namespace ompl_glider
