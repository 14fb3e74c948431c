#pragma once
/// @file LevelSetInternal.h
/// @brief Internal pieces of the level-set solver (LevelSet.h); not installed.
///
/// The solver is split by concern, one source file each (all in src/reachability/):
///  - LevelSetGrid.cpp       LevelSetSolver's constructor: its parameters checked, the grid and the forbidden set
///                           of a solver (SolverGrid) prepared once; defaultLevelSetResolution()
///  - LevelSet.cpp           LevelSetSolver::solve() as a sequence of steps (FrontPropagation, LevelSetFront.h:
///                           initial front, forbidden set, reinitialisation, goal) and the coarse corridor
///  - LevelSetStep.cpp       one step's work on the narrow band: the tiles and nodes that can change, the current
///                           sampled once per step, the minimum over each node's departure disc
///  - LevelSetDistance.cpp   signed distances to the forbidden set (polygons, node masks) and the reinitialisation
///                           of phi to a signed distance
///  - LevelSetBacktrack.cpp  the time-optimal path backtracked through the arrival field, and the queries of a
///                           Reachability (arrivalAt(), isochrone())

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/reachability/LevelSet.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
class CurrentField;
class Environment;
class IceZone;
class Polygon;
class TimeWindowedZone;
class ThreadPool;

namespace levelset_detail
{
/// Side of the square tiles of the narrow band, in nodes.
constexpr int kTile = 16;

/// The departure disc's radius V dt is at most this many cells: the minimum over a larger disc, found from the
/// gradient and three headings, is missed where the front curves (4 cells: 13 % slow in still water; 2.5: exact).
constexpr double kMaxDiscCells = 2.0;
/// The most nodes a step reads its current samples at from a node (FrontPropagation::sample_ at the largest cfl, 8).
constexpr int kMaxSampleReach = 18;
/// The automatic cfl (LevelSetParams::cfl = 0) in open water and where there is a forbidden set, and the
/// reinitialisation's period at each.
constexpr double kOpenWaterCfl = 4.0, kForbiddenCfl = 1.5;
constexpr int kOpenWaterReinit = 3, kForbiddenReinit = 4;
/// The coarse corridor (LevelSetParams::corridor): the coarse fronts' cell is this many fine ones (their work is
/// 1/9 of the fine front's each: a narrow band's work goes as 1 / h^2; at 2 the two coarse fronts cost half the fine
/// one and the corridor saved less), routes up to this fraction slower than the coarse front's are kept (the coarse
/// front is 0.2-0.5 % slow at 3 cells), and the corridor is grown by this many fine cells.
constexpr double kCorridorCoarsening = 3.0;
constexpr double kCorridorMargin = 0.03;
constexpr int kCorridorGrowth = 4;

/// The grid's geometry and the interpolation of a node field.
struct Grid
{
    double x0{0}, y0{0}, h{1};
    int nx{0}, ny{0};

    std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * nx + i; }
    std::size_t size() const { return static_cast<std::size_t>(nx) * ny; }
    double x(int i) const { return x0 + i * h; }
    double y(int j) const { return y0 + j * h; }
    bool inside(double px, double py) const
    {
        return px >= x0 && py >= y0 && px <= x0 + (nx - 1) * h && py <= y0 + (ny - 1) * h;
    }

