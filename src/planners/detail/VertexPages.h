#pragma once
/// @file detail/VertexPages.h (an internal of the lattice search, installed because TveSearch.h needs it; not API)
/// @brief Per-vertex values of a lattice search kept in pages of 32 x 32 grid vertices, allocated when a vertex of
/// the page is first written: O(1) access like a dense array, memory in proportion to the area the search visits
/// (no array over the whole lattice unless it is visited).

#include <cstddef>
#include <memory>
#include <vector>

#include "Lattice.h"

namespace ompl_glider
{
/// @brief Values of type T per lattice vertex, @p init where never written.
template <typename T> class VertexPages
{
public:
    /// @brief Sets the lattice geometry and the value of unwritten vertices; forgets every value.
    void reset(const Lattice &lattice, const T &init)
    {
        nx_ = lattice.nx();
        grid_ = lattice.numGridVertices();
        px_ = (nx_ + kSide - 1) / kSide;
        const long py = (lattice.ny() + kSide - 1) / kSide;
        init_ = init;
        pages_.clear();
        pages_.resize(static_cast<std::size_t>(px_ * py));
        extra_[0] = extra_[1] = extra_[2] = init;
        used_ = 0;
    }
    /// @brief Forgets every value (frees the pages).
    void clear()
    {
        for (auto &p : pages_)
            p.reset();
        extra_[0] = extra_[1] = extra_[2] = init_;
        used_ = 0;
    }
    /// @brief Value of v (init when never written).
    const T &get(Lattice::VertexId v) const
    {
        if (v >= grid_)
            return extra_[v - grid_ < 2 ? v - grid_ : 2];
        const std::size_t page = pageOf(v);
        const auto &p = pages_[page];
        return p ? p[offsetOf(v)] : init_;
    }
    /// @brief Writable value of v (allocates its page).
    T &ref(Lattice::VertexId v)
    {
        if (v >= grid_)
            return extra_[v - grid_ < 2 ? v - grid_ : 2];
        auto &p = pages_[pageOf(v)];
        if (!p)
        {
            p = std::make_unique<T[]>(kSide * kSide);
            for (std::size_t k = 0; k < kSide * kSide; ++k)
                p[k] = init_;
            ++used_;
        }
        return p[offsetOf(v)];
    }
    /// @brief Pages allocated (of kSide x kSide vertices each).
    std::size_t pagesUsed() const { return used_; }
    static constexpr long kSide = 32;

private:
    std::size_t pageOf(Lattice::VertexId v) const
    {
        const long i = static_cast<long>(v % static_cast<std::size_t>(nx_)),
                   j = static_cast<long>(v / static_cast<std::size_t>(nx_));
        return static_cast<std::size_t>(i / kSide + (j / kSide) * px_);
    }
    std::size_t offsetOf(Lattice::VertexId v) const
    {
        const long i = static_cast<long>(v % static_cast<std::size_t>(nx_)),
                   j = static_cast<long>(v / static_cast<std::size_t>(nx_));
        return static_cast<std::size_t>(i % kSide + (j % kSide) * kSide);
    }
    long nx_{1}, px_{1};
    std::size_t grid_{0};
    T init_{};
    std::vector<std::unique_ptr<T[]>> pages_;
    T extra_[3]{}; // the extra start and goal vertices, and a sink for ids beyond them
    std::size_t used_{0};
};
} // namespace ompl_glider
