#pragma once
/// @file ShardedCounter.h
/// @brief An event counter that stays exact and cheap when several threads count at once.

#include <atomic>
#include <cstddef>
#include <cstdint>

namespace ompl_glider
{
/// @brief Counts events (current-model calls, cost-function calls) from any number of threads.
///
/// A single shared atomic would be exact, but every increment from two cores fights over one cache line and can cost
/// as much as the current-model call it counts, which cancels the gain of evaluating dive profiles or departure
/// times in parallel. Here each thread adds to its own cache-line-sized slot (chosen once per thread, round robin);
/// load() sums the slots. Increments are relaxed atomics, so the total is exact once the counting threads are done.
class ShardedCounter
{
public:
    /// @brief Adds @p n to the count.
    void add(std::uint64_t n = 1) noexcept { slots_[slotIndex()].value.fetch_add(n, std::memory_order_relaxed); }
    /// @brief The count so far.
    std::uint64_t load() const noexcept
    {
        std::uint64_t sum = 0;
        for (const Slot &s : slots_)
            sum += s.value.load(std::memory_order_relaxed);
        return sum;
    }
    /// @brief Sets the count back to zero (call when no other thread is counting).
    void reset() noexcept
    {
        for (Slot &s : slots_)
            s.value.store(0, std::memory_order_relaxed);
    }

private:
    static constexpr std::size_t kSlots = 16;
    struct alignas(64) Slot
    {
        std::atomic<std::uint64_t> value{0};
    };
    static std::size_t slotIndex() noexcept
    {
        static std::atomic<std::size_t> next{0};
        thread_local const std::size_t index = next.fetch_add(1, std::memory_order_relaxed) % kSlots;
        return index;
    }
    Slot slots_[kSlots];
};
} // namespace ompl_glider
