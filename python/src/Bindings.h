#pragma once
// The Python module's C++ side (ompl_glider._core): a thin layer over the library's one pipeline. A mission is a
// MissionSpec (built-in, mission file, mission text, forecastMission()), changed by keyword arguments the way the
// command line's flags change it, planned by runMission() and written by the output layer.
#include <memory>

#include <pybind11/pybind11.h>

#include "ompl_glider/mission/MissionProblem.h"
#include <functional>

#include "ompl_glider/mission/Planning.h"

namespace ompl_glider_py
{
/// @brief One planned mission: the problem and runMission()'s result (what the output layer writes from).
struct PyResult
{
    std::shared_ptr<const ompl_glider::MissionProblem> problem;
    ompl_glider::MissionResult result;
};

/// @brief Runs @p work in a thread of its own, the GIL released, while the calling thread lets Python handle its
/// signals every 50 ms: Ctrl-C asks the plans and fetches to stop (StopRequest.h) and raises KeyboardInterrupt once
/// @p work has returned; an exception of @p work is rethrown. Called with the GIL held.
void runStoppable(const std::function<void()> &work);

/// @brief Binds MissionSpec (as Mission), the ways to build one and the keyword overrides.
void bindMission(pybind11::module_ &m);
/// @brief Binds run() and PyResult (as Result).
void bindResult(pybind11::module_ &m);
/// @brief Binds write_forecast(): numpy arrays as a CF NetCDF file, which the forecast reader then reads.
void bindArrays(pybind11::module_ &m);
/// @brief Binds read_observations(): a glider's fixes and DAC as the planner reads them, as numpy arrays.
void bindObservations(pybind11::module_ &m);
} // namespace ompl_glider_py
