// The output directory under faults (output/OutputWriter.h): a writer process killed (SIGKILL) at every step
// leaves either the complete earlier outputs or the complete new ones, and the next run removes what it left; a
// signal while files are staged leaves the earlier outputs and no staging directory; a file-size limit (as a full
// device) is an error naming the file; a directory locked by another process is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>

#include <pthread.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "OutputDirectory.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/OutputWriter.h"
#include "ompl_glider/output/SummaryJson.h"

namespace fs = std::filesystem;
using namespace ompl_glider;

namespace
{
fs::path freshDirectory(const std::string &name)
{
    const fs::path d = fs::temp_directory_path() / ("ompl_glider_faults_" + std::to_string(::getpid())) / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::map<std::string, std::string> snapshot(const fs::path &dir)
{
    std::map<std::string, std::string> files;
    if (!fs::exists(dir))
        return files;
    for (const auto &e : fs::directory_iterator(dir))
    {
        std::ifstream in(e.path(), std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        files[e.path().filename().string()] = s.str();
    }
    return files;
}

std::size_t stagingDirectories(const fs::path &parent)
{
    std::size_t n = 0;
    for (const auto &e : fs::directory_iterator(parent))
        n += e.path().filename().string().find(".tmp-") != std::string::npos;
    return n;
}

/// A run's files: summary.json listing them, and route files whose text names the run.
std::vector<OutputFile> runFiles(const std::string &run, const std::vector<std::string> &routeNames)
{
    std::string list = "\"summary.json\"";
    for (const std::string &n : routeNames)
        list += ", \"" + n + "\"";
    std::vector<OutputFile> files{{"summary.json", [run, list](const std::string &p) {
                                       output_detail::writeFileChecked(p, "{\"run\": \"" + run + "\", \"files\": [" +
                                                                              list + "]}\n");
                                   }}};
    for (const std::string &n : routeNames)
        files.push_back({n, [run, n](const std::string &p) { output_detail::writeFileChecked(p, run + " " + n); }});
    return files;
}

std::map<std::string, std::string> expected(const std::vector<OutputFile> &files, const fs::path &scratch)
{
    writeOutputFiles(scratch.string(), files);
    return snapshot(scratch);
}

int g_pipe = -1;
const char *g_stopAt = "";

void stopHere(const char *step)
{
    if (std::string(step) != g_stopAt)
        return;
    (void)!::write(g_pipe, "x", 1);
    ::pause(); // the parent kills us here
}
} // namespace

TEST(OutputFaults, KilledAtEveryStepLeavesOneCompleteRun)
{
    const fs::path root = freshDirectory("kill");
    const auto oldFiles = runFiles("old", {"waypoints.csv", "path.csv"});
    const auto newFiles = runFiles("new", {"waypoints.csv", "stints.csv"});
    const auto oldSet = expected(oldFiles, root / "scratch_old");
    const auto newSet = expected(newFiles, root / "scratch_new");
    // file k of the new run being written (k = 0..2), all written, committed
    const std::vector<std::string> steps = {"file0", "file1", "file2", "staged", "committed", "final"};
    for (const std::string &step : steps)
    {
        SCOPED_TRACE(step);
        const fs::path dir = root / ("out_" + step);
        writeOutputFiles(dir.string(), oldFiles);
        int fds[2];
        ASSERT_EQ(::pipe(fds), 0);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0)
        {
            g_pipe = fds[1];
            g_stopAt = step.c_str();
            output_detail::setStepHook(stopHere);
            std::vector<OutputFile> files = newFiles;
            for (std::size_t k = 0; k < files.size(); ++k)
            {
                auto write = files[k].write;
                const std::string name = "file" + std::to_string(k);
                files[k].write = [write, name](const std::string &p) {
                    std::ofstream(p) << "half"; // the file is half written when the process dies
                    stopHere(name.c_str());
                    write(p);
                };
            }
            writeOutputFiles(dir.string(), files);
            ::_exit(0);
        }
        char c;
        ASSERT_EQ(::read(fds[0], &c, 1), 1);
        ::kill(child, SIGKILL);
        int status = 0;
        ::waitpid(child, &status, 0);
        ::close(fds[0]);
        ::close(fds[1]);
        ASSERT_TRUE(WIFSIGNALED(status));
        EXPECT_EQ(snapshot(dir), step == "committed" || step == "final" ? newSet : oldSet);
        EXPECT_LE(stagingDirectories(root), 1u);
        // The next run removes what the killed one left.
        writeOutputFiles(dir.string(), newFiles);
        EXPECT_EQ(snapshot(dir), newSet);
        EXPECT_EQ(stagingDirectories(root), 0u);
    }
}

TEST(OutputFaults, SignalWhileStagingKeepsTheEarlierOutputs)
{
    const fs::path root = freshDirectory("signal");
    const fs::path dir = root / "out";
    writeOutputFiles(dir.string(), runFiles("old", {"waypoints.csv"}));
    const auto before = snapshot(dir);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0)
    {
        installOutputSignalHandlers();
        std::vector<OutputFile> files = runFiles("new", {"waypoints.csv", "path.csv"});
        files[1].write = [](const std::string &p) {
            output_detail::writeFileChecked(p, "new");
            ::raise(SIGTERM); // arrives while the run's files are staged
        };
        writeOutputFiles(dir.string(), files);
        ::_exit(0); // not reached: the signal ends the process at the next file
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), SIGTERM);
    EXPECT_EQ(snapshot(dir), before);
    EXPECT_EQ(stagingDirectories(root), 0u);
}

