#include "ompl_glider/planners/LatticePlanner.h"
#include "ompl_glider/ompl/Sectors.h"

#include <cmath>
#include <utility>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ResourceLimits.h"
#include "detail/Lattice.h"
#include "../io/NumberText.h"

namespace ompl_glider
{
void LatticePlanner::prepare(const PipelineSetup &setup)
{
    const Region &r = setup.region;
    const double grid = gridSize_;
    const double nx = std::floor((r.xMax - r.xMin) / grid + 1e-9) + 1.0;
    const double ny = std::floor((r.yMax - r.yMin) / grid + 1e-9) + 1.0;
    const std::string what =
        setup.where("planner.grid_size") +
        text::formatted(": a lattice spacing of %g gives %.0f x %.0f = %.3g vertices, which", grid, nx, ny, nx * ny);
    if (nx * ny > 2147483648.0)
        throw Error(what + " is more than the 2^31 a lattice can hold: use a larger spacing");
    checkMemory(nx * ny * static_cast<double>(sizeof(double) + sizeof(Lattice::VertexId)), what,
                "use a larger spacing");
}

namespace
{
constexpr double kMinGridSize = 1e-9; ///< the lattice spacing's range, in planning units
constexpr double kMaxGridSize = 1e12;
} // namespace

LatticePlanner::LatticePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name,
                               std::string className)
    : ompl::base::Planner(si, name), className_(std::move(className))
{
    // one statement of the range, declared and checked (planning units: dimensionless, or metres on a forecast)
    declareParam<double>("grid_size", this, &LatticePlanner::setGridSize, &LatticePlanner::getGridSize,
                         text::number(kMinGridSize) + ":0.01:" + text::number(kMaxGridSize));
    declareParam<unsigned>("sectors", this, &LatticePlanner::setSectors, &LatticePlanner::getSectors, "1:1:5");
}

void LatticePlanner::setGridSize(double g)
{
    if (!(g >= kMinGridSize && g <= kMaxGridSize))
        throw Error(className_ + ": grid_size must be in " + text::number(kMinGridSize) + ".." +
                    text::number(kMaxGridSize) + " (got " + text::number(g) + ")");
    const bool changed = g != gridSize_;
    gridSize_ = g;
    if (changed)
        latticeChanged();
}

void LatticePlanner::setSectors(unsigned n)
{
    if (n < static_cast<unsigned>(kMinSectors) || n > static_cast<unsigned>(kMaxSectors))
        throw Error(className_ + ": sectors must be in " + std::to_string(kMinSectors) + ".." +
                    std::to_string(kMaxSectors) + " (got " + std::to_string(n) + ")");
    const bool changed = n != sectors_;
    sectors_ = n;
    if (changed)
        latticeChanged();
}
} // namespace ompl_glider
