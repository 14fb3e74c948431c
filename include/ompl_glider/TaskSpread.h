#pragma once
/// @file TaskSpread.h
/// @brief Independent tasks spread over the processes of a job (the ranks of an MPI job), behind an interface that
/// knows nothing of MPI: the many-plan modes of the pipeline (ensemble candidates, the execution batch, the
/// departure search's evaluations, the speed sweep) ask activeTaskSpreader() and, when a job of several processes
/// is running, hand it their tasks as functions returning bytes (ByteWriter); otherwise they run in threads as
/// before. The MPI implementation lives in its own layer (ompl_glider/mpi/MpiTaskSpreader.h), set by the
/// executables with setTaskSpreader().
///
/// Every process of the job runs the same program (SPMD): every process calls run() at the same point with the
/// same tasks, and every process gets every task's result back, in task order, so that all go on identically.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace ompl_glider
{
/// @brief Appends values to a byte string, as they are in memory (doubles keep every bit).
class ByteWriter
{
public:
    template <class T> void put(const T &v)
    {
        static_assert(std::is_arithmetic<T>::value || std::is_enum<T>::value, "plain values only");
        bytes_.append(reinterpret_cast<const char *>(&v), sizeof v);
    }
    void put(const std::string &s)
    {
        put(static_cast<std::uint64_t>(s.size()));
        bytes_.append(s);
    }
    void put(bool b) { put(static_cast<std::uint8_t>(b ? 1 : 0)); }
    /// @brief A vector of plain values or strings.
    template <class T> void put(const std::vector<T> &v)
    {
        put(static_cast<std::uint64_t>(v.size()));
        for (const T &x : v)
            put(x);
    }
    /// @brief A vector of anything, each element written by @p write.
    template <class T, class F> void putEach(const std::vector<T> &v, F write)
    {
        put(static_cast<std::uint64_t>(v.size()));
        for (const T &x : v)
            write(*this, x);
    }
    std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
};

/// @brief Reads back what a ByteWriter wrote, in the same order; std::runtime_error past the end.
class ByteReader
{
public:
    explicit ByteReader(const std::string &bytes) : bytes_(bytes) {}
    template <class T> void get(T &v)
    {
        static_assert(std::is_arithmetic<T>::value || std::is_enum<T>::value, "plain values only");
        need(sizeof v);
        std::memcpy(&v, bytes_.data() + pos_, sizeof v);
        pos_ += sizeof v;
    }
    void get(std::string &s)
    {
        const std::size_t n = size();
        need(n);
        s.assign(bytes_, pos_, n);
        pos_ += n;
    }
    void get(bool &b)
    {
        std::uint8_t c = 0;
        get(c);
        b = c != 0;
    }
    template <class T> void get(std::vector<T> &v)
    {
        v.resize(size());
        for (auto &x : v)
        {
            T y{};
            get(y);
            x = y;
        }
    }
    template <class T, class F> void getEach(std::vector<T> &v, F read)
    {
        v.resize(size());
        for (T &x : v)
            read(*this, x);
    }
    template <class T> T value()
    {
        T v{};
        get(v);
        return v;
    }
    bool atEnd() const { return pos_ == bytes_.size(); }

private:
    std::size_t size()
    {
        std::uint64_t n = 0;
        get(n);
        return static_cast<std::size_t>(n);
    }
    void need(std::size_t n) const
    {
        if (n > bytes_.size() - pos_)
            throw std::runtime_error("ByteReader: message shorter than its contents");
    }
    const std::string &bytes_;
    std::size_t pos_{0};
};

/// @brief Runs independent tasks on the processes of a job.
class TaskSpreader
{
public:
    using Task = std::function<std::string(std::size_t)>;
    /// @brief Called on process 0 as results arrive: (tasks done, tasks in all).
    using Progress = std::function<void(std::size_t, std::size_t)>;

    virtual ~TaskSpreader() = default;
    /// @brief This process's number in the job (0: the one that writes outputs).
    virtual int rank() const = 0;
    /// @brief Processes in the job.
    virtual int size() const = 0;
    /// @brief Calls task(i) for every i in [0, n) once, somewhere in the job, and returns every result, in order,
    /// on every process. @p what names the tasks in messages ("ensemble candidate"). When a task throws, no further
    /// task is started and every process throws: ompl_glider::Error when the task threw one (bad input), else
    /// std::runtime_error; the message names the process, the task and the reason
    /// ("rank 2, ensemble candidate 7: ...").
    virtual std::vector<std::string> run(const std::string &what, std::size_t n, const Task &task,
                                         const Progress &progress = {}) = 0;
    /// @brief Called by every process once with a digest of what it read (@p what: "the mission"): every process
    /// throws ompl_glider::Error naming the processes whose digest differs from process 0's, so that a job whose
    /// processes read different inputs (a node-local copy) stops instead of mixing their results. The default (one
    /// process) does nothing.
    virtual void agree(const std::string & /*what*/, std::uint64_t /*digest*/) {}
};

/// @brief Makes @p spreader the process's (null: none; the executables set it once, before planning).
void setTaskSpreader(std::shared_ptr<TaskSpreader> spreader);

/// @brief The spreader to use now: the one set, when its job has more than one process and no run() of it is under
/// way in this process (tasks within a task run locally); else null (run in threads as always).
TaskSpreader *activeTaskSpreader();

/// @brief The process's number in the job of the spreader set (0 without one): only process 0 writes outputs.
int taskRank();

/// @brief Processes in the job of the spreader set (1 without one).
int taskProcesses();

/// @brief Marks a run() under way in this process (RAII; used by TaskSpreader implementations).
class TaskSpreadScope
{
public:
    TaskSpreadScope();
    ~TaskSpreadScope();
    TaskSpreadScope(const TaskSpreadScope &) = delete;
    TaskSpreadScope &operator=(const TaskSpreadScope &) = delete;
};
} // namespace ompl_glider
