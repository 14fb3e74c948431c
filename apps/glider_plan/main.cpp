// glider_plan: time-optimal glider routes from the command line. Every mode (the built-in Gulf Stream mission, a
// forecast (NetCDF, OPeNDAP, Zarr, GRIB) with --currents, a mission file with --mission) builds a MissionSpec and runs
// the library's one pipeline (mission/Planning.h) and output layer (output/). Running, messages and exit codes live
// here; the flags, their checks and the MissionSpec of the built-in and --currents modes in Flags.cpp (shared with
// fuzz/fuzz_cli). Under mpirun (a build with OMPL_GLIDER_WITH_MPI) every rank runs the same pipeline; the many-plan
// modes spread their tasks over the ranks (TaskSpread.h) and rank 0 alone prints and writes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <system_error>

#include <sys/resource.h>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <ompl/util/Console.h>

#include "Flags.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/TaskSpread.h"
#include "ompl_glider/io/GliderObservations.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/Fleet.h"
#include "ompl_glider/mission/InputDigest.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/FleetFiles.h"
#include "ompl_glider/output/OutputWriter.h"
#include "ompl_glider/output/Report.h"
#if OMPL_GLIDER_WITH_MPI
#include "ompl_glider/mpi/MpiTaskSpreader.h"
#endif

namespace
{
using namespace ompl_glider;
using namespace glider_plan;

constexpr int kNoPath = 1;
constexpr int kBadInput = 2;

void printProgress(const std::string &line, bool done)
{
    if (taskRank() != 0)
        return;
    std::fprintf(stderr, "\r%s%s", line.c_str(), done ? "\n" : "   ");
    std::fflush(stderr);
}

/// A fleet (the mission's `fleet`): every glider planned by the one pipeline (runFleet()), its files rendered where it
/// was planned; rank 0 prints the table and writes all folders in one transaction. Returns the exit status.
int runFleetMode(const Flags &f, const MissionSpec &spec, RunOptions options)
{
    if (!f.start.empty() || !f.goal.empty())
        throw UsageError{"--start and --goal cannot be combined with a mission file's fleet: each glider gives its "
                         "own (fleet[i].start, fleet[i].goal)"};
    if (::isatty(STDERR_FILENO)) // a line per glider on a terminal; a log gets the table
        options.progress = printProgress;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<FleetGlider> gliders = runFleet(spec, options, renderOutputFiles);
    int status = 0;
    for (const FleetGlider &g : gliders)
        status = std::max(status, !g.row.badInput.empty() ? kBadInput : g.row.solved ? 0 : kNoPath);
    if (taskRank() != 0)
        return status;
    if (status == kBadInput)
    {
        for (const FleetGlider &g : gliders)
            if (!g.row.badInput.empty())
                std::cerr << "glider_plan: glider '" << g.row.name << "': " << g.row.badInput << ": " << g.row.reason
                          << "\n";
        return kBadInput; // bad input: nothing is written
    }
    printFleetTable(std::cout, spec, gliders);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::vector<std::string> written =
        writeOutputFiles(spec.outputs.directory, fleetOutputFiles(spec, gliders, wall));
    std::cout << "wrote " << written.size()
              << " files: " << (spec.outputs.directory.empty() ? "." : spec.outputs.directory)
              << "/summary.json, fleet.csv and a folder per glider\n";
    for (const FleetGlider &g : gliders)
        if (!g.row.solved)
            std::cerr << "glider_plan: glider '" << g.row.name << "' has no route: " << g.row.reason << "\n";
    return status;
}

/// --show-observations: the fixes and DAC the planner reads from @p source, as a table on stdout.
int showObservations(const std::string &source, const std::string &cache)
{
    const GliderObservations o = readGliderObservations(source, {cache});
    const auto num = [](const char *format, double x) {
        char buf[64];
        std::snprintf(buf, sizeof buf, format, x);
        return std::string(std::isnan(x) ? "nan" : buf);
    };
    const auto iso = [](double t) { return std::isfinite(t) ? formatIsoTime(std::floor(t)) : std::string("-"); };
    std::cout << "observations '" << o.source << "': " << observationsText(o) << "\n";
    std::cout << "\nfixes: " << o.fixes.size() << "\n     time_s  time_utc                   lon           lat\n";
    for (const GliderFix &x : o.fixes)
        std::cout << num("%11.1f", x.time) << "  " << iso(x.time) << "  " << num("%12.7f", x.at.lon) << "  "
                  << num("%12.7f", x.at.lat) << "\n";
    std::cout << "\ndac: " << o.dac.size()
              << "\n     time_s  time_utc                   lon           lat        u_m/s      v_m/s  segment_start  "
                 "segment_end  depth_min  depth_max\n";
    for (const DacRecord &d : o.dac)
        std::cout << num("%11.1f", d.time) << "  " << iso(d.time) << "  " << num("%12.7f", d.at.lon) << "  "
                  << num("%12.7f", d.at.lat) << "  " << num("%9.5f", d.u) << "  " << num("%9.5f", d.v) << "  "
                  << num("%13.1f", d.segmentStart) << "  " << num("%11.1f", d.segmentEnd) << "  "
                  << num("%9.3f", d.depthMin) << "  " << num("%9.3f", d.depthMax) << "\n";
    return 0;
}

/// Plans, reports and writes. Returns the exit status.
int run(const Flags &f)
{
    if (f.showObservations)
    {
        if (f.observations.empty())
            throw UsageError{"--show-observations needs --observations (the glider's files or URL)"};
        return showObservations(f.observations, f.observationsCache);
    }
    MissionSpec spec = !f.mission.empty()    ? missionFileOf(f)
                       : !f.currents.empty() ? forecastMissionOf(f)
                                             : builtInMission(f);
    if (f.showMission)
    {
        // what the flags made of the mission, as Python's Mission.fields() shows it for the same keywords
        for (const auto &[field, value] : overridableFields(spec))
            std::cout << field << " = " << value << "\n";
        return 0;
    }
    // the processes of a job agree on what they read before any plan (a node-local copy of another version)
    if (TaskSpreader *job = activeTaskSpreader())
        job->agree("the mission (its file and the files it reads)", inputDigest(spec));
    const bool write = !f.mission.empty() || !f.out.empty();
    std::optional<OutputLock> lock; // held from here: a second run into the directory is refused at once
    if (write)
    {
        checkOutputDirectory(spec.outputs.directory);
        checkOutputNames(spec.outputs);
        if (taskRank() == 0) // an MPI job writes from rank 0 only
            lock.emplace(spec.outputs.directory);
    }
    RunOptions options;
    if (f.speeds)
        options.speeds = speedList(*f.speeds);
    options.optimum = f.optimum;
    if (!spec.fleet.empty())
        return runFleetMode(f, spec, options);
    const MissionProblem problem(spec);
    if (!f.mission.empty() || !f.currents.empty())
        options.progress = printProgress;
    const MissionResult result = runMission(problem, options);
    if (taskRank() != 0) // an MPI job's other ranks: rank 0 reports and writes
        return result.plan.solved || !result.plan.badInput.any() ? (result.plan.solved ? 0 : kNoPath) : kBadInput;
    if (!result.plan.solved && result.plan.badInput.any())
    {
        std::cerr << "glider_plan: " << problem.getSpec().place(result.plan.badInput.field()) << ": "
                  << result.plan.reason << "\n";
        return kBadInput; // bad input: nothing is written
    }
    printReport(std::cout, result, &problem);
    if (write)
        for (const std::string &file : writeOutputs(result, problem))
            std::cout << "wrote " << file << "\n";
    return result.plan.solved ? 0 : kNoPath;
}

/// Plans under run(), turning exceptions into messages (rank 0's only: every rank of a job meets the same bad input,
/// and a task's failure is thrown on every rank) and exit codes; @p failure gets the message.
int runAndReport(const Flags &f, std::string &failure)
{
    const bool speak = taskRank() == 0;
    std::string message;
    try
    {
        return run(f);
    }
    catch (const UsageError &e)
    {
        message = e.message + "\nTry 'glider_plan --help'.";
    }
    catch (const Error &e)
    {
        message = e.what();
    }
    catch (const std::bad_alloc &)
    {
        message = "out of memory while planning (the address-space limit, ulimit -v, or the machine's memory; "
                  "reduce the region, the grid or the window)";
    }
    catch (const std::system_error &e)
    {
        message = e.code() == std::errc::resource_unavailable_try_again
                      ? std::string("cannot start a thread: ") + e.what() +
                            " (the limit on processes and threads, ulimit -u, or on memory, ulimit -v, is too low)"
                      : e.what();
    }
    catch (const std::exception &e)
    {
        message = e.what();
    }
    if (speak)
        std::cerr << "glider_plan: " << message << "\n";
    failure = message;
    return kBadInput;
}
} // namespace

