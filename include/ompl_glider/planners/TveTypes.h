#pragma once
/// @file TveTypes.h
/// @brief The switches, outcome and result of the TVE / A*TVE / ZTVE / ZA*TVE search ([EichhornRAS] Sec. 2.2,
/// Tables 1 and 2): what ZAStarTVE's users set and read. The search itself (TveSearch, on the lattice's internals)
/// is internal to the library.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
/// @brief No lattice vertex (the start's predecessor in TveTreeVertex).
inline constexpr std::size_t kNoTveVertex = std::numeric_limits<std::size_t>::max();

/// @brief Switches and tunables of the search.
struct TveOptions
{
    bool heuristic{true}; ///< A*: h(u) = |x_u - x_g| / (V + max|c|) ([EichhornRAS] Eq. 1), or tighter (tightBounds)
    /// Lower bounds from LatticeHeuristic (an addition to [EichhornRAS]; default on; used when heuristic or zermelo is
    /// on): per-cell, per-direction speed bounds over the search's time window give a lower bound of every edge's
    /// travel time and, by an optimistic backward search from the goal, a consistent heuristic at least as large as
    /// Eq. 1's. They serve as (1) the A* heuristic max(Eq. 1, h), (2) the certificate of deferred edges
    /// (d[u] + edge bound + h(v), tight where the current is weak or against the edge), and (3) a test that skips
    /// the cost-function call of an edge that cannot improve its end vertex (d[u] + edge bound >= d[v]) or the goal
    /// (d[u] + edge bound + h(v) >= d[goal]). None of them changes the result: the search stays exact on the lattice.
    bool tightBounds{true};
    /// Lattice cells per side of the cells of LatticeHeuristic's velocity bounds (0 = automatic: 1 up to 2^16
    /// lattice cells, then coarser so that there are at most about 2^16 cells).
    unsigned boundCellFactor{0};
    bool zermelo{true}; ///< Zermelo pruning ([EichhornRAS] Sec. 2.2.2)
    /// Half-width of the accepted course range around phi_opt, radians ([EichhornRAS] Fig. 3, Table 2), before the turn
    /// widening below. Defaults (18 deg, courseExtrapolation 1, turnWidening 1.5) were tuned on the meandering jet
    /// (grid 0.4, 3 sectors; benchmarks/table4/README.md): where the course runs straight they keep 1 to 3 of the 31
    /// forward successors of a 3-sector lattice (the paper: 5). The paper's rule is courseExtrapolation = 0,
    /// turnWidening = 0 with a fixed range.
    double deltaPhiMax{18.0 * 3.14159265358979323846 / 180.0};
    /// Midpoint (RK2) steps of CALC-OPTDIR per half edge; each step costs 2 velocity + 2 Jacobian calls (CMC).
    unsigned zermeloSteps{1};
    /// Extrapolation of the predicted course: the cone is centred on phi_opt + k (phi_opt - phi_edge), where
    /// phi_edge is the direction of the predecessor edge. k = 0 is the paper's rule ([EichhornRAS] Table 2); k = 1
    /// continues the turn predicted from the middle of the predecessor edge over the next half edge.
    double courseExtrapolation{1.0};
    /// Widening of the cone with the predicted turn: half-width = deltaPhiMax + w |phi_opt - phi_edge| (0 = the
    /// paper's fixed range). Where Zermelo's law turns the course fast (jet flanks), a lattice path turns by more
    /// than the prediction over one edge; this keeps pruning hard where the course runs straight.
    double turnWidening{1.5};
    /// Reliability of the prediction: no pruning at a vertex whose predicted turn |phi_opt - phi_edge| exceeds this
    /// (radians; +inf = always prune). A large predicted turn marks the jet's flanks, where one midpoint step of
    /// CALC-OPTDIR from the middle of the predecessor edge mispredicts the lattice optimum's next edge most often.
    double reliableTurn{std::numeric_limits<double>::infinity()};
    /// No pruning at vertices within this distance of the goal (0 = prune everywhere but the goal edge): the final
    /// approach of the lattice optimum often turns towards the goal faster than Zermelo's law predicts.
    double goalRadius{0.0};
    /// Certification of the pruned search (an addition to [EichhornRAS] Table 2; default 0; < 0 = off, the paper's
    /// rule). Without it the pruning misses the lattice optimum on some problems (campaign open water +1.25 %, islands
    /// +5.1 %, random pairs up to +76 %; benchmarks/table4/README.md). Pruned edges are deferred instead of dropped,
    /// each with a lower bound of the queue key its end vertex would get through it: d[u] + (edge bound) + h(v)
    /// (LatticeHeuristic's edge bound with tightBounds, else |uv| / (V + max|c|); h the queue's heuristic, 0
    /// without A*). A deferred edge is examined once t0 + (bound - t0)(1 + tol) is not above the queue's smallest key,
    /// interleaved with the queue (its improvements are expanded with pruning, their pruned edges deferred again).
    /// With tol = 0 (and a consistent heuristic) every vertex is extracted with its final label: the result is TVE's
    /// (the fixpoint d(v) = min_u d(u) + w(u, v, d(u)), also where the field is not FIFO), at the cost of the deferred
    /// edges whose bound lies below the goal's arrival (benchmarks/search/README.md). A larger tol examines fewer of
    /// them and bounds the travel time by about (1 + tol) times TVE's.
    double certifyTolerance{0.0};
    /// When the pruned search (zermelo) exhausts without reaching the goal, continue without pruning, so that
    /// "no solution" still means "no path on this lattice" (an addition to [EichhornRAS] Table 2, which does not say).
    bool unprunedFallback{true};
    /// Never prune the edge into the goal vertex (an addition to [EichhornRAS] Table 2: near the goal the predicted
    /// course rarely points exactly at it, and without this a pruned search often has to fall back).
    bool neverPruneGoal{true};
    /// When no edge inside the cone of a vertex has a finite travel time (the predicted course leaves the region,
    /// runs into land, or is infeasible against the current), examine the vertex's other edges too (an addition to
    /// [EichhornRAS] Table 2; costs cost-function calls only at such dead ends).
    bool deadEndFallback{false};
    /// Latest arrival accepted by this search (NaN = the end of the planning window, region.tMax; a later value is
    /// clamped to it). Arrivals after it are dropped, and LatticeHeuristic's bounds cover only [t0, deadline], so a
    /// short deadline gives tighter bounds. The result is the same as with the full window whenever the optimum
    /// arrives by the deadline (the labels TVE computes are built in increasing order of arrival time, so those up to
    /// the deadline never use a later arrival); otherwise the search exhausts.
    double deadline{std::numeric_limits<double>::quiet_NaN()};
    /// Two phases (an addition to [EichhornRAS]; default on; with tightBounds and heuristic, when no deadline is
    /// given): first a greedy pruned search (weighted A*, key d + greedyWeight h, Zermelo pruning without
    /// certification) finds some arrival C1; then the search runs with deadline t0 + C1 and LatticeHeuristic's
    /// boxes narrowed to the space-time corridor of the paths that arrive by it (windowRounds rounds of
    /// LatticeHeuristic::refineWindows). Travel times computed in the first phase are reused in the second (same
    /// edge, same departure time). The result is the same as without the phases: if the optimum arrives after
    /// t0 + C1 (possible only where the field is not FIFO) the second phase exhausts and the search repeats
    /// without deadline.
    bool greedyDeadline{true};
    /// Weight of the heuristic in the first phase (greedyDeadline).
    double greedyWeight{1.5};
    /// Expand a vertex again when its label improves after its expansion (TVE's "discover or reopen",
    /// [EichhornRAS] Table 1; default). Off: each vertex is expanded once, with the label it had then; the search
    /// still returns the arrival of a real path, no longer the optimum. The greedy first phase of greedyDeadline
    /// runs without it: weighted A* with reopening re-expanded vertices of a coarse gridded lattice over a thousand
    /// times each on near-ties (micro-improvements of 1e-6), 21 million CFC where the exact search needed 900.
    bool reopen{true};
    /// Rounds of LatticeHeuristic::refineWindows when a deadline is set (0 = none; skipped on lattices of more than
    /// 2^18 vertices, where its two static searches over the whole lattice would cost more than they save).
    unsigned windowRounds{1};
    /// Weight w of the heuristic in the queue key d + w h (1 = A*; > 1 = weighted A*, which gives up exactness).
    double heuristicWeight{1.0};
    /// Holding in the search ([ThompsonICRA] Sec. III, hold-position actions; default on): when a leg from
    /// u is blocked by the environment at u's arrival time d[u] (a time-windowed zone closes the lane, or the end
    /// vertex is closed then) and the glider can hold at u (|c| < V over the hold, GliderContext::canHold), the leg is
    /// also tried departing just after each release time of the environment (Environment::releaseTimes(): the ends of
    /// the zones' windows) later than d[u], earliest first, up to the first that gives a free leg (a waiting edge; the
    /// path then holds at u: the same position twice with two times). With a goal window
    /// (GliderContext::arriveNotBefore / arriveNotAfter) an arrival at the goal counts only inside it: an early one
    /// where the goal can be held (the path then holds there up to the window's begin), else the edge into the goal
    /// is flown from u after a hold found by bisection so that it arrives at the window's begin (the earliest valid
    /// arrival); arrivals after the window's end are dropped. What remains heuristic: waits only at lattice
    /// vertices, only at release times (and before the goal edge), and the first free release time is taken, which
    /// is the best one only where arrival does not decrease with departure (FIFO); legs are flown at full speed,
    /// never slower. The lower bounds (A* heuristic, edge bounds, certification) stay bounds: they bound the flight
    /// time whatever the departure within the search's time window, and holding only adds time.
    bool waiting{true};
    /// With a goal window: when no path meets it (it closes before any arrival, or the goal cannot be held and the
    /// vertex before the goal edge cannot either), search again ignoring it and return that earliest arrival with
    /// TveResult::goalWindowMissed set, so that the caller can time the arrival elsewhere on the path or report why
    /// (planRoute() does both). Off: such a search exhausts.
    bool goalWindowFallback{true};
    /// Coarse-to-fine ([EichhornRAS] Sec. 2.2, the "pipe" around a first path; an addition to its Table 2): the
    /// search first runs on a lattice of spacing coarseFactor x gridSize over the same region, then on this
    /// lattice restricted to a corridor of blocks (coarseFactor x coarseFactor cells each) within corridorBlocks
    /// blocks (Chebyshev distance) of the blocks the coarse path crosses; while the fine path enters the outermost
    /// ring of blocks, or no path lies inside, the corridor is doubled and the fine search repeated (the corridor
    /// reaching the whole lattice is the full search). The result equals the full search's whenever the full
    /// search's optimum lies inside the final corridor; no bound certifies that (a path far outside the corridor,
    /// e.g. around an island the other way, that is faster is missed; benchmarks/search/README.md measures it).
    /// 0 = automatic: 8 on lattices of more than 2^19 grid vertices with the A* heuristic on (TVE, the plain
    /// reference search, stays a full search), else off; 1 = off.
    unsigned coarseFactor{0};
    /// First half-width of the corridor, in blocks (>= 1).
    unsigned corridorBlocks{2};
    /// Expansions between two calls of the termination callback.
    unsigned checkEvery{8};
};

