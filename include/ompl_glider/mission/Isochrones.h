#pragma once
/// @file Isochrones.h
/// @brief Reachable-set contours for pilots ([ThompsonICRA] Fig. 4 and Sec. III): where the glider can be
/// by each of a few times after the departure, from the level-set solver.

#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
class MissionProblem;
struct PlannedPath;

/// @brief One isochrone: the boundary of the set reachable from the start by @p time.
struct Isochrone
{
    double time{0.0};                        ///< absolute time (the mission's unit)
    std::string iso;                         ///< the date, where the mission has dates (else empty)
    std::vector<std::vector<Point2>> lines;  ///< polylines in the planning frame
    std::vector<std::vector<LonLat>> lonLat; ///< the same in lon/lat where the problem is geographic
};

/// @brief The isochrones of one run.
struct IsochroneSet
{
    double resolution{0.0};          ///< the level-set cell size
    double seconds{0.0};             ///< solver wall time
    std::vector<Isochrone> contours; ///< ascending times
    /// The level set's first-arrival field the contours are drawn on: node (i, j) at (x0 + i h, y0 + j h) in the
    /// planning frame, arrival[j * nx + i] the absolute time (+inf where the front never came)
    double x0{0.0}, y0{0.0}, h{0.0};
    int nx{0}, ny{0};            ///< node counts
    std::vector<double> arrival; ///< see x0
};

/// @brief Propagates the level-set front (LevelSetSolver, cell 1/100 of the region's larger side) from the start at
/// @p departure and draws its boundary every
/// @p interval (NaN: eight times evenly up to the planned arrival, or up to the horizon when there is no path) up to
/// the planned arrival (or the horizon).
IsochroneSet computeIsochrones(const MissionProblem &problem, const PlannedPath &plan, double departure,
                               double interval);
} // namespace ompl_glider
