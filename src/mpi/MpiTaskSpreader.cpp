// The TaskSpreader of an MPI job (MpiTaskSpreader.h): rank 0 dispatches task indices and computes tasks in a thread
// of its own; the other ranks ask for a task, compute it, send the result and ask again.
#include "ompl_glider/mpi/MpiTaskSpreader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

#include <mpi.h>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
constexpr int kTagResult = 7101; // worker -> rank 0: the finished task (or -1) and its result, asking for the next
constexpr int kTagTask = 7102;   // rank 0 -> worker: the next task index, -1: no more
constexpr int kTagFailed = 7103; // a rank that failed outside the tasks -> every other rank: its status and reason
constexpr int kTagDigest = 7104; // agree(): every rank -> rank 0 its digest; rank 0 -> every rank all of them
using Clock = std::chrono::steady_clock;

/// Ends the job when another rank said it failed outside the tasks (MpiTaskSpreader::endJob()): this rank waits for
/// something that rank will never do (a request, a task, a broadcast), so waiting would hang the job.
void abortOnFailureNotice()
{
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagFailed, MPI_COMM_WORLD, &flag, &st);
    if (!flag)
        return;
    int count = 0;
    MPI_Get_count(&st, MPI_BYTE, &count);
    std::string message(static_cast<std::size_t>(count), '\0');
    MPI_Recv(&message[0], count, MPI_BYTE, st.MPI_SOURCE, kTagFailed, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    ByteReader in(message);
    const int status = in.value<int>();
    const std::string reason = in.value<std::string>();
    std::fprintf(stderr, "\nrank %d failed outside the tasks: %s; the job is ended, nothing written\n", st.MPI_SOURCE,
                 reason.c_str());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, status > 0 ? status : 2);
}

/// Waits for a non-blocking request without spinning a core (OpenMPI's blocking calls poll busily); ends the job
/// when another rank failed outside the tasks.
void waitFor(MPI_Request &request)
{
    int flag = 0;
    MPI_Test(&request, &flag, MPI_STATUS_IGNORE);
    while (!flag)
    {
        abortOnFailureNotice();
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        MPI_Test(&request, &flag, MPI_STATUS_IGNORE);
    }
}

/// Broadcasts @p bytes from rank 0 (its size first; in pieces below 2^30 bytes).
void broadcast(std::string &bytes, double &moved)
{
    std::uint64_t size = bytes.size();
    MPI_Request r;
    MPI_Ibcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD, &r);
    waitFor(r);
    bytes.resize(static_cast<std::size_t>(size));
    const std::size_t piece = std::size_t(1) << 30;
    for (std::size_t at = 0; at < bytes.size(); at += piece)
    {
        const int count = static_cast<int>(std::min(piece, bytes.size() - at));
        MPI_Ibcast(&bytes[at], count, MPI_BYTE, 0, MPI_COMM_WORLD, &r);
        waitFor(r);
    }
    moved += 8.0 + static_cast<double>(bytes.size());
}

/// Runs one task, catching what it throws: (kind, result or reason); kind 0 ok, 1 ompl_glider::Error, 2 another.
/// OMPL_GLIDER_FAIL_TASK="what:i" makes task i of @p what fail as bad input would (the fault path's tests).
std::pair<int, std::string> attempt(const TaskSpreader::Task &task, std::size_t i, const std::string &what)
{
    try
    {
        const char *fail = std::getenv("OMPL_GLIDER_FAIL_TASK");
        if (fail && std::string(fail) == what + ":" + std::to_string(i))
            throw Error("failure injected by OMPL_GLIDER_FAIL_TASK=" + std::string(fail));
        return {0, task(i)};
    }
    catch (const Error &e)
    {
        return {1, e.what()};
    }
    catch (const std::bad_alloc &)
    {
        return {2, "out of memory"};
    }
    catch (const std::exception &e)
    {
        return {2, e.what()};
    }
    catch (...)
    {
        return {2, "unknown exception"};
    }
}
} // namespace

bool MpiTaskSpreader::launched()
{
    for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"})
        if (std::getenv(name))
            return true;
    return false;
}