TEST(OutputFaults, SignalWhileSwappingInKeepsTheEarlierOutputs)
{
    // a signal held while a fleet's files are swapped in (it arrives at the commit): the swap is taken back, so the
    // earlier outputs stay (an earlier run's fleet, and no directory at all when there was none)
    const fs::path root = freshDirectory("signal_commit");
    for (const bool earlier : {true, false})
    {
        SCOPED_TRACE(earlier ? "over an earlier fleet" : "no earlier outputs");
        const fs::path dir = root / (earlier ? "fleet" : "fresh");
        if (earlier)
            writeOutputFiles(dir.string(), runFiles("old", {"alpha/waypoints.csv", "bravo/waypoints.csv"}));
        const auto before = earlier ? snapshot(dir) : std::map<std::string, std::string>{};
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0)
        {
            installOutputSignalHandlers();
            output_detail::setStepHook([](const char *step) {
                if (std::string(step) == "committed")
                    ::raise(SIGINT);
            });
            writeOutputFiles(dir.string(), runFiles("new", {"alpha/waypoints.csv", "charlie/waypoints.csv"}));
            ::_exit(0); // not reached: the signal ends the process once the swap is taken back
        }
        int status = 0;
        ::waitpid(child, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status));
        EXPECT_EQ(WTERMSIG(status), SIGINT);
        if (earlier)
            EXPECT_EQ(snapshot(dir), before);
        else
            EXPECT_FALSE(fs::exists(dir));
        EXPECT_EQ(stagingDirectories(root), 0u);
    }
}

