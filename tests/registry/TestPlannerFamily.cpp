// The planner the pipeline asks for by family (plannerOfFamily(): the global check's level set, the heading
// fallback's heading planner and level set) is the first entry of the family in the registry's order: the built-in
// one where the family has one, so that a planner registered into such a family is found by name only and never
// takes the built-in one's place; in a family without a member, the first one registered.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include <ompl/base/Planner.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/registry/PlannerRegistry.h"

using namespace ompl_glider;

namespace
{
/// An entry that is never made: the lookups read the entries only.
PlannerEntry strangerOf(PlannerFamily family, const std::string &name)
{
    PlannerEntry e;
    e.name = name;
    e.description = "a planner registered by a test into a family";
    e.family = family;
    e.make = [](const ompl::base::SpaceInformationPtr &, const std::shared_ptr<const GliderContext> &) {
        return ompl::base::PlannerPtr();
    };
    return e;
}

void registerOnce(PlannerFamily family, const std::string &name)
{
    if (!findPlanner(name))
        registerPlanner(strangerOf(family, name));
}
} // namespace

TEST(PlannerFamily, EachBuiltInFamilyAnswersItsFirstEntry)
{
    EXPECT_EQ(plannerOfFamily(PlannerFamily::LevelSet).name, "LevelSet");
    EXPECT_EQ(plannerOfFamily(PlannerFamily::Headings).name, "Isochrone");
    EXPECT_EQ(plannerOfFamily(PlannerFamily::Lattice).name, "TVE"); // before A*TVE, ..., Wavefront
    EXPECT_EQ(plannerOfFamily(PlannerFamily::Sampling).name, "RRTstar");
    for (const PlannerFamily f : {PlannerFamily::Lattice, PlannerFamily::LevelSet, PlannerFamily::Headings,
                                  PlannerFamily::Sampling, PlannerFamily::Stints})
    {
        const PlannerEntry *e = findPlannerOfFamily(f);
        ASSERT_NE(e, nullptr) << plannerFamilyName(f);
        EXPECT_EQ(e, &plannerOfFamily(f));
        EXPECT_EQ(e->family, f);
        // the entry itself, the one findPlanner() gives for its name (the pipeline plans it by that name)
        EXPECT_EQ(e, findPlanner(e->name));
    }
}

TEST(PlannerFamily, AStrangerInAFamilyWithABuiltInOneIsFoundByNameOnly)
{
    const PlannerEntry *levelSet = &plannerOfFamily(PlannerFamily::LevelSet);
    const PlannerEntry *headings = &plannerOfFamily(PlannerFamily::Headings);
    registerOnce(PlannerFamily::LevelSet, "StrangerFront");
    registerOnce(PlannerFamily::Headings, "StrangerHeadings");
    ASSERT_NE(findPlanner("StrangerFront"), nullptr);
    EXPECT_EQ(findPlanner("strangerfront")->family, PlannerFamily::LevelSet);
    EXPECT_EQ(findPlanner("StrangerHeadings")->family, PlannerFamily::Headings);
    // still the built-in ones, the same entries (a deque: registering moves none)
    EXPECT_EQ(&plannerOfFamily(PlannerFamily::LevelSet), levelSet);
    EXPECT_EQ(plannerOfFamily(PlannerFamily::LevelSet).name, "LevelSet");
    EXPECT_EQ(findPlannerOfFamily(PlannerFamily::Headings), headings);
    EXPECT_EQ(plannerOfFamily(PlannerFamily::Headings).name, "Isochrone");
}

TEST(PlannerFamily, AFamilyWithoutAMemberTakesTheFirstRegistered)
{
    // no built-in planner is of family Other; another test of this executable may have registered one before
    const PlannerEntry *before = findPlannerOfFamily(PlannerFamily::Other);
    if (!before)
    {
        try
        {
            plannerOfFamily(PlannerFamily::Other);
            ADD_FAILURE() << "a family without a member must be refused";
        }
        catch (const Error &e)
        {
            EXPECT_STREQ(e.what(), "no registered planner of family Other");
        }
    }
    registerOnce(PlannerFamily::Other, "FirstStranger");
    registerOnce(PlannerFamily::Other, "SecondStranger");
    const PlannerEntry *first = before ? before : findPlanner("FirstStranger");
    EXPECT_EQ(findPlannerOfFamily(PlannerFamily::Other), first);
    EXPECT_EQ(&plannerOfFamily(PlannerFamily::Other), first);
    EXPECT_NE(plannerOfFamily(PlannerFamily::Other).name, "SecondStranger");
    EXPECT_EQ(plannerFamilyName(PlannerFamily::Other), "Other");
    EXPECT_EQ(plannerFamilyName(PlannerFamily::LevelSet), "LevelSet");
}
