#pragma once
/// @file MissionExecution.h
/// @brief The mission's execution in another ocean ([ThompsonICRA]): the plan of the pipeline is flown
/// with every control strategy of MissionSpec::execution in the "truth" current (MissionProblem::getTruth()),
/// and, for a batch, so are plans between random start/goal pairs of the region. Part of the one pipeline:
/// runMission() calls executeMission() when the mission has an `execution` section; the result is a member of
/// MissionResult and written by the output layer (execution.csv, execution_tracks.csv, the box plot, summary.json).

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/Progress.h"
#include "ompl_glider/execution/Execution.h"

namespace ompl_glider
{
class MissionProblem;
struct PlannedPath;

/// @brief A station of a mission of several legs as the execution flies to it (a via point): reached within its
/// radius, not before its window opens (the glider holds until then), then held for its stay.
struct ExecutionStop
{
    std::string name;                        ///< the via point's name
    Point2 at;                               ///< planning frame
    double radius{0.0};                      ///< length units
    bool window{false};                      ///< an arrival window is set
    double windowBegin{0.0}, windowEnd{0.0}; ///< field time
    double stay{0.0};                        ///< held after the arrival (field time units)
};

/// @brief One leg of a planned mission as the execution needs it: where it ends in the plan, its held headings.
struct ExecutionLeg
{
    std::size_t end{0};                   ///< index in the plan's path of the leg's end (its via point, the goal)
    std::optional<HeadingRoute> headings; ///< the leg's held headings where it is a heading route
};

/// @brief One start/goal pair, planned on the forecast and flown with each strategy.
struct ExecutionRun
{
    unsigned index{0};                    ///< 0: the mission's own start and goal; 1..: the batch's pairs
    Point2 start, goal;                   ///< planning frame
    bool planned{false};                  ///< the forecast gave a plan (runs without one are not flown)
    std::string reason;                   ///< why there is no plan
    double departure{0.0};                ///< departure (field units)
    double radius{0.0};                   ///< goal radius used (length units)
    std::vector<TimedPoint> plan;         ///< the plan flown (the final path of planRoute())
    std::optional<HeadingRoute> headings; ///< the plan's held headings when it is a heading route
    /// A mission of several legs: its legs in the plan (the stations are ExecutionResult::stops, the same for every
    /// run); empty for a mission of one leg
    std::vector<ExecutionLeg> legs;
    std::vector<FlownTrack> flown; ///< one per ExecutionResult::strategies
    /// The oracle (ExecutionResult::oracle): the pair planned on the truth and flown in it with the truth as its
    /// forecast (current_sensitive); its arrival (field time), NaN when it had no plan or did not reach
    double oracleArrival{std::numeric_limits<double>::quiet_NaN()};
    double oracleSeconds{0.0}; ///< wall time of the oracle's plan and flight (0 without an oracle)
};

/// @brief Quartiles of one measure over the runs of a strategy.
struct MeasureSpread
{
    std::size_t count{0}; ///< runs with a value
    double min{std::numeric_limits<double>::quiet_NaN()};
    double q1{std::numeric_limits<double>::quiet_NaN()};
    double median{std::numeric_limits<double>::quiet_NaN()};
    double q3{std::numeric_limits<double>::quiet_NaN()};
    double max{std::numeric_limits<double>::quiet_NaN()}; ///< the worst for distances and delays
    double mean{std::numeric_limits<double>::quiet_NaN()};
};

/// @brief Quartiles (linear interpolation between order statistics) of the finite values of @p v.
MeasureSpread measureSpread(std::vector<double> v);

/// @brief What a strategy did over the runs that were flown.
struct StrategySpread
{
    std::string strategy;        ///< controlStrategyName()
    MeasureSpread finalDistance; ///< distance to the goal at the planned arrival time
    MeasureSpread arrivalDelay;  ///< arrival (within radius) minus the planned arrival, runs that arrived
    MeasureSpread madeGoodSpeed; ///< speed made good
    std::size_t runs{0};         ///< runs flown
    std::size_t reached{0};      ///< runs that reached the goal within radius
    std::size_t grounded{0};     ///< runs that ended on land or in a forbidden region
    /// (arrival - departure) / (oracle's arrival - departure) over the runs this strategy and the oracle reached;
    /// empty (count 0) without an oracle (the truth is the forecast)
    MeasureSpread overOracle;
};

/// @brief Every run of an execution.
struct ExecutionResult
{
    std::vector<ControlStrategy> strategies; ///< in the mission's order
    std::string truth;                       ///< name of the truth field ("forecast" when it is the forecast itself)
    double surfacingInterval{0.0};           ///< field units
    /// Where the surfacing interval came from: "given", "default: 1 h", or for a mission without a time unit
    /// "default: a twentieth of the planned trip (the mission has no time unit)"
    std::string surfacingIntervalSource;
    /// What the execution could not do as asked, said plainly (e.g. a truth that ends before the flights would):
    /// printed in the report and written to summary.json (`execution.notes`)
    std::vector<std::string> notes;
    double step{0.0};               ///< integration step while submerged (field units)
    unsigned replanEvery{1};        ///< replan strategy: surfacings between plans
    std::vector<ExecutionRun> runs; ///< runs[0] is the mission's own pair
    /// A mission of several legs: its via points, flown to in order by every strategy of every run (each run's own
    /// start and goal, the same stations); empty for a mission of one leg
    std::vector<ExecutionStop> stops;
    std::vector<StrategySpread> spread; ///< one per strategy, over every run flown
    /// The oracle was computed: every run's pair also planned on the truth and flown in it with the truth as its
    /// forecast (ExecutionRun::oracleArrival), the fair yardstick of StrategySpread::overOracle. False when the
    /// truth is the forecast (nothing to compare against).
    bool oracle{false};
    double oracleSeconds{0.0}; ///< wall time of the oracle's plans and flights, summed over the runs
    /// The truth against the forecast over the planning box and the time window of the runs (departure to twice
    /// the latest planned travel time after it, within both fields; 24 times, a 40 x 40 grid of water points): RMS over
    /// space and time of |c_truth - c_forecast|, and the largest RMS over time at one point. 0 when the truth is the
    /// forecast.
    double rmsDifference{0.0};
    double maxPointRmsDifference{0.0};
    double differenceBegin{0.0}, differenceEnd{0.0}; ///< the time window of the comparison
    unsigned threads{1};                             ///< threads used
    double wallSeconds{0.0};                         ///< wall time of the execution
};

/// @brief RMS over @p samples times evenly spread over [t0, t1] of |a - b| at one point (x, y, depth z); NaN where
/// either field has no water.
double rmsDifference(const CurrentField &a, const CurrentField &b, double x, double y, double z, double t0, double t1,
                     int samples = 24);

/// @brief Flies @p plan (the pipeline's plan of the mission; when not solved, run 0 is reported without flights)
/// and the batch's pairs with every strategy of problem.getSpec().execution. @throws Error for bad settings.
/// A mission of several legs (@p legs, its via points the stations): every strategy flies the legs in turn, each
/// leg's plan re-timed from where and when the glider is (its held headings for planned_headings), with the leg's
/// station as the goal its replans aim at; at a station it holds until the window opens and for the stay (in place:
/// a stay is planned only where the current is slower than the glider), then flies on. A run is reached when every
/// station and the goal were, each in its window; the batch's pairs are planned as missions through the same
/// stations (planMission()).
ExecutionResult executeMission(const MissionProblem &problem, const PlannedPath &plan,
                               const std::vector<ExecutionLeg> &legs = {}, const ProgressSink &progress = {});

/// @brief The batch's start/goal pairs: uniform in the planning box, both ends in water in the forecast and the
/// truth and outside the forbidden regions at the departure, at least @p minDistance apart; deterministic for a
/// seed. Fewer than @p count only when 1000 tries per pair find none (then the error says so).
std::vector<std::pair<Point2, Point2>> executionPairs(const MissionProblem &problem, unsigned count, unsigned seed,
                                                      double minDistance, double departure);
} // namespace ompl_glider