TEST(OutputFaults, SignalAfterTheFinalCommitKeepsTheNewOutputsAndEndsAsFinished)
{
    // SIGTERM once the new outputs stand for good: ending by the signal would tell the caller that nothing was
    // written. The write completes, the signal is given by signalAfterOutputs() and the plans are asked to stop; a
    // signal while the next run's files are staged still ends the process and keeps that run's outputs out.
    const fs::path root = freshDirectory("signal_final");
    const fs::path dir = root / "out";
    writeOutputFiles(dir.string(), runFiles("old", {"waypoints.csv"}));
    const auto newFiles = runFiles("new", {"waypoints.csv", "path.csv"});
    const auto newSet = expected(newFiles, root / "scratch_new");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0)
    {
        installOutputSignalHandlers();
        clearStop();
        output_detail::setStepHook([](const char *step) {
            if (std::string(step) == "final")
                ::raise(SIGTERM);
        });
        writeOutputFiles(dir.string(), newFiles);
        const bool told = stopRequested() && signalAfterOutputs() == SIGTERM && signalAfterOutputs() == 0;
        ::raise(SIGTERM); // after the final commit, outside any write: noted again, the process goes on
        ::_exit(told && signalAfterOutputs() == SIGTERM ? 0 : 3);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_EQ(snapshot(dir), newSet);
    EXPECT_EQ(stagingDirectories(root), 0u);
    // the next write is staged anew: a signal while its files are written takes it back and ends the process
    const pid_t second = ::fork();
    ASSERT_GE(second, 0);
    if (second == 0)
    {
        installOutputSignalHandlers();
        writeOutputFiles(dir.string(), runFiles("later", {"waypoints.csv"})); // committed for good
        std::vector<OutputFile> files = runFiles("last", {"waypoints.csv", "path.csv"});
        files[1].write = [](const std::string &p) {
            output_detail::writeFileChecked(p, "last");
            ::raise(SIGTERM);
        };
        writeOutputFiles(dir.string(), files);
        ::_exit(0); // not reached
    }
    ::waitpid(second, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), SIGTERM);
    const auto after = snapshot(dir);
    EXPECT_EQ(after, expected(runFiles("later", {"waypoints.csv"}), root / "scratch_later"));
}

TEST(OutputFaults, AWriteThatFailsNamesTheFileAndKeepsTheEarlierOutputs)
{
    const fs::path root = freshDirectory("fsize");
    const fs::path dir = root / "out";
    writeOutputFiles(dir.string(), runFiles("old", {"waypoints.csv"}));
    const auto before = snapshot(dir);
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0)
    {
        // A file-size limit fails write() part way, as a full device does.
        ::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        std::vector<OutputFile> files = runFiles("new", {"waypoints.csv"});
        files.push_back(
            {"map.png", [](const std::string &p) { output_detail::writeFileChecked(p, std::string(10000, 'x')); }});
        std::string message = "no error";
        try
        {
            writeOutputFiles(dir.string(), files);
        }
        catch (const Error &e)
        {
            message = e.what();
        }
        (void)!::write(fds[1], message.data(), message.size());
        ::_exit(0);
    }
    ::close(fds[1]);
    std::string message;
    char buf[512];
    for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;)
        message.append(buf, static_cast<std::size_t>(n));
    ::close(fds[0]);
    ::waitpid(child, nullptr, 0);
    EXPECT_NE(message.find("cannot write '" + (dir / "map.png").string() + "': File too large (4096 of 10000 bytes"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("was left as it was"), std::string::npos) << message;
    EXPECT_EQ(snapshot(dir), before);
    EXPECT_EQ(stagingDirectories(root), 0u);
}

TEST(OutputFaults, ADirectoryInUseByAnotherProcessIsRefused)
{
    const fs::path root = freshDirectory("lock");
    const fs::path dir = root / "out";
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0)
    {
        const OutputLock lock(dir.string());
        (void)!::write(fds[1], "x", 1);
        ::pause();
        ::_exit(0);
    }
    char c;
    ASSERT_EQ(::read(fds[0], &c, 1), 1);
    try
    {
        writeOutputFiles(dir.string(), runFiles("second", {}));
        ADD_FAILURE() << "a locked directory was written";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("is in use by another glider_plan run"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir));
    ::kill(child, SIGKILL);
    ::waitpid(child, nullptr, 0);
    // Once that process is gone, the lock is free; this process may nest its own.
    const OutputLock mine(dir.string());
    writeOutputFiles(dir.string(), runFiles("third", {}));
    EXPECT_TRUE(fs::exists(dir / "summary.json"));
}

TEST(OutputFaults, NonFiniteNumbersNeverReachSummaryJson)
{
    MissionSpec m = defaultGulfStreamMission();
    m.planner.gridSize = 0.8;
    const MissionProblem problem(m);
    const MissionResult good = runMission(problem);
    EXPECT_NO_THROW(summaryJson(good, problem));
    MissionResult r = good;
    r.plan.pathLength = std::nan(""); // written as a number, not through the null of a missing value
    try
    {
        summaryJson(r, problem);
        ADD_FAILURE() << "NaN written";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("field 'path_length' holds a non-finite number"), std::string::npos)
            << e.what();
    }
    r = good;
    r.plan.reason = "land between (1, -3) at t = 0 and (-nan, nan) at t = 22.8"; // a number printed into a text
    try
    {
        summaryJson(r, problem);
        ADD_FAILURE() << "NaN written in a text";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("field 'reason'"), std::string::npos) << e.what();
    }
    r.plan.reason = "the infinite sea, financial nano"; // words, not numbers
    EXPECT_NO_THROW(summaryJson(r, problem));
}

