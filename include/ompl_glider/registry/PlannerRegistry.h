#pragma once
/// @file PlannerRegistry.h
/// @brief The planners known by name: one list used by the command line, mission files, Python, the Benchmark
/// campaign and the documentation. Adding a planner is its class (an ompl::base::Planner that implements
/// PipelinePlanner, ompl/PipelinePlanner.h, for what the pipeline asks of it), one entry here or a registerPlanner()
/// call, and its tests: nothing in mission/ names a planner (see docs/ARCHITECTURE.md).

#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <ompl/base/Planner.h>

#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief The kinds of planner, which decide what the pipeline gives them and how long they may run.
enum class PlannerFamily
{
    Lattice,  ///< a lattice search (the ZAStarTVE configurations, Wavefront): grid_size / sectors apply; runs to its
              ///< own end (no default time limit)
    LevelSet, ///< the level-set front: runs to its own end, like the lattice
    Headings, ///< a heading planner (IsochronePlanner): routes of held headings, for currents stronger than the
              ///< vehicle; runs to its own end
    Sampling, ///< an OMPL sampling planner: uses all the time it is given (10 s by default)
    Stints,   ///< a StintPlanner method: flies constant-bearing stints (a mission's `stints` section applies;
              ///< [IsernObstacles]); its own caps bound the work
    Other     ///< any other planner that runs to its own end (no default time limit); what it needs of the
              ///< mission it takes in PipelinePlanner::prepare()
};

/// @brief One planner that can be asked for by name.
struct PlannerEntry
{
    std::string name;                 ///< canonical name, also the OMPL planner name (e.g. "ZA*TVE", "RRTstar")
    std::vector<std::string> aliases; ///< other accepted spellings (matched without regard to case)
    std::string description;          ///< one line for --help and the docs
    PlannerFamily family{PlannerFamily::Sampling}; ///< what kind of planner it is
    /// @brief True for a lattice planner (grid_size and sectors apply).
    bool lattice() const { return family == PlannerFamily::Lattice; }
    /// @brief True for a stint planner (the mission's `stints` section applies).
    bool stints() const { return family == PlannerFamily::Stints; }
    /// @brief True when the planner runs to its own end, so no default time limit applies (all but sampling).
    bool runsToItsEnd() const { return family != PlannerFamily::Sampling; }
    /// Makes the planner on the problem's space information; ctx is the problem's context.
    std::function<ompl::base::PlannerPtr(const ompl::base::SpaceInformationPtr &,
                                         const std::shared_ptr<const GliderContext> &)>
        make;
};

/// @brief Every registered planner, in the order of the documentation (plannerNameList() gives the names): the
/// lattice searches (the ZAStarTVE configurations, [EichhornRAS] Sec. 2.2), the level set ([LollaLevelSet]), held
/// headings, the Wavefront ([ThompsonICRA] Sec. III), OMPL's geometric planners on the time-augmented space, then
/// the constant-bearing stint planners ([IsernObstacles]); then those registerPlanner() added.
const std::deque<PlannerEntry> &plannerRegistry();

/// @brief Adds @p entry to the registry, so that mission files, the command line, Python and the Benchmark campaign
/// can ask for it by name like a built-in planner (a planner of an application, or one registered by a test).
/// Call it before planning starts, not while other threads plan; pointers from findPlanner() stay valid.
/// @throws Error when the entry has no name or no make function, or its name or an alias is already taken.
void registerPlanner(PlannerEntry entry);

/// @brief The entry whose name or alias equals @p name (case-insensitive); null when there is none.
const PlannerEntry *findPlanner(const std::string &name);

/// @brief As findPlanner(). @throws Error "unknown planner 'X' (expected one of ...)" when there is none.
const PlannerEntry &plannerEntry(const std::string &name);

/// @brief The canonical names joined by @p separator (for messages and --help).
std::string plannerNameList(const std::string &separator = ", ");

/// @brief The family's name as the enumerator spells it ("Lattice", "LevelSet", "Headings", ...), for messages.
std::string plannerFamilyName(PlannerFamily family);

/// @brief The planner the pipeline asks for by family, not by name (the global check's level set, the heading
/// fallback's heading planner and level set): the first entry of @p family in the registry's order, that is the
/// built-in one where the family has one (plannerRegistry()'s order), else the first registered by registerPlanner();
/// null when the family has none. A planner registered into a family that already has a member is asked for by name
/// only, never in the family's place: a registration cannot change what a mission that names no planner gets.
const PlannerEntry *findPlannerOfFamily(PlannerFamily family);

/// @brief As findPlannerOfFamily(). @throws Error "no registered planner of family X" when the family has none.
const PlannerEntry &plannerOfFamily(PlannerFamily family);
} // namespace ompl_glider
