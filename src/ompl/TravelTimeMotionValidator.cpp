#include "ompl_glider/ompl/TravelTimeMotionValidator.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>

#include <ompl/base/SpaceInformation.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"

namespace ob = ompl::base;

namespace ompl_glider
{
std::string toString(MotionVerdict v)
{
    switch (v)
    {
    case MotionVerdict::Valid:
        return "valid";
    case MotionVerdict::NotForward:
        return "not forward in time";
    case MotionVerdict::CannotHold:
        return "cannot hold position (current at least the vehicle speed)";
    case MotionVerdict::Infeasible:
        return "infeasible leg (current too strong for every heading)";
    case MotionVerdict::TooEarly:
        return "too early (faster than the fastest travel time)";
    case MotionVerdict::TooLate:
        return "too late (slower than the slowest travel time, cannot hold)";
    case MotionVerdict::Blocked:
        return "blocked by a forbidden region";
    case MotionVerdict::InvalidEndState:
        return "invalid end state";
    }
    return "unknown";
}

TravelTimeMotionValidator::TravelTimeMotionValidator(const ob::SpaceInformationPtr &si,
                                                     std::shared_ptr<const GliderContext> ctx)
    : ob::MotionValidator(si), ctx_(std::move(ctx))
{
    init();
}

TravelTimeMotionValidator::TravelTimeMotionValidator(ob::SpaceInformation *si, std::shared_ptr<const GliderContext> ctx)
    : ob::MotionValidator(si), ctx_(std::move(ctx))
{
    init();
}

void TravelTimeMotionValidator::init()
{
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error("TravelTimeMotionValidator: the GliderContext must be non-null with a field and a travel-time "
                    "calculator");
    holdStep_ = ctx_->holdTimeStep();
    vMax_ = ctx_->speed() + ctx_->maxCurrent();
    if (!(vMax_ > 0.0))
        vMax_ = std::numeric_limits<double>::infinity();
    id_ = newCacheId();
}

std::uint64_t TravelTimeMotionValidator::newCacheId()
{
    static std::atomic<std::uint64_t> nextId{1};
    return nextId.fetch_add(1, std::memory_order_relaxed);
}

void TravelTimeMotionValidator::setRelativeTolerance(double tol)
{
    if (!(tol >= 0.0 && tol <= 0.1))
        throw Error("TravelTimeMotionValidator::setRelativeTolerance: tolerance must be in [0, 0.1] (got " +
                    std::to_string(tol) + ")");
    relTol_ = tol;
    id_ = newCacheId(); // invalidate cached verdicts
}

void TravelTimeMotionValidator::setHoldTimeStep(double dt)
{
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw Error("TravelTimeMotionValidator::setHoldTimeStep: step must be finite and > 0 (got " +
                    std::to_string(dt) + ")");
    holdStep_ = dt;
    id_ = newCacheId(); // invalidate cached verdicts
}

bool TravelTimeMotionValidator::canHold(double x, double y, double t1, double t2) const
{
    return ctx_->canHold(x, y, t1, t2, holdStep_);
}

MotionVerdict TravelTimeMotionValidator::classify(double x1, double y1, double t1, double x2, double y2,
                                                  double t2) const
{
    // One-entry cache per thread: OMPL planners often ask for a motion's cost (TravelTimeObjective::motionCost,
    // which validates it) and then check the same motion again.
    struct Cache
    {
        std::uint64_t id{0};
        double key[6];
        MotionVerdict verdict{MotionVerdict::Valid};
    };
    thread_local Cache cache;
    const double key[6] = {x1, y1, t1, x2, y2, t2};
    if (cache.id == id_ && std::equal(key, key + 6, cache.key))
        return cache.verdict;
    const MotionVerdict v = classifyUncached(x1, y1, t1, x2, y2, t2);
    cache.id = id_;
    std::copy(key, key + 6, cache.key);
    cache.verdict = v;
    return v;
}

MotionVerdict TravelTimeMotionValidator::classifyUncached(double x1, double y1, double t1, double x2, double y2,
                                                          double t2) const
{
    const double dt = t2 - t1;
    const double len = std::hypot(x2 - x1, y2 - y1);
    if (len == 0.0)
    {
        if (!(dt >= 0.0))
            return MotionVerdict::NotForward;
        if (dt > 0.0 && !canHold(x1, y1, t1, t2))
            return MotionVerdict::CannotHold;
    }
    else
    {
        if (!(dt > 0.0))
            return MotionVerdict::NotForward;
        // No ground speed exceeds V + max|c|: reject without integrating (no CFC).
        if (dt < len / vMax_ * (1.0 - relTol_))
            return MotionVerdict::TooEarly;
        const ArrivalWindow w = ctx_->travel->arrivalWindow(x1, y1, x2, y2, t1);
        if (!std::isfinite(w.earliest))
            return MotionVerdict::Infeasible;
        if (dt < w.earliest * (1.0 - relTol_))
            return MotionVerdict::TooEarly;
        if (std::isfinite(w.latest) && dt > w.latest * (1.0 + relTol_))
            return MotionVerdict::TooLate;
    }
    if (ctx_->environment && !ctx_->environment->legFree(x1, y1, t1, x2, y2, t2))
        return MotionVerdict::Blocked;
    return MotionVerdict::Valid;
}

MotionVerdict TravelTimeMotionValidator::classify(const ob::State *s1, const ob::State *s2) const
{
    const auto *a = s1->as<TimeSE2StateSpace::StateType>();
    const auto *b = s2->as<TimeSE2StateSpace::StateType>();
    // Cheap checks first: time order, then the end state, then the travel time (one CFC) and the environment.
    const double dt = b->getTime() - a->getTime();
    if (!(dt >= 0.0) || (dt == 0.0 && (a->getX() != b->getX() || a->getY() != b->getY())))
        return MotionVerdict::NotForward;
    if (!si_->isValid(s2))
        return MotionVerdict::InvalidEndState;
    return classify(a->getX(), a->getY(), a->getTime(), b->getX(), b->getY(), b->getTime());
}

bool TravelTimeMotionValidator::record(bool ok) const
{
    if (ok)
        ++valid_;
    else
        ++invalid_;
    return ok;
}

bool TravelTimeMotionValidator::checkMotion(const ob::State *s1, const ob::State *s2) const
{
    return record(classify(s1, s2) == MotionVerdict::Valid);
}

bool TravelTimeMotionValidator::checkMotion(const ob::State *s1, const ob::State *s2,
                                            std::pair<ob::State *, double> &lastValid) const
{
    if (classify(s1, s2) == MotionVerdict::Valid)
        return record(true);
    record(false);

    const ob::StateSpace &space = *si_->getStateSpace();
    ob::State *probe = space.allocState();
    auto validTo = [&](double tau) {
        space.interpolate(s1, s2, tau, probe);
        return classify(s1, probe) == MotionVerdict::Valid;
    };
    // Coarse scan: the first of 8 sample fractions whose sub-motion is invalid, then bisection below it.
    constexpr int kCoarse = 8;
    double lo = 0.0, hi = 1.0;
    for (int i = 1; i < kCoarse; ++i)
    {
        const double tau = static_cast<double>(i) / kCoarse;
        if (validTo(tau))
            lo = tau;
        else
        {
            hi = tau;
            break;
        }
    }
    for (int k = 0; k < 12; ++k)
    {
        const double mid = 0.5 * (lo + hi);
        if (validTo(mid))
            lo = mid;
        else
            hi = mid;
    }
    lastValid.second = lo;
    if (lastValid.first != nullptr)
        space.interpolate(s1, s2, lo, lastValid.first);
    space.freeState(probe);
    return false;
}
} // namespace ompl_glider
