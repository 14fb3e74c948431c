// The plan's status is an enum: OMPL's nine statuses with OMPL's own texts (asked of OMPL, not copied), and the
// pipeline's two ("No path", "Stopped"); every text names one status, and a fleet row carries it across processes.
#include <gtest/gtest.h>

#include <sstream>

#include <ompl/base/PlannerStatus.h>

#include "ompl_glider/mission/PlanStatus.h"

using namespace ompl_glider;

TEST(PlanStatus, OmplStatusesKeepOmplsTextsAndTheTextsNameOneStatusEach)
{
    for (int i = 0; i < ompl::base::PlannerStatus::TYPE_COUNT; ++i)
    {
        const auto omplStatus = static_cast<ompl::base::PlannerStatus::StatusType>(i);
        const PlanStatus s = planStatusOfOmpl(omplStatus);
        EXPECT_EQ(static_cast<int>(s), i);
        if (s != PlanStatus::Abort) // OMPL 1.5 writes ABORT "Unknown status", like UNKNOWN: ours is "Abort"
        {
            EXPECT_EQ(statusText(s), ompl::base::PlannerStatus(omplStatus).asString());
        }
        EXPECT_EQ(planStatusNamed(statusText(s)), s) << statusText(s);
    }
    EXPECT_EQ(planStatusOfOmpl(ompl::base::PlannerStatus::EXACT_SOLUTION), PlanStatus::ExactSolution);
    EXPECT_EQ(planStatusOfOmpl(ompl::base::PlannerStatus::TYPE_COUNT), PlanStatus::Unknown);
    EXPECT_EQ(planStatusOfOmpl(-1), PlanStatus::Unknown);
    EXPECT_EQ(statusText(PlanStatus::Abort), "Abort");
    EXPECT_EQ(statusText(PlanStatus::NoPath), "No path");
    EXPECT_EQ(statusText(PlanStatus::Stopped), "Stopped");
    EXPECT_EQ(planStatusNamed("No path"), PlanStatus::NoPath);
    EXPECT_EQ(planStatusNamed("Stopped"), PlanStatus::Stopped);
    EXPECT_FALSE(planStatusNamed("no path"));
    EXPECT_FALSE(planStatusNamed(""));
    std::ostringstream out;
    out << PlanStatus::InvalidGoal;
    EXPECT_EQ(out.str(), "Invalid goal");
}
