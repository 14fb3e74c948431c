#pragma once
/// @file OutputFormats.h
/// @brief The output formats a mission can ask for (`outputs.files`), as an enum with its table of names: the mission
/// loader and the command line parse the names once; the output layer (output/OutputWriter.cpp) writes the files.

#include <optional>
#include <string>
#include <vector>

namespace ompl_glider
{
/// @brief One output format of `outputs.files`.
enum class OutputFormatId
{
    Summary,     ///< summary.json (always written)
    Csv,         ///< waypoints.csv
    Path,        ///< path.csv
    GeoJson,     ///< path.geojson
    Isochrones,  ///< isochrones.geojson (also switches the isochrones' computation on)
    Goto,        ///< goto_lNN.ma
    Stints,      ///< stints.csv
    Map,         ///< map.svg, map.png
    Execution    ///< execution files (written whenever the mission has an execution section)
};

/// @brief One output format and how it is described.
struct OutputFormat
{
    OutputFormatId id;        ///< the format
    std::string name;         ///< as in `outputs.files`: summary, csv, path, geojson, isochrones, goto, stints, map, ...
    std::string files;        ///< the file(s) it writes, e.g. "waypoints.csv"
    std::string description;  ///< one line for the docs
    bool route{false};        ///< describes the route (not written, and removed, when there is no path)
};

/// @brief Every output format, in the order they are written.
const std::vector<OutputFormat> &outputFormats();

/// @brief The format named @p name in `outputs.files`; nullopt for an unknown name.
std::optional<OutputFormatId> outputFormatByName(const std::string &name);
}  // namespace ompl_glider
