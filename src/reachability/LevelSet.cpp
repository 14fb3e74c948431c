#include "ompl_glider/reachability/LevelSet.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ResourceLimits.h"
#include "ompl_glider/cost/DiveProfilePool.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/IceZone.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/TimeWindowedZone.h"

namespace ompl_glider
{
namespace
{
constexpr int kTile = 16;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// The grid's geometry and the interpolation of a node field.
struct Grid
{
    double x0{0}, y0{0}, h{1};
    int nx{0}, ny{0};

    std::size_t index(int i, int j) const
    {
        return static_cast<std::size_t>(j) * nx + i;
    }
    std::size_t size() const
    {
        return static_cast<std::size_t>(nx) * ny;
    }
    double x(int i) const
    {
        return x0 + i * h;
    }
    double y(int j) const
    {
        return y0 + j * h;
    }
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

/// A band-limited signed distance on some nodes (positive inside the forbidden set).
struct SparseDistance
{
    std::vector<std::uint32_t> nodes;
    std::vector<double> d;
};

/// Signed distance of polygon p shifted by (sx, sy) at the nodes within band of its bounding box; values below
/// -band are left out.
SparseDistance polygonDistance(const Grid &g, const Polygon &p, double sx, double sy, double band,
                               double clearance = 0.0)
{
    SparseDistance out;
    const Box &b = p.bounds();
    const int i0 = std::max(0, static_cast<int>(std::floor((b.xMin + sx - band - g.x0) / g.h)));
    const int i1 = std::min(g.nx - 1, static_cast<int>(std::ceil((b.xMax + sx + band - g.x0) / g.h)));
    const int j0 = std::max(0, static_cast<int>(std::floor((b.yMin + sy - band - g.y0) / g.h)));
    const int j1 = std::min(g.ny - 1, static_cast<int>(std::ceil((b.yMax + sy + band - g.y0) / g.h)));
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
        {
            const double d = p.signedDistance(g.x(i) - sx, g.y(j) - sy) + clearance;
            if (d > -band)
            {
                out.nodes.push_back(static_cast<std::uint32_t>(g.index(i, j)));
                out.d.push_back(std::min(d, band));
            }
        }
    return out;
}

/// Signed distance from a node mask (true = forbidden): the boundary is taken half-way between neighbouring nodes
/// of opposite kinds; band-limited.
void maskDistance(const Grid &g, const std::vector<char> &blocked, double band, std::vector<double> &d,
                  double clearance = 0.0)
{
    d.assign(g.size(), -band);
    std::vector<double> best(g.size(), kInf);
    const int r = static_cast<int>(std::ceil(band / g.h)) + 1;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
        {
            const char a = blocked[g.index(i, j)];
            for (int k = 0; k < 2; ++k)
            {
                const int i2 = i + (k == 0), j2 = j + (k == 1);
                if (i2 >= g.nx || j2 >= g.ny || blocked[g.index(i2, j2)] == a)
                    continue;
                const double mx = 0.5 * (g.x(i) + g.x(i2)), my = 0.5 * (g.y(j) + g.y(j2));
                for (int jj = std::max(0, j - r); jj <= std::min(g.ny - 1, j + r); ++jj)
                    for (int ii = std::max(0, i - r); ii <= std::min(g.nx - 1, i + r); ++ii)
                    {
                        double &b = best[g.index(ii, jj)];
                        b = std::min(b, std::hypot(g.x(ii) - mx, g.y(jj) - my));
                    }
            }
        }
    for (std::size_t n = 0; n < g.size(); ++n)
    {
        const double dist = std::min(best[n], band);
        d[n] = std::clamp((blocked[n] ? dist : -dist) + clearance, -band, band);
    }
}

/// Reinitialisation: phi becomes the signed distance (clipped to +-band) to its own zero level within the given
/// tiles, the zero level located by linear interpolation on the cell edges (marching squares segments) and left in
/// place. The minimum over the departure disc cannot lower phi below its least value, so without this the inside of
/// the front flattens to the initial disc's depth and the cubic sees a kinked profile ([LollaLevelSet] reinitialise
/// periodically too).
void reinitialise(const Grid &g, std::vector<double> &phi, const std::vector<std::uint32_t> &tiles, int tx,
                  double band, std::vector<double> &dist)
{
    if (dist.size() != g.size())
        dist.assign(g.size(), kInf);
    const int R = static_cast<int>(std::ceil(band / g.h));
    const auto segDist = [](double px, double py, double ax, double ay, double bx, double by) {
        const double ex = bx - ax, ey = by - ay, l2 = ex * ex + ey * ey;
        double s = l2 > 0.0 ? ((px - ax) * ex + (py - ay) * ey) / l2 : 0.0;
        s = std::clamp(s, 0.0, 1.0);
        return std::hypot(px - ax - s * ex, py - ay - s * ey);
    };
    for (std::uint32_t tile : tiles)
    {
        const int a = static_cast<int>(tile % tx), b = static_cast<int>(tile / tx);
        for (int j = b * kTile; j < std::min(g.ny - 1, (b + 1) * kTile); ++j)
            for (int i = a * kTile; i < std::min(g.nx - 1, (a + 1) * kTile); ++i)
            {
                const double v[4] = {phi[g.index(i, j)], phi[g.index(i + 1, j)], phi[g.index(i + 1, j + 1)],
                                     phi[g.index(i, j + 1)]};
                const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
                double px[4], py[4];
                int n = 0;
                for (int k = 0; k < 4; ++k)
                {
                    const int l = (k + 1) % 4;
                    if ((v[k] <= 0.0) != (v[l] <= 0.0))
                    {
                        const double s = v[k] / (v[k] - v[l]);
                        px[n] = g.x(ci[k]) + s * (g.x(ci[l]) - g.x(ci[k]));
                        py[n] = g.y(cj[k]) + s * (g.y(cj[l]) - g.y(cj[k]));
                        ++n;
                    }
                }
                if (n < 2)
                    continue;
                for (int sgi = 0; sgi + 1 < n; sgi += 2)
                {
                    for (int jj = std::max(0, j - R); jj <= std::min(g.ny - 1, j + 1 + R); ++jj)
                        for (int ii = std::max(0, i - R); ii <= std::min(g.nx - 1, i + 1 + R); ++ii)
                        {
                            double &d = dist[g.index(ii, jj)];
                            d = std::min(d, segDist(g.x(ii), g.y(jj), px[sgi], py[sgi], px[sgi + 1], py[sgi + 1]));
                        }
                }
                if (n == 4)  // a saddle: also the other pairing's first segment keeps both branches close
                    for (int jj = j; jj <= j + 1; ++jj)
                        for (int ii = i; ii <= i + 1; ++ii)
                        {
                            double &d = dist[g.index(ii, jj)];
                            d = std::min(d, segDist(g.x(ii), g.y(jj), px[1], py[1], px[2], py[2]));
                        }
            }
    }
    for (std::uint32_t tile : tiles)
    {
        const int a = static_cast<int>(tile % tx), b = static_cast<int>(tile / tx);
        for (int j = b * kTile; j < std::min(g.ny, (b + 1) * kTile); ++j)
            for (int i = a * kTile; i < std::min(g.nx, (a + 1) * kTile); ++i)
            {
                const std::size_t n = g.index(i, j);
                const double d = std::min(dist[n], band);
                phi[n] = phi[n] <= 0.0 ? -d : d;
                dist[n] = kInf;
            }
    }
}

/// First time in (0, tau] at which w (the offset from the start) is in the disc of centre c tau' and radius V tau'
/// (a uniform current over the first instant); +inf when never.
double discArrival(double wx, double wy, double cx, double cy, double V, double tau)
{
    const double w2 = wx * wx + wy * wy;
    if (w2 == 0.0)
        return 0.0;
    // |w - c s|^2 - V^2 s^2 = a s^2 + b s + w2 <= 0
    const double a = cx * cx + cy * cy - V * V, b = -2.0 * (wx * cx + wy * cy);
    double first = kInf;
    if (std::abs(a) < 1e-300)
        first = b < 0.0 ? -w2 / b : kInf;
    else
    {
        const double disc = b * b - 4.0 * a * w2;
        if (disc < 0.0)
            return kInf;
        const double sq = std::sqrt(disc);
        const double r1 = (-b - sq) / (2.0 * a), r2 = (-b + sq) / (2.0 * a);
        for (double r : {std::min(r1, r2), std::max(r1, r2)})
            if (r > 0.0)
            {
                first = r;
                break;
            }
    }
    return first <= tau * (1.0 + 1e-12) ? std::min(first, tau) : kInf;
}
}  // namespace

struct LevelSetSolver::Impl
{
    Grid grid;
    double band{0.3};
    std::vector<double> staticD;  ///< static forbidden set (polygons, land, region): signed distance, -band outside
    struct Zone
    {
        const TimeWindowedZone *zone;
        SparseDistance d;
    };
    std::vector<Zone> zones;
    std::vector<const IceZone *> ice;
    std::vector<const Environment *> others;  ///< environments known only by pointFree()
    std::shared_ptr<const Environment> envHold;
};

LevelSetSolver::LevelSetSolver(std::shared_ptr<const GliderContext> ctx, LevelSetParams params)
    : ctx_(std::move(ctx)), params_(params), impl_(std::make_unique<Impl>())
{
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error("LevelSetSolver: the problem context is null or has no field");
    if (!(params_.cellSize > 0.0) || !std::isfinite(params_.cellSize))
        throw Error("LevelSet: resolution (cell size) must be > 0, got " + std::to_string(params_.cellSize));
    if (!(params_.cfl > 0.0 && params_.cfl <= 2.0))
        throw Error("LevelSet: cfl must be in (0, 2], got " + std::to_string(params_.cfl));
    if (!(params_.clearance >= 0.0) || !std::isfinite(params_.clearance))
        throw Error("LevelSet: clearance must be >= 0, got " + std::to_string(params_.clearance));
    if (!(params_.band >= 4.0 && params_.band <= 50.0))
        throw Error("LevelSet: band must be in [4, 50] cells, got " + std::to_string(params_.band));
    const Region &r = ctx_->region;
    if (!std::isfinite(r.xMin) || !std::isfinite(r.xMax) || !std::isfinite(r.yMin) || !std::isfinite(r.yMax))
        throw Error("LevelSet: the planning region must be bounded");
    Grid &g = impl_->grid;
    g.h = params_.cellSize;
    g.x0 = r.xMin;
    g.y0 = r.yMin;
    const double cx = std::floor((r.xMax - r.xMin) / g.h + 1e-9), cy = std::floor((r.yMax - r.yMin) / g.h + 1e-9);
    if (cx < 4 || cy < 4)
        throw Error("LevelSet: resolution " + std::to_string(g.h) + " leaves fewer than 4 cells across the region");
    if (cx * cy > 2e8)
        throw Error("LevelSet: resolution " + std::to_string(g.h) + " gives more than 2e8 grid nodes");
    g.nx = static_cast<int>(cx) + 1;
    g.ny = static_cast<int>(cy) + 1;
    checkMemory(static_cast<double>(g.size()) * (3 * sizeof(double) + 2 * sizeof(double) + 2),
                "the level-set grid (" + std::to_string(g.nx) + " x " + std::to_string(g.ny) + " nodes)",
                "use a coarser resolution");
    impl_->band = params_.band * g.h;
    const double band = impl_->band;

    // Static forbidden set: land (the field's mask at the nodes) and static polygons.
    std::vector<char> land(g.size(), 0);
    bool anyLand = false;
    const double z = ctx_->travel->params().depth;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
            if (!ctx_->field->inWater(g.x(i), g.y(j), z))
                land[g.index(i, j)] = anyLand = 1;
    if (anyLand)
        maskDistance(g, land, band, impl_->staticD, params_.clearance);
    else
        impl_->staticD.assign(g.size(), -band);

    std::vector<const Environment *> members;
    if (const auto *fr = dynamic_cast<const ForbiddenRegions *>(ctx_->environment.get()))
        for (const auto &m : fr->regions())
            members.push_back(m.get());
    else if (ctx_->environment)
        members.push_back(ctx_->environment.get());
    for (const Environment *m : members)
    {
        if (const auto *s = dynamic_cast<const StaticRegion *>(m))
        {
            const SparseDistance d = polygonDistance(g, s->polygon(), 0.0, 0.0, band, params_.clearance);
            for (std::size_t k = 0; k < d.nodes.size(); ++k)
                impl_->staticD[d.nodes[k]] = std::max(impl_->staticD[d.nodes[k]], d.d[k]);
        }
        else if (const auto *tz = dynamic_cast<const TimeWindowedZone *>(m))
            impl_->zones.push_back({tz, polygonDistance(g, tz->polygon(), 0.0, 0.0, band, params_.clearance)});
        else if (const auto *iz = dynamic_cast<const IceZone *>(m))
        {
            if (params_.iceForbidden)
                impl_->ice.push_back(iz);
        }
        else
            impl_->others.push_back(m);
    }
}

LevelSetSolver::~LevelSetSolver() = default;

Reachability LevelSetSolver::solve(double sx, double sy, double t0, double tEnd, const std::optional<Point2> &goal,
                                   bool stopAtGoal, const std::function<bool()> &stop) const
{
    const auto wall0 = std::chrono::steady_clock::now();
    const Grid &g = impl_->grid;
    const double band = impl_->band;
    const CurrentField &field = *ctx_->field;
    const double V = ctx_->speed();
    const double z = ctx_->travel->params().depth;
    const std::uint64_t cmc0 = field.callCount();
    if (!std::isfinite(sx) || !std::isfinite(sy) || !std::isfinite(t0) || !(tEnd >= t0))
        throw Error("LevelSet: start, departure time or end time not finite, or end before departure");

    Reachability out;
    out.x0 = g.x0;
    out.y0 = g.y0;
    out.h = g.h;
    out.nx = g.nx;
    out.ny = g.ny;
    out.t0 = t0;
    out.arrival.assign(g.size(), kInf);
    const double cmax = std::max(ctx_->maxCurrent(), 0.0);
    const double dt = params_.cfl * g.h / (V + cmax);
    out.stats.dt = dt;
    out.stats.nodes = g.size();

    // The forbidden set at time t: static part, closed zones, drifted ice, other environments' masks.
    std::vector<double> obstacle(impl_->staticD);
    std::vector<std::uint32_t> dynamicNodes;  // nodes whose obstacle value differs from the static one
    const auto obstacleAt = [&](double t) {
        for (std::uint32_t n : dynamicNodes)
            obstacle[n] = impl_->staticD[n];
        dynamicNodes.clear();
        const auto raise = [&](std::uint32_t n, double d) {
            if (d > obstacle[n])
            {
                if (obstacle[n] == impl_->staticD[n])
                    dynamicNodes.push_back(n);
                obstacle[n] = d;
            }
        };
        for (const Impl::Zone &zn : impl_->zones)
            if (zn.zone->active(t))
                for (std::size_t k = 0; k < zn.d.nodes.size(); ++k)
                    raise(zn.d.nodes[k], zn.d.d[k]);
        for (const IceZone *iz : impl_->ice)
        {
            const Point2 s = iz->displacement(t);
            const SparseDistance d = polygonDistance(g, iz->shape(), s.x, s.y, band, params_.clearance);
            for (std::size_t k = 0; k < d.nodes.size(); ++k)
                raise(d.nodes[k], d.d[k]);
        }
        if (!impl_->others.empty())
        {
            std::vector<char> blocked(g.size(), 0);
            bool any = false;
            for (int j = 0; j < g.ny; ++j)
                for (int i = 0; i < g.nx; ++i)
                    for (const Environment *e : impl_->others)
                        if (!e->pointFree(g.x(i), g.y(j), t))
                            blocked[g.index(i, j)] = any = 1;
            if (any)
            {
                std::vector<double> d;
                maskDistance(g, blocked, band, d, params_.clearance);
                for (std::size_t n = 0; n < g.size(); ++n)
                    if (d[n] > -band)
                        raise(static_cast<std::uint32_t>(n), d[n]);
            }
        }
    };

    // Initial front: the exact reachable disc after dt0 ([LollaLevelSet]: start from the first instant's disc).
    const double r0 = 4.0 * g.h;  // 2 cells leave a dent in the front that persists; 3-6 agree
    const double dt0 = r0 / V;
    const Velocity c0 = field.velocity(sx, sy, z, t0 + 0.5 * dt0);
    const double cxs = sx + dt0 * c0.u, cys = sy + dt0 * c0.v;
    std::vector<double> phi(g.size()), next(g.size());
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
        {
            const std::size_t n = g.index(i, j);
            phi[n] = std::clamp(std::hypot(g.x(i) - cxs, g.y(j) - cys) - r0, -band, band);
            if (phi[n] <= 0.0)
                out.arrival[n] = t0 + std::min(discArrival(g.x(i) - sx, g.y(j) - sy, c0.u, c0.v, V, dt0), dt0);
        }
    double t = t0 + dt0;
    obstacleAt(t);
    for (std::size_t n = 0; n < g.size(); ++n)
        if (obstacle[n] > phi[n])
        {
            phi[n] = obstacle[n];
            if (phi[n] > 0.0)
                out.arrival[n] = kInf;
        }

    double goalPhi = goal ? g.cubic(phi, goal->x, goal->y, band) : band;
    if (goal && goalPhi <= 0.0)
    {
        out.goalReached = true;
        out.goalTime = t0 + std::min(discArrival(goal->x - sx, goal->y - sy, c0.u, c0.v, V, dt0), dt0);
    }

    // Tiles.
    const int tx = (g.nx + kTile - 1) / kTile, ty = (g.ny + kTile - 1) / kTile;
    std::vector<char> tileLive(static_cast<std::size_t>(tx) * ty, 0);
    std::vector<std::uint32_t> activeTiles;
    const double bandInner = band * (1.0 - 1e-9);
    const auto findActive = [&]() {
        std::fill(tileLive.begin(), tileLive.end(), 0);
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                if (std::abs(phi[g.index(i, j)]) < bandInner)
                    tileLive[static_cast<std::size_t>(j / kTile) * tx + i / kTile] = 1;
        activeTiles.clear();
        for (int b = 0; b < ty; ++b)
            for (int a = 0; a < tx; ++a)
            {
                bool on = false;
                for (int bb = std::max(0, b - 1); bb <= std::min(ty - 1, b + 1) && !on; ++bb)
                    for (int aa = std::max(0, a - 1); aa <= std::min(tx - 1, a + 1) && !on; ++aa)
                        on = tileLive[static_cast<std::size_t>(bb) * tx + aa];
                if (on || !params_.narrowBand)
                    activeTiles.push_back(static_cast<std::uint32_t>(b * tx + a));
            }
    };

    DiveProfilePool pool(params_.threads);
    out.stats.threads = pool.size();
    const double dth = 0.25;
    // One node's new value: the minimum of phi over the departure disc ([LollaLevelSet]; see the class comment).
    double ds = dt;  // this step's length (shortened to end at a zone's opening or closing)
    double r = V * ds;
    const auto update = [&](const std::vector<double> &f, double x, double y, double t1, double tm) {
        const Velocity c1 = field.velocity(x, y, z, t1);
        // Heading guess: the normal of the front at the departure point without the vehicle's own motion; where
        // phi is flat there (the band's clipped edge) the node's own neighbours, else a scan of 8 headings.
        double gx, gy;
        g.gradient(f, x - ds * c1.u, y - ds * c1.v, gx, gy);
        double gn = std::hypot(gx, gy);
        double nx = 1.0, ny = 0.0;
        const bool known = gn >= 0.2;  // phi stays close to a distance (|grad phi| ~ 1) near the front
        if (known)
        {
            nx = gx / gn;
            ny = gy / gn;
        }
        const Velocity cm = field.velocity(x - 0.5 * ds * (c1.u + V * nx), y - 0.5 * ds * (c1.v + V * ny), z, tm);
        const double qx = x - ds * cm.u, qy = y - ds * cm.v;
        const auto at = [&](double a) { return g.cubic(f, qx - r * std::cos(a), qy - r * std::sin(a), band); };
        // The disc's centre (u = 0: drifting, or holding where |c| < V) covers minima inside the disc (the start).
        const double centre = g.cubic(f, qx, qy, band);
        double a0 = std::atan2(ny, nx);
        if (params_.headingScan > 0)
        {
            double v = centre;
            for (int k = 0; k < params_.headingScan; ++k)
                v = std::min(v, at(2.0 * M_PI * k / params_.headingScan));
            return v;
        }
        if (!known)
        {
            double v = band;
            for (int k = 0; k < 8; ++k)
            {
                const double fk = at(k * M_PI / 4);
                if (fk < v)
                {
                    v = fk;
                    a0 = k * M_PI / 4;
                }
            }
            if (v >= band)
                return std::min(v, centre);
        }
        else
        {
            // The normal at the departure point itself.
            g.gradient(f, qx - r * nx, qy - r * ny, gx, gy);
            if (std::hypot(gx, gy) >= 0.2)
                a0 = std::atan2(gy, gx);
        }
        // Three headings and the parabola through them.
        const double f0 = at(a0), fm = at(a0 - dth), fp = at(a0 + dth);
        double v = std::min(std::min(f0, centre), std::min(fm, fp));
        const double curv = fm - 2.0 * f0 + fp;
        if (curv > 0.0)
        {
            const double off = 0.5 * dth * (fm - fp) / curv;
            if (std::abs(off) < dth)
                v = std::min(v, at(a0 + off));
        }
        return v;
    };
    std::uint64_t updates = 0;
    std::vector<double> reinitDist;
    // The times at which a time-windowed zone opens or closes: steps end there, so that a lane is not entered
    // part of a step before it opens.
    std::vector<double> events;
    for (const Impl::Zone &zn : impl_->zones)
        for (const Interval &w : zn.zone->windows())
        {
            events.push_back(w.lo);
            events.push_back(w.hi);
        }
    std::sort(events.begin(), events.end());
    const std::size_t maxSteps = static_cast<std::size_t>(std::ceil((tEnd - t) / dt)) + 1 + 2 * events.size();
    for (std::size_t step = 0; step < maxSteps && t < tEnd; ++step)
    {
        if (stop && stop())
            break;
        ds = dt;
        const auto ev = std::upper_bound(events.begin(), events.end(), t * (1 + 1e-12) + 1e-12);
        if (ev != events.end() && *ev < t + dt)
            ds = *ev - t;
        r = V * ds;
        const double t1 = t + ds, tm = t + 0.5 * ds;
        findActive();
        next = phi;  // tiles not updated keep their (clipped) values
        pool.parallelFor(activeTiles.size(), [&](std::size_t k) {
            const int a = static_cast<int>(activeTiles[k] % tx), b = static_cast<int>(activeTiles[k] / tx);
            for (int j = b * kTile; j < std::min(g.ny, (b + 1) * kTile); ++j)
                for (int i = a * kTile; i < std::min(g.nx, (a + 1) * kTile); ++i)
                {
                    const double x = g.x(i), y = g.y(j);
                    next[g.index(i, j)] = std::clamp(update(phi, x, y, t1, tm), -band, band);
                }
        });
        updates += static_cast<std::uint64_t>(activeTiles.size()) * kTile * kTile;
        obstacleAt(t1);
        for (std::uint32_t tile : activeTiles)
        {
            const int a = static_cast<int>(tile % tx), b = static_cast<int>(tile / tx);
            for (int j = b * kTile; j < std::min(g.ny, (b + 1) * kTile); ++j)
                for (int i = a * kTile; i < std::min(g.nx, (a + 1) * kTile); ++i)
                {
                    const std::size_t n = g.index(i, j);
                    double &v = next[n];
                    v = std::max(v, obstacle[n]);
                    if (v <= 0.0 && out.arrival[n] == kInf)
                    {
                        const double p0 = phi[n];
                        out.arrival[n] = p0 > 0.0 ? t + ds * p0 / (p0 - v) : t1;
                    }
                }
        }
        for (std::uint32_t n : dynamicNodes)  // a zone that closed outside the active tiles
            next[n] = std::max(next[n], obstacle[n]);
        phi.swap(next);
        if (params_.reinitEvery > 0 && (step + 1) % params_.reinitEvery == 0)
        {
            reinitialise(g, phi, activeTiles, tx, band, reinitDist);
            for (std::uint32_t tile : activeTiles)  // keep the forbidden set out (the distance may cut corners)
            {
                const int a = static_cast<int>(tile % tx), b = static_cast<int>(tile / tx);
                for (int j = b * kTile; j < std::min(g.ny, (b + 1) * kTile); ++j)
                    for (int i = a * kTile; i < std::min(g.nx, (a + 1) * kTile); ++i)
                        phi[g.index(i, j)] = std::max(phi[g.index(i, j)], obstacle[g.index(i, j)]);
            }
        }
        ++out.stats.steps;
        if (goal && !out.goalReached)
        {
            const double gp = g.cubic(phi, goal->x, goal->y, band);
            if (gp <= 0.0)
            {
                out.goalReached = true;
                out.goalTime = goalPhi > 0.0 ? t + ds * goalPhi / (goalPhi - gp) : t1;
            }
            goalPhi = gp;
        }
        t = t1;
        if (goal && out.goalReached && stopAtGoal)
            break;
    }
    out.stats.nodeUpdates = updates;

    // Backtracking from the goal through the arrival field.
    if (goal && out.goalReached)
    {
        // Node gradients of T (central where both neighbours are reached, one-sided otherwise).
        std::vector<double> tgx(g.size(), 0.0), tgy(g.size(), 0.0);
        std::vector<char> tok(g.size(), 0);
        const auto diff = [&](int i, int j, int di, int dj, double &d) {
            const double c = out.arrival[g.index(i, j)];
            const bool hasP = i + di < g.nx && j + dj < g.ny && std::isfinite(out.arrival[g.index(i + di, j + dj)]);
            const bool hasM = i - di >= 0 && j - dj >= 0 && std::isfinite(out.arrival[g.index(i - di, j - dj)]);
            if (hasP && hasM)
                d = (out.arrival[g.index(i + di, j + dj)] - out.arrival[g.index(i - di, j - dj)]) / (2 * g.h);
            else if (hasP)
                d = (out.arrival[g.index(i + di, j + dj)] - c) / g.h;
            else if (hasM)
                d = (c - out.arrival[g.index(i - di, j - dj)]) / g.h;
            else
                return false;
            return true;
        };
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
            {
                const std::size_t n = g.index(i, j);
                if (std::isfinite(out.arrival[n]))
                    tok[n] = diff(i, j, 1, 0, tgx[n]) && diff(i, j, 0, 1, tgy[n]);
            }
        const auto normal = [&](double px, double py, double &nx, double &ny) {
            const double gx = std::clamp((px - g.x0) / g.h, 0.0, g.nx - 1.0);
            const double gy = std::clamp((py - g.y0) / g.h, 0.0, g.ny - 1.0);
            const int i = std::min(static_cast<int>(gx), g.nx - 2), j = std::min(static_cast<int>(gy), g.ny - 2);
            const double fx = gx - i, fy = gy - j;
            double sx2 = 0, sy2 = 0, sw = 0;
            const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
            const std::size_t id[4] = {g.index(i, j), g.index(i + 1, j), g.index(i, j + 1), g.index(i + 1, j + 1)};
            for (int k = 0; k < 4; ++k)
                if (tok[id[k]])
                {
                    sx2 += w[k] * tgx[id[k]];
                    sy2 += w[k] * tgy[id[k]];
                    sw += w[k];
                }
            const double m = std::hypot(sx2, sy2);
            if (sw <= 0.0 || m <= 0.0)
                return false;
            nx = sx2 / m;
            ny = sy2 / m;
            return true;
        };
        std::vector<TimedPoint> back;
        double px = goal->x, py = goal->y, pt = out.goalTime;
        back.push_back({px, py, pt});
        const double holdTol = std::max(3.0 * dt, 2e-3 * (out.goalTime - t0));
        const double done = t0 + dt0;
        const std::size_t maxBack = 4 * static_cast<std::size_t>((out.goalTime - t0) / dt + 10);
        double lastNx = 0.0, lastNy = 0.0;  // the last normal found: kept for a few steps where the path runs
        int blind = 0;                      // along unreached nodes (the edge of a forbidden region)
        for (std::size_t k = 0; k < maxBack && pt > done; ++k)
        {
            const double Tx = out.arrivalAt(px, py);
            if (std::isfinite(Tx) && Tx < pt - holdTol)
            {
                const Velocity c = field.velocity(px, py, z, pt);
                if (std::hypot(c.u, c.v) < V)
                {
                    pt = std::max(Tx, done);
                    back.push_back({px, py, pt});
                    continue;
                }
            }
            const double h1 = std::min(dt, pt - done);
            double nx = lastNx, ny = lastNy;
            if (normal(px, py, nx, ny))
                blind = 0;
            else if (++blind > 8 || !(lastNx != 0.0 || lastNy != 0.0))
                break;  // off the reached nodes for long (along a forbidden region's edge): stop
            lastNx = nx;
            lastNy = ny;
            const Velocity c1 = field.velocity(px, py, z, pt);
            const double mx = px - 0.5 * h1 * (c1.u + V * nx), my = py - 0.5 * h1 * (c1.v + V * ny);
            double nmx = nx, nmy = ny;
            normal(mx, my, nmx, nmy);
            const Velocity cm = field.velocity(mx, my, z, pt - 0.5 * h1);
            // Near a moving forbidden region (drifting ice) T is not the front at the path's time: a step along
            // grad T may enter the region. Then the heading turns, 15 degrees at a time either way, to the nearest
            // one whose step ends where the region is not (a local repair; the legs are checked again later).
            double qx = px - h1 * (cm.u + V * nmx), qy = py - h1 * (cm.v + V * nmy);
            const auto blocked = [&](double x, double y, double t) {
                return ctx_->environment && !ctx_->environment->pointFree(x, y, t);
            };
            if (blocked(qx, qy, pt - h1))
                for (int k = 1; k <= 12; ++k)
                {
                    bool found = false;
                    for (int sgn = -1; sgn <= 1 && !found; sgn += 2)
                    {
                        const double a = sgn * k * M_PI / 12.0, ca = std::cos(a), sa = std::sin(a);
                        const double ux = nmx * ca - nmy * sa, uy = nmx * sa + nmy * ca;
                        const double rx = px - h1 * (cm.u + V * ux), ry = py - h1 * (cm.v + V * uy);
                        if (!blocked(rx, ry, pt - h1) && std::isfinite(out.arrivalAt(rx, ry)))
                        {
                            qx = rx;
                            qy = ry;
                            found = true;
                        }
                    }
                    if (found)
                        break;
                }
            px = qx;
            py = qy;
            pt -= h1;
            back.push_back({px, py, pt});
        }
        back.push_back({sx, sy, t0});
        out.path.assign(back.rbegin(), back.rend());
    }
    out.stats.currentCalls = field.callCount() - cmc0;
    out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return out;
}

double Reachability::arrivalAt(double x, double y) const
{
    const double gx = (x - x0) / h, gy = (y - y0) / h;
    if (!(gx >= 0.0 && gy >= 0.0 && gx <= nx - 1 && gy <= ny - 1))
        return kInf;
    const int i = std::min(static_cast<int>(gx), nx - 2), j = std::min(static_cast<int>(gy), ny - 2);
    const double fx = gx - i, fy = gy - j;
    const auto at = [&](int a, int b) { return arrival[static_cast<std::size_t>(b) * nx + a]; };
    const double a = at(i, j), b = at(i + 1, j), c = at(i, j + 1), d = at(i + 1, j + 1);
    if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c) || !std::isfinite(d))
    {
        // Near the front's edge: the nearest reached corner.
        const double cand[4] = {a, b, c, d};
        const double dist[4] = {fx * fx + fy * fy, (1 - fx) * (1 - fx) + fy * fy, fx * fx + (1 - fy) * (1 - fy),
                                (1 - fx) * (1 - fx) + (1 - fy) * (1 - fy)};
        double best = kInf, bd = kInf;
        for (int k = 0; k < 4; ++k)
            if (std::isfinite(cand[k]) && dist[k] < bd && dist[k] <= 0.5)
            {
                bd = dist[k];
                best = cand[k];
            }
        return best;
    }
    return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
}

