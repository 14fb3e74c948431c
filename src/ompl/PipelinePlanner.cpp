/// @file PipelinePlanner.cpp
/// @brief pipelineView(): the pipeline's one way to a planner's answers.

#include "ompl_glider/ompl/PipelinePlanner.h"

namespace ompl_glider
{
namespace
{
/// The answers of a planner that gives none of its own (OMPL's planners): every default.
class DefaultAnswers final : public PipelinePlanner
{
};
} // namespace

std::string PipelineSetup::where(const std::string &field) const
{
    return place ? place(field) : "field '" + field + "'";
}

bool PipelineSetup::isGiven(const std::string &field) const
{
    return given && given(field);
}

std::string PipelineSetup::placeOfFirstGiven(std::initializer_list<const char *> fields,
                                             const std::string &fallback) const
{
    for (const char *f : fields)
        if (isGiven(f))
            return where(f);
    return where(fallback);
}

std::string causeName(NoPathCause cause)
{
    switch (cause)
    {
    case NoPathCause::None:
        return "";
    case NoPathCause::BadInput:
        return "bad_input";
    case NoPathCause::Stopped:
        return "stopped";
    case NoPathCause::TimeLimit:
        return "time_limit";
    case NoPathCause::Approximate:
        return "approximate";
    case NoPathCause::LatticeExhausted:
        return "lattice_exhausted";
    case NoPathCause::SearchEnded:
        return "search_ended";
    case NoPathCause::Unreachable:
        return "unreachable";
    case NoPathCause::WalledOff:
        return "walled_off";
    case NoPathCause::NotFlyable:
        return "not_flyable";
    case NoPathCause::NotRobust:
        return "not_robust";
    case NoPathCause::ArrivalWindow:
        return "arrival_window";
    case NoPathCause::NoDeparture:
        return "no_departure";
    case NoPathCause::Other:
        return "other";
    }
    return "other";
}

const PipelinePlanner &pipelineView(const ompl::base::Planner &planner)
{
    static const DefaultAnswers none;
    const auto *own = dynamic_cast<const PipelinePlanner *>(&planner);
    return own ? *own : none;
}

PipelinePlanner &pipelineView(ompl::base::Planner &planner)
{
    thread_local DefaultAnswers none; // stateless: prepare() does nothing
    auto *own = dynamic_cast<PipelinePlanner *>(&planner);
    return own ? *own : none;
}
} // namespace ompl_glider