    /// Bicubic (Catmull-Rom) interpolation of f at (px, py), clipped to the corner values of the cell (monotone
    /// limiter); outside the grid: @p outside.
    double cubic(const std::vector<double> &f, double px, double py, double outside) const
    {
        const double gx = (px - x0) / h, gy = (py - y0) / h;
        if (!(gx >= 0.0 && gy >= 0.0 && gx <= nx - 1 && gy <= ny - 1))
            return outside;
        const int i = std::min(static_cast<int>(gx), nx - 2), j = std::min(static_cast<int>(gy), ny - 2);
        const double fx = gx - i, fy = gy - j;
        const auto weights = [](double s, double w[4]) {
            w[0] = s * (-0.5 + s * (1.0 - 0.5 * s));
            w[1] = 1.0 + s * s * (-2.5 + 1.5 * s);
            w[2] = s * (0.5 + s * (2.0 - 1.5 * s));
            w[3] = s * s * (-0.5 + 0.5 * s);
        };
        double wx[4], wy[4];
        weights(fx, wx);
        weights(fy, wy);
        int ci[4];
        for (int k = 0; k < 4; ++k)
            ci[k] = std::clamp(i - 1 + k, 0, nx - 1);
        double v = 0.0;
        for (int l = 0; l < 4; ++l)
        {
            const double *row = f.data() + static_cast<std::size_t>(std::clamp(j - 1 + l, 0, ny - 1)) * nx;
            v += wy[l] * (wx[0] * row[ci[0]] + wx[1] * row[ci[1]] + wx[2] * row[ci[2]] + wx[3] * row[ci[3]]);
        }
        const double a = f[index(i, j)], b = f[index(i + 1, j)], c = f[index(i, j + 1)], d = f[index(i + 1, j + 1)];
        return std::clamp(v, std::min(std::min(a, b), std::min(c, d)), std::max(std::max(a, b), std::max(c, d)));
    }

    /// Bilinear interpolation of f at (px, py); outside the grid: @p outside.
    double bilinear(const std::vector<double> &f, double px, double py, double outside) const
    {
        const double gx = (px - x0) / h, gy = (py - y0) / h;
        if (!(gx >= 0.0 && gy >= 0.0 && gx <= nx - 1 && gy <= ny - 1))
            return outside;
        const int i = std::min(static_cast<int>(gx), nx - 2), j = std::min(static_cast<int>(gy), ny - 2);
        const double fx = gx - i, fy = gy - j;
        const double *r0 = f.data() + index(i, j), *r1 = r0 + nx;
        return (1.0 - fy) * ((1.0 - fx) * r0[0] + fx * r0[1]) + fy * ((1.0 - fx) * r1[0] + fx * r1[1]);
    }

    /// Gradient of the bicubic (Catmull-Rom) interpolant of f at (px, py) (clamped into the grid): central
    /// differences at the nodes, smooth in between, so that the band's clipped edge does not tilt it.
    void gradient(const std::vector<double> &f, double px, double py, double &gxOut, double &gyOut) const
    {
        const double gx = std::clamp((px - x0) / h, 0.0, nx - 1.0), gy = std::clamp((py - y0) / h, 0.0, ny - 1.0);
        const int i = std::min(static_cast<int>(gx), nx - 2), j = std::min(static_cast<int>(gy), ny - 2);
        const double fx = gx - i, fy = gy - j;
        const auto weights = [](double s, double w[4], double dw[4]) {
            w[0] = s * (-0.5 + s * (1.0 - 0.5 * s));
            w[1] = 1.0 + s * s * (-2.5 + 1.5 * s);
            w[2] = s * (0.5 + s * (2.0 - 1.5 * s));
            w[3] = s * s * (-0.5 + 0.5 * s);
            dw[0] = -0.5 + s * (2.0 - 1.5 * s);
            dw[1] = s * (-5.0 + 4.5 * s);
            dw[2] = 0.5 + s * (4.0 - 4.5 * s);
            dw[3] = s * (-1.0 + 1.5 * s);
        };
        double wx[4], wy[4], dx[4], dy[4];
        weights(fx, wx, dx);
        weights(fy, wy, dy);
        int ci[4];
        for (int k = 0; k < 4; ++k)
            ci[k] = std::clamp(i - 1 + k, 0, nx - 1);
        double sx = 0.0, sy = 0.0;
        for (int l = 0; l < 4; ++l)
        {
            const double *row = f.data() + static_cast<std::size_t>(std::clamp(j - 1 + l, 0, ny - 1)) * nx;
            const double r0 = row[ci[0]], r1 = row[ci[1]], r2 = row[ci[2]], r3 = row[ci[3]];
            sx += wy[l] * (dx[0] * r0 + dx[1] * r1 + dx[2] * r2 + dx[3] * r3);
            sy += dy[l] * (wx[0] * r0 + wx[1] * r1 + wx[2] * r2 + wx[3] * r3);
        }
        gxOut = sx / h;
        gyOut = sy / h;
    }
};

