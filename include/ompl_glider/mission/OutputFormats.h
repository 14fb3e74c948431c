#pragma once
/// @file OutputFormats.h
/// @brief The output formats a mission can ask for (`outputs.files`), as an enum with its table of names: the mission
/// loader and the command line parse the names once; the output layer writes the files (each format's writer:
/// output/OutputFormatWriters.h, keyed by the same OutputFormatId).

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
    GeoJson,     ///< path.geojson, and route.kml in a geographic mission
    Isochrones,  ///< isochrones.geojson when the result has contours (also switches their computation on)
    Goto,        ///< goto_lNN.ma (Slocum) and targets (Seaglider), in a geographic mission
    Stints,      ///< stints.csv, for a plan with stints or a heading route
    Map,         ///< map.svg, map.png, map.html
    Execution,   ///< execution.csv, execution_tracks.csv, execution.svg/png, and model_difference.svg/png with a
                 ///< truth current (written whenever the mission has an execution section)
    Reachability ///< reachability.nc and reachability.geojson: the probability of reach over the ensemble's members
                 ///< (also switches its computation on; section `reachability`)
};

/// @brief One output format and how it is described.
struct OutputFormat
{
    OutputFormatId id; ///< the format
    std::string name;  ///< as in `outputs.files`: summary, csv, path, geojson, isochrones, goto, stints, map, ...
    /// the file(s) it writes, comma-separated, e.g. "waypoints.csv" or "execution.svg/png" (the names a run can
    /// write: checkOutputNames(); the files its writer makes where the format applies in full: the test of
    /// tests/output/TestOutputFormats.cpp)
    std::string files;
    std::string description; ///< one line for the docs
    bool route{false};       ///< describes the route (not written, and removed, when there is no path)
};

/// @brief Every output format, in the order they are written.
const std::vector<OutputFormat> &outputFormats();

/// @brief The format named @p name in `outputs.files`; nullopt for an unknown name.
std::optional<OutputFormatId> outputFormatByName(const std::string &name);
} // namespace ompl_glider
