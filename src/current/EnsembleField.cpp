#include "ompl_glider/current/EnsembleField.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
EnsembleMeanField::EnsembleMeanField(std::vector<std::shared_ptr<const CurrentField>> members)
    : members_(std::move(members))
{
    if (members_.empty())
        throw Error("EnsembleMeanField: no member");
    for (const auto &m : members_)
        if (!m)
            throw Error("EnsembleMeanField: a member is null");
}

EnsembleMeanField::EnsembleMeanField(std::vector<std::shared_ptr<const CurrentField>> members,
                                     std::vector<double> coefficients)
    : EnsembleMeanField(std::move(members))
{
    if (coefficients.size() != members_.size())
        throw Error("EnsembleMeanField: one coefficient per member");
    for (const double a : coefficients)
        if (!std::isfinite(a))
            throw Error("EnsembleMeanField: a coefficient is not finite");
    coefficients_ = std::move(coefficients);
}

double EnsembleMeanField::maxSpeed(const Region &region) const
{
    if (!coefficients_.empty())
    {
        double sum = 0.0;
        for (std::size_t i = 0; i < members_.size(); ++i)
            sum += std::abs(coefficients_[i]) * members_[i]->maxSpeed(region);
        return sum;
    }
    double s = 0.0;
    for (const auto &m : members_)
        s = std::max(s, m->maxSpeed(region));
    return s;
}

bool EnsembleMeanField::divergenceFree() const
{
    return std::all_of(members_.begin(), members_.end(), [](const auto &m) { return m->divergenceFree(); });
}

bool EnsembleMeanField::inWater(double x, double y, double z) const
{
    return std::all_of(members_.begin(), members_.end(), [&](const auto &m) { return m->inWater(x, y, z); });
}

std::vector<Segment2> EnsembleMeanField::landBoundary(double z) const
{
    std::vector<Segment2> out;
    for (const auto &m : members_)
    {
        const std::vector<Segment2> b = m->landBoundary(z);
        out.insert(out.end(), b.begin(), b.end());
    }
    return out;
}

bool EnsembleMeanField::segmentInWater(double x1, double y1, double x2, double y2, double z) const
{
    return std::all_of(members_.begin(), members_.end(),
                       [&](const auto &m) { return m->segmentInWater(x1, y1, x2, y2, z); });
}

double EnsembleMeanField::timeBegin() const
{
    double t = -std::numeric_limits<double>::infinity();
    for (const auto &m : members_)
        t = std::max(t, m->timeBegin());
    return t;
}

double EnsembleMeanField::timeEnd() const
{
    double t = std::numeric_limits<double>::infinity();
    for (const auto &m : members_)
        t = std::min(t, m->timeEnd());
    return t;
}

std::string EnsembleMeanField::name() const
{
    if (!coefficients_.empty())
        return "ensemble of " + std::to_string(members_.size()) + " weighted by the glider's DAC (" +
               members_.front()->name() + ", ...)";
    return "ensemble mean of " + std::to_string(members_.size()) + " (" + members_.front()->name() + ", ...)";
}

Velocity EnsembleMeanField::evaluate(double x, double y, double z, double t) const
{
    Velocity s{0.0, 0.0};
    if (!coefficients_.empty())
    {
        for (std::size_t i = 0; i < members_.size(); ++i)
        {
            const Velocity c = members_[i]->velocity(x, y, z, t);
            s.u += coefficients_[i] * c.u;
            s.v += coefficients_[i] * c.v;
        }
        return s;
    }
    for (const auto &m : members_)
    {
        const Velocity c = m->velocity(x, y, z, t);
        s.u += c.u;
        s.v += c.v;
    }
    const double n = static_cast<double>(members_.size());
    return {s.u / n, s.v / n};
}

Jacobian EnsembleMeanField::evaluateJacobian(double x, double y, double z, double t) const
{
    Jacobian s;
    if (!coefficients_.empty())
    {
        for (std::size_t i = 0; i < members_.size(); ++i)
        {
            const Jacobian j = members_[i]->jacobian(x, y, z, t);
            const double a = coefficients_[i];
            s.ux += a * j.ux;
            s.uy += a * j.uy;
            s.vx += a * j.vx;
            s.vy += a * j.vy;
        }
        return s;
    }
    for (const auto &m : members_)
    {
        const Jacobian j = m->jacobian(x, y, z, t);
        s.ux += j.ux;
        s.uy += j.uy;
        s.vx += j.vx;
        s.vy += j.vy;
    }
    const double n = static_cast<double>(members_.size());
    return {s.ux / n, s.uy / n, s.vx / n, s.vy / n};
}
} // namespace ompl_glider
