#include "ompl_glider/output/SlocumGoto.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "../io/TextUtil.h"
#include "ompl_glider/Exception.h"
#include "OutputDirectory.h"

namespace ompl_glider
{
std::string formatDegMin(double degrees)
{
    if (!std::isfinite(degrees) || std::abs(degrees) > 360.0)
        throw Error("formatDegMin: " + std::to_string(degrees) + " is not a coordinate in degrees");
    // Whole units of 1e-4 minutes; the sign goes on the whole number.
    const long long units = std::llround(std::abs(degrees) * 60.0 * 1e4);
    const long long deg = units / 600000;
    const long long rem = units % 600000; // minutes * 1e4, in [0, 600000)
    const bool negative = degrees < 0.0 && units != 0;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%lld%02lld.%04lld", negative ? "-" : "", deg, rem / 10000, rem % 10000);
    return buf;
}

std::string gotoFileName(int number)
{
    if (number < 0 || number > 99)
        throw Error("goto list number must be in 0..99 (got " + std::to_string(number) + ")");
    char buf[32];
    std::snprintf(buf, sizeof buf, "goto_l%02d.ma", number);
    return buf;
}

std::string formatGotoList(const GotoList &list)
{
    std::ostringstream s;
    s << "behavior_name=goto_list\n";
    s << "# " << gotoFileName(list.number) << " written by ompl_glider";
    if (!list.comment.empty())
    {
        std::string comment = text::oneLine(list.comment); // on its line, and no tag of the file's own in it
        for (char &c : comment)
            c = c == '<' ? '(' : c == '>' ? ')' : c;
        s << ": " << comment;
    }
    s << "\n";
    s << "<start:b_arg>\n";
    s << "    b_arg: num_legs_to_run(nodim) " << list.numLegsToRun << "\n";
    s << "    b_arg: start_when(enum) " << list.startWhen << "\n";
    s << "    b_arg: list_stop_when(enum) " << list.listStopWhen << "\n";
    char dist[48];
    std::snprintf(dist, sizeof dist, "%.10g", list.listWhenWptDist);
    s << "    b_arg: list_when_wpt_dist(m) " << dist << "\n";
    s << "    b_arg: initial_wpt(enum) " << list.initialWpt << "\n";
    s << "    b_arg: num_waypoints(nodim) " << list.waypoints.size() << "\n";
    s << "<end:b_arg>\n";
    s << "<start:waypoints>\n";
    for (std::size_t i = 0; i < list.waypoints.size(); ++i)
    {
        const LonLat &p = list.waypoints[i];
        if (i < list.notes.size() && !list.notes[i].empty())
            s << "# " << list.notes[i] << "\n";
        // A Slocum reads -180..180: a list built by hand in 0..360 is written in that convention too (185E is
        // -17500.0000); gotoList() already gives normalised longitudes (LocalProjection::inverse()).
        s << formatDegMin(normalizeLongitude(p.lon)) << " " << formatDegMin(p.lat) << "\n";
    }
    s << "<end:waypoints>\n";
    return s.str();
}

void writeGotoFile(const std::string &path, const GotoList &list)
{
    output_detail::writeFileChecked(path, formatGotoList(list));
}

GotoList parseGotoList(const std::string &text, const std::string &source)
{
    GotoList list;
    std::istringstream in(text);
    std::string line;
    enum class Block
    {
        None,
        Args,
        Waypoints,
        Done
    } block = Block::None;
    int lineNo = 0;
    long declared = -1;
    bool sawBehavior = false;
    std::string pending; // a comment line just before a waypoint: its note
    auto fail = [&](const std::string &what) { throw Error(source + ":" + std::to_string(lineNo) + ": " + what); };
    while (std::getline(in, line))
    {
        ++lineNo;
        if (block == Block::Waypoints)
        {
            const auto first = line.find_first_not_of(" \t");
            if (first != std::string::npos && line[first] == '#')
            {
                pending = line.substr(line.find_first_not_of(" \t", first + 1) == std::string::npos
                                          ? line.size()
                                          : line.find_first_not_of(" \t", first + 1));
                while (!pending.empty() && (pending.back() == '\r' || pending.back() == ' '))
                    pending.pop_back();
                continue;
            }
        }
        const auto hash = line.find('#');
        if (hash != std::string::npos)
            line.erase(hash);
        std::istringstream ls(line);
        std::string first;
        if (!(ls >> first))
            continue;
        if (first.rfind("behavior_name=", 0) == 0)
        {
            if (first != "behavior_name=goto_list")
                fail("expected behavior_name=goto_list, got " + first);
            sawBehavior = true;
            continue;
        }
        static const std::map<std::string, Block> markers = {{"<start:b_arg>", Block::Args},
                                                             {"<end:b_arg>", Block::None},
                                                             {"<start:waypoints>", Block::Waypoints},
                                                             {"<end:waypoints>", Block::Done}};
        if (const auto marker = markers.find(first); marker != markers.end())
        {
            block = marker->second;
            continue;
        }
        if (block == Block::Args)
        {
            std::string name;
            double number = 0.0;
            if (first != "b_arg:" || !(ls >> name >> number) || !std::isfinite(number))
                fail("expected 'b_arg: name(unit) value'");
            const long value = std::lround(number);
            const std::string key = name.substr(0, name.find('('));
            // the whole-number arguments the list keeps (the others: num_waypoints, list_when_wpt_dist)
            static const std::map<std::string, int GotoList::*> whole = {{"num_legs_to_run", &GotoList::numLegsToRun},
                                                                         {"start_when", &GotoList::startWhen},
                                                                         {"list_stop_when", &GotoList::listStopWhen},
                                                                         {"initial_wpt", &GotoList::initialWpt}};
            if (const auto it = whole.find(key); it != whole.end())
                list.*(it->second) = static_cast<int>(value);
            else if (key == "num_waypoints")
                declared = value;
            else if (key == "list_when_wpt_dist")
                list.listWhenWptDist = number;
        }
        else if (block == Block::Waypoints)
        {
            std::string lat;
            if (!(ls >> lat))
                fail("expected 'longitude latitude' in [-]DDDMM.MMMM");
            try
            {
                list.waypoints.push_back({parseDegMin(first), parseDegMin(lat)});
                if (!pending.empty())
                {
                    list.notes.resize(list.waypoints.size());
                    list.notes.back() = pending;
                }
                pending.clear();
            }
            catch (const Error &e)
            {
                fail(e.what());
            }
        }
        else
            fail("unexpected text '" + first + "' outside the b_arg and waypoints blocks");
    }
    if (!sawBehavior)
        throw Error(source + ": no behavior_name=goto_list line");
    if (block != Block::Done)
        throw Error(source + ": missing <end:waypoints>");
    if (declared != static_cast<long>(list.waypoints.size()))
        throw Error(source + ": num_waypoints is " + std::to_string(declared) + " but " +
                    std::to_string(list.waypoints.size()) + " waypoints are listed");
    return list;
}

GotoList readGotoFile(const std::string &path)
{
    std::ifstream in(path);
    if (!in)
        throw Error("cannot read goto list file '" + path + "'");
    std::ostringstream s;
    s << in.rdbuf();
    GotoList list = parseGotoList(s.str(), path);
    const auto slash = path.find_last_of('/');
    const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    int nn;
    char tail[8] = {0};
    if (std::sscanf(base.c_str(), "goto_l%2d.%2s", &nn, tail) == 2 && std::string(tail) == "ma")
        list.number = nn;
    return list;
}
} // namespace ompl_glider