/// A node on the boundary of the forbidden set (signed distance 0) counts as inside: a tiny positive value instead
/// of 0, so that the shared edge of two touching regions (0 from both) is no crack of phi = 0 the front runs along.
inline double closedBoundary(double d, double h)
{
    return d >= 0.0 ? std::max(d, 1e-6 * h) : d;
}

/// A band-limited signed distance on some nodes (positive inside the forbidden set).
struct SparseDistance
{
    std::vector<std::uint32_t> nodes;
    std::vector<double> d;
};

/// What a solver prepares once for all its solves: the grid, the band's half-width and the forbidden set split by
/// how it changes in time.
struct SolverGrid
{
    Grid grid;
    double band{0.3};            ///< half-width of the narrow band (the field's length unit)
    double cfl{1.5};             ///< the cfl in use (LevelSetParams::cfl, or the automatic one)
    int reinitEvery{4};          ///< the reinitialisation's period in use (0: never)
    bool staticForbidden{false}; ///< some node is in the static forbidden set (else water connects every two nodes)
    std::vector<double> staticD; ///< static forbidden set (polygons, land, region): signed distance, -band outside
    /// A time-windowed zone and its distance (applied while the zone is closed).
    struct Zone
    {
        const TimeWindowedZone *zone;
        SparseDistance d;
    };
    std::vector<Zone> zones;
    std::vector<const IceZone *> ice;        ///< ice zones kept out at their drifted position
    std::vector<const Environment *> others; ///< environments known only by pointFree()
};

/// Signed distance of polygon p shifted by (sx, sy) at the nodes within band of its bounding box; values below
/// -band are left out.
SparseDistance polygonDistance(const Grid &g, const Polygon &p, double sx, double sy, double band,
                               double clearance = 0.0);

/// True when a chain of nodes outside the static forbidden set (staticD <= 0), each within @p reach nodes
/// (Chebyshev) of the last, links the nodes near @p a to those near @p b: false proves that no front started at
/// @p a reaches @p b (one step moves information at most @p reach nodes; the other forbidden sets only add).
bool waterConnects(const SolverGrid &sg, Point2 a, Point2 b, int reach);

/// Signed distance from a node mask (true = forbidden): the boundary is taken half-way between neighbouring nodes
/// of opposite kinds; band-limited.
void maskDistance(const Grid &g, const std::vector<char> &blocked, double band, std::vector<double> &d,
                  double clearance = 0.0);

/// Reinitialisation: phi becomes the signed distance (clipped to +-band) to its own zero level within the given
/// tiles (tx tiles per row), the zero level located by linear interpolation on the cell edges (marching squares
/// segments) and left in place. @p dist is scratch space kept between calls (+inf at every node between calls).
/// With @p pool the tiles are shared by its threads, four colours in turn.
/// The minimum over the departure disc cannot lower phi below its least value, so without this the inside of the
/// front flattens to the initial disc's depth and the cubic sees a kinked profile ([LollaLevelSet] reinitialise
/// periodically too).
void reinitialise(const Grid &g, std::vector<double> &phi, const std::vector<std::uint32_t> &tiles, int tx, double band,
                  std::vector<double> &dist, ThreadPool *pool = nullptr);

/// What the backtracking needs besides the arrival field.
struct BacktrackSetup
{
    const CurrentField *field{nullptr};      ///< the current (its calls count as the solve's)
    const Environment *environment{nullptr}; ///< forbidden regions checked by the local repair (may be null)
    double speed{0.0};                       ///< V
    double depth{0.0};                       ///< z of the current's evaluations
    double dt{0.0};                          ///< the solve's time step
    double dt0{0.0};                         ///< the initial disc's time (the path ends at t0 + dt0 then jumps)
};

/// Time-optimal path from @p start (at r.t0) to @p goal (at r.goalTime), backtracked through r's arrival field on
/// grid @p g (see LevelSetSolver); the path in forward time order.
std::vector<TimedPoint> backtrackPath(const Reachability &r, const Grid &g, Point2 start, Point2 goal,
                                      const BacktrackSetup &s);
} // namespace levelset_detail

/// The solver's grid and forbidden set (SolverGrid), prepared by the constructor (LevelSetGrid.cpp) and read by
/// solve() (LevelSet.cpp).
struct LevelSetSolver::Impl : levelset_detail::SolverGrid
{
};
} // namespace ompl_glider
