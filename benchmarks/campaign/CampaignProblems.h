#pragma once
/// @file CampaignProblems.h
/// @brief The problems of the benchmark campaign. The "classic" set: four problems on the meandering jet of
/// [EichhornRAS] Sec. 6.1, region x in [0, 10], y in [-4, 4], V = 0.5, t0 = 0, from the south-west to the north-east
/// across the jet. The "strong" set: currents several times the glider's speed, where straight legs fail
/// and OMPL's control planners (heading controls, GliderControl.h) run beside the registry's planners.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/IceZone.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/TimeWindowedZone.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/ompl/GliderSetup.h"

namespace ompl_glider
{
/// @brief One campaign problem: the GliderProblem and its forbidden regions (null for open water).
struct CampaignProblem
{
    std::string name;                              ///< "open_water", "islands", "ice", "closure", "jet_v020", ...
    std::string description;                       ///< one line
    GliderProblem problem;                         ///< field, box, t0, horizon, start, goal, V
    std::shared_ptr<ForbiddenRegions> environment; ///< forbidden regions (also in problem.environment)
    std::string set{"classic"};                    ///< "classic" or "strong"
    /// Finest cell of the level-set reference (the campaign also solves at 2x and 4x this cell and extrapolates)
    double referenceCell{0.025};
    /// The optimum also by Zermelo shooting (ZermeloReference; open water of the classic set only)
    bool shooting{true};
    /// Registry planners to run; empty: the campaign's default list
    std::vector<std::string> planners;
    /// Run OMPL's control planners (oc::SST, oc::RRT, oc::KPIECE1) on the heading-control setup as well
    bool control{false};
};

/// @brief Registry planners of the strong-current problems: the lattice default, the level set and the heading
/// planner "Isochrone" (skipped with a note when the registry does not have it).
inline std::vector<std::string> strongCurrentPlanners()
{
    return {"ZA*TVE", "LevelSet", "Isochrone"};
}

/// @brief The strong-current problems:
///   - jet_v020, jet_v015: the built-in Gulf Stream mission (meandering jet, peak speed about 1, box [0, 10] x
///     [-4, 4], horizon 60) from (1, -3) to (8, 3) across the jet at V = 0.2 and 0.15, as `glider_plan --speed V`;
///   - gyre: the double gyre of the registry ("double_gyre", amplitude 0.5, length 1: two gyres on [0, 2] x [0, 1],
///     peak speed pi A / L = 1.571) at V = 0.26, the flow 6.04 times the speed, from (0.3, 0.3) in the western gyre to
///     (1.7, 0.7) in the eastern one, horizon 10.
inline std::vector<CampaignProblem> makeStrongCurrentProblems()
{
    std::vector<CampaignProblem> out;
    for (const auto &[name, V] : std::vector<std::pair<std::string, double>>{{"jet_v020", 0.2}, {"jet_v015", 0.15}})
    {
        CampaignProblem c;
        c.name = name;
        c.description = "meandering jet (Gulf Stream mission), start (1, -3), goal (8, 3), V = " + std::to_string(V);
        c.problem = gulfStreamProblem();
        c.problem.travel.speed = V;
        c.set = "strong";
        c.shooting = false;
        c.planners = strongCurrentPlanners();
        c.control = true;
        out.push_back(c);
    }
    {
        CampaignProblem c;
        c.name = "gyre";
        c.description = "double gyre A = 0.5, L = 1 (peak 1.571) at V = 0.26, from (0.3, 0.3) to (1.7, 0.7)";
        c.problem.field = makeAnalyticField("double_gyre", {{"amplitude", 0.5}, {"length", 1.0}});
        c.problem.travel.speed = 0.26;
        c.problem.xMin = 0.0;
        c.problem.xMax = 2.0;
        c.problem.yMin = 0.0;
        c.problem.yMax = 1.0;
        c.problem.t0 = 0.0;
        c.problem.horizon = 10.0;
        c.problem.start = {0.3, 0.3};
        c.problem.goal = {1.7, 0.7};
        c.problem.goalTolerance = 1e-3;
        c.set = "strong";
        c.referenceCell = 0.005;
        c.shooting = false;
        c.planners = strongCurrentPlanners();
        c.control = true;
        out.push_back(c);
    }
    return out;
}

/// @brief Start, goal and common settings of every campaign problem.
inline GliderProblem campaignBaseProblem(std::shared_ptr<const CurrentField> field)
{
    // The built-in Gulf Stream problem (region, V = 0.5, t0 = 0), with the campaign's own start, goal and horizon.
    GliderProblem p = gulfStreamProblem();
    p.field = std::move(field);
    p.horizon = 40.0;
    p.start.x = 0.6;
    p.start.y = -2.6;
    p.goal.x = 9.4;
    p.goal.y = 2.6;
    p.goalTolerance = 1e-3;
    return p;
}

/// @brief The four problems: open water; islands on the open-water route; ice zones drifting across it; and a
/// shipping-lane closure x in [4.6, 5.4], y in [-4, 2.2] during t in [0, 8] that the route must wait out or pass
/// around in the north.
inline std::vector<CampaignProblem> makeCampaignProblems(std::shared_ptr<const CurrentField> field)
{
    std::vector<CampaignProblem> out;
    {
        CampaignProblem c;
        c.name = "open_water";
        c.description = "meandering jet, no forbidden regions";
        c.problem = campaignBaseProblem(field);
        out.push_back(c);
    }
    {
        CampaignProblem c;
        c.name = "islands";
        c.description = "three islands (a 40-gon, a concave island, a ring-shaped atoll with a lagoon)";
        c.problem = campaignBaseProblem(field);
        c.environment = std::make_shared<ForbiddenRegions>();
        c.environment->add(
            std::make_shared<StaticRegion>("A", Polygon::regular(3.0, -1.6, 0.7, 40, 0.1, "A"), "island"));
        c.environment->add(std::make_shared<StaticRegion>(
            "B", Polygon({{5.2, -0.4}, {6.6, -0.2}, {6.8, 1.2}, {6.1, 0.5}, {5.4, 1.0}}, {}, "B"), "island"));
        std::vector<Point2> outer, lagoon;
        for (int i = 0; i < 24; ++i)
        {
            const double a = 2 * M_PI * i / 24;
            outer.push_back({7.6 + 0.8 * std::cos(a), 2.0 + 0.6 * std::sin(a)});
            lagoon.push_back({7.6 + 0.4 * std::cos(a), 2.0 + 0.3 * std::sin(a)});
        }
        c.environment->add(std::make_shared<StaticRegion>("C", Polygon(outer, {lagoon}, "C"), "island"));
        c.problem.environment = c.environment;
        out.push_back(c);
    }
    {
        CampaignProblem c;
        c.name = "ice";
        c.description = "two ice zones drifting across the route; at most 0.5 time units under ice";
        c.problem = campaignBaseProblem(field);
        c.environment = std::make_shared<ForbiddenRegions>();
        c.environment->add(
            std::make_shared<IceZone>("I1", Polygon::rectangle(1.0, -1.6, 3.4, 0.4, "I1"), 0.0, 0.12, 0.0, 0.5));
        c.environment->add(
            std::make_shared<IceZone>("I2", Polygon::rectangle(5.0, 1.0, 7.0, 3.5, "I2"), 0.0, 0.0, -0.1, 0.5));
        c.problem.environment = c.environment;
        out.push_back(c);
    }
    {
        CampaignProblem c;
        c.name = "closure";
        c.description = "shipping lane x in [4.6, 5.4], y <= 2.2 closed during t in [0, 8]";
        c.problem = campaignBaseProblem(field);
        c.environment = std::make_shared<ForbiddenRegions>();
        c.environment->add(std::make_shared<TimeWindowedZone>("lane", Polygon::rectangle(4.6, -4.0, 5.4, 2.2, "lane"),
                                                              std::vector<Interval>{{0.0, 8.0}}));
        c.problem.environment = c.environment;
        out.push_back(c);
    }
    return out;
}
} // namespace ompl_glider
