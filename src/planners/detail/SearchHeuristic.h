#pragma once
/// @file detail/SearchHeuristic.h (an internal of the lattice search, installed because TveSearch.h needs it; not API)
/// @brief A tight admissible and consistent A* heuristic for the lattice search: an optimistic backward search over
/// the lattice with per-cell, per-direction speed bounds, and the per-edge lower bound it is built from.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <queue>
#include <unordered_map>
#include <vector>

#include "ompl_glider/current/CurrentField.h"
#include "Lattice.h"
#include "VertexPages.h"

namespace ompl_glider
{
/// @brief Bounds of the current components over a region of space and time: u in [uMin, uMax], v in [vMin, vMax].
struct VelocityBox
{
    double uMin{0.0}, uMax{0.0}, vMin{0.0}, vMax{0.0};
};

/// @brief Bounds of the current over @p region (x, y and the time window [tMin, tMax]) at depth @p z.
///
/// For a MeanderingJet: an interval-arithmetic evaluation of the jet's closed form ([EichhornRAS] Eq. 7-9) over the
/// region, split into @p timeSlices equal sub-windows and 2 x 2 sub-boxes (each evaluation encloses every value the
/// formula takes on its box, so the union is a true bound); it costs no current-model call (the model is not sampled).
/// A field with CurrentField::velocityBounds() (a gridded forecast with linear schemes): its node extremes over the
/// region. Every other field: the box [-M, M]^2 with M = field.maxSpeed(region), the field's own bound (no gain, but
/// true).
/// The components are also clamped to [-M, M].
VelocityBox currentBounds(const CurrentField &field, const Region &region, unsigned timeSlices = 0);

/// @brief Velocity boxes of the cells of a lattice (cellFactor x cellFactor lattice cells each) per time slice
/// [origin + k dt, origin + (k + 1) dt], computed by currentBounds() on first use and kept: the box of a cell over
/// any window is the union of the boxes of the slices it overlaps (a true bound, slightly wider than the window's
/// own). Lets the searches of one problem (random pairs, departure sweeps, the phases of one run) share the interval
/// evaluations.
class CellBoxCache
{
public:
    CellBoxCache(std::shared_ptr<const CurrentField> field, const Lattice &lattice, double depth, unsigned cellFactor,
                 double origin, double dt);
    /// @brief Box of cell (I, J) over [ta, tb] (finite, ta <= tb). Thread-safe. Once @p stop answers true no new
    /// slice is computed: the box is then unbounded (the caller's global bound applies).
    VelocityBox box(long I, long J, double ta, double tb, const std::function<bool()> &stop = {});
    /// @brief Origin and length of the time slices.
    double origin() const { return origin_; }
    double dt() const { return dt_; }
    /// @brief True when built for this field, lattice geometry, depth, cell factor and slices.
    bool matches(const CurrentField *field, const Lattice &lattice, double depth, unsigned cellFactor, double origin,
                 double dt) const;
    /// @brief The process-wide cache for these arguments (made on first use; the last 16 are kept), so that the
    /// searches of one problem share it even when each builds its own TveSearch (departure sweeps, the mission code).
    static std::shared_ptr<CellBoxCache> shared(const std::shared_ptr<const CurrentField> &field,
                                                const Lattice &lattice, double depth, unsigned cellFactor,
                                                double origin, double dt);

private:
    std::shared_ptr<const CurrentField> field_;
    double xMin_, yMin_, g_;
    long nx_, ny_;
    double depth_, origin_, dt_;
    unsigned f_;
    long NX_, NY_;
    std::mutex mutex_;
    std::unordered_map<long, std::vector<VelocityBox>> slices_; // slice index -> per cell
};

/// @brief Optimistic lower bound of the travel time of straight legs, from per-cell velocity boxes, and an A*
/// heuristic from it: an optimistic backward search over the lattice.
///
/// **Edge bound.** A vehicle of speed V holding the course e along a leg in current c progresses at the fast root
/// s = c.e + sqrt(V^2 - (c.n)^2) ([EichhornRAS] Eq. 5-6; n the leg's normal), so s <= max c.e + sqrt(V^2 - min (c.n)^2)
/// over every current c the leg can meet, and the leg is infeasible where that bound is <= 0 or min |c.n| >= V.
/// The currents a leg meets lie in the velocity boxes of the cells its bounding box touches, over the time window
/// [t0, tEnd] of the search (arrivals after tEnd are dropped by the search). So
/// edgeLowerBound(u, v) = |uv| / sMax <= the travel time of the leg at any departure in the window (+inf when even
/// the optimistic speed is <= 0). The adaptive integration of CALC-TRAVELTIME ([EichhornIWK] Table III) uses the
/// current at points of the leg and means of two such currents, whose along-track speeds obey the same bound, so
/// the computed travel time obeys it too. sMax is also capped by V + maxSpeed (the bound of [EichhornRAS] Eq. 1), so
/// the bound is never weaker than that of the Euclidean heuristic.
///
/// **Heuristic.** h(v) = the smallest sum of edge bounds over the lattice paths from v to the goal (a static
/// Dijkstra search run backwards from the goal over the lattice with the edge bounds as weights, only through
/// water vertices). Admissible: the lattice optimum from v, departing at any time in the window, is the sum of
/// true edge travel times along some lattice path from v to the goal, and each is >= its edge bound, so it is >=
/// h(v). Consistent: h(u) <= edgeLowerBound(u, v) + h(v) <= w(u, v, t) + h(v) for every edge and departure time
/// (triangle inequality of shortest paths). The search is resumed lazily ("reverse resumable A*"): h(v) settles
/// vertices in order of h only until v is settled; labels are kept in a hash map, so memory grows with the
/// vertices settled, not with the lattice.
///
/// Cells: the velocity boxes are kept per coarse cell of cellFactor x cellFactor lattice cells; for each cell and
/// connectivity offset the largest bound over the cells an edge from that cell can touch is tabulated, so an edge
/// bound costs a table look-up.
class LatticeHeuristic
{
public:
    /// @brief Bounds for @p lattice (its start/goal need not be set yet) over the time window [tBegin, tEnd] at the
    /// travel depth z, vehicle speed V. cellFactor 0 picks one so that there are at most about 2^16 cells.
    /// @p stop (if any) is asked between rows of cells, slices and rounds, and by the backward search: once it answers
    /// true the bounds built so far stand (the rest are the global bound, still lower bounds) and h() answers 0 where
    /// it has not settled a vertex yet, so that the search that asked can stop within a second.
    LatticeHeuristic(const Lattice &lattice, const CurrentField &field, double speed, double depth, double tBegin,
                     double tEnd, unsigned cellFactor = 0, CellBoxCache *cache = nullptr,
                     std::function<bool()> stop = {});
    /// @brief The cell factor LatticeHeuristic picks for @p lattice when asked for 0.
    static unsigned autoCellFactor(const Lattice &lattice);

