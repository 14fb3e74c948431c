#pragma once
/// @file OutputWriter.h
/// @brief The one output layer: every mode writes its files here, all or nothing.
///
/// Writing goes to a temporary directory beside the target and the files are moved into place only when every
/// one was written; then the route files an earlier run left in the directory and this run does not write (listed
/// in that run's summary.json) are removed. So a run that finds no path leaves no stale route beside its
/// summary.json (which says why), and a run that fails (exit 2) leaves the directory as it was.

#include <functional>
#include <string>
#include <vector>

#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/mission/OutputFormats.h"

namespace ompl_glider
{
/// @brief A file to write: its name in the output directory and the function that writes it to a path.
struct OutputFile
{
    std::string name;                                ///< file name (no directory part)
    std::function<void(const std::string &)> write;  ///< writes the file at the given path; throws Error on failure
};

/// @brief The files of @p result: summary.json always, then the formats of result.spec.outputs.files that apply
/// (route files only with a path; the goto list only with geographic coordinates), each also as
/// `<prefix>_<name>` when outputs.prefix is set.
std::vector<OutputFile> outputFiles(const MissionResult &result, const MissionProblem &problem);

/// @brief Checks before planning that @p directory can be written: it is a directory (or can be created) and a
/// file can be created beside or in it. @throws Error saying what is wrong.
void checkOutputDirectory(const std::string &directory);

/// @brief Writes @p files into @p directory (created when missing) all or nothing (see the file comment); the
/// route files of an earlier run are found in the `files` list of the summary.json already there.
/// @return the paths written. @throws Error naming the file that could not be written; the directory is unchanged.
std::vector<std::string> writeOutputFiles(const std::string &directory, const std::vector<OutputFile> &files);

/// @brief outputFiles() then writeOutputFiles() into result.spec.outputs.directory.
std::vector<std::string> writeOutputs(const MissionResult &result, const MissionProblem &problem);
}  // namespace ompl_glider
