// Uses the installed library: one leg in a uniform current, checked against the closed form.
#include <cmath>
#include <cstdio>
#include <memory>

#include <ompl_glider/cost/TravelTimeCalculator.h>
#include <ompl_glider/current/UniformCurrent.h>

int main()
{
    auto field = std::make_shared<ompl_glider::UniformCurrent>(0.3, 0.0);
    ompl_glider::TravelTimeParams p;
    p.speed = 0.5;
    ompl_glider::TravelTimeCalculator calc(field, p);
    const double t = calc.travelTime(0.0, 0.0, 4.0, 0.0, 0.0);
    std::printf("travel time %.9f (expected %.9f)\n", t, 4.0 / 0.8);
    return std::abs(t - 5.0) < 1e-9 ? 0 : 1;
}
