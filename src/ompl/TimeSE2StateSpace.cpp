#include "ompl_glider/ompl/TimeSE2StateSpace.h"

#include <cmath>
#include <string>

#include <ompl/base/ProjectionEvaluator.h>

#include "ompl_glider/Exception.h"

namespace ob = ompl::base;

namespace ompl_glider
{
namespace
{
/// Default projection: (x, y, t) with cells of 1/20 of each extent (for KPIECE-like planners).
class TimeSE2Projection : public ob::ProjectionEvaluator
{
public:
    explicit TimeSE2Projection(const TimeSE2StateSpace *space) : ob::ProjectionEvaluator(space), space_(space) {}
    unsigned int getDimension() const override { return 3; }
    void defaultCellSizes() override
    {
        const ob::RealVectorBounds &xy = space_->getXYBounds();
        cellSizes_.resize(3);
        cellSizes_[0] = (xy.high[0] - xy.low[0]) / 20.0;
        cellSizes_[1] = (xy.high[1] - xy.low[1]) / 20.0;
        cellSizes_[2] = (space_->tMax() - space_->tMin()) / 20.0;
    }
    void project(const ob::State *state, Eigen::Ref<Eigen::VectorXd> projection) const override
    {
        const auto *s = state->as<TimeSE2StateSpace::StateType>();
        projection(0) = s->getX();
        projection(1) = s->getY();
        projection(2) = s->getTime();
    }

private:
    const TimeSE2StateSpace *space_;
};
} // namespace

TimeSE2StateSpace::TimeSE2StateSpace(const ob::RealVectorBounds &xyBounds, double tMin, double tMax)
{
    if (xyBounds.low.size() != 2 || xyBounds.high.size() != 2)
        throw Error("TimeSE2StateSpace: xyBounds must have dimension 2 (got " + std::to_string(xyBounds.low.size()) +
                    ")");
    for (int i = 0; i < 2; ++i)
        if (!std::isfinite(xyBounds.low[i]) || !std::isfinite(xyBounds.high[i]) ||
            !(xyBounds.low[i] < xyBounds.high[i]))
            throw Error(std::string("TimeSE2StateSpace: ") + (i == 0 ? "x" : "y") +
                        " bounds must be finite with low < high (got [" + std::to_string(xyBounds.low[i]) + ", " +
                        std::to_string(xyBounds.high[i]) + "])");
    if (!std::isfinite(tMin) || !std::isfinite(tMax) || !(tMin < tMax))
        throw Error("TimeSE2StateSpace: time window must be finite with tMin < tMax (got [" + std::to_string(tMin) +
                    ", " + std::to_string(tMax) + "])");

    setName("TimeSE2" + getName());
    auto se2 = std::make_shared<ob::SE2StateSpace>();
    se2->setName("SE2");
    se2->setBounds(xyBounds);
    se2->setSubspaceWeight(1, 0.01); // yaw weight, see setYawWeight()
    auto time = std::make_shared<ob::RealVectorStateSpace>(1);
    time->setName("Time");
    ob::RealVectorBounds tb(1);
    tb.setLow(tMin);
    tb.setHigh(tMax);
    time->setBounds(tb);
    addSubspace(se2, 1.0);
    addSubspace(time, 1.0);
    lock();
}

const ob::RealVectorBounds &TimeSE2StateSpace::getXYBounds() const
{
    return as<ob::SE2StateSpace>(0)->getBounds();
}

const ob::RealVectorBounds &TimeSE2StateSpace::getTimeBounds() const
{
    return as<ob::RealVectorStateSpace>(1)->getBounds();
}

void TimeSE2StateSpace::setTimeWeight(double w)
{
    if (!(w > 0.0) || !std::isfinite(w))
        throw Error("TimeSE2StateSpace::setTimeWeight: weight must be finite and > 0 (got " + std::to_string(w) + ")");
    setSubspaceWeight(1, w);
}

double TimeSE2StateSpace::getTimeWeight() const
{
    return getSubspaceWeight(1);
}

void TimeSE2StateSpace::setYawWeight(double w)
{
    if (!(w > 0.0) || !std::isfinite(w))
        throw Error("TimeSE2StateSpace::setYawWeight: weight must be finite and > 0 (got " + std::to_string(w) + ")");
    as<ob::SE2StateSpace>(0)->setSubspaceWeight(1, w);
}

double TimeSE2StateSpace::getYawWeight() const
{
    return as<ob::SE2StateSpace>(0)->getSubspaceWeight(1);
}

double TimeSE2StateSpace::xyDistance(const ob::State *a, const ob::State *b)
{
    const auto *sa = a->as<StateType>();
    const auto *sb = b->as<StateType>();
    return std::hypot(sa->getX() - sb->getX(), sa->getY() - sb->getY());
}

ob::State *TimeSE2StateSpace::allocState() const
{
    auto *state = new StateType();
    allocStateComponents(state);
    return state;
}

void TimeSE2StateSpace::freeState(ob::State *state) const
{
    CompoundStateSpace::freeState(state);
}

void TimeSE2StateSpace::registerProjections()
{
    registerDefaultProjection(std::make_shared<TimeSE2Projection>(this));
}
} // namespace ompl_glider
