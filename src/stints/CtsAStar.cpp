// CTS-A* over constant-bearing stints ([IsernObstacles] Sec. II.1, III.A); see CtsAStar.h.
#include "ompl_glider/stints/CtsAStar.h"

#include <cmath>
#include <queue>
#include <unordered_set>
#include <vector>

#include "../routes/StintStep.h"

namespace ompl_glider
{
namespace
{
struct Node
{
    double x, y, t;
    std::size_t depth;
    long parent;     // index into the node list, -1 for the start
    double bearing;  // of the stint that reached this node
    double bound;    // lower bound of the cost through it (exact for a terminal)
    double distance; // to the goal
    bool terminal;   // mission end or goal reached
    bool reached;
    double arrival;
    double closest, closestTime; // closest approach to the goal so far (with a radius)
};

struct Key
{
    std::size_t depth;
    long long ix, iy;
    bool operator==(const Key &o) const { return depth == o.depth && ix == o.ix && iy == o.iy; }
};

struct KeyHash
{
    std::size_t operator()(const Key &k) const
    {
        std::size_t h = std::hash<long long>()(k.ix) * 1000003u;
        h ^= std::hash<long long>()(k.iy) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        return h ^ (k.depth * 2654435761u);
    }
};

std::vector<double> bearingsTo(const std::vector<Node> &nodes, long i)
{
    std::vector<double> b;
    for (; i >= 0 && nodes[static_cast<std::size_t>(i)].parent >= 0; i = nodes[static_cast<std::size_t>(i)].parent)
        b.push_back(nodes[static_cast<std::size_t>(i)].bearing);
    return {b.rbegin(), b.rend()};
}
} // namespace

CtsAStarResult ctsAStar(const StintSimulator &sim, const CtsAStarParams &params)
{
    const StintSettings &s = sim.settings();
    const double cell = params.cellSize > 0.0 ? params.cellSize : 0.5 * sim.speed() * s.duration;
    const std::size_t count = s.stintCount();
    const int rose = std::max(1, static_cast<int>(std::lround(360.0 / s.bearingStep)));
    const double end = sim.endTime();
    const std::uint64_t flown0 = sim.stintsFlown();

    std::vector<Node> nodes;
    const Point2 g = sim.goal();
    auto dist = [&](double x, double y) { return std::hypot(g.x - x, g.y - y); };
    nodes.push_back({sim.start().x, sim.start().y, sim.t0(), 0, -1, 0.0,
                     sim.lowerBound(sim.start().x, sim.start().y, sim.t0()), dist(sim.start().x, sim.start().y), false,
                     false, 0.0, dist(sim.start().x, sim.start().y), sim.t0()});
    using Entry = std::pair<std::pair<double, double>, long>; // (bound, distance), node
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    open.push({{nodes[0].bound, nodes[0].distance}, 0});
    std::unordered_set<Key, KeyHash> closed;
    CtsAStarResult out;
    long best = -1; // best terminal so far
    double bestCost = INFINITY;
    long bestPartial = 0; // expanded node with the best (bound, distance), for an unfinished search
    bool stopped = false;
    while (!open.empty())
    {
        const auto [prio, i] = open.top();
        if (prio.first >= bestCost)
            break;
        open.pop();
        const Node n = nodes[static_cast<std::size_t>(i)];
        if (n.terminal)
        {
            best = i;
            bestCost = n.bound;
            break;
        }
        const Key key{n.depth, static_cast<long long>(std::floor(n.x / cell)),
                      static_cast<long long>(std::floor(n.y / cell))};
        if (!closed.insert(key).second)
            continue;
        if (out.expansions >= params.maxExpansions || (params.stop && params.stop()))
        {
            stopped = true;
            break;
        }
        ++out.expansions;
        const Node &bp = nodes[static_cast<std::size_t>(bestPartial)];
        if (n.depth > bp.depth || (n.depth == bp.depth && n.distance < bp.distance))
            bestPartial = i;
        for (int k = 0; k < rose; ++k)
        {
            const double b = k * 360.0 / rose;
            const DiveEnd e = sim.flyStint(n.x, n.y, n.t, b);
            if (e.grounded)
                continue;
            Node c{e.x,       e.y,           e.t,       n.depth + 1,  i, b, 0.0, dist(e.x, e.y), false,
                   e.reached, e.arrivalTime, n.closest, n.closestTime};
            if (e.closestDistance < c.closest)
            {
                c.closest = e.closestDistance;
                c.closestTime = e.closestTime;
            }
            c.terminal = e.reached || c.depth >= count || e.t >= end - 1e-12 * std::max(1.0, std::abs(end));
            if (c.terminal)
            {
                StintPlan p; // only what cost() reads
                p.surfacings.push_back({e.x, e.y, e.t});
                p.remainingDistance = c.distance;
                p.reached = e.reached;
                p.arrivalTime = e.arrivalTime;
                if (s.radius > 0.0)
                {
                    p.closestDistance = c.closest;
                    p.closestTime = c.closestTime;
                }
                c.bound = sim.cost(p);
            }
            else
                c.bound = sim.lowerBound(e.x, e.y, e.t);
            if (c.bound >= bestCost)
                continue;
            if (c.terminal)
            {
                best = static_cast<long>(nodes.size());
                bestCost = c.bound;
            }
            nodes.push_back(c);
            open.push({{c.bound, c.distance}, static_cast<long>(nodes.size()) - 1});
        }
    }
    out.complete = !stopped && best >= 0;
    if (best >= 0)
        out.plan = sim.simulate(bearingsTo(nodes, best));
    else
    {
        // no complete plan: finish the most advanced partial one direct to the goal
        std::vector<double> b = bearingsTo(nodes, bestPartial);
        const StintPlan head = sim.simulate(b, false);
        double x = head.surfacings.back().x, y = head.surfacings.back().y, t = head.surfacings.back().t;
        while (b.size() < count && t < end && !head.grounded)
        {
            b.push_back(sim.bearingToGoal(x, y));
            if (flyOneStint(sim, x, y, t, b.back()))
                break;
        }
        out.plan = sim.simulate(b);
    }
    out.stints = sim.stintsFlown() - flown0;
    return out;
}
} // namespace ompl_glider
