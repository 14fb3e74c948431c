#pragma once
/// @file MpiTaskSpreader.h
/// @brief The TaskSpreader of an MPI job (TaskSpread.h): rank 0 hands out task indices one at a time to the ranks
/// that ask for the next (dynamic load balancing: tasks differ a lot in length) and computes tasks itself in a
/// thread of its own between the requests; every result goes to rank 0, which broadcasts them all (or the first
/// failure) to every rank. Only the executables include this layer (library: ompl_glider_mpi, CMake option
/// OMPL_GLIDER_WITH_MPI); MPI calls are made by each rank's main thread only (MPI_THREAD_FUNNELED).

#include <memory>
#include <string>

#include "ompl_glider/TaskSpread.h"

namespace ompl_glider
{
class MpiTaskSpreader : public TaskSpreader
{
public:
    /// @brief Initialises MPI (MPI_Init_thread) unless it is already; finalises it on destruction if it did.
    MpiTaskSpreader(int &argc, char **&argv);
    ~MpiTaskSpreader() override;
    MpiTaskSpreader(const MpiTaskSpreader &) = delete;
    MpiTaskSpreader &operator=(const MpiTaskSpreader &) = delete;

    /// @brief True when the environment says an MPI launcher started this process (mpirun / mpiexec of OpenMPI or
    /// MPICH, Slurm's srun with PMI or PMIx): only then do the executables initialise MPI.
    static bool launched();

    int rank() const override { return rank_; }
    int size() const override { return size_; }
    std::vector<std::string> run(const std::string &what, std::size_t n, const Task &task,
                                 const Progress &progress = {}) override;
    /// @brief Every rank's digest gathered on every rank (MPI_Allgather); every rank throws the same Error when one
    /// differs from rank 0's.
    void agree(const std::string &what, std::uint64_t digest) override;

    /// @brief Bytes sent and received by this rank in run() so far (task indices, results, broadcasts).
    double bytesMoved() const { return bytes_; }
    /// @brief A task running longer than this many seconds (> 0) on a rank ends the job (MPI_Abort) with a message
    /// naming the rank and the task; 0: no limit. Read from OMPL_GLIDER_TASK_TIME_LIMIT by the constructor.
    void setTaskTimeLimit(double seconds) { timeLimit_ = seconds; }

    /// @brief The end of the job, called by every rank once with its exit status and, when it failed, the reason
    /// (empty: it did not). A failing rank first tells every other rank, so that one waiting for it (for its
    /// requests, a task, a broadcast) ends the job (MPI_Abort with the failing rank and its reason) instead of
    /// hanging; then every rank waits for all, each takes the notices sent to it, and rank 0 prints those that
    /// differ from its own failure. @return the highest status of all ranks.
    int endJob(int status, const std::string &failure);

private:
    std::vector<std::string> master(const std::string &what, std::size_t n, const Task &task, const Progress &progress);
    void worker(const std::string &what, std::size_t n, const Task &task);
    std::vector<std::string> share(const std::string &what, std::vector<std::string> results);

    int rank_{0};
    int size_{1};
    bool initialised_{false};
    double timeLimit_{0.0};
    double bytes_{0.0};
    std::size_t tasks_{0}; ///< tasks this rank computed
    // OMPL_GLIDER_MPI_STATS set: each rank prints its tasks and bytes when the spreader ends
    // the first failure of a run, as rank 0 knows it (kind 1: ompl_glider::Error, 2: another exception)
    struct Failure
    {
        int kind{0};
        int rank{0};
        long long task{-1};
        std::string reason;
    } failure_;
};

/// @brief For an executable's main(): when an MPI launcher started the process (MpiTaskSpreader::launched()), makes
/// an MpiTaskSpreader the active task spreader for the scope's life, then unsets it (MPI is finalised with it).
class MpiLaunchScope
{
public:
    MpiLaunchScope(int &argc, char **&argv)
    {
        if (!MpiTaskSpreader::launched())
            return;
        spreader_ = std::make_shared<MpiTaskSpreader>(argc, argv);
        setTaskSpreader(spreader_);
    }
    /// @brief MpiTaskSpreader::endJob() when MPI runs, else @p status.
    int end(int status, const std::string &failure) const
    {
        return spreader_ ? spreader_->endJob(status, failure) : status;
    }
    ~MpiLaunchScope()
    {
        if (spreader_)
            setTaskSpreader(nullptr);
    }
    MpiLaunchScope(const MpiLaunchScope &) = delete;
    MpiLaunchScope &operator=(const MpiLaunchScope &) = delete;

private:
    std::shared_ptr<MpiTaskSpreader> spreader_;
};
} // namespace ompl_glider
