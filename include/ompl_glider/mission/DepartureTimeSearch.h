#pragma once
/// @file DepartureTimeSearch.h
/// @brief Optimal departure time ([EichhornRAS] Sec. 5, [EichhornIWK] Sec. 4): supporting points over the departure
/// window, Akima interpolation to bracket the global minimum, Brent's method to refine it; every evaluation is a full
/// search.

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "ompl_glider/Progress.h"

namespace ompl_glider
{
/// @brief Travel time (arrival - departure) of a full search for a given departure time; +inf when no path exists
/// (impassable, or the trip is not covered by the forecast). Must be safe to call from several threads at once
/// when DepartureSearchParams::threads != 1.
using TravelTimeOfDeparture = std::function<double(double tDep)>;

/// @brief Parameters of the departure-time search.
struct DepartureSearchParams
{
    double windowBegin{0.0}; ///< earliest departure
    double windowEnd{0.0};   ///< latest departure (before the horizon cut)
    /// Delta t_dep between supporting points ([EichhornRAS] Sec. 5.2: should resolve the local minima)
    double spacing{1.0};
    double tolerance{1e-3};           ///< absolute tolerance of Brent's method on the departure time
    unsigned maxBrentEvaluations{40}; ///< at most this many refining searches
    /// Half-width of Brent's bracket around the Akima minimum, in supporting-point spacings; <= 0: 1 with fine
    /// supporting points, 2 with coarse ones (a coarser graph can shift the minimum by about a spacing).
    double bracketSpacings{0.0};
    /// Forecast horizon: a departure whose arrival lies after it does not count (its travel time is +inf), and the
    /// window is cut at horizon - minTripDuration ([EichhornRAS] Sec. 5.3). +inf: no horizon.
    double horizon{std::numeric_limits<double>::infinity()};
    double minTripDuration{0.0}; ///< lower bound of any trip's duration (e.g. distance / (V + max|c|))
    unsigned threads{0};         ///< supporting points evaluated on this many threads; 0 = all cores, 1 = serial
    ProgressSink progress;       ///< progress lines (none when empty)
};

/// @brief One evaluated departure.
struct DepartureSample
{
    double tDep{0.0};       ///< departure time
    double travelTime{0.0}; ///< travel time (+inf when impassable / not covered)
    bool coarse{false};     ///< evaluated with the coarse search
};

/// @brief Outcome of the departure-time search.
struct DepartureSearchResult
{
    bool found{false}; ///< false when no departure in the window has a finite travel time
    double departure{std::numeric_limits<double>::quiet_NaN()}; ///< best departure time
    double travelTime{std::numeric_limits<double>::infinity()}; ///< its travel time (fine search)
    double windowEnd{0.0};                                      ///< the window's end after the horizon cut
    double bracketLo{0.0}, bracketHi{0.0};                      ///< interval given to Brent's method
    double interpolatedMinimum{0.0};                            ///< departure at the minimum of the Akima curve
    std::vector<DepartureSample> supportingPoints;              ///< step 1 (coarse when a coarse search was given)
    std::vector<DepartureSample> refinements;                   ///< step 3 (Brent), fine search
    std::size_t fineEvaluations{0};                             ///< full searches with the fine graph
    std::size_t coarseEvaluations{0};                           ///< full searches with the coarse graph
    double wallSeconds{0.0};                                    ///< wall time of the whole search
};

/// @brief Brent's method for a minimum of f on [a, b] (golden section with parabolic steps, [BrentMin] Ch. 5),
/// started at x0 when x0 is inside (a, b). Stops when the bracket is below 2 tol or after maxEvaluations calls.
/// Non-finite values are handled as larger than every finite one. Returns (argmin, min); appends every call to
/// @p calls when given.
std::pair<double, double> brentMinimize(const std::function<double(double)> &f, double a, double b, double x0,
                                        double tol, unsigned maxEvaluations,
                                        std::vector<DepartureSample> *calls = nullptr);

/// @brief Optimal departure time ([EichhornRAS] Sec. 5.2, three steps).
///  1. Supporting points every @c spacing over [windowBegin, windowEnd'] (windowEnd' = the horizon cut), evaluated in
///     parallel with @p coarse when given (a coarser graph, [EichhornRAS] Sec. 5.3), else with @p fine.
///  2. Akima interpolation through them (impassable points take a value above every finite one); its global
///     minimum t* is bracketed by [t* - w, t* + w] within the window, w = bracketSpacings * spacing.
///  3. Brent's method with @p fine inside the bracket, started at t*.
/// The result is the best fine evaluation (supporting points included when they were fine).
DepartureSearchResult optimalDepartureTime(const TravelTimeOfDeparture &fine, const DepartureSearchParams &params,
                                           const TravelTimeOfDeparture &coarse = {});

/// @brief Brute force reference: the fine search at every departure windowBegin + k * spacing (in parallel).
DepartureSearchResult bruteForceDepartureTime(const TravelTimeOfDeparture &fine, const DepartureSearchParams &params);
} // namespace ompl_glider
