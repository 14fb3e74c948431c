// glider_plan: placeholder main job until the planner lands; prints the travel time of a few legs in the
// Gulf Stream (meandering jet) model.
#include <cmath>
#include <cstdio>
#include <memory>

#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/current/MeanderingJet.h"

int main()
{
    using namespace ompl_glider;
    auto jet = std::make_shared<MeanderingJet>();
    TravelTimeCalculator calc(jet);
    const double legs[][5] = {{0, -2, 2, 0, 0}, {2, 0, 5, 1, 0}, {5, 1, 8, -1, 3}, {8, 1, 2, 1, 0}};
    std::printf("Gulf Stream model (meandering jet), V = %.2f\n", calc.params().speed);
    for (const auto &l : legs)
    {
        const double t = calc.travelTime(l[0], l[1], l[2], l[3], l[4]);
        std::printf("leg (%.1f,%.1f)->(%.1f,%.1f) depart %.1f: travel time %s%.4f\n", l[0], l[1], l[2], l[3], l[4],
                    std::isfinite(t) ? "" : "impassable ", t);
    }
    std::printf("cost function calls %llu, current model calls %llu\n",
                (unsigned long long)calc.costFunctionCalls(), (unsigned long long)jet->callCount());
    return 0;
}