/// @brief How a search ended.
enum class TveOutcome
{
    Exact,        ///< the goal vertex was extracted from the queue: waypoints hold the optimal lattice path
    Exhausted,    ///< the queue ran empty: no path to the goal exists on this lattice (within the field's time)
    Terminated,   ///< the termination callback fired: waypoints lead to the reached vertex closest to the goal
    InvalidStart, ///< start outside the bounds, on land or in a forbidden region at t0, or t0 not finite or
                  ///< outside [region.tMin, region.tMax] (see message)
    InvalidGoal   ///< goal outside the bounds, on land or in a forbidden region (see message)
};

/// @brief Result of one search.
struct TveResult
{
    TveOutcome outcome{TveOutcome::Exhausted}; ///< how the search ended
    std::vector<TimedPoint> waypoints;         ///< start ... goal (Exact) or ... closest reached vertex (Terminated)
    double travelTime{std::numeric_limits<double>::infinity()}; ///< arrival at the goal - t0 (Exact only)
    std::uint64_t costFunctionCalls{0};                         ///< CFC of this search ([EichhornRAS] Table 4)
    std::uint64_t currentModelCalls{0}; ///< CMC of this search, CALC-OPTDIR included ([EichhornRAS] Table 4)
    std::uint64_t expansions{0};        ///< vertices extracted from the queue (reopenings counted again)
    std::uint64_t prunedEdges{0};       ///< edges not examined because of Zermelo pruning
    std::uint64_t reopenedEdges{0};     ///< deferred (pruned) edges examined by the certification phase
    std::uint64_t deadEnds{0};          ///< expansions whose Zermelo cone was a dead end (see deadEndFallback)
    std::uint64_t boundSkips{0};        ///< edges whose CFC the lower bounds saved (TveOptions::tightBounds)
    std::uint64_t heuristicSettled{0};  ///< vertices settled by LatticeHeuristic's backward search
    unsigned corridorRounds{0};         ///< fine searches of coarse-to-fine (TveOptions::coarseFactor), 0 = not used
    unsigned corridorBlocks{0};         ///< half-width of the final corridor in blocks (0 = not used)
    bool fallbackUsed{false};           ///< the pruned search exhausted and continued without pruning
    /// No path meets the goal window: the waypoints are the earliest arrival ignoring it
    /// (TveOptions::goalWindowFallback)
    bool goalWindowMissed{false};
    std::string message; ///< why the start or goal is invalid
};

/// @brief One vertex of the explored tree (a vertex that received a finite arrival time).
struct TveTreeVertex
{
    std::size_t id{kNoTveVertex};     ///< lattice vertex
    std::size_t parent{kNoTveVertex}; ///< predecessor pi[v] (kNoTveVertex for the start)
    double x{0.0}, y{0.0};            ///< position
    double t{0.0};                    ///< arrival time d[v]
};

} // namespace ompl_glider
