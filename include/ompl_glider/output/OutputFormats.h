#pragma once
/// @file OutputFormats.h
/// @brief The names of the output formats (mission files' `outputs.files`, the docs). The writers behind them are
/// in OutputWriter.cpp; this header only names them, so that the mission loader can check a name.

#include <string>
#include <vector>

namespace ompl_glider
{
/// @brief One output format.
struct OutputFormat
{
    std::string name;         ///< as in `outputs.files`: summary, csv, path, geojson, goto, map
    std::string files;        ///< the file(s) it writes, e.g. "waypoints.csv"
    std::string description;  ///< one line for the docs
    bool route{false};        ///< describes the route (not written, and removed, when there is no path)
};

/// @brief Every output format, in the order they are written.
const std::vector<OutputFormat> &outputFormats();
}  // namespace ompl_glider
