// Parallel evaluation of the dive profiles of a leg ([EichhornOceans] Sec. IV: the profiles of one cost-function call
// are independent and run on a thread pool). Times DiveProfileTravelTime::bestProfile() with pools of 1..N threads
// on legs of the meandering jet made depth-varying (the jet decays with depth over a scale of 300 m and a
// 0.15 counter-current flows below), and checks that every pool gives the serial result bit for bit.
//
// Usage: bench_dive_profiles [legs=400] [max_threads=hardware] [climb_levels=3] [dive_levels=4] [step=0.1]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <thread>

#include <sys/resource.h>

#include "ompl_glider/cost/DiveProfile.h"
#include "ompl_glider/current/MeanderingJet.h"

using namespace ompl_glider;

namespace
{
/// The meandering jet times exp(-z / 300) plus an eastward counter-current -0.15 (1 - exp(-z / 300)).
class LayeredJet : public CurrentField
{
public:
    double maxSpeed(const Region &r) const override { return jet_.maxSpeed(r) + 0.15; }
    std::string name() const override { return "layered jet"; }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override
    {
        const Velocity c = jet_.velocity(x, y, 0.0, t);
        const double w = std::exp(-z / 300.0);
        return {w * c.u - 0.15 * (1 - w), w * c.v};
    }
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override
    {
        Jacobian j = jet_.jacobian(x, y, 0.0, t);
        const double w = std::exp(-z / 300.0);
        return {w * j.ux, w * j.uy, w * j.vx, w * j.vy};
    }

private:
    MeanderingJet jet_;
};

/// Process CPU time (user + system) in seconds.
double cpu()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6 * u.ru_stime.tv_usec;
}

double now()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
} // namespace

int main(int argc, char **argv)
{
    const int legs = argc > 1 ? std::atoi(argv[1]) : 400;
    const unsigned maxThreads =
        argc > 2 ? static_cast<unsigned>(std::atoi(argv[2])) : std::max(2u, std::thread::hardware_concurrency());
    DiveProfileParams d;
    d.zMin = 5;
    d.zMax = 1000;
    d.climbToMax = 200;
    d.minRange = 200;
    d.climbToLevels = argc > 3 ? std::atoi(argv[3]) : 3;
    d.diveToLevels = argc > 4 ? std::atoi(argv[4]) : 4;
    d.step = argc > 5 ? std::atof(argv[5]) : 0.1;
    auto field = std::make_shared<LayeredJet>();
    TravelTimeParams tp;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ux(0, 10), uy(-3, 3), ut(0, 15), ua(0, 2 * M_PI), ul(0.4, 1.2);
    struct Leg
    {
        double x1, y1, x2, y2, t;
    };
    std::vector<Leg> set;
    for (int i = 0; i < legs; ++i)
    {
        const double x = ux(rng), y = uy(rng), a = ua(rng), l = ul(rng);
        set.push_back({x, y, x + l * std::cos(a), y + l * std::sin(a), ut(rng)});
    }
    DiveProfileTravelTime serial(field, tp, d, nullptr, 1);
    std::printf("dive profiles: %zu profiles per leg, %d segments per leg, %d legs (length 0.4..1.2) in the layered "
                "jet; hardware threads %u\n",
                serial.profiles().size(), static_cast<int>(std::ceil(1 / d.step - 1e-9)), legs,
                std::thread::hardware_concurrency());
    // Each configuration runs `repeats` times, interleaved, and keeps its fastest run (the machine is shared).
    const int repeats = 5;
    std::vector<DiveLegResult> reference;
    double serialTime = 1e300, serialCpu = 0;
    for (int k = 0; k < repeats; ++k)
    {
        reference.clear();
        const double t0 = now(), c0 = cpu();
        for (const Leg &l : set)
            reference.push_back(serial.bestProfileSerial(l.x1, l.y1, l.x2, l.y2, l.t));
        if (now() - t0 < serialTime)
        {
            serialTime = now() - t0;
            serialCpu = cpu() - c0;
        }
    }
    int feasible = 0;
    for (const auto &r : reference)
        feasible += r.profile >= 0;
    std::printf("threads  wall [s]  legs/s   speedup  cores used  identical   (fastest of %d runs; cores used = "
                "CPU time / wall time: below the thread count the machine had no free core)\n",
                repeats);
    std::printf("%7u  %8.3f  %7.0f  %7.2f  %10.2f  %s\n", 1u, serialTime, legs / serialTime, 1.0,
                serialCpu / serialTime, "reference");
    for (unsigned n = 2; n <= maxThreads; ++n)
    {
        DiveProfileTravelTime par(field, tp, d, nullptr, n);
        std::vector<DiveLegResult> out;
        double wall = 1e300, cpuUsed = 0;
        for (int k = 0; k < repeats; ++k)
        {
            out.clear();
            const double t0 = now(), c0 = cpu();
            for (const Leg &l : set)
                out.push_back(par.bestProfile(l.x1, l.y1, l.x2, l.y2, l.t));
            if (now() - t0 < wall)
            {
                wall = now() - t0;
                cpuUsed = cpu() - c0;
            }
            double ts = now();
            for (int j = 0; j < 50 && j < static_cast<int>(set.size()); ++j)
                serial.bestProfileSerial(set[j].x1, set[j].y1, set[j].x2, set[j].y2, set[j].t);
            (void)ts;
        }
        bool same = true;
        for (std::size_t i = 0; i < out.size(); ++i)
            same = same && out[i].profile == reference[i].profile && out[i].profileTimes == reference[i].profileTimes;
        std::printf("%7u  %8.3f  %7.0f  %7.2f  %10.2f  %s\n", n, wall, legs / wall, serialTime / wall, cpuUsed / wall,
                    same ? "yes" : "NO");
    }
    double load[3] = {0, 0, 0};
    if (FILE *f = std::fopen("/proc/loadavg", "r"))
    {
        if (std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3)
            load[0] = -1;
        std::fclose(f);
    }
    std::printf("feasible legs: %d of %d; load average %.2f on %u hardware threads\n", feasible, legs, load[0],
                std::thread::hardware_concurrency());
    return 0;
}
