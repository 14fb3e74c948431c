// Map data of the campaign problems for the report figures: one ZA*TVE path and one RRT* path per problem
// (same seed and budget as the campaign), the forbidden regions, and a few current-field samples. Both planners come
// from the planner registry (registry/PlannerRegistry.h) as in the campaign; ZA*TVE returns its smoothed and refined
// path (its "smooth" and "refine" params are on by default).
//
// Usage: glider_campaign_paths [--time SECONDS] [--grid G] [--seed S] OUTDIR
// Writes OUTDIR/maps.json: {problem: {regions: [...], paths: {planner: [[x, y, t], ...]}, ...}}.
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "ompl_glider/ompl/PathResimulation.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/registry/PlannerRegistry.h"

#include "CampaignProblems.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;
using namespace ompl_glider;

namespace
{
std::string ring(const std::vector<Point2> &r, double dx = 0, double dy = 0)
{
    std::ostringstream os;
    os << "[";
    for (std::size_t i = 0; i < r.size(); ++i)
        os << (i ? "," : "") << "[" << r[i].x + dx << "," << r[i].y + dy << "]";
    os << "]";
    return os.str();
}

std::string pathJson(const og::PathGeometric &p)
{
    std::ostringstream os;
    os << "[";
    for (std::size_t i = 0; i < p.getStateCount(); ++i)
    {
        const auto *s = p.getState(i)->as<TimeSE2StateSpace::StateType>();
        os << (i ? "," : "") << "[" << s->getX() << "," << s->getY() << "," << s->getTime() << "]";
    }
    os << "]";
    return os.str();
}
} // namespace

int main(int argc, char **argv)
{
    double budget = 1.5, grid = 0.4;
    std::uint32_t seed = 20240601;
    std::string outdir;
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        if (a == "--time" && i + 1 < argc)
            budget = std::stod(argv[++i]);
        else if (a == "--grid" && i + 1 < argc)
            grid = std::stod(argv[++i]);
        else if (a == "--seed" && i + 1 < argc)
            seed = static_cast<std::uint32_t>(std::stoul(argv[++i]));
        else
            outdir = a;
    }
    if (outdir.empty())
    {
        std::cerr << "usage: glider_campaign_paths [--time SECONDS] [--grid G] [--seed S] OUTDIR\n";
        return 2;
    }
    ompl::RNG::setSeed(seed);
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const auto field = std::make_shared<MeanderingJet>();
    std::ofstream js(outdir + "/maps.json");
    js << std::setprecision(8) << "{";
    bool firstProblem = true;
    for (const CampaignProblem &p : makeCampaignProblems(field))
    {
        std::shared_ptr<GliderContext> ctx;
        og::SimpleSetupPtr ss = makeSimpleSetup(p.problem, &ctx);
        js << (firstProblem ? "" : ",") << "\"" << p.name << "\":{";
        firstProblem = false;
        js << "\"start\":[" << p.problem.start.x << "," << p.problem.start.y << "],\"goal\":[" << p.problem.goal.x
           << "," << p.problem.goal.y << "],\"regions\":[";
        bool firstRegion = true;
        if (p.environment)
            for (const auto &r : p.environment->regions())
            {
                js << (firstRegion ? "" : ",") << "{\"name\":\"" << r->name() << "\",\"kind\":\"" << r->kind() << "\"";
                firstRegion = false;
                if (auto s = std::dynamic_pointer_cast<const StaticRegion>(r))
                    js << ",\"outer\":" << ring(s->polygon().outer());
                else if (auto w = std::dynamic_pointer_cast<const TimeWindowedZone>(r))
                {
                    js << ",\"outer\":" << ring(w->polygon().outer()) << ",\"windows\":[";
                    for (std::size_t k = 0; k < w->windows().size(); ++k)
                        js << (k ? "," : "") << "[" << w->windows()[k].lo << "," << w->windows()[k].hi << "]";
                    js << "]";
                }
                else if (auto ice = std::dynamic_pointer_cast<const IceZone>(r))
                {
                    js << ",\"outer\":" << ring(ice->shape().outer()) << ",\"limit\":" << ice->maxSubmergedTime()
                       << ",\"drift\":[";
                    for (int k = 0; k <= 8; ++k)
                    {
                        const Point2 d = ice->displacement(2.5 * k);
                        js << (k ? "," : "") << "[" << 2.5 * k << "," << d.x << "," << d.y << "]";
                    }
                    js << "]";
                }
                js << "}";
            }
        js << "],\"paths\":{";
        bool firstPath = true;
        for (const std::string name : {"ZA*TVE", "RRTstar"})
        {
            ss->clear();
            const PlannerEntry &entry = plannerEntry(name);
            const ob::PlannerPtr planner = entry.make(ss->getSpaceInformation(), ctx);
            std::ostringstream gridText;
            gridText << std::setprecision(17) << grid;
            if (entry.lattice() && !planner->params().setParam("grid_size", gridText.str()))
            {
                std::cerr << "glider_campaign_paths: " << name << " refuses grid_size " << grid << "\n";
                return 2;
            }
            ss->setPlanner(planner);
            const ob::PlannerStatus st = ss->solve(budget);
            std::cout << p.name << " " << name << ": " << st.asString();
            if (ss->haveExactSolutionPath())
            {
                const PathResimulation r = resimulatePath(*ctx, ss->getSolutionPath(), p.problem.t0);
                std::cout << ", re-simulated travel time " << r.travelTime << (r.valid ? " (valid)" : " (INVALID: ")
                          << (r.valid ? "" : r.reason + ")") << ", " << ss->getSolutionPath().getStateCount()
                          << " waypoints";
                js << (firstPath ? "" : ",") << "\"" << name << "\":{\"travel_time\":";
                if (std::isfinite(r.travelTime))
                    js << r.travelTime;
                else
                    js << "null";
                js << ",\"valid\":" << (r.valid ? "true" : "false") << ",\"states\":" << pathJson(ss->getSolutionPath())
                   << "}";
                firstPath = false;
            }
            std::cout << std::endl;
        }
        js << "}}";
    }
    js << "}\n";
    return 0;
}
