#pragma once
/// @file LevelSet.h
/// @brief Reachability by a level-set equation: the set a glider can reach from a start by each time, its first
/// arrival time everywhere, the time-optimal path by backtracking, and isochrones ([LollaLevelSet]).

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief Resolution and numerics of the level-set solver.
struct LevelSetParams
{
    double cellSize{0.05}; ///< grid spacing h (the field's length unit); > 0
    /// time step dt = cfl * h / (V + max|c|), and V dt at most 2 cells; cfl in (0, 8], or 0: automatic, 4 in open
    /// water and 1.5 where there is a forbidden set (semi-Lagrangian: stable beyond 1; fewer, longer steps
    /// interpolate phi fewer times, so in open water up to about 4 the front is both faster and more accurate,
    /// bench_levelset; near a coast or an island a step reaches past what a straight drift can, and the front comes
    /// out slow: 1.2 % on the islands of test_reachability at cfl 4)
    double cfl{0.0};
    double band{6.0};    ///< narrow band: phi is kept within +-band cells of the front; in [4, 50]
    unsigned threads{0}; ///< threads sharing each step (0: all cores)
    /// reinitialise phi to a signed distance every this many steps; 0: automatic (every 4 steps at cfl 1.5, every 3
    /// at cfl 4: every 4 there leaves dents in the front that persist, the uniform-current disc test; every step adds
    /// the reinitialisation's own error); < 0: never
    int reinitEvery{0};
    double clearance{0.0};   ///< forbidden regions grown by this distance (>= 0; the planner keeps half a cell so that
                             ///< its straight legs clear them; 0 for the reference optimum)
    bool narrowBand{true};   ///< update only the tiles near the front (false: every node every step; for measuring)
    int headingScan{0};      ///< 0: the heading along grad phi, +-0.25 rad and the parabola (4 evaluations); N > 0:
                             ///< N evenly spaced headings instead (for measuring what the gradient buys)
    bool iceForbidden{true}; ///< ice zones are kept out of the front (the glider cannot surface there); false: they
                             ///< are ignored (the limit on the time under ice is not modelled either way)
    /// Coarse to fine, for a solve that stops at its goal where the forbidden set does not change in time: a front at
    /// three times the cell finds the goal's arrival, a backward front from the goal (the current reversed in time)
    /// the latest departure from every point that still arrives within 3 % of it, and the fine front updates only
    /// the corridor of points that can still be on the fastest route, grown by 4 cells (the whole front again when
    /// the corridor cut the route); false: every node, for measuring
    bool corridor{true};
    /// Stop once this many node updates are done (0: no limit): a budget of work that, unlike a time limit, ends the
    /// same solve at the same step on any machine and under any load
    std::uint64_t maxNodeUpdates{0};
};

/// @brief Work done by one solve.
struct LevelSetStats
{
    std::uint64_t steps{0};        ///< time steps taken
    std::uint64_t nodeUpdates{0};  ///< node updates (the narrow band's work)
    std::uint64_t currentCalls{0}; ///< current-model calls (CMC)
    double seconds{0.0};           ///< wall time
    unsigned threads{1};           ///< threads used
    double dt{0.0};                ///< time step
    std::size_t nodes{0};          ///< grid nodes
    bool budgetSpent{false};       ///< LevelSetParams::maxNodeUpdates ended the propagation
};

/// @brief What one solve gives: the first-arrival field on the grid, the goal's arrival and the optimal path.
struct Reachability
{
    double x0{0.0}, y0{0.0}, h{1.0}; ///< node (i, j) is at (x0 + i h, y0 + j h)
    int nx{0}, ny{0};                ///< node counts
    double t0{0.0};                  ///< departure time
    /// First arrival time per node (index j * nx + i; absolute time); +inf where the front never came.
    std::vector<double> arrival;
    bool goalReached{false};                                  ///< the front reached the goal (within the time limit)
    double goalTime{std::numeric_limits<double>::infinity()}; ///< first arrival at the goal (absolute)
    /// No water links the goal to the start on the grid (a flood fill through the static forbidden set, with jumps
    /// as long as one step's reach): the front cannot reach it, and no step was taken.
    bool goalWalledOff{false};
    /// Time-optimal path from the start (t0) to the goal (goalTime) by backtracking; empty without a goal. A hold
    /// appears as two points at the same position.
    std::vector<TimedPoint> path;
    LevelSetStats stats;

    /// @brief First arrival time at (x, y) by bilinear interpolation of the nodes (+inf where a corner is unreached
    /// or outside the grid).
    double arrivalAt(double x, double y) const;
    /// @brief The boundary of the set reached by time @p t ({T <= t}): polylines (closed ones repeat their first
    /// point) by marching squares on the arrival field.
    std::vector<std::vector<Point2>> isochrone(double t) const;
};

