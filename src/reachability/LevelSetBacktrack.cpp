/// @file LevelSetBacktrack.cpp
/// @brief The level-set solver's time-optimal path, backtracked through the arrival field, and the queries of a
/// Reachability: the arrival time at a point and the isochrones ([LollaLevelSet]); see LevelSetInternal.h.

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "LevelSetInternal.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/environment/Environment.h"

namespace ompl_glider
{
namespace levelset_detail
{
namespace
{
/// The front's outward normal from the arrival field T: node gradients of T (central differences where both
/// neighbours are reached, one-sided otherwise), interpolated bilinearly over the cell's corners that have one.
class ArrivalNormals
{
public:
    ArrivalNormals(const Reachability &r, const Grid &g)
        : g_(g), tgx_(g.size(), 0.0), tgy_(g.size(), 0.0), tok_(g.size(), 0)
    {
        const auto diff = [&](int i, int j, int di, int dj, double &d) {
            const double c = r.arrival[g.index(i, j)];
            const bool hasP = i + di < g.nx && j + dj < g.ny && std::isfinite(r.arrival[g.index(i + di, j + dj)]);
            const bool hasM = i - di >= 0 && j - dj >= 0 && std::isfinite(r.arrival[g.index(i - di, j - dj)]);
            if (hasP && hasM)
                d = (r.arrival[g.index(i + di, j + dj)] - r.arrival[g.index(i - di, j - dj)]) / (2 * g.h);
            else if (hasP)
                d = (r.arrival[g.index(i + di, j + dj)] - c) / g.h;
            else if (hasM)
                d = (c - r.arrival[g.index(i - di, j - dj)]) / g.h;
            else
                return false;
            return true;
        };
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
            {
                const std::size_t n = g.index(i, j);
                if (std::isfinite(r.arrival[n]))
                    tok_[n] = diff(i, j, 1, 0, tgx_[n]) && diff(i, j, 0, 1, tgy_[n]);
            }
    }

    /// The unit normal (nx, ny) at (px, py) (clamped into the grid); false (nx, ny unchanged) where no corner of the
    /// cell has a gradient or it vanishes.
    bool normal(double px, double py, double &nx, double &ny) const
    {
        const Grid &g = g_;
        const double gx = std::clamp((px - g.x0) / g.h, 0.0, g.nx - 1.0);
        const double gy = std::clamp((py - g.y0) / g.h, 0.0, g.ny - 1.0);
        const int i = std::min(static_cast<int>(gx), g.nx - 2), j = std::min(static_cast<int>(gy), g.ny - 2);
        const double fx = gx - i, fy = gy - j;
        double sx2 = 0, sy2 = 0, sw = 0;
        const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
        const std::size_t id[4] = {g.index(i, j), g.index(i + 1, j), g.index(i, j + 1), g.index(i + 1, j + 1)};
        for (int k = 0; k < 4; ++k)
            if (tok_[id[k]])
            {
                sx2 += w[k] * tgx_[id[k]];
                sy2 += w[k] * tgy_[id[k]];
                sw += w[k];
            }
        const double m = std::hypot(sx2, sy2);
        if (sw <= 0.0 || m <= 0.0)
            return false;
        nx = sx2 / m;
        ny = sy2 / m;
        return true;
    }

private:
    const Grid &g_;
    std::vector<double> tgx_, tgy_; ///< node gradients of T
    std::vector<char> tok_;         ///< the node has a gradient
};

/// The point one step of length @p h1 back in time from (px, py) at time pt, heading (ux, uy), with the current
/// @p cm at the step's midpoint. Near a moving forbidden region (drifting ice) T is not the front at the path's
/// time: a step along grad T may enter the region; along an island's edge the discrete normal may point into it
/// (the nodes within the clearance are never reached). Where a step ends in a region or where the front never came,
/// the heading turns, 15 degrees at a time either way, to the nearest one whose step ends where the region is not
/// and the front came (a local repair; the legs are checked again later). Unchanged when no such heading exists.
Point2 stepBack(const Reachability &r, const BacktrackSetup &s, double px, double py, double pt, double h1,
                const Velocity &cm, double ux, double uy)
{
    const double V = s.speed;
    double qx = px - h1 * (cm.u + V * ux), qy = py - h1 * (cm.v + V * uy);
    const auto blocked = [&](double x, double y, double t) {
        return s.environment && !s.environment->pointFree(x, y, t);
    };
    if (blocked(qx, qy, pt - h1) || !std::isfinite(r.arrivalAt(qx, qy)))
        for (int k = 1; k <= 12; ++k)
        {
            bool found = false;
            for (int sgn = -1; sgn <= 1 && !found; sgn += 2)
            {
                const double a = sgn * k * M_PI / 12.0, ca = std::cos(a), sa = std::sin(a);
                const double tx = ux * ca - uy * sa, ty = ux * sa + uy * ca;
                const double rx = px - h1 * (cm.u + V * tx), ry = py - h1 * (cm.v + V * ty);
                if (!blocked(rx, ry, pt - h1) && std::isfinite(r.arrivalAt(rx, ry)))
                {
                    qx = rx;
                    qy = ry;
                    found = true;
                }
            }
            if (found)
                break;
        }
    return {qx, qy};
}
} // namespace

std::vector<TimedPoint> backtrackPath(const Reachability &r, const Grid &g, Point2 start, Point2 goal,
                                      const BacktrackSetup &s)
{
    const ArrivalNormals normals(r, g);
    const CurrentField &field = *s.field;
    const double V = s.speed, z = s.depth, dt = s.dt, t0 = r.t0;
    std::vector<TimedPoint> back;
    double px = goal.x, py = goal.y, pt = r.goalTime;
    back.push_back({px, py, pt});
    const double holdTol = std::max(3.0 * dt, 2e-3 * (r.goalTime - t0));
    const double done = t0 + s.dt0;
    const std::size_t maxBack = 4 * static_cast<std::size_t>((r.goalTime - t0) / dt + 10);
    double lastNx = 0.0, lastNy = 0.0; // the last normal found: kept for a few steps where the path runs
    int blind = 0;                     // along unreached nodes (the edge of a forbidden region)
    for (std::size_t k = 0; k < maxBack && pt > done; ++k)
    {
        // Where T is earlier than the path's time by more than the tolerance, the glider held there.
        const double Tx = r.arrivalAt(px, py);
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
        // One midpoint step back along dx/dt = c + V n.
        const double h1 = std::min(dt, pt - done);
        double nx = lastNx, ny = lastNy;
        if (normals.normal(px, py, nx, ny))
            blind = 0;
        else if (++blind > 8 || !(lastNx != 0.0 || lastNy != 0.0))
            break; // off the reached nodes for long (along a forbidden region's edge): stop
        lastNx = nx;
        lastNy = ny;
        const Velocity c1 = field.velocity(px, py, z, pt);
        const double mx = px - 0.5 * h1 * (c1.u + V * nx), my = py - 0.5 * h1 * (c1.v + V * ny);
        double nmx = nx, nmy = ny;
        normals.normal(mx, my, nmx, nmy);
        const Velocity cm = field.velocity(mx, my, z, pt - 0.5 * h1);
        const Point2 q = stepBack(r, s, px, py, pt, h1, cm, nmx, nmy);
        px = q.x;
        py = q.y;
        pt -= h1;
        back.push_back({px, py, pt});
    }
    back.push_back({start.x, start.y, t0});
    return std::vector<TimedPoint>(back.rbegin(), back.rend());
}
} // namespace levelset_detail

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
            std::vector<Point2> pts; // crossings on edges k -> k+1
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
} // namespace ompl_glider