TEST(OutputFaults, DatesOutsideTheYears0To9999AreRefused)
{
    EXPECT_EQ(formatIsoTime(253402300799.0), "9999-12-31T23:59:59Z");
    EXPECT_EQ(formatIsoTime(-62167219200.0), "0000-01-01T00:00:00Z");
    EXPECT_THROW(formatIsoTime(253402300800.0), Error); // would be 10000-01-01T00:00:00Z
    EXPECT_THROW(formatIsoTime(-62167219201.0), Error);
}

// A SIGTERM at any moment of a write, taken by another thread of the process than the one writing (a planner's
// worker: a process-directed signal goes to any thread that does not block it), never ends the process by the signal
// once the new outputs stand: ended by SIGTERM, the directory holds the earlier run's complete outputs; ended
// normally, the new ones. The handler reads the write's state once (one atomic), so the main thread's commit cannot
// change it between two of its reads. Random moments over the write's span, many times.
TEST(OutputFaults, ASignalOnAnotherThreadAtAnyMomentLeavesOneCompleteRun)
{
    const fs::path root = freshDirectory("signal_any_thread");
    const fs::path dir = root / "out";
    const auto oldFiles = runFiles("old", {"waypoints.csv"});
    const auto newFiles = runFiles("new", {"waypoints.csv", "path.csv", "track.csv"});
    const auto oldSet = expected(oldFiles, root / "scratch_old");
    const auto newSet = expected(newFiles, root / "scratch_new");
    // the moments are drawn over twice the write's own span, timed here (a sanitized build beside other tests takes
    // several times as long as an idle optimised one), at least 20 ms; more runs while one outcome is still missing
    const auto begin = std::chrono::steady_clock::now();
    writeOutputFiles((root / "timed").string(), newFiles);
    const long span = static_cast<long>(
        std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - begin).count());
    std::mt19937 rng(17);
    std::uniform_int_distribution<long> delay(0, std::max(20000L, 2 * span)); // microseconds after the write begins
    int bySignal = 0, finished = 0;
    for (int run = 0; run < 40 || (run < 200 && (bySignal == 0 || finished == 0)); ++run)
    {
        fs::remove_all(dir);
        writeOutputFiles(dir.string(), oldFiles);
        const long wait = delay(rng);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0)
        {
            installOutputSignalHandlers();
            clearStop();
            // the worker takes the signal while the main thread writes
            std::thread worker([wait] {
                ::usleep(static_cast<useconds_t>(wait));
                ::pthread_kill(::pthread_self(), SIGTERM);
                for (;;)
                    ::pause();
            });
            worker.detach();
            writeOutputFiles(dir.string(), newFiles);
            ::usleep(25000); // the worker's signal, if not yet sent, comes while the outputs stand
            ::_exit(0);
        }
        int status = 0;
        ::waitpid(child, &status, 0);
        if (WIFSIGNALED(status))
        {
            ASSERT_EQ(WTERMSIG(status), SIGTERM);
            ++bySignal;
            EXPECT_EQ(snapshot(dir), oldSet) << "run " << run << ": ended by the signal, yet the outputs changed";
        }
        else
        {
            ASSERT_TRUE(WIFEXITED(status));
            EXPECT_EQ(WEXITSTATUS(status), 0);
            ++finished;
            EXPECT_EQ(snapshot(dir), newSet) << "run " << run << ": finished, yet the new outputs are not whole";
        }
        EXPECT_EQ(stagingDirectories(root), 0u) << "run " << run;
    }
    // both outcomes met: the moments spanned the write
    EXPECT_GT(bySignal, 0);
    EXPECT_GT(finished, 0);
}
