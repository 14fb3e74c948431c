// Speed of the forbidden-region tests on a many-vertex coastline: Polygon::segmentIntersects and contains on a
// star-shaped polygon of N vertices (uniform-grid edge index) against a brute-force scan of every edge.
#include <benchmark/benchmark.h>

#include <cmath>
#include <array>
#include <random>
#include <vector>

#include "ompl_glider/environment/Polygon.h"

using namespace ompl_glider;

namespace
{
std::vector<Point2> star(int n)
{
    // a coastline-like star: smooth large bays plus a little noise (short edges, like a digitised coast)
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> noise(-0.002, 0.002);
    std::vector<Point2> r;
    for (int i = 0; i < n; ++i)
    {
        const double a = 2 * M_PI * (i + 0.5) / n;
        const double q = 0.8 + 0.12 * std::sin(7 * a) + 0.05 * std::sin(31 * a + 1) + noise(rng);
        r.push_back({q * std::cos(a), q * std::sin(a)});
    }
    return r;
}

std::vector<std::array<double, 4>> segments()
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    std::vector<std::array<double, 4>> s;
    for (int k = 0; k < 256; ++k)
    {
        const double ax = u(rng), ay = u(rng), a = 0.7 * k;
        s.push_back({ax, ay, ax + 0.2 * std::cos(a), ay + 0.2 * std::sin(a)});
    }
    return s;
}

bool bruteForce(const std::vector<Point2> &r, const std::array<double, 4> &s)
{
    auto o = [](double px, double py, double qx, double qy, double rx, double ry) {
        return (qx - px) * (ry - py) - (qy - py) * (rx - px);
    };
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
    {
        const double o1 = o(s[0], s[1], s[2], s[3], r[j].x, r[j].y), o2 = o(s[0], s[1], s[2], s[3], r[i].x, r[i].y);
        const double o3 = o(r[j].x, r[j].y, r[i].x, r[i].y, s[0], s[1]),
                     o4 = o(r[j].x, r[j].y, r[i].x, r[i].y, s[2], s[3]);
        if (o1 * o2 <= 0 && o3 * o4 <= 0)
            return true;
    }
    return false;
}
} // namespace

static void BM_SegmentIndexed(benchmark::State &state)
{
    const Polygon p(star(static_cast<int>(state.range(0))));
    const auto segs = segments();
    std::size_t k = 0, hits = 0;
    for (auto _ : state)
        hits += p.segmentIntersects(segs[k][0], segs[k][1], segs[k][2], segs[k][3]), k = (k + 1) % segs.size();
    benchmark::DoNotOptimize(hits);
}
BENCHMARK(BM_SegmentIndexed)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000);

static void BM_SegmentBruteForce(benchmark::State &state)
{
    const auto r = star(static_cast<int>(state.range(0)));
    const auto segs = segments();
    std::size_t k = 0, hits = 0;
    for (auto _ : state)
        hits += bruteForce(r, segs[k]), k = (k + 1) % segs.size();
    benchmark::DoNotOptimize(hits);
}
BENCHMARK(BM_SegmentBruteForce)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000);

static void BM_ContainsIndexed(benchmark::State &state)
{
    const Polygon p(star(static_cast<int>(state.range(0))));
    const auto segs = segments();
    std::size_t k = 0, hits = 0;
    for (auto _ : state)
        hits += p.contains(segs[k][0], segs[k][1]), k = (k + 1) % segs.size();
    benchmark::DoNotOptimize(hits);
}
BENCHMARK(BM_ContainsIndexed)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000);

BENCHMARK_MAIN();
