#pragma once
/// @file FileList.h
/// @brief The files of a forecast given as a list: paths, shell-style patterns, URLs (any gridded source's files).

#include <string>
#include <vector>

namespace ompl_glider
{
/// @brief The files of a list: each item a path, or a shell-style pattern (an item with `*`, `?` or `[`) expanded
/// with glob(3) (its matches in glob's order: by name). Relative items are taken relative to baseDir (empty: as
/// they are). @throws Error for an empty item, a pattern that matches nothing (naming it) or cannot be expanded,
/// and an empty list. Existence of plain paths is not checked. URLs and in-memory datasets are taken as they are.
std::vector<std::string> expandForecastFiles(const std::vector<std::string> &items, const std::string &baseDir = "");

/// @brief expandForecastFiles() of a comma-separated list ("a.nc,b.nc", "hycom_202603*.nc", "a.nc, b_*.nc").
std::vector<std::string> forecastFileList(const std::string &commaSeparated, const std::string &baseDir = "");
}  // namespace ompl_glider
