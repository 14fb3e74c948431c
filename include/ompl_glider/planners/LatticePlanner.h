#pragma once
/// @file LatticePlanner.h
/// @brief Base class of the planners that search a Lattice over the planning region (ZAStarTVE, Wavefront): the
/// lattice spacing and connectivity as OMPL parameters.

#include <string>

#include <ompl/base/Planner.h>

#include "ompl_glider/ompl/PipelinePlanner.h"

namespace ompl_glider
{
/// @brief An ompl::base::Planner that searches the rectangular Lattice over the planning region. It owns the lattice
/// spacing and connectivity and declares them once as the OMPL parameters "grid_size" (range "0.:0.01:1000.",
/// default 0.4, the spacing of [EichhornRAS]) and "sectors" (range "1:1:5", default 3), so that a caller can set both
/// on any lattice planner by name: planner->params().setParam("grid_size", "0.2").
class LatticePlanner : public ompl::base::Planner, public PipelinePlanner
{
public:
    /// @brief Refuses, naming planner.grid_size, a spacing whose lattice over the setup's region would not fit in
    /// memory (a travel time and a predecessor per vertex) or exceed the 2^31 vertices a lattice can hold.
    void prepare(const PipelineSetup &setup) override;

    /// @brief Lattice spacing (param "grid_size", default 0.4). Throws ompl_glider::Error unless g is finite and > 0.
    void setGridSize(double g);
    /// @brief Lattice spacing.
    double getGridSize() const { return gridSize_; }
    /// @brief Lattice connectivity n in 1..5 (param "sectors", default 3; see Lattice; 1 gives the 8 compass
    /// directions). Throws ompl_glider::Error otherwise.
    void setSectors(unsigned n);
    /// @brief Lattice connectivity.
    unsigned getSectors() const { return sectors_; }

protected:
    /// @brief Planner @p name on @p si; @p className starts the setters' error messages ("ZAStarTVE: grid_size must
    /// be ...").
    LatticePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name, std::string className);

    /// @brief Called by setGridSize() and setSectors() when the value changes (after it is stored); does nothing here.
    virtual void latticeChanged() {}

private:
    std::string className_;
    double gridSize_{0.4};
    unsigned sectors_{3};
};
} // namespace ompl_glider
