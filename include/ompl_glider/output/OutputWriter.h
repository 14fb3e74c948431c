#pragma once
/// @file OutputWriter.h
/// @brief The one output layer: every mode writes its files here, all or nothing.
///
/// Writing goes to a staging directory beside the target (`.NAME.tmp-PID-N`); every write, fsync and close is
/// checked. Only when every file was written is it committed: a missing target, or one that holds only an earlier
/// run's outputs (the regular files its summary.json lists), is replaced by the staging directory in one rename
/// (renameat2 RENAME_EXCHANGE), so a process killed at any moment leaves either the complete earlier outputs or
/// the complete new ones, and at most a staging directory that the next run into the target removes. A directory
/// that holds other files too (the mission file's own folder, the working directory) gets the files one by one,
/// summary.json last; then the files an earlier run listed and this run does not write are removed. A name in
/// the target that is a directory is refused before anything is replaced. So a run that finds no path leaves no
/// stale route beside its summary.json (which says why), and a run that fails (exit 2) leaves the directory as
/// it was. An exclusive lock (flock on `.NAME.lock` beside the target) keeps two runs from writing into one
/// directory: the second is refused.

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
    std::string name;                               ///< file name (no directory part)
    std::function<void(const std::string &)> write; ///< writes the file at the given path; throws Error on failure
};

/// @brief An exclusive lock on an output directory: flock() on `.NAME.lock` beside it, held for the object's
/// life; nested locks of one process on one directory are counted. @throws Error when another process holds it.
class OutputLock
{
public:
    explicit OutputLock(const std::string &directory);
    ~OutputLock();
    OutputLock(const OutputLock &) = delete;
    OutputLock &operator=(const OutputLock &) = delete;

private:
    std::string path_;
};

/// @brief SIGINT, SIGTERM and SIGHUP (unless ignored) end the process at once, except while writeOutputFiles()
/// writes its staging directory: then that directory is removed first (the earlier outputs stay), or, where the
/// commit has begun, it is taken back; then the process ends by the signal. A signal once the new outputs stand for
/// good (the commit is final) no longer ends the process by the signal, which would tell a caller that nothing was
/// written: it asks the plans still under way to stop (requestStop()) and is given by signalAfterOutputs(); the
/// program ends as finished. SIGXCPU (the CPU time limit, ulimit -t) likewise, ending with a message and exit status
/// 128 + SIGXCPU instead of a core dump. For programs (glider_plan).
void installOutputSignalHandlers();

/// @brief The signal that arrived after the last outputs were committed for good (0: none); cleared by the call.
int signalAfterOutputs();

/// @brief The files of @p result: summary.json always, then the formats of result.spec.outputs.files that apply
/// (route files only with a path; the goto list only with geographic coordinates), in the order of outputFormats(),
/// each format's files made by its writer (OutputFormatWriters.h), each also as `<prefix>_<name>` when
/// outputs.prefix is set.
std::vector<OutputFile> outputFiles(const MissionResult &result, const MissionProblem &problem);

/// @brief Checks before planning that @p directory can be written: it is a directory (or can be created) and a
/// file can be created beside or in it; a symbolic link to a missing directory is refused.
/// @throws Error saying what is wrong.
void checkOutputDirectory(const std::string &directory);

/// @brief Checks before planning that no name a run with @p outputs can write (any format, with the prefix) is a
/// directory in outputs.directory. @throws Error naming it.
void checkOutputNames(const OutputSpec &outputs);

/// @brief Writes @p files into @p directory (created when missing) all or nothing (see the file comment); a name may
/// hold one folder ("alpha/summary.json": a fleet's glider, made in the directory; a file standing where the folder
/// goes is refused before anything is replaced, and an earlier run's folder left empty is removed); the
/// route files of an earlier run are found in the `files` list of the summary.json already there. Takes the
/// directory's OutputLock (unless this process holds it) and removes staging directories killed runs left.
/// @return the paths written. @throws Error naming the file that could not be written; the directory is unchanged.
std::vector<std::string> writeOutputFiles(const std::string &directory, const std::vector<OutputFile> &files);

/// @brief outputFiles() then writeOutputFiles() into result.spec.outputs.directory.
std::vector<std::string> writeOutputs(const MissionResult &result, const MissionProblem &problem);
} // namespace ompl_glider
