#include "ompl_glider/ompl/GliderSetup.h"

#include "../io/NumberText.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/GliderStateSampler.h"
#include "ompl_glider/ompl/GliderStateValidityChecker.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/ompl/TravelTimeMotionValidator.h"
#include "ompl_glider/ompl/TravelTimeObjective.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace ompl_glider
{
namespace
{

void checkPoint(const GliderProblem &p, const char *what, double x, double y)
{
    if (!std::isfinite(x) || !std::isfinite(y))
        throw Error(std::string("GliderProblem: ") + what + " position (" + what + "X, " + what +
                    "Y) must be set to finite values (got " + text::number(x, 6) + ", " + text::number(y, 6) + ")");
    if (x < p.xMin || x > p.xMax || y < p.yMin || y > p.yMax)
        throw Error(std::string("GliderProblem: ") + what + " (" + text::number(x, 6) + ", " + text::number(y, 6) +
                    ") is outside the planning box x in [" + text::number(p.xMin, 6) + ", " + text::number(p.xMax, 6) +
                    "], y in [" + text::number(p.yMin, 6) + ", " + text::number(p.yMax, 6) + "]");
}
} // namespace

ob::PlannerStatus checkStartAndGoal(const ob::ProblemDefinition &pdef, std::string *why)
{
    const ob::SpaceInformationPtr &si = pdef.getSpaceInformation();
    auto checker = std::dynamic_pointer_cast<const GliderStateValidityChecker>(si->getStateValidityChecker());
    if (pdef.getStartStateCount() == 0)
    {
        if (why)
            *why = "no start state";
        return ob::PlannerStatus::INVALID_START;
    }
    for (unsigned i = 0; i < pdef.getStartStateCount(); ++i)
    {
        const ob::State *st = pdef.getStartState(i);
        if (si->isValid(st))
            continue;
        if (why)
        {
            const auto *s = st->as<TimeSE2StateSpace::StateType>();
            std::ostringstream os;
            os << "invalid start: "
               << (checker ? checker->whyInvalid(st)
                           : "(" + text::number(s->getX()) + ", " + text::number(s->getY()) + ") at time " +
                                 text::number(s->getTime()) + " is rejected by the state validity checker");
            *why = os.str();
        }
        return ob::PlannerStatus::INVALID_START;
    }
    if (auto goal = std::dynamic_pointer_cast<const PositionGoal>(pdef.getGoal()))
    {
        if (goal->maxSampleCount() == 0)
        {
            if (why)
            {
                std::ostringstream os;
                os << "invalid goal at every time of the goal window [" << goal->getEarliestTime() << ", "
                   << goal->getLatestTime() << "], e.g. " << goal->whyInvalidAt(goal->getEarliestTime());
                *why = os.str();
            }
            return ob::PlannerStatus::INVALID_GOAL;
        }
    }
    return ob::PlannerStatus::UNKNOWN;
}

GliderSimpleSetup::GliderSimpleSetup(const ob::StateSpacePtr &space) : og::SimpleSetup(space) {}

bool GliderSimpleSetup::rejectStartOrGoal()
{
    setup();
    lastCheckMessage_.clear();
    const ob::PlannerStatus st = checkStartAndGoal(*pdef_, &lastCheckMessage_);
    if (st == ob::PlannerStatus::UNKNOWN)
        return false;
    OMPL_ERROR("%s", lastCheckMessage_.c_str());
    pdef_->clearSolutionPaths();
    lastStatus_ = st;
    planTime_ = 0.0;
    return true;
}

ob::PlannerStatus GliderSimpleSetup::solve(double time)
{
    if (rejectStartOrGoal())
        return lastStatus_;
    return og::SimpleSetup::solve(time);
}

ob::PlannerStatus GliderSimpleSetup::solve(const ob::PlannerTerminationCondition &ptc)
{
    if (rejectStartOrGoal())
        return lastStatus_;
    return og::SimpleSetup::solve(ptc);
}

std::string departureProblem(const GliderProblem &p)
{
    if (!std::isfinite(p.t0))
        return "departure time t0 must be finite (got " + text::number(p.t0, 6) + ")";
    // A time so large that doubles cannot resolve the integration tolerance near it would give travel times of 0.
    const double limit = 1e-3 * p.travel.eps / std::numeric_limits<double>::epsilon();
    if (std::abs(p.t0) + (std::isfinite(p.horizon) ? p.horizon : 0.0) > limit)
        return "departure time t0 = " + text::number(p.t0, 6) + " with horizon " + text::number(p.horizon, 6) +
               " is too large to resolve the integration tolerance eps = " + text::number(p.travel.eps, 6) +
               " (times must stay below " + text::number(limit, 6) + ")";
    return {};
}

bool GliderContext::canHold(double x, double y, double t1, double t2, double step, int subdivide) const
{
    if (!(t2 >= t1))
        return false;
    const CurrentField &f = *field;
    const double V = speed();
    const double z = travel->params().depth;
    if (!f.inWater(x, y, z))
        return false;
    const int n = std::max(1, static_cast<int>(std::ceil((t2 - t1) / step))) * std::max(1, subdivide);
    for (int i = 0; i <= n; ++i)
    {
        const double t = (i == n) ? t2 : t1 + (t2 - t1) * i / n;
        if (t < f.timeBegin() || t > f.timeEnd())
            return false;
        const Velocity c = f.velocity(x, y, z, t);
        if (!(c.u * c.u + c.v * c.v < V * V))
            return false;
    }
    return true;
}

double GliderContext::holdTimeStep() const
{
    const double span = region.tMax - region.tMin;
    return (std::isfinite(span) && span > 0.0) ? span / 256.0 : 1.0;
}

std::shared_ptr<GliderContext> makeGliderContext(const GliderProblem &p)
{
    if (!p.field)
        throw Error("GliderProblem: field is null (a current field is required)");
    if (!std::isfinite(p.xMin) || !std::isfinite(p.xMax) || !(p.xMin < p.xMax))
        throw Error("GliderProblem: x bounds must be finite with xMin < xMax (got [" + text::number(p.xMin, 6) + ", " +
                    text::number(p.xMax, 6) + "])");
    if (!std::isfinite(p.yMin) || !std::isfinite(p.yMax) || !(p.yMin < p.yMax))
        throw Error("GliderProblem: y bounds must be finite with yMin < yMax (got [" + text::number(p.yMin, 6) + ", " +
                    text::number(p.yMax, 6) + "])");
    if (!(p.horizon > 0.0) || !std::isfinite(p.horizon))
        throw Error("GliderProblem: horizon must be finite and > 0 (got " + text::number(p.horizon, 6) + ")");
    if (const std::string why = departureProblem(p); !why.empty())
        throw Error("GliderProblem: " + why);
    if (p.t0 < p.field->timeBegin() || p.t0 >= p.field->timeEnd())
        throw Error("GliderProblem: departure time t0 = " + text::number(p.t0, 6) + " is outside the time span [" +
                    text::number(p.field->timeBegin(), 6) + ", " + text::number(p.field->timeEnd(), 6) +
                    ") of the field '" + p.field->name() + "'");
    checkPoint(p, "start", p.start.x, p.start.y);
    checkPoint(p, "goal", p.goal.x, p.goal.y);
    if (!(p.goalTolerance >= 0.0) || !std::isfinite(p.goalTolerance))
        throw Error("GliderProblem: goalTolerance must be finite and >= 0 (got " + text::number(p.goalTolerance, 6) +
                    ")");

    auto ctx = std::make_shared<GliderContext>();
    ctx->field = p.field;
    ctx->travel = std::make_shared<TravelTimeCalculator>(p.field, p.travel); // validates the travel parameters
    ctx->environment = p.environment;
    ctx->region.xMin = p.xMin;
    ctx->region.xMax = p.xMax;
    ctx->region.yMin = p.yMin;
    ctx->region.yMax = p.yMax;
    ctx->region.zMin = ctx->region.zMax = p.travel.depth;
    ctx->region.tMin = p.t0;
    ctx->region.tMax = p.t0 + p.horizon;
    ctx->arriveNotBefore = p.arriveNotBefore;
    ctx->arriveNotAfter = p.arriveNotAfter;
    const double cmax = ctx->maxCurrent();
    if (!(cmax >= 0.0) || !std::isfinite(cmax))
        throw Error("GliderProblem: the field '" + p.field->name() +
                    "' gives no finite maximum current speed over the region (got " + text::number(cmax, 6) + ")");
    return ctx;
}

std::shared_ptr<GliderSimpleSetup> makeSimpleSetup(const GliderProblem &p, std::shared_ptr<GliderContext> *ctxOut)
{
    auto ctx = makeGliderContext(p);
    if (ctxOut)
        *ctxOut = ctx;
    return makeSimpleSetup(p, ctx);
}

std::shared_ptr<GliderSimpleSetup> makeSimpleSetup(const GliderProblem &p, std::shared_ptr<GliderContext> ctx)
{
    if (!ctx)
        throw Error("makeSimpleSetup: the GliderContext is null");
    checkPoint(p, "start", p.start.x, p.start.y);
    checkPoint(p, "goal", p.goal.x, p.goal.y);
    const Region &r = ctx->region;
    if (!(p.t0 >= r.tMin && p.t0 <= r.tMax))
        throw Error("makeSimpleSetup: departure time t0 = " + text::number(p.t0, 6) +
                    " lies outside the context's time window [" + text::number(r.tMin, 6) + ", " +
                    text::number(r.tMax, 6) + "]");
    ob::RealVectorBounds b(2);
    b.setLow(0, r.xMin);
    b.setHigh(0, r.xMax);
    b.setLow(1, r.yMin);
    b.setHigh(1, r.yMax);
    auto space = std::make_shared<TimeSE2StateSpace>(b, r.tMin, r.tMax);
    const double vMax = ctx->speed() + ctx->maxCurrent();
    space->setTimeWeight(vMax);
    const double sx = p.start.x, sy = p.start.y, t0 = p.t0; // the start state's time
    space->setStateSamplerAllocator([sx, sy, t0, vMax](const ob::StateSpace *sp) {
        return std::make_shared<GliderStateSampler>(sp, sx, sy, t0, vMax);
    });

    auto ss = std::make_shared<GliderSimpleSetup>(space);
    const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
    std::shared_ptr<const GliderContext> cctx = ctx;
    ss->setStateValidityChecker(std::make_shared<GliderStateValidityChecker>(si, cctx));
    si->setMotionValidator(std::make_shared<TravelTimeMotionValidator>(si, cctx));
    ss->setOptimizationObjective(std::make_shared<TravelTimeObjective>(si, cctx));

    ob::ScopedState<TimeSE2StateSpace> start(space);
    start->setXYT(p.start.x, p.start.y, p.t0);
    start->setYaw(0.0);
    ss->setStartState(start);

    const double straight = std::hypot(p.goal.x - p.start.x, p.goal.y - p.start.y);
    const double tEarliest = std::min(r.tMax, p.t0 + straight / vMax);
    ss->setGoal(std::make_shared<PositionGoal>(si, p.goal.x, p.goal.y, p.goalTolerance, tEarliest, r.tMax));
    return ss;
}
} // namespace ompl_glider
