// Fuzz target: glider_plan's command line (apps/glider_plan/Flags.h). Bytes split at NUL or newline -> argv (after
// "glider_plan") -> the parser and its checks -> for the built-in mode the MissionSpec and the MissionProblem, and
// the --speeds list; no planning, nothing written. --mission is parsed but not loaded; --currents points at a file
// that does not exist. CLI11's parse errors, UsageError and ompl_glider::Error are the expected answers to bad
// arguments; any other exception, a crash, a sanitizer report or a hang is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "Flags.h"
#include "FuzzUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionProblem.h"

namespace
{
std::string gMissing; // a path in an empty directory
}

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
    gMissing = ompl_glider_fuzz::scratchDirectory("fuzz_cli") + "/missing.nc";
    ompl_glider_fuzz::quietOmpl();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    std::vector<std::string> args{"glider_plan"};
    std::string arg;
    for (std::size_t i = 0; i <= size; ++i)
        if (i == size || data[i] == '\0' || data[i] == '\n')
        {
            if (i < size || !arg.empty())
                args.push_back(arg);
            arg.clear();
        }
        else
            arg += static_cast<char>(data[i]);
    std::vector<const char *> argv;
    for (const std::string &a : args)
        argv.push_back(a.c_str());

    using namespace glider_plan;
    CLI::App app{"glider_plan (fuzzed)", "glider_plan"};
    Flags f;
    defineFlags(app, f);
    try
    {
        parseFlags(app, f, static_cast<int>(argv.size()), argv.data());
        if (f.speeds)
            (void)speedList(*f.speeds);
        if (!f.mission.empty())
            return 0; // a mission file: loading it is fuzz_mission's part
        if (!f.currents.empty())
        {
            f.currents = gMissing;
            (void)forecastMissionOf(f);
            return 0;
        }
        const ompl_glider::MissionProblem problem(builtInMission(f));
        (void)problem.getStart();
    }
    catch (const CLI::Error &)
    {
    }
    catch (const UsageError &)
    {
    }
    catch (const ompl_glider::Error &)
    {
    }
    return 0;
}
