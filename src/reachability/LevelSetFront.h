#pragma once
/// @file LevelSetFront.h
/// @brief One solve of the level-set equation (FrontPropagation); internal, not installed. Its setup, steps and
/// forbidden set are in LevelSet.cpp, the step's work on the narrow band (which tiles and nodes, the current sampled
/// once per step, the minimum over the departure disc) in LevelSetStep.cpp.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "LevelSetInternal.h"
#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
class ThreadPool;

namespace levelset_detail
{
/// First time in (0, tau] at which w (the offset from the start) is in the disc of centre c tau' and radius V tau'
/// (a uniform current over the first instant); +inf when never.
double discArrival(double wx, double wy, double cx, double cy, double V, double tau);

/// Which way a front runs in time. Forward: from a start at t0 on. Backward: from a goal back in time, the front's
/// time s standing for the absolute time tRef - s and the current reversed (-c(x, tRef - s)): its first arrival at
/// x is how long before tRef the glider must leave x to reach the goal by tRef (the coarse corridor's second half).
struct FrontDirection
{
    bool backward{false};
    double tRef{0.0};
};

/// One solve of the level-set equation (see LevelSetSolver): the front phi on the grid, the narrow band's tiles, the
/// forbidden set at the front's time and the result being filled. initialise() sets the first instant's disc;
/// propagate() then takes steps t -> t + ds, each:
///  1. the active tiles (the band's tiles and their neighbours) and, per tile, the nodes that can change (an
///     unclipped value within reach of the step's departure points and their cubic stencil: the others keep their
///     clipped value exactly), and the current sampled once at the step's midpoint time at the nodes the step reads
///     (structure of arrays, one field call per node);
///  2. the minimum over every changing node's departure disc (nodeValue());
///  3. the forbidden set kept out, the first arrivals recorded, the band's tiles found again;
/// each phase shared by the threads tile by tile, with no serial pass over the grid. reinitialiseIfDue() and
/// checkGoal() follow.
class FrontPropagation
{
public:
    FrontPropagation(const SolverGrid &sg, const GliderContext &ctx, const LevelSetParams &params,
                     FrontDirection direction = {});

    /// The initial front: the exact reachable disc after dt0 ([LollaLevelSet]: start from the first instant's
    /// disc), the forbidden set kept out of it, and the goal's arrival when the disc holds it.
    void initialise(double sx, double sy, double t0, const std::optional<Point2> &goal);
    /// Only nodes with keep[n] != 0 are ever updated (the others keep +band: outside the reachable set); empty: all.
    void restrictTo(std::vector<char> keep) { keep_ = std::move(keep); }
    /// Counts @p work node updates done before this front (a coarse corridor's) against the budget and in the stats.
    void countWork(std::uint64_t work) { updates_ += work; }
    /// Steps until @p tEnd, until the goal is reached when @p stopAtGoal, or until @p stop (if any) answers true;
    /// may be called again to go on.
    void propagate(double tEnd, bool stopAtGoal, const std::function<bool()> &stop);

    /// The result so far (arrival field, goal, work done); moved out by the caller at the end.
    Reachability &result() { return out_; }
    double dt() const { return dt_; }
    double dt0() const { return dt0_; }

private:
    // LevelSet.cpp: the forbidden set, the first arrivals, the goal, the reinitialisation.
    void updateForbidden(double t);
    std::vector<double> eventTimes() const;
    double stepLength(const std::vector<double> &events) const;
    void reinitialiseIfDue(std::size_t step, ThreadPool &pool);
    void checkGoal(double t1);
    /// The current at (x, y) at the front's time @p t (reversed for a backward front).
    Velocity current(double x, double y, double t) const
    {
        if (!direction_.backward)
            return field_.velocity(x, y, z_, t);
        const Velocity c = field_.velocity(x, y, z_, direction_.tRef - t);
        return {-c.u, -c.v};
    }

    // LevelSetStep.cpp: one step's work on the band.
    void step(ThreadPool &pool, double t1, double tm);
    void findActive();
    void markTile(std::uint32_t tile, double tm);
    void settleTile(std::uint32_t tile, double t1);
    void refreshLive(std::uint32_t tile);
    Velocity sampledCurrent(double x, double y, double tm) const;
    bool crossesForbidden(double x, double y, double px, double py) const;
    double nodeValue(std::size_t n, double x, double y, double tm) const;

    /// Calls fn(i, j) for every node (i, j) of @p tile.
    template <typename Fn> void forTileNodes(std::uint32_t tile, Fn &&fn) const
    {
        const int a = static_cast<int>(tile % tx_), b = static_cast<int>(tile / tx_);
        for (int j = b * kTile; j < std::min(g_.ny, (b + 1) * kTile); ++j)
            for (int i = a * kTile; i < std::min(g_.nx, (a + 1) * kTile); ++i)
                fn(i, j);
    }

    const SolverGrid &sg_;
    const Grid &g_;
    const LevelSetParams &params_;
    const CurrentField &field_;
    const double band_, V_, z_;
    const FrontDirection direction_;
    std::optional<Point2> goal_;
    Reachability out_;
    double dt_{0.0};   ///< the time step
    double dt0_{0.0};  ///< the initial disc's time
    double t_{0.0};    ///< the front's time
    double tEnd_{0.0}; ///< the end asked of propagate(): no goal arrival after it

    // The forbidden set at time t_: static part, closed zones, drifted ice, other environments' masks.
    std::vector<double> obstacle_;
    std::vector<std::uint32_t> dynamicNodes_; ///< nodes whose obstacle value differs from the static one
    std::vector<char> keep_;                  ///< the corridor (restrictTo()); empty: every node

    std::vector<double> phi_, next_; ///< the front now and after the step (next_ only on the active tiles)
    double goalPhi_{0.0};            ///< phi at the goal (interpolated) after the last step

    // Tiles of the narrow band.
    int tx_{0}, ty_{0};
    std::vector<char> tileLive_;             ///< the tile holds an unclipped value of phi
    std::vector<std::uint32_t> activeTiles_; ///< this step's tiles
    std::vector<std::uint32_t> tileUpdates_; ///< per active tile: the nodes updated
    double bandInner_{0.0};
    int reach_{0};  ///< nodes a step's departure point and its cubic stencil reach from the node (Chebyshev)
    int sample_{0}; ///< nodes the step's current samples are read at from the node
    /// Every node's departure ways are checked against the forbidden set (a step longer than the band is wide);
    /// else only those of nodes within the band of it.
    bool guardAll_{false};

    // Per node, this step: 1 = update (the minimum over its disc), and the current at the step's midpoint time
    // (structure of arrays) with the step that sampled it.
    std::vector<char> update_;
    std::vector<double> cu_, cv_;
    std::vector<std::uint32_t> sampled_;
    std::uint32_t stepId_{0};

    double ds_{0.0}; ///< this step's length (shortened to end at a zone's opening or closing)
    double r_{0.0};  ///< the departure disc's radius V ds
    std::uint64_t updates_{0};
    std::vector<double> reinitDist_;
};
} // namespace levelset_detail
} // namespace ompl_glider