    /// @brief Narrows the time window of each cell's velocity box for the paths that arrive at the goal by the
    /// deadline tEnd() ("corridor in space-time"), in @p rounds rounds, and restarts the backward search.
    ///
    /// On a path that leaves the start at t0 and reaches the goal by tEnd, a vertex v is visited at a time in
    /// [t0 + a(v), tEnd - h(v)], where a(v) is the smallest sum of edge bounds from the start to v (a static forward
    /// search) and h(v) the smallest from v to the goal (the heuristic): both sums bound the true travel times from
    /// below, since every edge of such a path is flown inside the window the current bounds cover. An edge touching
    /// a cell has both ends within n lattice cells of it, so the currents it meets in that cell occur in the union of
    /// these intervals over the vertices near the cell: the box of the cell over that window (empty: no such path
    /// touches the cell) still bounds them, and the edge bounds and heuristic rebuilt from these boxes remain true
    /// lower bounds for every path that arrives by tEnd. By induction this holds after every round. Needs the
    /// lattice's start and goal set; costs two static searches over the lattice per round, no CFC or CMC.
    void refineWindows(unsigned rounds, const std::function<bool(Lattice::VertexId)> &inWater);

    /// @brief Starts a new backward search from the lattice's goal (call after Lattice::setGoal). @p inWater tells
    /// whether a vertex may be used (the search's land test); it must stay valid until the next reset().
    void reset(std::function<bool(Lattice::VertexId)> inWater);

    /// @brief Forgets the land test given to reset() and the stop test (call before they go out of scope).
    void releaseLandTest()
    {
        inWater_ = nullptr;
        stop_ = nullptr;
    }
    /// @brief The stop test of the search that uses these bounds now (see the constructor).
    void setStop(std::function<bool()> stop) { stop_ = std::move(stop); }

