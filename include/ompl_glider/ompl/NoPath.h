#pragma once
/// @file NoPath.h
/// @brief Why a search or a plan ended without a path, typed: the cause the pipeline decides on, its figures, and
/// the words for people in parts (the finding, generic advice, what bounds the arrival), so that the pipeline can
/// drop advice or move a bound without reading the words. Code branches on NoPath::cause, never on the text.

#include <cstdint>
#include <limits>
#include <string>
#include <utility>

namespace ompl_glider
{
/// @brief What ended a search or a plan without a path.
enum class NoPathCause : std::uint8_t
{
    None = 0,         ///< no cause (a path; or a planner with nothing to add to OMPL's status)
    BadInput,         ///< the start, goal or departure is refused (PlannedPath::badInput names which)
    Stopped,          ///< a stop request (Ctrl-C) ended the search
    TimeLimit,        ///< the time limit ended the search: more time may find a path
    Approximate,      ///< the planner reached only an approximate solution
    LatticeExhausted, ///< every vertex of a lattice was expanded: no path on this lattice (a finer one may hold one)
    SearchEnded,      ///< a search that proves nothing ended without a route (an isochrone front died out)
    Unreachable,      ///< proven: the reachable front never reaches the goal within the time window
    WalledOff,        ///< proven: no water links the goal to the start
    NotFlyable,       ///< a route was found but cannot be flown (its check, its accurate re-flight, its closure)
    NotRobust,        ///< an ensemble: no candidate can be flown in every member
    ArrivalWindow,    ///< the arrival cannot be moved into the goal window
    NoDeparture,      ///< no departure in the departure window has a path
    Other             ///< OMPL's status, nothing more known
};

/// @brief What bounds the arrival of an exhausted search.
enum class ArrivalBound : std::uint8_t
{
    None = 0,
    ForecastEnd,    ///< the path must arrive before the forecast ends
    PlanningHorizon ///< the path must arrive within the planning horizon
};

/// @brief Why there is no path: the cause, its figures and its words.
struct NoPath
{
    NoPathCause cause{NoPathCause::None};
    std::string what; ///< the finding, in words ("no path exists on this lattice (812 vertices expanded)")
    /// Generic advice that follows the finding ("; a finer grid, ... may find one"): dropped once a diagnosis or
    /// another planner has said more
    std::string advice;
    ArrivalBound bound{ArrivalBound::None}; ///< what bounds the arrival (an exhausted lattice search)
    double boundSpan{std::numeric_limits<double>::quiet_NaN()}; ///< that bound after departure (field time units)
    std::string boundText;     ///< the bound in words ("; the path must arrive before the forecast ends, ...")
    double timeLimit{0.0};     ///< TimeLimit: the limit that ended the search (s)
    std::uint64_t expanded{0}; ///< LatticeExhausted: the vertices expanded
    std::size_t leg{0};        ///< a mission of several legs: the leg without a path (1-based; 0: not a leg's)

    NoPath() = default;
    /// @brief A cause and its finding in words.
    NoPath(NoPathCause c, std::string finding) : cause(c), what(std::move(finding)) {}

    /// @brief True when the cause proves that no route exists (not only that none was found).
    bool proven() const { return cause == NoPathCause::Unreachable || cause == NoPathCause::WalledOff; }
    /// @brief The words: the finding, the advice, the bound.
    std::string text() const { return what + advice + boundText; }
};

/// @brief The cause as summary.json and Python name it ("time_limit", "lattice_exhausted", ...; "" for None).
std::string causeName(NoPathCause cause);
} // namespace ompl_glider
