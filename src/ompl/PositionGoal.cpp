#include "ompl_glider/ompl/PositionGoal.h"

#include <cmath>
#include <string>

#include <ompl/base/goals/GoalState.h>
#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/GliderStateValidityChecker.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"

namespace ob = ompl::base;

namespace ompl_glider
{
PositionGoal::PositionGoal(const ob::SpaceInformationPtr &si, double x, double y, double tolerance, double tEarliest,
                           double tLatest)
    : ob::GoalSampleableRegion(si), x_(x), y_(y), tEarliest_(tEarliest), tLatest_(tLatest)
{
    if (!std::isfinite(x) || !std::isfinite(y))
        throw Error("PositionGoal: goal position must be finite (got " + std::to_string(x) + ", " + std::to_string(y) +
                    ")");
    if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
        throw Error("PositionGoal: tolerance must be finite and >= 0 (got " + std::to_string(tolerance) + ")");
    setThreshold(tolerance);
    setTimeWindow(tEarliest, tLatest);
}

void PositionGoal::setTimeWindow(double tEarliest, double tLatest)
{
    if (!std::isfinite(tEarliest) || !std::isfinite(tLatest) || !(tEarliest <= tLatest))
        throw Error("PositionGoal: goal time window must be finite with tEarliest <= tLatest (got [" +
                    std::to_string(tEarliest) + ", " + std::to_string(tLatest) + "])");
    tEarliest_ = tEarliest;
    tLatest_ = tLatest;
}

double PositionGoal::distanceGoal(const ob::State *st) const
{
    const auto *s = st->as<TimeSE2StateSpace::StateType>();
    return std::hypot(s->getX() - x_, s->getY() - y_);
}

void PositionGoal::checkValidity() const
{
    std::call_once(once_, [this] {
        ob::State *st = si_->allocState();
        auto *s = st->as<TimeSE2StateSpace::StateType>();
        constexpr int kGrid = 256;
        for (int i = 0; i <= kGrid; ++i)
        {
            const double t = tEarliest_ + (tLatest_ - tEarliest_) * i / kGrid;
            s->setXYT(x_, y_, t);
            s->setYaw(0.0);
            if (si_->isValid(st))
                validTimes_.push_back(t);
        }
        si_->freeState(st);
    });
}

void PositionGoal::sampleGoal(ob::State *st) const
{
    checkValidity();
    auto *s = st->as<TimeSE2StateSpace::StateType>();
    s->setYaw(0.0);
    for (int attempt = 0; attempt < 20; ++attempt)
    {
        s->setXYT(x_, y_, tEarliest_ == tLatest_ ? tEarliest_ : rng_.uniformReal(tEarliest_, tLatest_));
        if (validTimes_.empty() || si_->isValid(st))
            return;
    }
    s->setTime(validTimes_[rng_.uniformInt(0, static_cast<int>(validTimes_.size()) - 1)]);
}

unsigned int PositionGoal::maxSampleCount() const
{
    checkValidity();
    return static_cast<unsigned int>(validTimes_.size());
}
} // namespace ompl_glider

namespace ompl_glider
{
std::string PositionGoal::whyInvalidAt(double t) const
{
    auto checker = std::dynamic_pointer_cast<const GliderStateValidityChecker>(si_->getStateValidityChecker());
    ob::State *st = si_->allocState();
    auto *s = st->as<TimeSE2StateSpace::StateType>();
    s->setXYT(x_, y_, t);
    s->setYaw(0.0);
    std::string why;
    if (checker)
        why = checker->whyInvalid(st);
    else if (!si_->isValid(st))
        why = "rejected by the state validity checker";
    si_->freeState(st);
    return why;
}

std::optional<Point2> goalPosition(const ob::Goal &goal, std::string *why)
{
    using TimeState = TimeSE2StateSpace::StateType;
    if (const auto *pg = dynamic_cast<const PositionGoal *>(&goal))
        return Point2{pg->getX(), pg->getY()};
    if (const auto *gs = dynamic_cast<const ob::GoalState *>(&goal))
        return Point2{gs->getState()->as<TimeState>()->getX(), gs->getState()->as<TimeState>()->getY()};
    if (const auto *gr = dynamic_cast<const ob::GoalSampleableRegion *>(&goal))
    {
        if (!gr->canSample())
        {
            if (why)
                *why = "the goal region cannot be sampled";
            return std::nullopt;
        }
        const ob::SpaceInformationPtr &si = gr->getSpaceInformation();
        ob::State *tmp = si->allocState();
        gr->sampleGoal(tmp);
        const Point2 p{tmp->as<TimeState>()->getX(), tmp->as<TimeState>()->getY()};
        si->freeState(tmp);
        return p;
    }
    if (why)
        *why = "unknown goal type (need PositionGoal, GoalState or GoalSampleableRegion)";
    return std::nullopt;
}

std::optional<StartAndGoal> startAndGoal(const ob::ProblemDefinition &pdef, const std::string &planner,
                                         ob::PlannerStatus &status)
{
    if (pdef.getStartStateCount() == 0)
    {
        OMPL_ERROR("%s: invalid start: no start state given", planner.c_str());
        status = ob::PlannerStatus::INVALID_START;
        return std::nullopt;
    }
    const auto *st = pdef.getStartState(0)->as<TimeSE2StateSpace::StateType>();
    std::string why;
    const std::optional<Point2> goal = goalPosition(*pdef.getGoal(), &why);
    if (!goal)
    {
        OMPL_ERROR("%s: %s", planner.c_str(), why.c_str());
        status = ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
        return std::nullopt;
    }
    return StartAndGoal{st->getX(), st->getY(), st->getTime(), *goal};
}
} // namespace ompl_glider
