#include "ompl_glider/environment/ForbiddenRegions.h"

#include <algorithm>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
void ForbiddenRegions::add(std::shared_ptr<const ForbiddenRegion> region)
{
    if (!region)
        throw Error("ForbiddenRegions::add: null region");
    regions_.push_back(std::move(region));
}

bool ForbiddenRegions::isStatic() const
{
    for (const auto &r : regions_)
        if (!r->isStatic())
            return false;
    return true;
}

bool ForbiddenRegions::pointFree(double x, double y, double t) const
{
    for (const auto &r : regions_)
        if (!r->pointFree(x, y, t))
            return false;
    return true;
}

bool ForbiddenRegions::legFree(double x1, double y1, double t1, double x2, double y2, double t2) const
{
    for (const auto &r : regions_)
        if (!r->legFree(x1, y1, t1, x2, y2, t2))
            return false;
    return true;
}

std::string ForbiddenRegions::whyBlocked(double x, double y, double t) const
{
    std::string out;
    for (const auto &r : regions_)
    {
        const std::string why = r->whyBlocked(x, y, t);
        if (!why.empty())
            out += (out.empty() ? "" : "; ") + why;
    }
    return out;
}

std::string ForbiddenRegions::whyLegBlocked(double x1, double y1, double t1, double x2, double y2, double t2) const
{
    std::string out;
    for (const auto &r : regions_)
    {
        const std::string why = r->whyLegBlocked(x1, y1, t1, x2, y2, t2);
        if (!why.empty())
            out += (out.empty() ? "" : "; ") + why;
    }
    return out;
}
std::vector<double> ForbiddenRegions::releaseTimes() const
{
    std::vector<double> all;
    for (const auto &r : regions_)
    {
        const std::vector<double> t = r->releaseTimes();
        all.insert(all.end(), t.begin(), t.end());
    }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
}
} // namespace ompl_glider
