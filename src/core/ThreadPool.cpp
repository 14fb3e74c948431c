#include "ompl_glider/ThreadPool.h"

#include <algorithm>
#include <chrono>
#include <system_error>

namespace ompl_glider
{
ThreadPool::ThreadPool(unsigned threads)
{
    if (threads == 0)
        threads = std::max(1u, std::thread::hardware_concurrency());
    for (unsigned i = 1; i < threads; ++i)
    {
        try
        {
            workers_.emplace_back([this] { workerLoop(); });
        }
        catch (const std::system_error &)
        {
            break; // no more threads (ulimit -u, memory): the pool works with those it has, and the caller
        }
    }
}

ThreadPool::~ThreadPool()
{
    {
        std::lock_guard<std::mutex> lock(m_);
        stop_ = true;
    }
    wake_.notify_all();
    for (auto &w : workers_)
        w.join();
}

void ThreadPool::runIndices()
{
    for (;;)
    {
        const std::size_t i = next_.fetch_add(1, std::memory_order_relaxed);
        if (i >= n_)
            return;
        try
        {
            (*job_)(i);
        }
        catch (...)
        {
            std::lock_guard<std::mutex> lock(m_);
            if (!error_)
                error_ = std::current_exception();
        }
    }
}

void ThreadPool::workerLoop()
{
    // Jobs come back to back (the legs of a mission: one parallelFor per leg, about 0.1 ms each), so a worker spins
    // briefly for the next one before it sleeps: waking a sleeping thread costs about as much as the job itself.
    constexpr auto kSpin = std::chrono::microseconds(200);
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(m_);
    for (;;)
    {
        lock.unlock();
        const auto spinUntil = std::chrono::steady_clock::now() + kSpin;
        while (generation_.load(std::memory_order_acquire) == seen && !stop_.load(std::memory_order_acquire) &&
               std::chrono::steady_clock::now() < spinUntil)
            std::this_thread::yield();
        lock.lock();
        wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
        if (stop_)
            return;
        seen = generation_;
        if (job_ == nullptr)
            continue;
        ++active_;
        lock.unlock();
        runIndices();
        lock.lock();
        if (--active_ == 0)
            done_.notify_all();
    }
}

void ThreadPool::parallelFor(std::size_t n, const std::function<void(std::size_t)> &fn)
{
    std::unique_lock<std::mutex> callLock(callMutex_, std::try_to_lock);
    if (n <= 1 || workers_.empty() || !callLock.owns_lock())
    {
        for (std::size_t i = 0; i < n; ++i)
            fn(i);
        return;
    }
    {
        std::lock_guard<std::mutex> lock(m_);
        job_ = &fn;
        n_ = n;
        next_.store(0, std::memory_order_relaxed);
        error_ = nullptr;
        ++generation_;
    }
    wake_.notify_all();
    runIndices();
    std::exception_ptr err;
    {
        std::unique_lock<std::mutex> lock(m_);
        // the workers are mid-job: wait for them briefly without sleeping, then on the condition variable
        const auto spinUntil = std::chrono::steady_clock::now() + std::chrono::microseconds(200);
        while (active_ != 0 && std::chrono::steady_clock::now() < spinUntil)
        {
            lock.unlock();
            std::this_thread::yield();
            lock.lock();
        }
        done_.wait(lock, [&] { return active_ == 0; });
        job_ = nullptr;
        err = error_;
        error_ = nullptr;
    }
    if (err)
        std::rethrow_exception(err);
}
} // namespace ompl_glider
