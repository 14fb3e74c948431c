/// @file LevelSetDistance.cpp
/// @brief Signed distances to the forbidden set on the level-set grid (polygons, node masks) and the
/// reinitialisation of phi to a signed distance ([LollaLevelSet]); see LevelSetInternal.h.

#include <algorithm>
#include <cmath>

#include "LevelSetInternal.h"
#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/environment/Polygon.h"

namespace ompl_glider
{
namespace levelset_detail
{
/// Signed distance of polygon p shifted by (sx, sy) at the nodes within band of its bounding box; values below
/// -band are left out.
SparseDistance polygonDistance(const Grid &g, const Polygon &p, double sx, double sy, double band, double clearance)
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
                  double clearance)
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
void reinitialise(const Grid &g, std::vector<double> &phi, const std::vector<std::uint32_t> &tiles, int tx, double band,
                  std::vector<double> &dist, ThreadPool *pool)
{
    if (dist.size() != g.size())
        dist.assign(g.size(), kInf);
    const int R = static_cast<int>(std::ceil(band / g.h));
    const auto segDist = [](double px, double py, double ax, double ay, double bx, double by) {
        const double ex = bx - ax, ey = by - ay, l2 = ex * ex + ey * ey;
        double s = l2 > 0.0 ? ((px - ax) * ex + (py - ay) * ey) / l2 : 0.0;
        s = std::clamp(s, 0.0, 1.0);
        const double dx = px - ax - s * ex, dy = py - ay - s * ey;
        return std::sqrt(dx * dx + dy * dy); // not hypot: no overflow to guard against here, and 4x faster
    };
    // the distance from one tile's zero level, written within R + 1 nodes of the tile
    const auto scatter = [&](std::uint32_t tile) {
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
                if (n == 4) // a saddle: also the other pairing's first segment keeps both branches close
                    for (int jj = j; jj <= j + 1; ++jj)
                        for (int ii = i; ii <= i + 1; ++ii)
                        {
                            double &d = dist[g.index(ii, jj)];
                            d = std::min(d, segDist(g.x(ii), g.y(jj), px[1], py[1], px[2], py[2]));
                        }
            }
    };
    // the tile's nodes: phi becomes the distance with its sign, the scratch space is cleared
    const auto finish = [&](std::uint32_t tile) {
        const int a = static_cast<int>(tile % tx), b = static_cast<int>(tile / tx);
        for (int j = b * kTile; j < std::min(g.ny, (b + 1) * kTile); ++j)
            for (int i = a * kTile; i < std::min(g.nx, (a + 1) * kTile); ++i)
            {
                const std::size_t n = g.index(i, j);
                const double d = std::min(dist[n], band);
                phi[n] = phi[n] <= 0.0 ? -d : d;
                dist[n] = kInf;
            }
    };
    if (pool && pool->size() > 1 && R + 1 <= kTile / 2)
    {
        // tiles of one colour (column and row parity) are a tile apart: their writes never meet, so each colour
        // is shared by the threads, with no lock
        std::vector<std::uint32_t> colour;
        for (std::uint32_t c = 0; c < 4; ++c)
        {
            colour.clear();
            for (std::uint32_t tile : tiles)
                if ((tile % tx) % 2 + 2 * ((tile / tx) % 2) == c)
                    colour.push_back(tile);
            pool->parallelFor(colour.size(), [&](std::size_t k) { scatter(colour[k]); });
        }
        pool->parallelFor(tiles.size(), [&](std::size_t k) { finish(tiles[k]); });
        return;
    }
    for (std::uint32_t tile : tiles)
        scatter(tile);
    for (std::uint32_t tile : tiles)
        finish(tile);
}
bool waterConnects(const SolverGrid &sg, Point2 a, Point2 b, int reach)
{
    const Grid &g = sg.grid;
    auto node = [&](Point2 p, int &i, int &j) {
        i = std::clamp(static_cast<int>(std::lround((p.x - g.x0) / g.h)), 0, g.nx - 1);
        j = std::clamp(static_cast<int>(std::lround((p.y - g.y0) / g.h)), 0, g.ny - 1);
    };
    int ai = 0, aj = 0, bi = 0, bj = 0;
    node(a, ai, aj);
    node(b, bi, bj);
    std::vector<char> seen(g.size(), 0);
    std::vector<std::uint32_t> todo;
    auto visitAround = [&](int ci, int cj) {
        for (int j = std::max(0, cj - reach); j <= std::min(g.ny - 1, cj + reach); ++j)
            for (int i = std::max(0, ci - reach); i <= std::min(g.nx - 1, ci + reach); ++i)
            {
                const std::size_t n = g.index(i, j);
                if (!seen[n] && !(sg.staticD[n] > 0.0))
                {
                    seen[n] = 1;
                    todo.push_back(static_cast<std::uint32_t>(n));
                }
            }
    };
    visitAround(ai, aj);
    while (!todo.empty())
    {
        const std::uint32_t n = todo.back();
        todo.pop_back();
        const int i = static_cast<int>(n % static_cast<std::uint32_t>(g.nx)),
                  j = static_cast<int>(n / static_cast<std::uint32_t>(g.nx));
        if (std::abs(i - bi) <= reach && std::abs(j - bj) <= reach)
            return true;
        visitAround(i, j);
    }
    return false;
}
} // namespace levelset_detail
} // namespace ompl_glider
