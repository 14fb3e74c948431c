/// @file PlannerSetup.cpp
/// @brief The planner of the mission and the problem of one departure: makePlanner() (the one place where the
/// pipeline's grid size, sectors and stint settings reach a planner: OMPL's ParamSet, then PipelinePlanner::prepare(),
/// which refuses the work a planner cannot do), the mission's planner parameters, the checked problem of a departure,
/// and stintSettings().

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>

#include "../../io/NumberText.h"
#include "PlanningInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/ResourceLimits.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#include "ompl_glider/ompl/PipelinePlanner.h"

namespace ompl_glider
{
namespace planning_detail
{
namespace
{
/// Pipeline settings that a mission gives as planner fields, not as planner parameters.
bool pipelineParameter(const std::string &name)
{
    return name == "refiner_max_evaluations";
}

/// The settings of the pipeline that OMPL's lattice planners declare as parameters too, by the name of the planner
/// field that sets them.
const std::map<std::string, std::string> kPipelineFields = {
    {"grid_size", "grid_size"}, {"sectors", "sectors"}, {"smooth", "smoothing"}, {"refine", "refinement"}};

/// The declared range "lo:step:hi" of a numeric parameter as [lo, hi]; false for other forms ("0,1", empty).
bool declaredRange(const std::string &range, double &lo, double &hi)
{
    const std::size_t a = range.find(':'), b = range.rfind(':');
    if (a == std::string::npos || b == a)
        return false;
    char *endLo = nullptr, *endHi = nullptr;
    const std::string loText = range.substr(0, a), hiText = range.substr(b + 1);
    lo = std::strtod(loText.c_str(), &endLo);
    hi = std::strtod(hiText.c_str(), &endHi);
    return endLo != loText.c_str() && *endLo == '\0' && endHi != hiText.c_str() && *endHi == '\0';
}

/// Sets the mission's planner parameters through OMPL's ParamSet (the names of declareParam); a number outside the
/// declared range (declareParam's "lo:step:hi") is refused, naming the range.
void applyParameters(const MissionSpec &m, ompl::base::Planner &planner)
{
    ompl::base::ParamSet &params = planner.params();
    for (const auto &[name, value] : m.planner.parameters)
    {
        if (const auto field = kPipelineFields.find(name); field != kPipelineFields.end())
            throw Error(parameterPlace(m, name) + ": set it as planner." + field->second +
                        ", which every planner of the pipeline honours");
        if (params.hasParam(name))
        {
            const std::string range = params[name].getRangeSuggestion();
            // OMPL reads any text other than "true"/"1" as false for a bool parameter (range "0,1")
            static const std::set<std::string> booleans = {"0", "1", "true", "false"};
            if (range == "0,1" && !booleans.count(value))
                throw Error(parameterPlace(m, name) + ": planner " + planner.getName() +
                            " expects true or false, got '" + value + "'");
            bool accepted = false;
            try
            {
                accepted = params.setParam(name, value);
            }
            catch (const std::exception &e) // a setter that refuses the value with its own reason
            {
                throw Error(parameterPlace(m, name) + ": " + e.what());
            }
            if (!accepted)
                throw Error(parameterPlace(m, name) + ": planner " + planner.getName() + " rejects the value '" +
                            value + "' (range " + range + ")");
            // OMPL converts leniently ("1e12" becomes 1 for an integer): read the value back and refuse a change.
            const std::string stored = params[name].getValue();
            char *endA = nullptr, *endB = nullptr;
            const double want = std::strtod(value.c_str(), &endA), got = std::strtod(stored.c_str(), &endB);
            if (endA != value.c_str() && *endA == '\0' && endB != stored.c_str() &&
                !(std::abs(want - got) <= 1e-9 * std::max(1.0, std::abs(want))))
                throw Error(parameterPlace(m, name) + ": planner " + planner.getName() + " rejects the value '" +
                            value + "' (it would be read as " + stored + "; range " + range + ")");
            // the setter's own checks first (their reasons are the more precise), then the declared range
            double lo = 0.0, hi = 0.0;
            if (!pipelineParameter(name) && declaredRange(range, lo, hi) && endA != value.c_str() && *endA == '\0' &&
                !(want >= lo && want <= hi))
                throw Error(parameterPlace(m, name) + ": planner " + planner.getName() + " accepts " + name + " in " +
                            text::number(lo) + " .. " + text::number(hi) + " (its declared range " + range +
                            "), got '" + value + "'");
        }
        else if (!pipelineParameter(name))
        {
            std::vector<std::string> names;
            params.getParamNames(names);
            std::string list;
            for (const std::string &n : names)
                if (!kPipelineFields.count(n))
                    list += (list.empty() ? "" : ", ") + n;
            throw Error(parameterPlace(m, name) + ": planner " + planner.getName() + " has no parameter '" + name +
                        "' (it has: " + (list.empty() ? std::string("none") : list) + ")");
        }
    }
}
} // namespace

std::string parameterPlace(const MissionSpec &m, const std::string &name)
{
    const auto it = m.planner.parameterMarks.find(name);
    const SourceMark mark = it != m.planner.parameterMarks.end() ? it->second : SourceMark{m.file, 0};
    return (mark.line > 0 ? mark.file + ":" + std::to_string(mark.line) : mark.file) + ": field 'planner.parameters." +
           name + "'";
}

RefinerParams refinerParams(const MissionSpec &m)
{
    RefinerParams rp;
    const auto it = m.planner.parameters.find("refiner_max_evaluations");
    if (it != m.planner.parameters.end())
    {
        char *end = nullptr;
        const double v = std::strtod(it->second.c_str(), &end);
        const bool inRange = v >= kMinRefinerEvaluations && v <= kMaxRefinerEvaluations;
        if (end == it->second.c_str() || *end != '\0' || !inRange || v != std::floor(v))
            throw Error(parameterPlace(m, it->first) + ": expected an integer in " +
                        text::number(kMinRefinerEvaluations) + ".." + text::number(kMaxRefinerEvaluations) + ", got '" +
                        it->second + "'");
        rp.maxEvaluations = static_cast<unsigned>(v);
    }
    return rp;
}

/// The configured planner of the mission on the setup's space information.
ompl::base::PlannerPtr makePlanner(const MissionProblem &problem, const ompl::base::SpaceInformationPtr &si,
                                   const std::shared_ptr<const GliderContext> &ctx, double grid, int sectors,
                                   double departure, const std::string &other, const std::string &gridField)
{
    const MissionSpec &m = problem.getSpec();
    const PlannerEntry &entry = plannerEntry(other.empty() ? m.planner.name : other);
    ompl::base::PlannerPtr planner = entry.make(si, ctx);
    // The lattice planners (LatticePlanner) declare grid_size and sectors, ZAStarTVE also smooth and refine: set by
    // name through OMPL's ParamSet. The pipeline smooths and refines every planner's path alike, so the planner's own
    // smoothing and refinement are off.
    const std::pair<const char *, std::string> settings[] = {
        {"grid_size", text::number(grid, 17)}, // 17 digits: the same double back
        {"sectors", std::to_string(sectors)},
        {"smooth", "0"},
        {"refine", "0"}};
    ompl::base::ParamSet &params = planner->params();
    for (const auto &[name, value] : settings)
        if (params.hasParam(name) && !params.setParam(name, value))
            throw Error(m.place(std::string("planner.") + name) + ": planner '" + entry.name + "' refused " + name +
                        " = " + value);
    if (other.empty())
        applyParameters(m, *planner);
    // what the planner itself needs to know and refuses (PipelinePlanner::prepare()), its messages naming the
    // mission's fields: planner.grid_size is the coarse search's field when the departure search runs one
    const std::optional<StintSettings> stints =
        m.stints.set ? std::optional<StintSettings>(stintSettings(problem, departure)) : std::nullopt;
    PipelineSetup setup;
    setup.departure = departure;
    setup.start = problem.getStart();
    setup.goal = problem.getGoal();
    setup.region = ctx->region;
    setup.stints = stints ? &*stints : nullptr;
    setup.place = [&m, &gridField, &problem](const std::string &field) {
        const std::string prefix = "planner.parameters.";
        if (field.rfind(prefix, 0) == 0)
            return parameterPlace(m, field.substr(prefix.size()));
        // a spacing nobody gave is not blamed on a setting: it is the automatic one, which a given one replaces
        if (field == "planner.grid_size" && gridField == "planner.grid_size" && problem.gridSizeAutomatic())
            return (m.file.empty() ? std::string() : m.file + ": ") +
                   "the automatic lattice spacing (chosen from the leg's length; give one: " +
                   m.term("planner.grid_size") + ")";
        return m.place(field == "planner.grid_size" ? gridField : field);
    };
    setup.given = [&m, other](const std::string &field) {
        const std::string prefix = "planner.parameters.";
        if (field.rfind(prefix, 0) == 0)
            return other.empty() && m.planner.parameters.count(field.substr(prefix.size())) > 0;
        return m.marks.count(field) > 0;
    };
    pipelineView(*planner).prepare(setup);
    return planner;
}

/// The problem of one departure, its departure time checked first so that the error names where it was given.
GliderProblem checkedProblem(const MissionProblem &problem, double departure, double speed)
{
    GliderProblem gp = problem.gliderProblem(departure, speed);
    if (const std::string why = departureProblem(gp); !why.empty())
        throw Error(problem.getSpec().place("departure.time") + ": " + why);
    return gp;
}

} // namespace planning_detail

StintSettings stintSettings(const MissionProblem &problem, double departure)
{
    const MissionSpec &m = problem.getSpec();
    StintSettings s = m.stints; // the section's settings, read at the vehicle's depth
    s.depth = m.vehicle.depth;
    const double end = problem.getField()->timeEnd();
    if (std::isfinite(end) && departure + s.missionDuration > end * (1.0 + 1e-12))
        throw Error(m.place("stints.mission_duration") +
                    ": the mission would end at t = " + text::number(departure + s.missionDuration) +
                    ", after the forecast (it ends at t = " + text::number(end) +
                    "): shorten it, depart earlier, or hold the last forecast time "
                    "(current.horizon: hold_last)");
    return s;
}
} // namespace ompl_glider
