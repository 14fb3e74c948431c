// The LevelSet planner named in a mission gives a flyable route around islands whenever its front reaches the goal:
// randomized islands (regular polygons, concave hooks, thin bars) in the meandering jet ([EichhornRAS] Sec. 6.1),
// random start and goal pairs, each planned through the pipeline (runMission) with LevelSet and with ZA*TVE. The
// level set's route must be solved, leave no island crossed (every leg checked by the environment, a reference that
// shares no code with the planners' search) and take no longer than the best of the two routes by 0.5 %.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;

namespace
{
struct Island
{
    std::vector<std::pair<double, double>> points;
    double cx, cy, r; // a circle that holds it
};

Island regular(double cx, double cy, double r, int n, double turn)
{
    Island s{{}, cx, cy, r};
    for (int k = 0; k < n; ++k)
    {
        const double a = turn + 2.0 * M_PI * k / n;
        s.points.emplace_back(cx + r * std::cos(a), cy + r * std::sin(a));
    }
    return s;
}

/// A hook: an arc of a ring, thickness w, opening toward @p turn (a concave island that traps a backtrack).
Island hook(double cx, double cy, double r, double w, double turn)
{
    Island s{{}, cx, cy, r};
    const int n = 16;
    for (int k = 0; k <= n; ++k)
    {
        const double a = turn + 0.35 * M_PI + 1.3 * M_PI * k / n;
        s.points.emplace_back(cx + r * std::cos(a), cy + r * std::sin(a));
    }
    for (int k = n; k >= 0; --k)
    {
        const double a = turn + 0.35 * M_PI + 1.3 * M_PI * k / n;
        s.points.emplace_back(cx + (r - w) * std::cos(a), cy + (r - w) * std::sin(a));
    }
    return s;
}

/// A thin bar of length 2r and width w, turned by @p turn.
Island bar(double cx, double cy, double r, double w, double turn)
{
    Island s{{}, cx, cy, r};
    const double c = std::cos(turn), sn = std::sin(turn);
    for (const auto &[a, b] :
         std::vector<std::pair<double, double>>{{-r, -w / 2}, {r, -w / 2}, {r, w / 2}, {-r, w / 2}})
        s.points.emplace_back(cx + a * c - b * sn, cy + a * sn + b * c);
    return s;
}

struct Case
{
    std::string yaml;
    std::string label;
};

/// A random problem: three islands between a start near the western edge and a goal near the eastern one.
Case randomCase(std::mt19937 &rng, int index)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const auto in = [&](double a, double b) { return a + (b - a) * u(rng); };
    const double sx = in(0.4, 1.4), sy = in(-3.4, 3.4), gx = in(8.6, 9.6), gy = in(-3.4, 3.4);
    std::vector<Island> islands;
    while (islands.size() < 3)
    {
        const double cx = in(2.2, 7.8), cy = in(-3.0, 3.0), r = in(0.35, 0.9), turn = in(0.0, 2.0 * M_PI);
        const int kind = static_cast<int>(u(rng) * 3.0);
        const Island s = kind == 0   ? regular(cx, cy, r, 12 + static_cast<int>(u(rng) * 30), turn)
                         : kind == 1 ? hook(cx, cy, r, in(0.12, 0.25), turn)
                                     : bar(cx, cy, r, in(0.08, 0.2), turn);
        bool clear = std::hypot(cx - sx, cy - sy) > r + 0.4 && std::hypot(cx - gx, cy - gy) > r + 0.4;
        for (const Island &o : islands)
            clear = clear && std::hypot(cx - o.cx, cy - o.cy) > r + o.r + 0.3;
        if (clear)
            islands.push_back(s);
    }
    std::ostringstream y;
    y.precision(6);
    y << "name: islands" << index << "\ncurrent: {type: meandering_jet}\n"
      << "region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
      << "start: {x: " << sx << ", y: " << sy << "}\ngoal: {x: " << gx << ", y: " << gy << "}\n"
      << "vehicle: {speed: 0.5}\nforbidden:\n  obstacles:\n";
    for (std::size_t k = 0; k < islands.size(); ++k)
    {
        y << "    - name: I" << k << "\n      points: [";
        for (std::size_t p = 0; p < islands[k].points.size(); ++p)
            y << (p ? ", " : "") << "[" << islands[k].points[p].first << ", " << islands[k].points[p].second << "]";
        y << "]\n";
    }
    std::ostringstream label;
    label << "case " << index << ": start (" << sx << ", " << sy << "), goal (" << gx << ", " << gy << ")";
    return {y.str(), label.str()};
}

MissionResult planWith(const std::string &yaml, const std::string &planner)
{
    const std::string extra = planner == "LevelSet" ? "planner: {name: LevelSet, horizon: 40, parameters: "
                                                      "{resolution: 0.05}}\n"
                                                    : "planner: {name: " + planner + ", horizon: 40}\n";
    MissionSpec spec = parseMission(yaml + extra, "islands.yaml");
    spec.outputs.files.clear();
    const MissionProblem problem(spec);
    MissionResult r = runMission(problem);
    if (r.plan.solved)
    {
        const auto &p = r.plan.path;
        for (std::size_t i = 1; i < p.size(); ++i)
            EXPECT_TRUE(problem.getEnvironment()->legFree(p[i - 1].x, p[i - 1].y, p[i - 1].t, p[i].x, p[i].y, p[i].t))
                << planner << ": leg " << i << " from (" << p[i - 1].x << ", " << p[i - 1].y << ")";
    }
    return r;
}

void checkCases(unsigned seed, int count)
{
    std::mt19937 rng(seed);
    for (int k = 0; k < count; ++k)
    {
        const Case c = randomCase(rng, k);
        SCOPED_TRACE(c.label);
        const MissionResult ls = planWith(c.yaml, "LevelSet");
        const MissionResult za = planWith(c.yaml, "ZA*TVE");
        // The lattice's route proves that a path exists within the horizon; the level set's front then reaches the goal
        // and its route must fly.
        ASSERT_TRUE(za.plan.solved) << c.yaml << za.plan.reason;
        ASSERT_TRUE(ls.plan.solved) << c.yaml << ls.plan.status << ": " << ls.plan.reason;
        const double best = std::min(ls.plan.travelTime, za.plan.travelTime);
        std::printf("%s: LevelSet %.4f, ZA*TVE %.4f\n", c.label.c_str(), ls.plan.travelTime, za.plan.travelTime);
        EXPECT_LE(ls.plan.travelTime, best * 1.005) << c.yaml;
    }
}
} // namespace

TEST(LevelSetIslands, RandomIslandsGiveFlyableRoutesWithinHalfAPercentOfTheBest)
{
    checkCases(20261207u, 3);
}

TEST(LevelSetIslands, ManyRandomIslandsGiveFlyableRoutesWithinHalfAPercentOfTheBest)
{
    checkCases(7411u, 12);
}
