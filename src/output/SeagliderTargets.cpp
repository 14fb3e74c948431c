/// @file SeagliderTargets.cpp
/// @brief The Seaglider targets file (SeagliderTargets.h) of a planned route.

#include "ompl_glider/output/SeagliderTargets.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>

#include "../io/TextUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/RouteFiles.h"

namespace ompl_glider
{
namespace
{
/// [-]D..DMM.MMMM with @p degreeDigits digits of degrees; the sign on the whole number (also for |x| < 1).
std::string degreesMinutes(double degrees, int degreeDigits)
{
    const bool negative = degrees < 0.0;
    // whole 1e-4 minutes first, so that minutes never round up to 60
    const auto units = static_cast<std::int64_t>(std::llround(std::abs(degrees) * 60.0 * 1e4));
    const std::int64_t whole = units / 600000, rest = units % 600000;
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s%0*lld%02lld.%04lld", negative && units > 0 ? "-" : "", degreeDigits,
                  static_cast<long long>(whole), static_cast<long long>(rest / 10000),
                  static_cast<long long>(rest % 10000));
    return buf;
}
} // namespace

std::string seagliderLatitude(double degrees)
{
    return degreesMinutes(degrees, 2);
}

std::string seagliderLongitude(double degrees)
{
    return degreesMinutes(std::remainder(degrees, 360.0), 3);
}

std::vector<SeagliderTarget> seagliderTargets(const MissionResult &r, const MissionProblem *problem)
{
    if (r.waypoints.empty() || !r.waypoints.front().geographic)
        throw Error(r.spec.file + ": a Seaglider targets file needs longitudes and latitudes (give a 'projection')");
    bool headings = false;
    for (const MissionWaypoint &w : r.waypoints)
        headings = headings || std::isfinite(w.heading);
    const std::vector<HeldHeading> holds = headings ? uploadHolds(r, problem) : std::vector<HeldHeading>{};
    const std::vector<std::size_t> turns = gotoWaypointIndices(r, problem, holds);
    std::set<std::string> used;
    for (const ViaPointSpec &v : r.spec.waypoints)
        used.insert(v.name);
    std::vector<SeagliderTarget> out;
    if (const auto stay = resumedStay(r)) // a stay under way: held first, until the plan departs
    {
        SeagliderTarget t;
        t.name = stay->name;
        t.position = stay->at;
        t.radius = stay->radius;
        t.note = stayNote(r, *stay);
        used.insert(t.name);
        out.push_back(t);
    }
    int turn = 0;
    for (const std::size_t i : turns)
    {
        if (i == 0)
            continue; // the start: where the glider is
        SeagliderTarget t;
        t.position = r.waypoints[i].lonLat;
        t.radius = r.spec.outputs.gotoWptDist;
        const std::string stop = stopName(r, i);
        if (i + 1 == r.waypoints.size())
            t.name = "GOAL";
        else if (!stop.empty() && stop != "start")
        {
            t.name = stop;
            for (const ViaPointSpec &v : r.spec.waypoints)
                if (v.name == stop && std::isfinite(v.radius))
                    t.radius = v.radius * r.spec.metresPerUnit();
        }
        else
            do
                t.name = "T" + std::to_string(++turn);
            while (used.count(t.name));
        if (!out.empty() && out.back().name == t.name)
            continue; // the end of a stay at the via point just listed
        for (const HeldHeading &h : holds)
            if (h.to == i)
                t.note = headingNote(r, h);
        if (const auto stay = stayAt(r, i))
            t.note += (t.note.empty() ? "" : "; then ") + stayNote(r, *stay);
        used.insert(t.name);
        out.push_back(t);
    }
    for (std::size_t k = 0; k < out.size(); ++k)
        out[k].next = k + 1 < out.size() ? out[k + 1].name : out[k].name;
    return out;
}

std::string formatSeagliderTargets(const std::vector<SeagliderTarget> &targets, const std::string &mission)
{
    std::string s = "/ Seaglider targets: " + text::oneLine(mission) +
                    " (ompl_glider)\n/ name lat=DDMM.MMMM lon=DDDMM.MMMM "
                    "radius=metres goto=next\n";
    for (const SeagliderTarget &t : targets)
    {
        char radius[32];
        std::snprintf(radius, sizeof radius, "%.0f", std::max(1.0, std::round(t.radius)));
        if (!t.note.empty())
            s += "/ " + text::oneLine(t.note) + "\n";
        s += t.name + " lat=" + seagliderLatitude(t.position.lat) + " lon=" + seagliderLongitude(t.position.lon) +
             " radius=" + radius + " goto=" + t.next + "\n";
    }
    return s;
}
} // namespace ompl_glider
