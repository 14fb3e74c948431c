#pragma once
/// @file ForecastRuns.h
/// @brief A stream of forecast runs: the files a model issues one run at a time (Copernicus Marine's daily 10-day
/// forecast, HYCOM/ESPC's and RTOFS's daily runs), each with its reference time and the time it becomes available
/// (the reference time plus a delay). At a time t a pilot plans on the newest run available at t; a glider at sea
/// steers on the newest run's current. The runs' fields are read on the mission's clock, each once, when first
/// asked for.

#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/current/ForecastSource.h"

namespace ompl_glider
{
/// @brief One forecast run (times on the mission's clock: field time).
struct ForecastRun
{
    std::string file; ///< the file or URL holding it
    /// in a file of several runs (a THREDDS FMRC), its index along the run dimension (ForecastRequest::run);
    /// unset: the file is this run alone
    std::optional<std::size_t> runIndex;
    /// a run in several files (HYCOM's one file per time step): all of them in time order (`file` the first);
    /// empty: `file` alone
    std::vector<std::string> files;
    double reference{0.0};     ///< its reference time (CF forecast_reference_time; else its first time)
    double available{0.0};     ///< when it became available: reference + the run delay
    double begin{0.0};         ///< its first time
    double end{0.0};           ///< its last time
    std::string referenceFrom; ///< where the reference time was read (ForecastTimeAxis::referenceFrom)
};

/// @brief Where one of a forecast's runs is read, and its time axis (ForecastTimeAxis of that run alone).
struct RunSource
{
    std::vector<std::string> files;      ///< one, or several in time order (a run in several files)
    std::optional<std::size_t> runIndex; ///< its index in a file of several runs (a THREDDS FMRC)
    ForecastTimeAxis axis;               ///< its times and reference time
};

/// @brief The runs of @p entries (files or URLs, as `current.runs` lists them) read by @p source with @p request (its
/// files and run replaced): a file of several runs (ForecastTimeAxis::runs) is each of its runs; files whose
/// reference time the file states (CF forecast_reference_time, HYCOM's tau; not a first time taken for it) and is
/// the same are one run in several files (HYCOM's one file per time step), read as one forecast. In the order of
/// @p entries (a run in several files where its first file is). @throws Error as the source does.
std::vector<RunSource> forecastRunSources(const GriddedSource &source, ForecastRequest request,
                                          const std::vector<std::string> &entries);

/// @brief The runs of a mission, ordered by reference time, and their fields (loaded once each, on first use;
/// thread-safe).
class ForecastRuns
{
public:
    /// Reads one run's field on the mission's clock.
    using Loader = std::function<std::shared_ptr<const CurrentField>(const ForecastRun &)>;

    /// @brief @p runs (at least one; sorted here by reference time, a later file first among equal ones is refused
    /// by the caller) read by @p load. @throws Error for no run or no loader.
    ForecastRuns(std::vector<ForecastRun> runs, Loader load);

    const std::vector<ForecastRun> &runs() const { return runs_; }
    std::size_t size() const { return runs_.size(); }
    const ForecastRun &operator[](std::size_t k) const { return runs_.at(k); }

    /// @brief The newest run available at @p t (available <= t); nullopt before the first run is available.
    std::optional<std::size_t> newestAt(double t) const;
    /// @brief The run planned on at @p t: newestAt(t), else the first run (a time before any is available).
    std::size_t runAt(double t) const { return newestAt(t).value_or(0); }
    /// @brief The times after @p t0 at which a newer run than the one at @p t0 becomes available, ascending.
    std::vector<double> arrivalsAfter(double t0) const;

    /// @brief Run @p k's field (read on first use, then shared). @throws Error as the loader does.
    std::shared_ptr<const CurrentField> field(std::size_t k) const;
    /// @brief Gives run @p k the field @p f already read (the plan's run, read with the mission's records).
    void setField(std::size_t k, std::shared_ptr<const CurrentField> f);

private:
    struct Slot
    {
        std::mutex lock;
        std::shared_ptr<const CurrentField> field;
    };
    std::vector<ForecastRun> runs_;
    Loader load_;
    std::vector<std::unique_ptr<Slot>> slots_;
};

/// @brief The forecast error's spread that a model's runs show where they overlap ([ParrishDerberNMC], the "NMC
/// method"): the differences between consecutive runs valid at the same times, sampled on a grid over a box, give
/// the error's variance and, from their correlation at growing distances and time lags fitted by the correction's
/// Gaussian kernel (CorrectionKernel.h), its length and time scales: the priors of the correction by the DAC.
struct RunSpread
{
    std::size_t pairs{0};   ///< pairs of consecutive runs that overlap
    std::size_t samples{0}; ///< differences (nodes in water x times) used
    /// The error's standard deviation per component (field units): the differences' RMS per component over sqrt(2)
    /// (two runs' independent errors)
    double sigma{std::numeric_limits<double>::quiet_NaN()};
    double lengthScale{std::numeric_limits<double>::quiet_NaN()}; ///< NaN: not resolved by the box
    double timeScale{std::numeric_limits<double>::quiet_NaN()};   ///< NaN: not resolved by the overlaps
};

/// @brief runSpread() of @p runs over @p box (x/y; its time window unused) at depth @p depth: each overlap of
/// consecutive runs sampled at 17 times on 24 x 24 nodes, each snapshot's mean removed (a uniform bias is the
/// correction's mean, not its interpolation). Reads every run.
RunSpread runSpread(const ForecastRuns &runs, const Region &box, double depth);

/// @brief The forecast as it is known at a time: for each time t, the current of the newest run available at t
/// ("live": what a glider at sea steers on), or, as known at a fixed time @p asOf, the newest run then: after its end
/// as its field goes on (the `beyond` rule), before its first time its first field held (a DAC measured before the
/// run compared with the run's own analysis, its nearest estimate of that time, not with an older run's forecast).
/// Land, grid and name are the first run's (one model's runs share a grid). Every run is read when it is made (its
/// queries take no lock).
class RunStreamField : public CurrentField
{
public:
    /// @brief The live stream of @p runs (not null).
    explicit RunStreamField(std::shared_ptr<const ForecastRuns> runs);
    /// @brief The runs as known at @p asOf.
    RunStreamField(std::shared_ptr<const ForecastRuns> runs, double asOf);

    /// @brief The run whose current is given at @p t.
    std::size_t runFor(double t) const;

    double maxSpeed(const Region &region) const override;
    bool inWater(double x, double y, double z) const override { return first_->inWater(x, y, z); }
    bool segmentInWater(double x1, double y1, double x2, double y2, double z) const override
    {
        return first_->segmentInWater(x1, y1, x2, y2, z);
    }
    std::vector<Segment2> landBoundary(double z) const override { return first_->landBoundary(z); }
    double timeBegin() const override { return first_->timeBegin(); }
    double timeEnd() const override;
    std::string name() const override;
    const FieldGrid *grid() const override { return first_->grid(); }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override;
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override;

private:
    std::shared_ptr<const ForecastRuns> runs_;
    std::optional<std::size_t> asOf_;                         ///< the run newest at the fixed time (unset: live)
    std::vector<std::shared_ptr<const CurrentField>> fields_; ///< the runs' fields
    std::shared_ptr<const CurrentField> first_;
};
} // namespace ompl_glider