    /// @brief h(v): lower bound of the remaining travel time from v to the goal (+inf when even the optimistic
    /// search cannot reach the goal from v). The extra start vertex gets 0 (it has no predecessor edges).
    double operator()(Lattice::VertexId v);

    /// @brief Lower bound of the travel time of the lattice edge u -> v (any two vertices joined by an edge).
    double edgeLowerBound(Lattice::VertexId u, Lattice::VertexId v) const;

    /// @brief True when currentBounds() has local bounds for this field (a MeanderingJet, or a field whose
    /// CurrentField::hasVelocityBounds() is true); other fields get the global box everywhere.
    static bool hasLocalBounds(const CurrentField &field);
    /// @brief True when the local bounds are worth keeping per unit time slice (CellBoxCache): the jet's interval
    /// evaluation narrows with the slice; a gridded field's node bounds change only at its forecast records and
    /// are computed per window directly.
    static bool hasSlicedBounds(const CurrentField &field);
    /// @brief True when some cell's box is narrower than the field's global bound (else the bounds are those of
    /// [EichhornRAS] Eq. 1 and the backward search would only cost time).
    bool informative() const { return informative_; }
    /// @brief Time window of the bounds.
    double tBegin() const { return tBegin_; }
    /// @brief Time window of the bounds.
    double tEnd() const { return tEnd_; }
    /// @brief Lattice cells per coarse cell side.
    unsigned cellFactor() const { return f_; }
    /// @brief Vertices settled by the backward search since reset().
    std::size_t settled() const { return settled_; }
    /// @brief Velocity box of coarse cell (I, J).
    const VelocityBox &cellBox(long I, long J) const { return boxes_[static_cast<std::size_t>(I + J * NX_)]; }
    /// @brief Coarse cells along x and y.
    long cellsX() const { return NX_; }
    long cellsY() const { return NY_; }

private:
    /// Speed bound along unit direction (ex, ey) for box b (>= 0; 0 = the leg cannot be flown).
    double speedBound(const VelocityBox &b, double ex, double ey) const;
    long cellOfColumn(long i) const { return std::min(i / static_cast<long>(f_), NX_ - 1); }
    long cellOfRow(long j) const { return std::min(j / static_cast<long>(f_), NY_ - 1); }
    double genericBound(double x1, double y1, double x2, double y2) const;
    void buildTable();
    /// Static search over the whole lattice (forward from the start or backward from the goal) with the edge bounds.
    std::vector<double> staticSearch(bool forward, const std::function<bool(Lattice::VertexId)> &inWater) const;
    long cellOfVertex(Lattice::VertexId v) const;

    const Lattice &lat_;
    const CurrentField &field_;
    double depth_;
    double V_, vCap_, tBegin_, tEnd_;
    std::vector<unsigned char> empty_; // per coarse cell: no path within the deadline touches it
    bool informative_{false};
    CellBoxCache *cache_{nullptr};
    VelocityBox box(long I, long J, double ta, double tb, const Region &region, unsigned slices) const;
    unsigned f_;
    long NX_{1}, NY_{1};
    int n_;                          // sectors
    std::vector<VelocityBox> boxes_; // per coarse cell
    std::vector<double> invSpeed_;   // per coarse cell x offset: 1 / (largest speed bound), +inf = infeasible
    std::vector<double> len_;        // per offset: |o| g
    std::vector<int> offsetIndex_;   // (dx + n) + (dy + n) (2n + 1) -> offset index
    std::function<bool(Lattice::VertexId)> inWater_;
    std::function<bool()> stop_;
    bool stopped() const { return stop_ && stop_(); }

    struct Label
    {
        double d{std::numeric_limits<double>::infinity()}; ///< +inf: not reached
        bool settled{false};
    };
    struct QEntry
    {
        double d;
        Lattice::VertexId v;
        bool operator>(const QEntry &o) const { return d > o.d || (d == o.d && v > o.v); }
    };
    VertexPages<Label> labels_; // pages of vertices: memory grows with the area settled
    std::priority_queue<QEntry, std::vector<QEntry>, std::greater<QEntry>> queue_;
    std::size_t settled_{0};
};
} // namespace ompl_glider
