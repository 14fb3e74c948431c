#pragma once
/// @file StintStep.h
/// @brief Internal to the library (not installed): one stint flown from a running position, the step of the
/// bearing loops of CtsAStar and PathToStints.

#include "ompl_glider/routes/StintSimulator.h"

namespace ompl_glider
{
/// @brief Flies one stint of @p sim from (x, y) at @p t on @p bearing (StintSimulator::flyStint()) and moves
/// (x, y, t) to where and when it surfaces.
/// @return true when the stint reached the goal or grounded: the caller flies no further stint.
inline bool flyOneStint(const StintSimulator &sim, double &x, double &y, double &t, double bearing)
{
    const DiveEnd e = sim.flyStint(x, y, t, bearing);
    x = e.x;
    y = e.y;
    t = e.t;
    return e.grounded || e.reached;
}
} // namespace ompl_glider