int main(int argc, char **argv)
{
#if OMPL_GLIDER_WITH_MPI
    // started by mpirun or srun: the ranks share the many-plan modes' tasks (finalised when main returns)
    const MpiLaunchScope mpi(argc, argv);
#endif
    CLI::App app{"Plans a time-optimal glider route through time-varying currents and prints travel time, path "
                 "length, waypoints, CFC and CMC.\nWithout --mission or --currents: the built-in Gulf Stream "
                 "mission (meandering jet, x in [0, 10], y in [-4, 4], V = 0.5, dimensionless units).",
                 "glider_plan"};
    Flags f;
    defineFlags(app, f);
    int status = 0;
    std::string failure;
    try
    {
        parseFlags(app, f, argc, argv);
    }
    catch (const CLI::CallForHelp &e)
    {
        return app.exit(e);
    }
    catch (const CLI::ParseError &e)
    {
        failure = e.what();
    }
    catch (const UsageError &e)
    {
        failure = e.message;
    }
    if (!failure.empty())
    {
        if (taskRank() == 0)
            std::cerr << "glider_plan: " << failure << "\nTry 'glider_plan --help'.\n";
        status = kBadInput;
    }
    else
    {
        if (!f.verbose)
            ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
        installOutputSignalHandlers(); // SIGINT/SIGTERM while files are written: the earlier outputs stay
        // a CPU time limit whose soft and hard values agree (ulimit -t) kills at once; one second less of soft limit
        // first sends SIGXCPU, answered with a message
        struct rlimit cpu
        {
        };
        if (::getrlimit(RLIMIT_CPU, &cpu) == 0 && cpu.rlim_cur != RLIM_INFINITY && cpu.rlim_cur == cpu.rlim_max &&
            cpu.rlim_cur > 1)
        {
            cpu.rlim_cur -= 1;
            (void)::setrlimit(RLIMIT_CPU, &cpu);
        }
        status = runAndReport(f, failure);
        if (const int sig = signalAfterOutputs(); sig != 0 && taskRank() == 0)
            std::cerr << "glider_plan: " << strsignal(sig)
                      << " arrived after the outputs were written in full: they stand, and the run ends as finished\n";
    }
#if OMPL_GLIDER_WITH_MPI
    // a rank that failed alone must not leave the others waiting for it (MpiTaskSpreader::endJob())
    return mpi.end(status, failure);
#else
    return status;
#endif
}