std::vector<std::vector<Point2>> Reachability::isochrone(double t) const
{
    // Marching squares on T - t (unreached = above every level); segments joined into polylines by their ends.
    using Key = std::pair<long long, long long>;
    struct Seg
    {
        Point2 a, b;
    };
    std::vector<Seg> segs;
    const auto val = [&](int i, int j) {
        const double v = arrival[static_cast<std::size_t>(j) * nx + i];
        return std::isfinite(v) ? v - t : 1e300;
    };
    const auto cross = [&](int i1, int j1, double v1, int i2, int j2, double v2) {
        const double s = v1 / (v1 - v2);
        return Point2{x0 + h * (i1 + s * (i2 - i1)), y0 + h * (j1 + s * (j2 - j1))};
    };
    for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i)
        {
            const double v[4] = {val(i, j), val(i + 1, j), val(i + 1, j + 1), val(i, j + 1)};
            const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
            int code = 0;
            for (int k = 0; k < 4; ++k)
                code |= (v[k] <= 0.0) << k;
            if (code == 0 || code == 15)
                continue;
            std::vector<Point2> pts;  // crossings on edges k -> k+1
            for (int k = 0; k < 4; ++k)
            {
                const int l = (k + 1) % 4;
                if ((v[k] <= 0.0) != (v[l] <= 0.0))
                    pts.push_back(cross(ci[k], cj[k], v[k], ci[l], cj[l], v[l]));
            }
            if (pts.size() == 2)
                segs.push_back({pts[0], pts[1]});
            else if (pts.size() == 4)
            {
                // Saddle: decide by the centre's mean (finite values only).
                const double mean = 0.25 * (v[0] + v[1] + v[2] + v[3]);
                if ((mean <= 0.0) == (v[0] <= 0.0))
                {
                    segs.push_back({pts[0], pts[1]});
                    segs.push_back({pts[2], pts[3]});
                }
                else
                {
                    segs.push_back({pts[3], pts[0]});
                    segs.push_back({pts[1], pts[2]});
                }
            }
        }
    const double q = h * 1e-6;
    const auto key = [&](const Point2 &p) { return Key{std::llround(p.x / q), std::llround(p.y / q)}; };
    std::multimap<Key, std::size_t> ends;
    for (std::size_t s = 0; s < segs.size(); ++s)
    {
        ends.emplace(key(segs[s].a), s);
        ends.emplace(key(segs[s].b), s);
    }
    std::vector<char> used(segs.size(), 0);
    std::vector<std::vector<Point2>> lines;
    const auto take = [&](const Point2 &p, std::size_t self) -> std::optional<Point2> {
        auto range = ends.equal_range(key(p));
        for (auto it = range.first; it != range.second; ++it)
            if (!used[it->second] && it->second != self)
            {
                used[it->second] = 1;
                const Seg &s = segs[it->second];
                return key(s.a) == key(p) ? s.b : s.a;
            }
        return std::nullopt;
    };
    for (std::size_t s = 0; s < segs.size(); ++s)
    {
        if (used[s])
            continue;
        used[s] = 1;
        std::vector<Point2> fwd{segs[s].a, segs[s].b};
        while (auto p = take(fwd.back(), s))
            fwd.push_back(*p);
        std::vector<Point2> bwd;
        Point2 head = fwd.front();
        while (auto p = take(head, s))
        {
            bwd.push_back(*p);
            head = *p;
        }
        std::vector<Point2> line(bwd.rbegin(), bwd.rend());
        line.insert(line.end(), fwd.begin(), fwd.end());
        lines.push_back(std::move(line));
    }
    return lines;
}
}  // namespace ompl_glider