MpiTaskSpreader::MpiTaskSpreader(int &argc, char **&argv)
{
    int done = 0;
    MPI_Initialized(&done);
    if (!done)
    {
        int provided = 0;
        MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
        initialised_ = true;
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    if (const char *limit = std::getenv("OMPL_GLIDER_TASK_TIME_LIMIT"))
        timeLimit_ = std::atof(limit);
}

MpiTaskSpreader::~MpiTaskSpreader()
{
    if (std::getenv("OMPL_GLIDER_MPI_STATS"))
        std::fprintf(stderr, "rank %d: %zu tasks, %.0f bytes sent and received\n", rank_, tasks_, bytes_);
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (initialised_ && !finalized)
        MPI_Finalize();
}

std::vector<std::string> MpiTaskSpreader::run(const std::string &what, std::size_t n, const Task &task,
                                              const Progress &progress)
{
    const TaskSpreadScope scope; // tasks within these tasks run locally
    failure_ = Failure();
    std::vector<std::string> results;
    if (rank_ == 0)
        results = master(what, n, task, progress);
    else
        worker(what, n, task);
    return share(what, std::move(results));
}

void MpiTaskSpreader::agree(const std::string &what, std::uint64_t digest)
{
    // point to point, not a collective: a rank that failed before it got here is in endJob()'s collective, and the
    // waits below end the job on its notice (waitFor())
    std::vector<std::uint64_t> all(static_cast<std::size_t>(size_), digest);
    if (rank_ == 0)
    {
        for (int r = 1; r < size_; ++r)
        {
            MPI_Request q;
            MPI_Irecv(&all[static_cast<std::size_t>(r)], 1, MPI_UINT64_T, r, kTagDigest, MPI_COMM_WORLD, &q);
            waitFor(q);
        }
        for (int r = 1; r < size_; ++r)
        {
            MPI_Request q;
            MPI_Isend(all.data(), size_, MPI_UINT64_T, r, kTagDigest, MPI_COMM_WORLD, &q);
            waitFor(q);
        }
    }
    else
    {
        MPI_Request q;
        MPI_Isend(&digest, 1, MPI_UINT64_T, 0, kTagDigest, MPI_COMM_WORLD, &q);
        waitFor(q);
        MPI_Irecv(all.data(), size_, MPI_UINT64_T, 0, kTagDigest, MPI_COMM_WORLD, &q);
        waitFor(q);
    }
    bytes_ += 8.0 * static_cast<double>(rank_ == 0 ? 2 * (size_ - 1) : 1 + size_);
    std::string differ;
    for (int r = 1; r < size_; ++r)
        if (all[static_cast<std::size_t>(r)] != all[0])
            differ += (differ.empty() ? "" : ", ") + std::to_string(r);
    if (!differ.empty())
        throw Error("the job's ranks read different inputs: " + what + " of rank" +
                    (differ.find(',') != std::string::npos ? "s " : " ") + differ +
                    " differs from rank 0's (a "
                    "node-local copy of another version?); every rank must read the same files: the job is stopped, "
                    "nothing planned or written");
}

std::vector<std::string> MpiTaskSpreader::master(const std::string &what, std::size_t n, const Task &task,
                                                 const Progress &progress)
{
    std::mutex m;
    std::size_t next = 0, done = 0;
    bool stop = false;
    std::vector<std::string> results(n);
    std::vector<long long> running(static_cast<std::size_t>(size_), -1); // the task of each rank
    std::vector<Clock::time_point> since(static_cast<std::size_t>(size_));
    const auto take = [&](int rank) -> long long {
        std::lock_guard<std::mutex> lock(m);
        const long long i = (stop || next >= n) ? -1 : static_cast<long long>(next++);
        running[static_cast<std::size_t>(rank)] = i;
        since[static_cast<std::size_t>(rank)] = Clock::now();
        return i;
    };
    const auto finish = [&](int rank, long long i, std::pair<int, std::string> outcome) {
        std::lock_guard<std::mutex> lock(m);
        if (outcome.first == 0)
        {
            results[static_cast<std::size_t>(i)] = std::move(outcome.second);
            ++done;
        }
        else
        {
            if (failure_.kind == 0)
                failure_ = {outcome.first, rank, i, outcome.second};
            stop = true;
        }
    };
    // rank 0's own share, in a thread that makes no MPI calls
    std::thread local([&] {
        for (long long i = take(0); i >= 0; i = take(0))
        {
            finish(0, i, attempt(task, static_cast<std::size_t>(i), what));
            ++tasks_;
        }
    });
    int stopped = 0;
    std::size_t reported = 0;
    while (stopped < size_ - 1)
    {
        int flag = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &st);
        if (!flag)
        {
            abortOnFailureNotice();
            std::lock_guard<std::mutex> lock(m);
            if (progress && done != reported)
                progress(reported = done, n);
            for (int r = 0; r < size_ && timeLimit_ > 0.0; ++r)
                if (running[static_cast<std::size_t>(r)] >= 0 &&
                    std::chrono::duration<double>(Clock::now() - since[static_cast<std::size_t>(r)]).count() >
                        timeLimit_)
                {
                    std::fprintf(stderr,
                                 "\nrank %d, %s %lld: still running after %g s (OMPL_GLIDER_TASK_TIME_LIMIT); "
                                 "the job is ended, nothing written\n",
                                 r, what.c_str(), running[static_cast<std::size_t>(r)], timeLimit_);
                    std::fflush(stderr);
                    MPI_Abort(MPI_COMM_WORLD, 3);
                }
            std::this_thread::sleep_for(std::chrono::microseconds(200));
            continue;
        }
        int count = 0;
        MPI_Get_count(&st, MPI_BYTE, &count);
        std::string message(static_cast<std::size_t>(count), '\0');
        MPI_Recv(&message[0], count, MPI_BYTE, st.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        bytes_ += count;
        ByteReader in(message);
        const auto i = in.value<long long>();
        const auto kind = in.value<int>();
        std::string payload;
        in.get(payload);
        if (i >= 0)
            finish(st.MPI_SOURCE, i, {kind, std::move(payload)});
        long long give = take(st.MPI_SOURCE);
        MPI_Send(&give, 1, MPI_LONG_LONG, st.MPI_SOURCE, kTagTask, MPI_COMM_WORLD);
        bytes_ += sizeof give;
        if (give < 0)
            ++stopped;
    }
    local.join();
    if (progress && failure_.kind == 0 && done != reported)
        progress(done, n);
    return results;
}

void MpiTaskSpreader::worker(const std::string &what, std::size_t n, const Task &task)
{
    long long i = -1;
    std::pair<int, std::string> outcome{0, ""};
    for (;;)
    {
        ByteWriter out;
        out.put(i);
        out.put(outcome.first);
        out.put(outcome.second);
        std::string message = out.take();
        MPI_Request r;
        MPI_Isend(message.data(), static_cast<int>(message.size()), MPI_BYTE, 0, kTagResult, MPI_COMM_WORLD, &r);
        waitFor(r); // (a large result waits for rank 0: not for ever when rank 0 failed outside the tasks)
        bytes_ += static_cast<double>(message.size());
        MPI_Irecv(&i, 1, MPI_LONG_LONG, 0, kTagTask, MPI_COMM_WORLD, &r);
        waitFor(r);
        bytes_ += sizeof i;
        if (i < 0 || static_cast<std::size_t>(i) >= n)
            return;
        outcome = attempt(task, static_cast<std::size_t>(i), what);
        ++tasks_;
    }
}

std::vector<std::string> MpiTaskSpreader::share(const std::string &what, std::vector<std::string> results)
{
    std::string head;
    if (rank_ == 0)
    {
        ByteWriter w;
        w.put(failure_.kind);
        w.put(failure_.rank);
        w.put(failure_.task);
        w.put(failure_.reason);
        if (failure_.kind == 0)
            w.put(results);
        head = w.take();
    }
    broadcast(head, bytes_);
    ByteReader in(head);
    in.get(failure_.kind);
    in.get(failure_.rank);
    in.get(failure_.task);
    in.get(failure_.reason);
    if (failure_.kind != 0)
    {
        const std::string message = "rank " + std::to_string(failure_.rank) + ", " + what + " " +
                                    std::to_string(failure_.task) + ": " + failure_.reason;
        if (failure_.kind == 1)
            throw Error(message);
        throw std::runtime_error(message);
    }
    if (rank_ != 0)
        in.get(results);
    return results;
}

int MpiTaskSpreader::endJob(int status, const std::string &failure)
{
    if (size_ < 2)
        return status;
    // a failure: every other rank is told first, so that a rank waiting for this one (for its requests in a run(),
    // for a task from rank 0, in a broadcast) ends the job instead of waiting for ever
    const bool failed = !failure.empty();
    std::string notice;
    std::vector<MPI_Request> sends;
    if (failed)
    {
        ByteWriter w;
        w.put(status);
        w.put(failure);
        notice = w.take();
        for (int r = 0; r < size_; ++r)
            if (r != rank_)
            {
                sends.emplace_back();
                MPI_Isend(notice.data(), static_cast<int>(notice.size()), MPI_BYTE, r, kTagFailed, MPI_COMM_WORLD,
                          &sends.back());
            }
    }
    // every rank at the end: how many failed (each rank then takes the notices sent to it)
    int mine = failed ? 1 : 0, all = 0;
    MPI_Request r;
    MPI_Iallreduce(&mine, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD, &r);
    int flag = 0;
    for (MPI_Test(&r, &flag, MPI_STATUS_IGNORE); !flag; MPI_Test(&r, &flag, MPI_STATUS_IGNORE))
        std::this_thread::sleep_for(std::chrono::microseconds(500));
    for (int k = 0; k < all - mine; ++k)
    {
        MPI_Status st;
        MPI_Probe(MPI_ANY_SOURCE, kTagFailed, MPI_COMM_WORLD, &st);
        int count = 0;
        MPI_Get_count(&st, MPI_BYTE, &count);
        std::string message(static_cast<std::size_t>(count), '\0');
        MPI_Recv(&message[0], count, MPI_BYTE, st.MPI_SOURCE, kTagFailed, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        ByteReader in(message);
        const int theirs = in.value<int>();
        const std::string reason = in.value<std::string>();
        if (rank_ == 0 && reason != failure) // the same failure on every rank is said once (by rank 0's caller)
            std::fprintf(stderr, "rank %d failed: %s\n", st.MPI_SOURCE, reason.c_str());
        status = std::max(status, theirs);
    }
    MPI_Waitall(static_cast<int>(sends.size()), sends.data(), MPI_STATUSES_IGNORE);
    return status;
}
} // namespace ompl_glider
