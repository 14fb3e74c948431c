// The truth an execution flies in, checked against the flights and compared with the forecast (ExecutionTruth.h).
#include "ExecutionTruth.h"

#include <algorithm>
#include <cmath>

#include "ompl_glider/Exception.h"
#include "../../io/NumberText.h"

namespace ompl_glider::execution_truth
{
/// A truth that does not cover the flights in time is never extrapolated: refused when it starts after the
/// departure or ends before the plan arrives, else the flights stop at its end and a note says so.
void checkTruthTimes(const MissionProblem &problem, const PlannedPath &plan, double window, ExecutionResult &r)
{
    const MissionSpec &m = problem.getSpec();
    if (!m.execution.truth)
        return;
    const CurrentField &truth = *problem.getTruth();
    const auto at = [&](double t) {
        const std::string iso = problem.isoTime(t);
        return "t = " + text::number(t) + (iso.empty() ? "" : " (" + iso + ")");
    };
    if (truth.timeBegin() > plan.departure)
        throw Error(m.place("execution.truth") + ": the truth begins at " + at(truth.timeBegin()) +
                    ", after the departure at " + at(plan.departure) + ": give a truth that covers the flights");
    const double arrival = plan.solved ? plan.path.back().t : plan.departure;
    if (truth.timeEnd() < arrival)
        throw Error(m.place("execution.truth") + ": the truth ends at " + at(truth.timeEnd()) +
                    ", before the plan arrives at " + at(arrival) + ": give a truth that covers the flights");
    if (truth.timeEnd() < plan.departure + window)
        r.notes.push_back("the truth ends at " + at(truth.timeEnd()) + ", before the flights' window ends at " +
                          at(plan.departure + window) + ": every flight stops there (not extrapolated)");
}

/// A gridded truth that covers only part of the region: refused when the plan leaves its grid (where, when);
/// else a note says that a flight leaving the grid stops there (it is not land).
void checkTruthSpace(const MissionProblem &problem, const PlannedPath &plan, ExecutionResult &r)
{
    const MissionSpec &m = problem.getSpec();
    const FieldGrid *grid = problem.getTruth() ? problem.getTruth()->grid() : nullptr;
    if (!m.execution.truth || !grid)
        return;
    const Region e = grid->extent(), &box = problem.getBox();
    auto inside = [&](double x, double y) { return x >= e.xMin && x <= e.xMax && y >= e.yMin && y <= e.yMax; };
    auto place = [&](double x, double y) {
        if (problem.isGeographic())
        {
            const LonLat g = problem.toGeographic({x, y});
            return "lon " + text::number(g.lon, 6) + ", lat " + text::number(g.lat, 6);
        }
        return "(" + text::number(x, 6) + ", " + text::number(y, 6) + ")";
    };
    const std::string covers = "the truth's grid covers " + place(e.xMin, e.yMin) + " to " + place(e.xMax, e.yMax);
    const std::vector<TimedPoint> &p = plan.path;
    for (std::size_t k = 0; plan.solved && k < p.size(); ++k)
        for (int s = 0; s <= (k + 1 < p.size() ? 8 : 0); ++s)
        {
            const TimedPoint a = p[k], b = k + 1 < p.size() ? p[k + 1] : p[k];
            const double q = s / 8.0, x = a.x + q * (b.x - a.x), y = a.y + q * (b.y - a.y);
            if (!inside(x, y))
                throw Error(m.place("execution.truth") + ": " + covers + "; the plan leaves it at " + place(x, y) +
                            ", t = " + text::number(a.t + q * (b.t - a.t), 6) +
                            ": give a truth that covers the flights");
        }
    if (!inside(box.xMin, box.yMin) || !inside(box.xMax, box.yMax))
        r.notes.push_back(covers + ", less than the planning region (" + place(box.xMin, box.yMin) + " to " +
                          place(box.xMax, box.yMax) + "): a flight that leaves it stops there (not land)");
}

/// The truth against the forecast over the planning box and the time window of the runs (ExecutionResult's
/// rmsDifference, maxPointRmsDifference and their window).
void modelDifference(const MissionProblem &problem, const PlannedPath &plan, ExecutionResult &r)
{
    const MissionSpec &m = problem.getSpec();
    const ExecutionSpec &e = m.execution;
    const Region &box = problem.getBox();
    double latest = plan.departure;
    for (const ExecutionRun &run : r.runs)
        if (run.planned)
            latest = std::max(latest, run.plan.back().t);
    r.differenceBegin = plan.departure;
    r.differenceEnd = plan.departure + 2.0 * (latest - plan.departure);
    if (e.truth)
    {
        const CurrentField &f = *problem.getField(), &tr = *problem.getTruth();
        const double tEnd = std::max(r.differenceBegin, std::min({r.differenceEnd, f.timeEnd(), tr.timeEnd()}));
        r.differenceEnd = tEnd; // within both fields
        double sum = 0.0;
        std::size_t count = 0;
        for (int j = 0; j < 40; ++j)
            for (int i = 0; i < 40; ++i)
            {
                const double x = box.xMin + (i + 0.5) * (box.xMax - box.xMin) / 40.0;
                const double y = box.yMin + (j + 0.5) * (box.yMax - box.yMin) / 40.0;
                const double d = rmsDifference(f, tr, x, y, m.vehicle.depth, r.differenceBegin, tEnd);
                if (std::isnan(d))
                    continue;
                sum += d * d;
                ++count;
                r.maxPointRmsDifference = std::max(r.maxPointRmsDifference, d);
            }
        r.rmsDifference = count > 0 ? std::sqrt(sum / static_cast<double>(count)) : 0.0;
    }
}

} // namespace ompl_glider::execution_truth
