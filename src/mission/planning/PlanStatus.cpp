#include "ompl_glider/mission/PlanStatus.h"

#include <ompl/base/PlannerStatus.h>

namespace ompl_glider
{
namespace
{
// OMPL's enum and ours share the first nine values (PlanStatus.h)
static_assert(static_cast<int>(PlanStatus::ExactSolution) == ompl::base::PlannerStatus::EXACT_SOLUTION);
static_assert(static_cast<int>(PlanStatus::Abort) == ompl::base::PlannerStatus::ABORT);
static_assert(static_cast<int>(PlanStatus::NoPath) == ompl::base::PlannerStatus::TYPE_COUNT);
constexpr int kLast = static_cast<int>(PlanStatus::Stopped);
} // namespace

std::string statusText(PlanStatus status)
{
    switch (status)
    {
    case PlanStatus::NoPath:
        return "No path";
    case PlanStatus::Stopped:
        return "Stopped";
    case PlanStatus::Abort:
        return "Abort"; // OMPL 1.5's asString() says "Unknown status" for ABORT, as for UNKNOWN
    default:
        return ompl::base::PlannerStatus(static_cast<ompl::base::PlannerStatus::StatusType>(status)).asString();
    }
}

std::optional<PlanStatus> planStatusNamed(std::string_view text)
{
    for (int i = 0; i <= kLast; ++i)
        if (text == statusText(static_cast<PlanStatus>(i)))
            return static_cast<PlanStatus>(i);
    return std::nullopt;
}

PlanStatus planStatusOfOmpl(int omplStatus)
{
    return omplStatus >= 0 && omplStatus < ompl::base::PlannerStatus::TYPE_COUNT ? static_cast<PlanStatus>(omplStatus)
                                                                                 : PlanStatus::Unknown;
}

std::string BadInput::field() const
{
    switch (input)
    {
    case Input::None:
        return "";
    case Input::Start:
        return "start";
    case Input::Goal:
        return "goal";
    case Input::ViaPoint:
        return "waypoints[" + std::to_string(via) + "]";
    case Input::DepartureTime:
        return "departure.time";
    }
    return "";
}
} // namespace ompl_glider
