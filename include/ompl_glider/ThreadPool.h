#pragma once
/// @file ThreadPool.h
/// @brief The project's one pool of worker threads for independent evaluations in parallel: the dive profiles of one
/// leg ([EichhornOceans] Sec. IV: "a thread pool is created at the start of the mission planning system"), the
/// independent departure-time searches ([EichhornRAS] Sec. 5.3), the level set's tiles, the ensemble members and the
/// execution batch.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace ompl_glider
{
/// @brief Fixed pool of threads with a blocking parallelFor(). The calling thread works too, so a pool of size n
/// has n - 1 worker threads. One parallelFor() runs at a time; a call made while the pool is busy (from another
/// thread, or nested inside a job) runs serially in the caller, so nesting never deadlocks.
class ThreadPool
{
public:
    /// @brief Pool of @p threads threads in total (the caller included); 0 means std::thread::hardware_concurrency().
    explicit ThreadPool(unsigned threads = 0);
    ~ThreadPool();
    ThreadPool(const ThreadPool &) = delete;
    ThreadPool &operator=(const ThreadPool &) = delete;

    /// @brief Number of threads that take part in a parallelFor() (workers + caller).
    unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1u; }

    /// @brief Calls fn(i) for every i in [0, n), spread over the pool; returns when all calls are done. The first
    /// exception thrown by a call is rethrown here (the other indices still run).
    void parallelFor(std::size_t n, const std::function<void(std::size_t)> &fn);

private:
    void workerLoop();
    void runIndices();

    std::vector<std::thread> workers_;
    std::mutex callMutex_;
    std::mutex m_;
    std::condition_variable wake_;
    std::condition_variable done_;
    const std::function<void(std::size_t)> *job_{nullptr};
    std::size_t n_{0};
    std::atomic<std::size_t> next_{0};
    std::size_t active_{0};
    std::atomic<std::uint64_t> generation_{0}; ///< changed under m_; read without it while spinning
    std::atomic<bool> stop_{false};
    std::exception_ptr error_;
};
} // namespace ompl_glider
