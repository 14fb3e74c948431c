/// @file ExecutionPacking.cpp
/// @brief An execution run as bytes for the processes of a job (ExecutionPacking.h).

#include "ExecutionPacking.h"

#include <cstdint>

#include "ompl_glider/TaskSpread.h"

namespace ompl_glider
{
namespace
{
void putPoints(ByteWriter &w, const std::vector<TimedPoint> &v)
{
    w.putEach(v, [](ByteWriter &o, const TimedPoint &p) {
        o.put(p.x);
        o.put(p.y);
        o.put(p.t);
    });
}

void getPoints(ByteReader &r, std::vector<TimedPoint> &v)
{
    r.getEach(v, [](ByteReader &i, TimedPoint &p) {
        i.get(p.x);
        i.get(p.y);
        i.get(p.t);
    });
}

void putHeadings(ByteWriter &w, const HeadingRoute &h)
{
    w.put(h.start.x);
    w.put(h.start.y);
    w.put(h.departure);
    w.put(h.step);
    w.putEach(h.segments, [](ByteWriter &o, const HeadingSegment &g) {
        o.put(g.bearing);
        o.put(g.duration);
    });
}

void getHeadings(ByteReader &r, HeadingRoute &h)
{
    r.get(h.start.x);
    r.get(h.start.y);
    r.get(h.departure);
    r.get(h.step);
    r.getEach(h.segments, [](ByteReader &i, HeadingSegment &g) {
        i.get(g.bearing);
        i.get(g.duration);
    });
}

} // namespace

std::string execution_detail::packRun(const ExecutionRun &run)
{
    ByteWriter w;
    w.put(run.planned);
    w.put(run.reason);
    putPoints(w, run.plan);
    w.put(run.headings.has_value());
    if (run.headings)
        putHeadings(w, *run.headings);
    w.putEach(run.legs, [](ByteWriter &o, const ExecutionLeg &l) {
        o.put(static_cast<std::uint64_t>(l.end));
        o.put(l.headings.has_value());
        if (l.headings)
            putHeadings(o, *l.headings);
    });
    w.putEach(run.flown, [](ByteWriter &o, const FlownTrack &f) {
        putPoints(o, f.fixes);
        putPoints(o, f.track);
        o.put(f.headings);
        o.put(f.plannedArrival);
        o.put(f.finalDistance);
        o.put(f.arrivalTime);
        o.put(f.reached);
        o.put(f.grounded);
        o.put(f.groundedWhy);
        o.put(f.madeGoodSpeed);
        o.put(f.replans);
        o.put(static_cast<std::uint64_t>(f.stationsReached));
        o.put(static_cast<std::uint64_t>(f.windowsMissed));
        o.put(f.notReachedWhy);
    });
    w.put(run.oracleArrival);
    w.put(run.oracleSeconds);
    return w.take();
}

void execution_detail::unpackRun(const std::string &bytes, ExecutionRun &run)
{
    ByteReader r(bytes);
    r.get(run.planned);
    r.get(run.reason);
    getPoints(r, run.plan);
    if (r.value<bool>())
    {
        HeadingRoute h;
        getHeadings(r, h);
        run.headings = h;
    }
    r.getEach(run.legs, [](ByteReader &i, ExecutionLeg &l) {
        l.end = static_cast<std::size_t>(i.value<std::uint64_t>());
        if (i.value<bool>())
        {
            HeadingRoute h;
            getHeadings(i, h);
            l.headings = h;
        }
    });
    r.getEach(run.flown, [](ByteReader &i, FlownTrack &f) {
        getPoints(i, f.fixes);
        getPoints(i, f.track);
        i.get(f.headings);
        i.get(f.plannedArrival);
        i.get(f.finalDistance);
        i.get(f.arrivalTime);
        i.get(f.reached);
        i.get(f.grounded);
        i.get(f.groundedWhy);
        i.get(f.madeGoodSpeed);
        i.get(f.replans);
        f.stationsReached = static_cast<std::size_t>(i.value<std::uint64_t>());
        f.windowsMissed = static_cast<std::size_t>(i.value<std::uint64_t>());
        i.get(f.notReachedWhy);
    });
    r.get(run.oracleArrival);
    r.get(run.oracleSeconds);
}
} // namespace ompl_glider
