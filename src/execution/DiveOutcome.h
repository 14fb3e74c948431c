#pragma once
/// @file DiveOutcome.h
/// @brief Internal to the library (not installed): a dive's arrival and grounding carried into the result of a run
/// (FlownTrack of execute()) or of a stint plan (StintPlan of StintSimulator).

#include "ompl_glider/execution/Dive.h"

namespace ompl_glider
{
/// @brief When the dive @p e reached the goal, marks @p out reached at the dive's arrival time; when it grounded,
/// marks @p out grounded with the dive's reason. Leaves @p out as it is otherwise. @p Outcome has the members
/// reached, arrivalTime, grounded and groundedWhy (FlownTrack, StintPlan).
template <class Outcome> void noteDiveOutcome(const DiveEnd &e, Outcome &out)
{
    if (e.reached)
    {
        out.reached = true;
        out.arrivalTime = e.arrivalTime;
    }
    if (e.grounded)
    {
        out.grounded = true;
        out.groundedWhy = e.why;
    }
}
} // namespace ompl_glider
