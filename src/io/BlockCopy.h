#pragma once
// Internal to the library: blocks of a multidimensional array kept in memory (the values fetched from a remote
// source), and a block cut out of an enclosing one. Not installed.
#include <cstddef>
#include <vector>

namespace ompl_glider::gridded_detail
{
/// True when the block at (s, c) lies inside the block at (bs, bc).
inline bool inside(const std::vector<std::size_t> &s, const std::vector<std::size_t> &c,
                   const std::vector<std::size_t> &bs, const std::vector<std::size_t> &bc)
{
    if (s.size() != bs.size())
        return false;
    for (std::size_t d = 0; d < s.size(); ++d)
        if (s[d] < bs[d] || s[d] + c[d] > bs[d] + bc[d])
            return false;
    return true;
}

/// Copies the block (s, c) out of the values of the enclosing block (bs, bc) (row-major, last index fastest).
inline void copyOut(const std::vector<double> &from, const std::vector<std::size_t> &bs,
                    const std::vector<std::size_t> &bc, const std::vector<std::size_t> &s,
                    const std::vector<std::size_t> &c, double *out)
{
    const std::size_t nd = s.size();
    if (nd == 0)
    {
        out[0] = from[0];
        return;
    }
    std::vector<std::size_t> idx(nd, 0);
    std::size_t n = 1;
    for (const std::size_t x : c)
        n *= x;
    for (std::size_t k = 0; k < n; ++k)
    {
        std::size_t off = 0;
        for (std::size_t d = 0; d < nd; ++d)
            off = off * bc[d] + (s[d] - bs[d] + idx[d]);
        out[k] = from[off];
        for (std::size_t d = nd; d-- > 0;)
        {
            if (++idx[d] < c[d])
                break;
            idx[d] = 0;
        }
    }
}
} // namespace ompl_glider::gridded_detail
