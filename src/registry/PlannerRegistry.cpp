#include "ompl_glider/registry/PlannerRegistry.h"

#include <algorithm>
#include <cctype>

#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/LBTRRT.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTsharp.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/geometric/planners/sst/SST.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/planners/IsochronePlanner.h"
#include "ompl_glider/planners/Wavefront.h"
#include "ompl_glider/planners/ZAStarTVE.h"
#include "ompl_glider/reachability/LevelSetPlanner.h"
#include "ompl_glider/stints/StintPlanner.h"

namespace ompl_glider
{
namespace
{
std::string lowerName(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

PlannerEntry lattice(const std::string &name, std::vector<std::string> aliases, const std::string &what)
{
    PlannerEntry e;
    e.name = name;
    e.aliases = std::move(aliases);
    e.description = what;
    e.family = PlannerFamily::Lattice;
    e.make = [name](const ompl::base::SpaceInformationPtr &si, const std::shared_ptr<const GliderContext> &ctx) {
        return std::make_shared<ZAStarTVE>(si, ctx, name);
    };
    return e;
}

PlannerEntry wavefront()
{
    PlannerEntry e;
    e.name = "Wavefront";
    e.aliases = {"wavefront"};
    e.description = "earliest valid arrival over (vertex, time interval) nodes with holding ([ThompsonICRA])";
    e.family = PlannerFamily::Lattice;
    e.make = [](const ompl::base::SpaceInformationPtr &si, const std::shared_ptr<const GliderContext> &ctx) {
        return std::make_shared<Wavefront>(si, ctx);
    };
    return e;
}

template <class P>
PlannerEntry sampling(const std::string &name, std::vector<std::string> aliases, const std::string &what)
{
    PlannerEntry e;
    e.name = name;
    e.aliases = std::move(aliases);
    e.description = what;
    e.make = [](const ompl::base::SpaceInformationPtr &si, const std::shared_ptr<const GliderContext> &) {
        return std::make_shared<P>(si);
    };
    return e;
}
PlannerEntry levelSet()
{
    PlannerEntry e;
    e.name = "LevelSet";
    e.aliases = {"level_set", "levelset"};
    e.description = "level-set reachability front, the continuous optimum (parameter resolution)";
    e.family = PlannerFamily::LevelSet;
    e.make = [](const ompl::base::SpaceInformationPtr &si, const std::shared_ptr<const GliderContext> &ctx) {
        return std::make_shared<LevelSetPlanner>(si, ctx);
    };
    return e;
}
PlannerEntry isochrone()
{
    PlannerEntry e;
    e.name = "Isochrone";
    e.aliases = {};
    e.description =
        "held headings for strong currents: isochrone fronts on a heading lattice, then shooting refinement";
    e.family = PlannerFamily::Headings;
    e.make = [](const ompl::base::SpaceInformationPtr &si, const std::shared_ptr<const GliderContext> &ctx) {
        return std::make_shared<IsochronePlanner>(si, ctx);
    };
    return e;
}
PlannerEntry stint(StintMethod method, std::vector<std::string> aliases, const std::string &what)
{
    PlannerEntry e;
    e.name = stintMethodName(method);
    e.aliases = std::move(aliases);
    e.description = what;
    e.family = PlannerFamily::Stints;
    e.make = [method](const ompl::base::SpaceInformationPtr &si, const std::shared_ptr<const GliderContext> &ctx) {
        return std::make_shared<StintPlanner>(si, ctx, method);
    };
    return e;
}
} // namespace

namespace
{
/// The registry: the built-in planners, then those of registerPlanner(); a deque, so that an entry never moves.
std::deque<PlannerEntry> &entries()
{
    namespace og = ompl::geometric;
    static std::deque<PlannerEntry> entries = {
        lattice("TVE", {"tve"}, "time-dependent Dijkstra on the lattice"),
        lattice("A*TVE", {"astartve", "AStarTVE"}, "TVE with the admissible A* heuristic"),
        lattice("ZTVE", {"ztve"}, "TVE with Zermelo pruning"),
        lattice("ZA*TVE", {"zastartve", "ZAStarTVE"}, "TVE with A* heuristic and certified Zermelo pruning (default)"),
        levelSet(),
        isochrone(),
        wavefront(),
        sampling<og::RRTstar>("RRTstar", {"RRT*"}, "OMPL RRT*"),
        sampling<og::InformedRRTstar>("InformedRRTstar", {"InformedRRT*"}, "OMPL Informed RRT*"),
        sampling<og::PRM>("PRM", {}, "OMPL PRM"),
        sampling<og::PRMstar>("PRMstar", {"PRM*"}, "OMPL PRM*"),
        sampling<og::RRT>("RRT", {}, "OMPL RRT"),
        sampling<og::RRTConnect>("RRTConnect", {}, "OMPL RRT-Connect"),
        sampling<og::RRTsharp>("RRT#", {"RRTsharp"}, "OMPL RRT#"),
        sampling<og::LBTRRT>("LBTRRT", {}, "OMPL lower-bound tree RRT"),
        sampling<og::BITstar>("BITstar", {"BIT*"}, "OMPL BIT*"),
        sampling<og::SST>("SST", {}, "OMPL stable sparse RRT"),
        stint(StintMethod::InitOptim, {"Init-Optim", "initoptim"},
              "stints: bearings optimised from CTS-A*'s (needs a stints section)"),
        stint(StintMethod::Optim, {"Optim"}, "stints: bearings optimised from the direct bearings"),
        stint(StintMethod::CtsAStar, {"CTS-A*", "ctsastar"}, "stints: A* over a bearing rose per stint"),
        stint(StintMethod::Direct, {"direct_to_goal"}, "stints: the bearing to the goal at every surfacing"),
    };
    return entries;
}
} // namespace

const std::deque<PlannerEntry> &plannerRegistry()
{
    return entries();
}

void registerPlanner(PlannerEntry entry)
{
    if (entry.name.empty() || !entry.make)
        throw Error("registerPlanner: a planner needs a name and a make function");
    for (const std::string &name : [&entry] {
             std::vector<std::string> all{entry.name};
             all.insert(all.end(), entry.aliases.begin(), entry.aliases.end());
             return all;
         }())
        if (const PlannerEntry *taken = findPlanner(name))
            throw Error("registerPlanner: the name '" + name + "' is taken by planner " + taken->name);
    entries().push_back(std::move(entry));
}

const PlannerEntry *findPlanner(const std::string &name)
{
    const std::string key = lowerName(name);
    for (const PlannerEntry &e : plannerRegistry())
    {
        if (lowerName(e.name) == key)
            return &e;
        for (const std::string &a : e.aliases)
            if (lowerName(a) == key)
                return &e;
    }
    return nullptr;
}

const PlannerEntry &plannerEntry(const std::string &name)
{
    if (const PlannerEntry *e = findPlanner(name))
        return *e;
    throw Error("unknown planner '" + name + "' (expected one of " + plannerNameList() + ")");
}

std::string plannerNameList(const std::string &separator)
{
    std::string out;
    for (const PlannerEntry &e : plannerRegistry())
        out += (out.empty() ? "" : separator) + e.name;
    return out;
}

std::string plannerFamilyName(PlannerFamily family)
{
    switch (family)
    {
    case PlannerFamily::Lattice:
        return "Lattice";
    case PlannerFamily::LevelSet:
        return "LevelSet";
    case PlannerFamily::Headings:
        return "Headings";
    case PlannerFamily::Sampling:
        return "Sampling";
    case PlannerFamily::Stints:
        return "Stints";
    case PlannerFamily::Other:
        break;
    }
    return "Other";
}

const PlannerEntry *findPlannerOfFamily(PlannerFamily family)
{
    for (const PlannerEntry &e : plannerRegistry())
        if (e.family == family)
            return &e;
    return nullptr;
}

const PlannerEntry &plannerOfFamily(PlannerFamily family)
{
    if (const PlannerEntry *e = findPlannerOfFamily(family))
        return *e;
    throw Error("no registered planner of family " + plannerFamilyName(family));
}
} // namespace ompl_glider
