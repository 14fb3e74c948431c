#pragma once
/// @file DiveProfile.h
/// @brief Glider dive profiles: travel time of a leg flown as a saw-tooth through a depth-varying current
/// ([EichhornOceans] Table I) and the optimal dive profile among a generated set ([EichhornOceans] Sec. III.B).

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/ShardedCounter.h"
#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/io/Bathymetry.h"

namespace ompl_glider
{
/// @brief One dive profile: the glider climbs to z_climb-to and dives to z_dive-to (depths positive down).
struct DiveProfile
{
    double climbTo{0.0}; ///< shallowest depth of the saw-tooth
    double diveTo{0.0};  ///< deepest depth of the saw-tooth
    /// @brief Depth amplitude diveTo - climbTo (the data a profile collects grows with it).
    double amplitude() const { return diveTo - climbTo; }
};

/// @brief How the profile of a leg is chosen ([EichhornOceans] Sec. III.B).
enum class DiveProfileSelection
{
    Fastest,          ///< the profile with the least travel time
    DeepestUnderLimit ///< the largest amplitude whose time stays under the limit (data at all depths), else fastest
};

/// @brief Parameters that generate the profile set ([EichhornOceans] Sec. III.B, Fig. 4) and choose among it.
///
/// Climb-to levels: climbToLevels values evenly spaced in [zMin, climbToMax]; dive-to levels: diveToLevels values
/// evenly spaced in [zMin + minRange, zMax]; every pair with diveTo - climbTo >= minRange is a profile.
/// (With one level, the climb-to level is zMin and the dive-to level is zMax.)
struct DiveProfileParams
{
    double zMin{0.0};       ///< minimum diving depth z_min
    double zMax{100.0};     ///< maximum diving depth z_max
    double climbToMax{0.0}; ///< maximum climb-to depth z_climb-to_max
    double minRange{10.0};  ///< minimum dive amplitude z_minRange
    int climbToLevels{1};   ///< n_climb-to_levels
    int diveToLevels{1};    ///< n_dive-to_levels
    double step{0.1};       ///< h of Table I: the leg is split into ceil(1/h) segments
    DiveProfileSelection selection{DiveProfileSelection::Fastest};
    /// For DeepestUnderLimit: a profile qualifies when its time <= maxTimeFactor * (fastest time) ...
    double maxTimeFactor{1.2};
    /// ... and <= maxTime (absolute, field time units; +inf = no absolute limit).
    double maxTime{std::numeric_limits<double>::infinity()};
    double clearance{0.0}; ///< distance kept above the seafloor when a bathymetry is given
};

/// @brief Builds and validates the profile set of @p params (throws Error naming the bad parameter).
std::vector<DiveProfile> makeDiveProfiles(const DiveProfileParams &params);

/// @brief Bathymetry given by a function (an analytic seafloor, or an adapter over a gridded NetCDF depth).
class FunctionBathymetry : public Bathymetry
{
public:
    explicit FunctionBathymetry(std::function<double(double, double)> depth) : depth_(std::move(depth)) {}
    double seafloorDepth(double x, double y) const override { return depth_(x, y); }

private:
    std::function<double(double, double)> depth_;
};

/// @brief Outcome of the optimal-dive-profile evaluation of one leg.
struct DiveLegResult
{
    double travelTime{std::numeric_limits<double>::infinity()}; ///< time of the chosen profile (+inf: impassable)
    int profile{-1};                  ///< index of the chosen profile in profiles(); -1 when none is feasible
    std::vector<double> profileTimes; ///< travel time of every profile (same order as profiles())
};

/// @brief Travel time of legs flown with dive profiles through a depth-varying current.
///
/// TRAVELTIME-GLIDER ([EichhornOceans] Table I): the leg is split into n = ceil(1/h) equal segments; in each segment
/// the glider goes from the climb-to depth at the segment's start to the dive-to depth at its end, its depth linear in
/// the horizontal progress, and the segment's time is integrated with the adaptive step of CALC-TRAVELTIME
/// ([EichhornIWK] Table III) reading the current at the local depth. In a depth-uniform current the result is exactly
/// the sum of TravelTimeCalculator::travelTime() over the same segments (same arithmetic), and with h = 1 exactly the
/// 2-D travel time of the leg. The vehicle speed is the horizontal speed through water.
///
/// With a bathymetry, a segment's dive is limited to (shallowest seafloor at its start, middle and end) minus the
/// clearance; the climb-to depth is limited to that too; a segment where that limit is <= 0 is impassable.
///
/// bestProfile() evaluates all profiles, in parallel on the pool ([EichhornOceans] Sec. IV), and chooses per
/// DiveProfileParams::selection ([EichhornOceans] Sec. III.B). Each profile evaluation counts one CFC. Thread-safe.
class DiveProfileTravelTime
{
public:
    /// @param field current field (read at depth)
    /// @param travel step-size law and vehicle speed (TravelTimeParams::depth is ignored)
    /// @param dive profile set and selection
    /// @param bathymetry optional seafloor
    /// @param threads pool size for bestProfile(); 0 = all cores, 1 = serial
    DiveProfileTravelTime(std::shared_ptr<const CurrentField> field, TravelTimeParams travel, DiveProfileParams dive,
                          std::shared_ptr<const Bathymetry> bathymetry = nullptr, unsigned threads = 0);

    /// @brief TRAVELTIME-GLIDER ([EichhornOceans] Table I) of one profile; +inf when impassable. One CFC.
    double travelTime(const DiveProfile &profile, double x1, double y1, double x2, double y2, double tStart) const;

    /// @brief All profiles evaluated (in parallel), the chosen one per [EichhornOceans] Sec. III.B.
    DiveLegResult bestProfile(double x1, double y1, double x2, double y2, double tStart) const;

    /// @brief Same as bestProfile() on the calling thread only (the serial reference of the speedup benchmark).
    DiveLegResult bestProfileSerial(double x1, double y1, double x2, double y2, double tStart) const;

    /// @brief Chooses among already computed profile times per the selection rule ([EichhornOceans] Sec. III.B).
    int choose(const std::vector<double> &times) const;

    /// @brief The generated profile set.
    const std::vector<DiveProfile> &profiles() const { return profiles_; }
    /// @brief Dive parameters in use.
    const DiveProfileParams &diveParams() const { return dive_; }
    /// @brief Travel parameters in use.
    const TravelTimeParams &travelParams() const { return segments_.params(); }
    /// @brief Threads used by bestProfile().
    unsigned threads() const { return pool_ ? pool_->size() : 1u; }
    /// @brief Number of profile evaluations (CFC) so far.
    std::uint64_t costFunctionCalls() const { return calls_.load(); }

private:
    DiveLegResult evaluate(double x1, double y1, double x2, double y2, double tStart, bool parallel) const;

    /// CALC-TRAVELTIME of each dive segment (depth linear from climb-to to dive-to); holds the field and the travel
    /// parameters, validates them and throws when the field is null
    TravelTimeCalculator segments_;
    DiveProfileParams dive_;
    std::shared_ptr<const Bathymetry> bathymetry_;
    std::vector<DiveProfile> profiles_;
    std::unique_ptr<ThreadPool> pool_;
    mutable ShardedCounter calls_;
};

/// @brief "fastest" / "deepest_under_limit" <-> DiveProfileSelection (throws Error on an unknown name).
DiveProfileSelection diveProfileSelectionFromString(const std::string &name);
/// @brief Name of a selection rule.
std::string toString(DiveProfileSelection selection);
} // namespace ompl_glider
