/// @file LevelSetStep.cpp
/// @brief One step of the level-set front (FrontPropagation::step(), LevelSetFront.h): the band's tiles, the nodes
/// of each tile that can change, the current sampled once per step at the nodes the step reads, the minimum of phi
/// over each changing node's departure disc ([LollaLevelSet]) and the forbidden set kept out, each phase shared by
/// the threads tile by tile.

#include <algorithm>
#include <cmath>

#include "LevelSetFront.h"
#include "ompl_glider/ThreadPool.h"

namespace ompl_glider
{
namespace levelset_detail
{
namespace
{
/// A summed-area table of a flag over a window of the grid: how many flagged nodes a box holds, in O(1). The window
/// is a tile and kMaxSampleReach nodes around it at most (on the stack: no allocation, no thread-local lookup).
class BoxCount
{
public:
    void reset(int i0, int j0, int w, int h)
    {
        i0_ = i0;
        j0_ = j0;
        w_ = w;
        h_ = h;
        std::fill(sum_, sum_ + static_cast<std::size_t>(w + 1) * (h + 1), 0);
    }
    /// Called row by row, column by column, once per node of the window.
    void add(int i, int j, bool flag)
    {
        const int a = i - i0_ + 1, b = j - j0_ + 1;
        at(a, b) = at(a - 1, b) + at(a, b - 1) - at(a - 1, b - 1) + (flag ? 1 : 0);
    }
    /// True when a node within @p r (Chebyshev) of (i, j), inside the window, is flagged.
    bool any(int i, int j, int r) const
    {
        const int a0 = std::max(i - r - i0_, 0), a1 = std::min(i + r - i0_ + 1, w_);
        const int b0 = std::max(j - r - j0_, 0), b1 = std::min(j + r - j0_ + 1, h_);
        return atc(a1, b1) - atc(a0, b1) - atc(a1, b0) + atc(a0, b0) > 0;
    }

private:
    static constexpr int kSide = kTile + 2 * kMaxSampleReach + 1;
    int &at(int a, int b) { return sum_[static_cast<std::size_t>(b) * (w_ + 1) + a]; }
    int atc(int a, int b) const { return sum_[static_cast<std::size_t>(b) * (w_ + 1) + a]; }
    int i0_{0}, j0_{0}, w_{0}, h_{0};
    int sum_[kSide * kSide];
};

/// The eight headings scanned where grad phi is too small to trust.
constexpr double kDiag = 0.70710678118654752440;
constexpr double kEight[8][2] = {{1, 0},  {kDiag, kDiag},   {0, 1},  {-kDiag, kDiag},
                                 {-1, 0}, {-kDiag, -kDiag}, {0, -1}, {kDiag, -kDiag}};
/// The heading's neighbours: 0.25 rad to each side.
constexpr double kSide = 0.25;
} // namespace

/// The active tiles (into activeTiles_): those holding an unclipped value of phi, and their neighbours (every tile
/// without the narrow band). A step moves information less than a tile, so a tile away from these keeps its values.
void FrontPropagation::findActive()
{
    const int tx = tx_, ty = ty_;
    activeTiles_.clear();
    for (int b = 0; b < ty; ++b)
        for (int a = 0; a < tx; ++a)
        {
            bool on = !params_.narrowBand;
            for (int bb = std::max(0, b - 1); bb <= std::min(ty - 1, b + 1) && !on; ++bb)
                for (int aa = std::max(0, a - 1); aa <= std::min(tx - 1, a + 1) && !on; ++aa)
                    on = tileLive_[static_cast<std::size_t>(bb) * tx + aa];
            if (on)
                activeTiles_.push_back(static_cast<std::uint32_t>(b * tx + a));
        }
}

/// Whether @p tile holds an unclipped value of phi (into tileLive_).
void FrontPropagation::refreshLive(std::uint32_t tile)
{
    bool live = false;
    forTileNodes(tile, [&](int i, int j) { live = live || std::abs(phi_[g_.index(i, j)]) < bandInner_; });
    tileLive_[tile] = live;
}

/// Phase 1 for @p tile: which of its nodes change in this step (into update_), and the current at the midpoint time
/// @p tm at the nodes a changing node's step may read (into cu_, cv_, stamped in sampled_). A node whose every
/// neighbour within reach_ holds the same clipped value (+band: far outside; -band: deep inside) keeps it exactly:
/// the cubic of a constant is that constant, and the limiter clips it there.
void FrontPropagation::markTile(std::uint32_t tile, double tm)
{
    const Grid &g = g_;
    const int a = static_cast<int>(tile % tx_), b = static_cast<int>(tile / tx_);
    const int i0 = a * kTile, i1 = std::min(g.nx, i0 + kTile), j0 = b * kTile, j1 = std::min(g.ny, j0 + kTile);
    const auto sample = [&](int i, int j, std::size_t n) {
        const Velocity c = current(g.x(i), g.y(j), tm);
        cu_[n] = c.u;
        cv_[n] = c.v;
        sampled_[n] = stepId_;
    };
    if (!params_.narrowBand)
    {
        for (int j = j0; j < j1; ++j)
            for (int i = i0; i < i1; ++i)
            {
                const std::size_t n = g.index(i, j);
                update_[n] = keep_.empty() || keep_[n];
                sample(i, j, n);
            }
        return;
    }
    // not +band (notOut) and not -band (notIn) near each node, within the window the step can read
    BoxCount notOut, notIn;
    const int H = sample_;
    const int wi0 = std::max(0, i0 - H), wi1 = std::min(g.nx, i1 + H);
    const int wj0 = std::max(0, j0 - H), wj1 = std::min(g.ny, j1 + H);
    notOut.reset(wi0, wj0, wi1 - wi0, wj1 - wj0);
    notIn.reset(wi0, wj0, wi1 - wi0, wj1 - wj0);
    for (int j = wj0; j < wj1; ++j)
        for (int i = wi0; i < wi1; ++i)
        {
            const double p = phi_[g.index(i, j)];
            notOut.add(i, j, p < bandInner_);
            notIn.add(i, j, p > -bandInner_);
        }
    for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i)
        {
            const std::size_t n = g.index(i, j);
            const double p = phi_[n];
            const bool out = p >= bandInner_, in = p <= -bandInner_;
            bool changes = out ? notOut.any(i, j, reach_) : in ? notIn.any(i, j, reach_) : true;
            if (!keep_.empty() && !keep_[n])
                changes = false;
            update_[n] = changes;
            // read by a changing node's step only if both kinds lie within sample_ (or the node is unclipped)
            if (changes || (!out && !in) || (notOut.any(i, j, H) && notIn.any(i, j, H)))
                sample(i, j, n);
        }
}

/// The current at (x, y) at the step's midpoint time @p tm: bilinear between this step's samples where the four
/// nodes around hold one, else from the field.
Velocity FrontPropagation::sampledCurrent(double x, double y, double tm) const
{
    const Grid &g = g_;
    const double gx = (x - g.x0) / g.h, gy = (y - g.y0) / g.h;
    if (gx >= 0.0 && gy >= 0.0 && gx <= g.nx - 1 && gy <= g.ny - 1)
    {
        const int i = std::min(static_cast<int>(gx), g.nx - 2), j = std::min(static_cast<int>(gy), g.ny - 2);
        const std::size_t n = g.index(i, j);
        if (sampled_[n] == stepId_ && sampled_[n + 1] == stepId_ && sampled_[n + g.nx] == stepId_ &&
            sampled_[n + g.nx + 1] == stepId_)
        {
            const double fx = gx - i, fy = gy - j;
            const double w00 = (1 - fx) * (1 - fy), w10 = fx * (1 - fy), w01 = (1 - fx) * fy, w11 = fx * fy;
            const std::size_t m = n + g.nx;
            return {w00 * cu_[n] + w10 * cu_[n + 1] + w01 * cu_[m] + w11 * cu_[m + 1],
                    w00 * cv_[n] + w10 * cv_[n + 1] + w01 * cv_[m] + w11 * cv_[m + 1]};
        }
    }
    return current(x, y, tm);
}

/// True when the straight way from the node (x, y) to a departure point (px, py) passes through the forbidden set
/// at the step's end (sampled every half cell): a long step must not carry the front across a thin island or a
/// keep-off band it could not cross. The forbidden set itself, not its clearance: the chord of a way that hugs a
/// convex coast at the clearance dips into the clearance, and the nodes keep the front out of it anyway.
bool FrontPropagation::crossesForbidden(double x, double y, double px, double py) const
{
    const double dx = px - x, dy = py - y;
    const int m = std::max(1, static_cast<int>(std::ceil(2.0 * std::sqrt(dx * dx + dy * dy) / g_.h)));
    for (int k = 1; k <= m; ++k)
    {
        const double s = static_cast<double>(k) / m;
        if (g_.bilinear(obstacle_, x + s * dx, y + s * dy, band_) > params_.clearance)
            return true;
    }
    return false;
}

/// One node's new value: the minimum of phi over the departure disc of the node (x, y) for the step with midpoint
/// time tm ([LollaLevelSet]; see the class comment of LevelSetSolver). Headings are unit vectors turned by fixed
/// rotations (no trigonometry but the parabola's one angle).
double FrontPropagation::nodeValue(std::size_t n, double x, double y, double tm) const
{
    const Grid &g = g_;
    const std::vector<double> &f = phi_;
    const double band = band_, V = V_, ds = ds_, r = r_;
    const double cx = cu_[n], cy = cv_[n]; // the current at the node at tm
    // Heading guess: the normal of the front at the departure point without the vehicle's own motion; where phi is
    // flat there (the band's clipped edge), a scan of 8 headings.
    double gx, gy;
    g.gradient(f, x - ds * cx, y - ds * cy, gx, gy);
    const double gn = std::sqrt(gx * gx + gy * gy);
    double nx = 1.0, ny = 0.0;
    const bool known = gn >= 0.2; // phi stays close to a distance (|grad phi| ~ 1) near the front
    if (known)
    {
        nx = gx / gn;
        ny = gy / gn;
    }
    const Velocity cm = sampledCurrent(x - 0.5 * ds * (cx + V * nx), y - 0.5 * ds * (cy + V * ny), tm);
    const double qx = x - ds * cm.u, qy = y - ds * cm.v;
    // a departure point lies within reach_ - 2 < band of the node: only a node near the forbidden set can cross it
    const bool guard = guardAll_ || obstacle_[n] > -bandInner_;
    const auto value = [&](double px, double py) {
        return guard && crossesForbidden(x, y, px, py) ? band : g.cubic(f, px, py, band);
    };
    const auto at = [&](double ux, double uy) { return value(qx - r * ux, qy - r * uy); };
    // The disc's centre (u = 0: drifting, or holding where |c| < V) covers minima inside the disc (the start).
    const double centre = value(qx, qy);
    if (params_.headingScan > 0)
    {
        double v = centre;
        for (int k = 0; k < params_.headingScan; ++k)
        {
            const double a = 2.0 * M_PI * k / params_.headingScan;
            v = std::min(v, at(std::cos(a), std::sin(a)));
        }
        return v;
    }
    double ax = nx, ay = ny;
    if (!known)
    {
        double v = band;
        for (const auto &d : kEight)
        {
            const double fk = at(d[0], d[1]);
            if (fk < v)
            {
                v = fk;
                ax = d[0];
                ay = d[1];
            }
        }
        if (v >= band)
            return std::min(v, centre);
    }
    else
    {
        // The normal at the departure point itself.
        g.gradient(f, qx - r * nx, qy - r * ny, gx, gy);
        const double gm = std::sqrt(gx * gx + gy * gy);
        if (gm >= 0.2)
        {
            ax = gx / gm;
            ay = gy / gm;
        }
    }
    // Three headings and the parabola through them.
    static const double cs = std::cos(kSide), sn = std::sin(kSide);
    const double f0 = at(ax, ay), fm = at(ax * cs + ay * sn, ay * cs - ax * sn),
                 fp = at(ax * cs - ay * sn, ay * cs + ax * sn);
    double v = std::min(std::min(f0, centre), std::min(fm, fp));
    const double curv = fm - 2.0 * f0 + fp;
    if (curv > 0.0)
    {
        const double off = 0.5 * kSide * (fm - fp) / curv;
        if (std::abs(off) < kSide)
        {
            const double co = std::cos(off), so = std::sin(off);
            v = std::min(v, at(ax * co - ay * so, ay * co + ax * so));
        }
    }
    return v;
}

/// Phase 3 for @p tile: the forbidden set at t1 kept out of the new front (phi = max(phi, d)), the first arrival of
/// every node the front reached in the step (linear in phi within the step), the new values made phi_, and whether
/// the tile still holds the band.
void FrontPropagation::settleTile(std::uint32_t tile, double t1)
{
    const Grid &g = g_;
    const double t = t_, ds = ds_;
    forTileNodes(tile, [&](int i, int j) {
        const std::size_t n = g.index(i, j);
        const double v = std::max(next_[n], obstacle_[n]);
        if (v <= 0.0 && out_.arrival[n] == kInf)
        {
            const double p0 = phi_[n];
            out_.arrival[n] = p0 > 0.0 ? t + ds * p0 / (p0 - v) : t1;
        }
        phi_[n] = v;
    });
    refreshLive(tile);
}

/// One step t_ -> t1 (midpoint tm): the three phases over the active tiles, each shared by the pool's threads, then
/// a zone that closed outside them.
void FrontPropagation::step(ThreadPool &pool, double t1, double tm)
{
    const Grid &g = g_;
    const double band = band_;
    ++stepId_;
    findActive();
    updateForbidden(t1);
    const std::size_t count = activeTiles_.size();
    tileUpdates_.assign(count, 0);
    pool.parallelFor(count, [&](std::size_t k) { markTile(activeTiles_[k], tm); });
    pool.parallelFor(count, [&](std::size_t k) {
        std::uint32_t done = 0;
        forTileNodes(activeTiles_[k], [&](int i, int j) {
            const std::size_t n = g.index(i, j);
            if (update_[n])
            {
                next_[n] = std::clamp(nodeValue(n, g.x(i), g.y(j), tm), -band, band);
                ++done;
            }
            else
                next_[n] = phi_[n];
        });
        tileUpdates_[k] = done;
    });
    pool.parallelFor(count, [&](std::size_t k) { settleTile(activeTiles_[k], t1); });
    for (std::uint32_t n : dynamicNodes_) // a zone that closed outside the active tiles
        if (obstacle_[n] > phi_[n])
        {
            phi_[n] = obstacle_[n];
            const int i = static_cast<int>(n % static_cast<std::uint32_t>(g.nx)),
                      j = static_cast<int>(n / static_cast<std::uint32_t>(g.nx));
            tileLive_[static_cast<std::size_t>(j / kTile) * tx_ + i / kTile] = 1; // refreshed when next active
        }
    for (std::uint32_t done : tileUpdates_)
        updates_ += done;
}
} // namespace levelset_detail
} // namespace ompl_glider
