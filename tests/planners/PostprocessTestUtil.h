#pragma once
// Shared helpers of the smoothing / refinement tests: contexts and a test-only forbidden rectangle.
#include <cmath>
#include <memory>
#include <string>

#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/environment/Environment.h"
#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider::test
{
/// An axis-aligned forbidden box; a leg is blocked when any point of it (sampled densely) is inside.
class BoxEnvironment : public Environment
{
public:
    BoxEnvironment(double x0, double x1, double y0, double y1) : x0_(x0), x1_(x1), y0_(y0), y1_(y1) {}
    bool pointFree(double x, double y, double) const override { return !(x > x0_ && x < x1_ && y > y0_ && y < y1_); }
    bool legFree(double xa, double ya, double ta, double xb, double yb, double tb) const override
    {
        const int n = 2000;
        for (int i = 0; i <= n; ++i)
        {
            const double f = double(i) / n;
            if (!pointFree(xa + f * (xb - xa), ya + f * (yb - ya), ta + f * (tb - ta)))
                return false;
        }
        return true;
    }
    std::string whyBlocked(double x, double y, double t) const override
    {
        return pointFree(x, y, t) ? "" : "inside test box";
    }

private:
    double x0_, x1_, y0_, y1_;
};

inline std::shared_ptr<GliderContext> makeContext(std::shared_ptr<const CurrentField> field, double V, Region region,
                                                  std::shared_ptr<const Environment> env = nullptr, double eps = 1e-3)
{
    auto ctx = std::make_shared<GliderContext>();
    TravelTimeParams tp;
    tp.speed = V;
    tp.eps = eps;
    ctx->field = field;
    ctx->travel = std::make_shared<TravelTimeCalculator>(field, tp);
    ctx->environment = std::move(env);
    ctx->region = region;
    return ctx;
}

inline Region box(double x0, double x1, double y0, double y1)
{
    Region r;
    r.xMin = x0;
    r.xMax = x1;
    r.yMin = y0;
    r.yMax = y1;
    return r;
}
} // namespace ompl_glider::test
