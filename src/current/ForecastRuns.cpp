/// @file ForecastRuns.cpp
/// @brief A stream of forecast runs and the forecast as known at a time (ForecastRuns.h).
#include "ompl_glider/current/ForecastRuns.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
ForecastRuns::ForecastRuns(std::vector<ForecastRun> runs, Loader load) : runs_(std::move(runs)), load_(std::move(load))
{
    if (runs_.empty())
        throw Error("ForecastRuns: no run");
    if (!load_)
        throw Error("ForecastRuns: no loader");
    std::stable_sort(runs_.begin(), runs_.end(),
                     [](const ForecastRun &a, const ForecastRun &b) { return a.reference < b.reference; });
    for (std::size_t k = 0; k < runs_.size(); ++k)
        slots_.push_back(std::make_unique<Slot>());
}

std::optional<std::size_t> ForecastRuns::newestAt(double t) const
{
    std::optional<std::size_t> out;
    for (std::size_t k = 0; k < runs_.size(); ++k)
        if (runs_[k].available <= t && (!out || runs_[k].reference >= runs_[*out].reference))
            out = k;
    return out;
}

std::vector<double> ForecastRuns::arrivalsAfter(double t0) const
{
    std::vector<double> out;
    for (const ForecastRun &r : runs_)
        if (r.available > t0)
            out.push_back(r.available);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    // a run that arrives after t0 but is older than the one newest at its arrival changes nothing
    std::vector<double> newer;
    std::optional<std::size_t> last = newestAt(t0);
    for (double t : out)
    {
        const std::optional<std::size_t> k = newestAt(t);
        if (k && (!last || *k != *last))
            newer.push_back(t);
        last = k;
    }
    return newer;
}

std::shared_ptr<const CurrentField> ForecastRuns::field(std::size_t k) const
{
    Slot &s = *slots_.at(k);
    std::lock_guard<std::mutex> hold(s.lock);
    if (!s.field)
        s.field = load_(runs_[k]);
    return s.field;
}

void ForecastRuns::setField(std::size_t k, std::shared_ptr<const CurrentField> f)
{
    Slot &s = *slots_.at(k);
    std::lock_guard<std::mutex> hold(s.lock);
    s.field = std::move(f);
}

RunStreamField::RunStreamField(std::shared_ptr<const ForecastRuns> runs) : runs_(std::move(runs))
{
    if (!runs_)
        throw Error("RunStreamField: no runs");
    for (std::size_t k = 0; k < runs_->size(); ++k)
        fields_.push_back(runs_->field(k));
    first_ = fields_.front();
}

RunStreamField::RunStreamField(std::shared_ptr<const ForecastRuns> runs, double asOf) : RunStreamField(std::move(runs))
{
    asOf_ = runs_->runAt(asOf);
}

std::size_t RunStreamField::runFor(double t) const
{
    const std::size_t live = runs_->runAt(t);
    if (!asOf_)
        return live;
    // as known at the fixed time: its newest run where it has begun; before, the run newest then
    return t >= (*runs_)[*asOf_].begin ? *asOf_ : std::min(live, *asOf_);
}

double RunStreamField::maxSpeed(const Region &region) const
{
    double out = 0.0;
    for (const auto &f : fields_)
        out = std::max(out, f->maxSpeed(region));
    return out;
}

double RunStreamField::timeEnd() const
{
    double out = -std::numeric_limits<double>::infinity();
    for (const auto &f : fields_)
        out = std::max(out, f->timeEnd());
    return out;
}

std::string RunStreamField::name() const
{
    return first_->name() + " (" + std::to_string(runs_->size()) + " runs, " + (asOf_ ? "as known then" : "newest") +
           ")";
}

Velocity RunStreamField::evaluate(double x, double y, double z, double t) const
{
    return fields_[runFor(t)]->velocity(x, y, z, t);
}

Jacobian RunStreamField::evaluateJacobian(double x, double y, double z, double t) const
{
    return fields_[runFor(t)]->jacobian(x, y, z, t);
}
} // namespace ompl_glider