/// @brief The level-set solver: the reachable set from a start at t0 is {phi <= 0} with
///   phi_t + V |grad phi| + c(x, t) . grad phi = 0  ([LollaLevelSet]),
/// on a uniform grid over the context's region, forbidden regions kept outside the front.
///
/// Scheme (semi-Lagrangian, one step t -> t + dt): the set reachable at t + dt is the set of points x = y +
/// dt (c + V u), |u| <= 1, with y reachable at t, so phi(x, t + dt) = min over |u| <= 1 of phi(y(u), t), the
/// departure point y(u) = x - dt (c(x_m, t + dt/2) + V u) by the midpoint rule (x_m = x - dt/2 (c(x, t + dt) +
/// V u)). The minimum over the disc is taken at the heading along grad phi (the cubic's gradient at the departure
/// point; exact for a locally linear phi), at 0.25 rad to each side and at the vertex of the parabola through those
/// three (the kinks where fronts meet), and at the disc's centre, u = 0 (drifting, or holding where |c| < V; it
/// covers a minimum inside the disc, the start); where grad phi is too small to trust, at 8 headings.
/// phi between nodes is bicubic (Catmull-Rom) with a monotone limiter (clipped to the cell's corner values):
/// bilinear is too diffusive, an unlimited cubic overshoots at the band's edge and at obstacles. The splitting of
/// the two terms into an upwind expansion and an advection step, which fails where |c| > V, is not used: the
/// departure point moves with both at once.
///
/// Start: the exact reachable disc of the first instant (centre start + dt0 c(start), radius V dt0 = four cells;
/// with two, the first steps leave a dent in the front that persists), first arrivals inside it in closed form.
/// Reinitialisation: every reinitEvery steps phi becomes the signed distance to its zero level (located by linear
/// interpolation on the cell edges, left in place): a minimum over a disc never lowers phi below its least value,
/// so without it the inside flattens to the first disc's depth and the cubic sees a kinked profile.
/// Forbidden regions: after each step phi = max(phi, d(x, t) + clearance), d the signed distance to the forbidden
/// set (positive inside): exact for polygons (static regions; time-windowed zones while closed; ice zones at their
/// drifted position unless iceForbidden is false), from the node mask for land (the field's inWater()) and for any
/// other Environment (pointFree() at the nodes). Points outside the region are unreachable. A step ends where a
/// time-windowed zone opens or closes.
/// Narrow band: phi is clipped to +-band h; only 16 x 16 tiles holding an unclipped value, and their neighbours,
/// are updated; the tiles of a step are shared by the threads.
/// First arrival T(x) = the time phi(x) first becomes <= 0, linear in phi within the step; the goal's by the
/// interpolated phi at the goal. Convergence is first order in the cell size, the front slow, never fast.
/// Backtracking: from the goal at its arrival time back in time with dx/dt = c + V n, n = grad T / |grad T| (the
/// front's outward normal at the point it passes at that time), midpoint rule; where T(x) is earlier than the
/// path's time by more than a tolerance the glider held there (it arrived earlier and waited, e.g. for a lane to
/// open): the path holds until T(x), if |c| < V there. Near a moving forbidden region T is not the front at the
/// path's time, so a step that enters the region turns to the nearest free heading (a local repair).
/// Memory: three doubles per node (phi twice, T), nothing per step.
class LevelSetSolver
{
public:
    /// @throws Error for a null context or a parameter out of range, or when the grid would exceed the memory limit
    LevelSetSolver(std::shared_ptr<const GliderContext> ctx, LevelSetParams params = {});
    ~LevelSetSolver();

    /// @brief Propagates the front from (sx, sy) at t0 until @p tEnd, or until the goal is reached when
    /// @p goal is given and @p stopAtGoal. Checks @p stop (if any) every step and returns what it has when it
    /// answers true.
    Reachability solve(double sx, double sy, double t0, double tEnd, const std::optional<Point2> &goal,
                       bool stopAtGoal = true, const std::function<bool()> &stop = {}) const;

    /// @brief The parameters in use.
    const LevelSetParams &params() const { return params_; }

private:
    /// The coarse corridor (LevelSetParams::corridor) of a solve from (sx, sy) at t0 to @p goal: per node of the
    /// grid, 1 where the fastest route may pass; empty where it does not apply or the coarse front did not reach the
    /// goal. Adds the coarse work (node updates) to @p work; @p tRef: the latest goal arrival the corridor keeps.
    std::vector<char> corridor(double sx, double sy, double t0, double tEnd, Point2 goal,
                               const std::function<bool()> &stop, std::uint64_t &work, double &tRef) const;

    struct Impl;
    std::shared_ptr<const GliderContext> ctx_;
    LevelSetParams params_;
    std::unique_ptr<Impl> impl_;
};
/// @brief The cell size LevelSetPlanner uses for resolution 0: 1/200 of the region's larger side.
double defaultLevelSetResolution(const GliderContext &ctx);
} // namespace ompl_glider
