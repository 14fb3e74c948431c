#pragma once
/// @file PathPattern.h
/// @brief Internal to src/io: shell-style patterns of file names, the one expansion of a pattern into files that the
/// forecast's file list (FileList.h) and the glider observations (GliderObservations.h) share.
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ompl_glider::io_detail
{
/// @brief True for a text with a wildcard of a shell-style pattern (`*`, `?` or `[`).
inline bool hasWildcards(const std::string &text)
{
    return text.find_first_of("*?[") != std::string::npos;
}

/// @brief What a pattern matches: glob(3)'s answer (0, GLOB_NOMATCH, GLOB_NOSPACE, GLOB_ABORTED), how many files it
/// matches, and those files in glob's order (by name; none where they are more than asked for).
struct PatternMatches
{
    int status{0};
    std::size_t count{0};
    std::vector<std::string> files;
};

/// @brief The files @p pattern matches (glob(3)), at most @p most of them.
PatternMatches matchPattern(const std::string &pattern, std::size_t most = std::numeric_limits<std::size_t>::max());
} // namespace ompl_glider::io_detail
