#pragma once
/// @file ReachProbability.h
/// @brief The probability of reach over an ensemble forecast ([SubramaniStochastic]): each member's first-arrival
/// field from the mission's start and departure by the level set ([LollaLevelSet]), then at every grid node
/// p(x, t) = sum over members m of w_m [T_m(x) <= t], the members' first arrivals at the goal, the probability of
/// reaching it by the horizon and the weighted quantiles of the arrival. A single current source is an ensemble of
/// one (p is 0 or 1). The output format "reachability" asks for it (mission section `reachability`).

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
class MissionProblem;
struct PlannedPath;

/// @brief One quantile of the arrival time at the goal over the members.
struct ReachQuantile
{
    double q{0.5};       ///< the quantile, in (0, 1)
    bool reached{false}; ///< the members that reach the goal by the horizon attain it
    double arrival{std::numeric_limits<double>::infinity()};    ///< absolute time (+inf: not reached by the horizon)
    double travelTime{std::numeric_limits<double>::infinity()}; ///< arrival - departure (+inf: not reached)
    std::string iso; ///< the arrival's date (empty without dates or when not reached)
};

/// @brief The boundary of {p(x, t) >= level} at one frame.
struct ReachContour
{
    double time{0.0};                        ///< absolute time (the frame's)
    std::string iso;                         ///< its date (empty without dates)
    double level{0.5};                       ///< the probability
    std::vector<std::vector<Point2>> lines;  ///< polylines in the planning frame
    std::vector<std::vector<LonLat>> lonLat; ///< the same in lon/lat where the problem is geographic
};

/// @brief What computeReachProbability() gives.
struct ReachProbability
{
    std::size_t members{1};      ///< ensemble members (1: a single current source)
    std::vector<double> weights; ///< per member, sum 1: equal, or as the glider's observations weighed them
    bool weighed{false};         ///< the weights are the observations' (not equal)
    /// Node (i, j) at (x0 + i h, y0 + j h) in the planning frame; fields indexed j * nx + i
    double resolution{0.0}, x0{0.0}, y0{0.0}, h{0.0};
    int nx{0}, ny{0}; ///< node counts
    /// Each node's lon/lat where the problem is geographic (nx * ny each), else empty
    std::vector<double> lon, lat;
    double departure{0.0};        ///< absolute
    double horizon{0.0};          ///< absolute end of the fronts (departure + the horizon used)
    std::vector<double> times;    ///< the frames (absolute, ascending; the last is the horizon)
    std::vector<std::string> iso; ///< their dates (empty strings without dates)
    std::vector<double> levels;   ///< the contours' probabilities
    /// p(x, t) per frame (times.size() fields of nx * ny, in [0, 1], non-decreasing from frame to frame)
    std::vector<std::vector<float>> probability;
    /// Each member's first-arrival field (absolute; +inf where its front did not come; the fronts run one step past
    /// the horizon, and what came in that step is kept: p and the goal count only what came by the horizon)
    std::vector<std::vector<double>> memberArrival;
    std::vector<double> goalTimes; ///< each member's first arrival at the goal (absolute; +inf: not by the horizon)
    double goalProbability{0.0};   ///< sum of the weights of the members reaching the goal by the horizon
    std::vector<ReachQuantile> quantiles; ///< the arrival's quantiles at the goal
    std::vector<ReachContour> contours;   ///< per frame, per level (frame-major)
    unsigned threadsPerSolve{1};          ///< threads of each member's solve
    bool stopped{false};                  ///< a stop request ended the fronts early (the fields hold what was computed)
    double seconds{0.0};                  ///< wall time
};

/// @brief The weighted @p q-quantile of @p values (weights @p weights, summing to 1): the smallest value t with
/// sum of the weights of the values <= t at least @p q (equal weights: the ceil(q M)-th smallest value, as
/// planner.quantile defines it). +inf when the finite values do not attain it (+inf values count as never).
double weightedQuantile(const std::vector<double> &values, const std::vector<double> &weights, double q);

/// @brief Solves every member of @p problem's ensemble (the field alone when it has none) from its start at
/// @p departure with the registry's level-set planner (PipelinePlanner::reachableSet(), through the registry; the
/// members side by side on the cores) and combines them as the mission's `reachability` section says. @p plan
/// sets the default horizon (1.5 times its travel time when it has a route). A stop request (StopRequest.h) ends
/// the fronts where they are (ReachProbability::stopped).
/// @throws Error naming the field for a horizon or interval that gives no frame or too many.
ReachProbability computeReachProbability(const MissionProblem &problem, const PlannedPath &plan, double departure);

/// @brief What computeReachProbability() would refuse before any plan is made: its memory (the members' fields on
/// the cell, with as few frames as the section allows), so that a refusal comes at once, not after the planning.
/// @throws Error as computeReachProbability() does for the memory.
void checkReachProbabilityMemory(const MissionProblem &problem);
} // namespace ompl_glider
