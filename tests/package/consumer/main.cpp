// Uses the installed library: one leg in a uniform current, checked against the closed form, when the package
// has the NetCDF component a unit conversion through UDUNITS-2 (a private dependency a static library carries),
// and, when it has the mission component, the built-in Gulf Stream mission through the planning pipeline.
#include <cmath>
#include <cstdio>
#include <memory>

#include <ompl_glider/Config.h>
#include <ompl_glider/cost/TravelTimeCalculator.h>
#include <ompl_glider/current/UniformCurrent.h>
#if OMPL_GLIDER_WITH_NETCDF
#include <ompl_glider/current/UnitConversion.h>
#endif
#if OMPL_GLIDER_WITH_MISSION
#include <ompl_glider/mission/Planning.h>
#endif

int main()
{
    auto field = std::make_shared<ompl_glider::UniformCurrent>(0.3, 0.0);
    ompl_glider::TravelTimeParams p;
    p.speed = 0.5;
    ompl_glider::TravelTimeCalculator calc(field, p);
    const double t = calc.travelTime(0.0, 0.0, 4.0, 0.0, 0.0);
    std::printf("travel time %.9f (expected %.9f)\n", t, 4.0 / 0.8);
    if (std::abs(t - 5.0) >= 1e-9)
        return 1;
#if OMPL_GLIDER_WITH_NETCDF
    const double knot = ompl_glider::velocityToMetresPerSecond("knots").factor;
    std::printf("1 knot = %.12f m/s\n", knot);
    if (std::abs(knot - 1852.0 / 3600.0) > 1e-15)
        return 1;
#endif
#if OMPL_GLIDER_WITH_MISSION
    const ompl_glider::MissionProblem problem(ompl_glider::defaultGulfStreamMission());
    const ompl_glider::MissionResult r = ompl_glider::runMission(problem);
    std::printf("Gulf Stream mission: %s, travel time %.4f\n", statusText(r.plan.status).c_str(), r.plan.travelTime);
    if (!r.plan.solved || !(r.plan.travelTime > 10.0 && r.plan.travelTime < 12.0))
        return 1;
#endif
    return 0;
}
