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
}  // namespace

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

const PipelinePlanner &pipelineView(const ompl::base::Planner &planner)
{
    static const DefaultAnswers none;
    const auto *own = dynamic_cast<const PipelinePlanner *>(&planner);
    return own ? *own : none;
}

PipelinePlanner &pipelineView(ompl::base::Planner &planner)
{
    thread_local DefaultAnswers none;  // stateless: prepare() does nothing
    auto *own = dynamic_cast<PipelinePlanner *>(&planner);
    return own ? *own : none;
}
}  // namespace ompl_glider
