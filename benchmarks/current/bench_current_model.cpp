// Current-model calls per second (CMC/s) of the gridded ocean-current model ([EichhornOceans] Sec. II.C) for each pair
// of x/y scheme (nearest, bilinear, bicubic) and time scheme (nearest, linear, cubic, Akima), on a cached subset
// held in memory: a rectilinear Cartesian grid (as loaded from a Cartesian file) and a projected geographic grid
// (curvilinear: point location by bucket + inverse bilinear map). Single-threaded.
//   build-*/benchmarks/bench_current_model --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "ompl_glider/current/GriddedCurrentField.h"

using namespace ompl_glider;

namespace
{
constexpr std::size_t kNx = 120, kNy = 100, kNt = 41; // ~ a 600 x 500 km region at 5 km, 10 days every 6 h

/// A smooth synthetic field on the mission-sized subset; nz depth layers (1 = surface forecast).
GriddedData makeData(bool curvilinear, std::size_t nz)
{
    GriddedData d;
    d.nx = kNx;
    d.ny = kNy;
    const double h = 5000.0;
    if (curvilinear)
    {
        // a projected lon/lat grid: slightly rotated and converging rows, like meridians away from the centre
        for (std::size_t j = 0; j < kNy; ++j)
            for (std::size_t i = 0; i < kNx; ++i)
            {
                const double x = (double(i) - 60.0) * h, y = (double(j) - 50.0) * h;
                const double a = 2e-7 * x; // convergence angle grows with x
                d.nodeX.push_back(x * std::cos(a) - y * std::sin(a));
                d.nodeY.push_back(x * std::sin(a) + y * std::cos(a));
            }
    }
    else
    {
        for (std::size_t i = 0; i < kNx; ++i)
            d.x.push_back(double(i) * h);
        for (std::size_t j = 0; j < kNy; ++j)
            d.y.push_back(double(j) * h);
    }
    d.depth.clear();
    for (std::size_t k = 0; k < nz; ++k)
        d.depth.push_back(10.0 * double(k * k));
    d.time.clear();
    for (std::size_t t = 0; t < kNt; ++t)
        d.time.push_back(21600.0 * double(t));
    for (std::size_t t = 0; t < kNt; ++t)
        for (std::size_t k = 0; k < nz; ++k)
            for (std::size_t j = 0; j < kNy; ++j)
                for (std::size_t i = 0; i < kNx; ++i)
                {
                    d.u.push_back(float(0.3 * std::sin(0.1 * i + 0.05 * t) * std::cos(0.07 * j) / (1.0 + 0.1 * k)));
                    d.v.push_back(float(0.2 * std::cos(0.08 * i - 0.03 * t) / (1.0 + 0.1 * k)));
                }
    return d;
}

struct Query
{
    double x, y, z, t;
};

/// Queries along random legs (as the travel-time code asks: consecutive points a few hundred metres apart).
std::vector<Query> makeQueries(const GriddedCurrentField &f, std::size_t nz)
{
    const Region e = f.extent();
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> X(e.xMin + 0.2 * (e.xMax - e.xMin), e.xMax - 0.2 * (e.xMax - e.xMin));
    std::uniform_real_distribution<double> Y(e.yMin + 0.2 * (e.yMax - e.yMin), e.yMax - 0.2 * (e.yMax - e.yMin));
    std::uniform_real_distribution<double> A(0, 2 * M_PI), T(0, 21600.0 * (kNt - 2));
    std::vector<Query> q;
    while (q.size() < 8192)
    {
        double x = X(rng), y = Y(rng), t = T(rng);
        const double a = A(rng);
        const double z = nz > 1 ? 35.0 : 0.0;
        for (int s = 0; s < 32; ++s)
        {
            q.push_back({x, y, z, t});
            x += 300.0 * std::cos(a);
            y += 300.0 * std::sin(a);
            t += 600.0;
        }
    }
    return q;
}

void run(benchmark::State &state, bool curvilinear, std::size_t nz, bool jacobian)
{
    GriddedFieldOptions o;
    o.xy = static_cast<Interp2D>(state.range(0));
    o.time = static_cast<Interp1D>(state.range(1));
    o.depth = Interp1D::Linear;
    static const std::shared_ptr<GriddedData> data[2][2] = {
        {std::make_shared<GriddedData>(makeData(false, 1)), std::make_shared<GriddedData>(makeData(false, 6))},
        {std::make_shared<GriddedData>(makeData(true, 1)), std::make_shared<GriddedData>(makeData(true, 6))}};
    const GriddedCurrentField f(*data[curvilinear][nz > 1], o);
    const std::vector<Query> qs = makeQueries(f, nz);
    std::size_t i = 0;
    double sink = 0;
    for (auto _ : state)
    {
        const Query &q = qs[i];
        if (jacobian)
        {
            const Jacobian J = f.jacobian(q.x, q.y, q.z, q.t);
            sink += J.ux + J.vy;
        }
        else
        {
            const Velocity c = f.velocity(q.x, q.y, q.z, q.t);
            sink += c.u + c.v;
        }
        if (++i == qs.size())
            i = 0;
    }
    benchmark::DoNotOptimize(sink);
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
    state.SetLabel(toString(o.xy) + "/" + toString(o.time) + (nz > 1 ? " depth linear (6 layers)" : " surface") +
                   (jacobian ? " jacobian" : ""));
}

void BM_Rectilinear(benchmark::State &s)
{
    run(s, false, 1, false);
}
void BM_Rectilinear3D(benchmark::State &s)
{
    run(s, false, 6, false);
}
void BM_Projected(benchmark::State &s)
{
    run(s, true, 1, false);
}
void BM_RectilinearJacobian(benchmark::State &s)
{
    run(s, false, 1, true);
}

void allPairs(benchmark::internal::Benchmark *b)
{
    for (int xy = 0; xy < 3; ++xy)
        for (int t = 0; t < 4; ++t)
            b->Args({xy, t});
}
} // namespace

BENCHMARK(BM_Rectilinear)->Apply(allPairs);
BENCHMARK(BM_Rectilinear3D)->Args({1, 1})->Args({2, 2})->Args({1, 3});
BENCHMARK(BM_Projected)->Args({0, 1})->Args({1, 1})->Args({2, 1})->Args({1, 3});
BENCHMARK(BM_RectilinearJacobian)->Args({1, 1})->Args({2, 1})->Args({1, 3});
BENCHMARK_MAIN();
