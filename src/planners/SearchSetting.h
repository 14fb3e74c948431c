#pragma once
/// @file SearchSetting.h
/// @brief Internal to the library (not installed): what one lattice search of TveSearch (TveSearch::Core) and of
/// Wavefront (Wavefront::Search) reads from the problem: the context, the field, the travel-time code, the forbidden
/// regions, the depth, and the start and goal.

#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief The problem one lattice search works on: @c ctx with its field, travel-time calculator, environment
/// (null when there are no forbidden regions) and depth @c z (the travel-time parameters' depth), the start
/// (sx, sy) at the departure t0 and the goal (gx, gy). The base of TveSearch::Core and Wavefront::Search.
struct SearchSetting
{
    /// @brief The setting of a search of @p context from (startX, startY), departing at @p departure, to
    /// (goalX, goalY).
    SearchSetting(const GliderContext &context, double startX, double startY, double departure, double goalX,
                  double goalY)
        : ctx(context), field(*ctx.field), travel(*ctx.travel), env(ctx.environment.get()), z(travel.params().depth),
          sx(startX), sy(startY), t0(departure), gx(goalX), gy(goalY)
    {
    }

    const GliderContext &ctx;
    const CurrentField &field;
    const TravelTimeCalculator &travel;
    const Environment *env;
    const double z;
    const double sx, sy, t0, gx, gy;
};
} // namespace ompl_glider
