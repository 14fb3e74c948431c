#pragma once
/// @file OutputDirectory.h
/// @brief Internal to the output layer (not installed): checked file writes, the staging directory and its
/// commit, the signal state of a write in progress.

#include <filesystem>
#include <string>
#include <vector>

namespace ompl_glider::output_detail
{
/// @brief Writes @p bytes to @p path (created or truncated) with every write(), fsync() and close() checked.
/// @throws Error naming the file and the system's reason (a full or read-only device, a file-size limit).
void writeFileChecked(const std::string &path, const std::string &bytes);

/// @brief The output directory as it will be used: absolute, normalised, a symbolic link to a directory followed.
/// @throws Error for a dangling symbolic link (naming where it points).
std::filesystem::path resolveOutputDirectory(const std::string &directory);

/// @brief Removes the staging directories an earlier run into @p target left behind (a run ended by SIGKILL);
/// call with the directory's lock held.
void removeStaleStaging(const std::filesystem::path &target);

/// @brief A new, empty staging directory beside @p target.
std::filesystem::path makeStaging(const std::filesystem::path &target);
/// Where the lock file and the staging directory of @p target go: beside it, or inside it when its parent may not be
/// written (the run then fills the target file by file).
std::filesystem::path workDirOf(const std::filesystem::path &target);

/// @brief Moves the files @p names of @p staging into @p target (see OutputWriter.h): one exchange of the two
/// directories when @p target is missing or holds only an earlier run's outputs (@p previous, its summary.json's
/// list), else file by file (summary.json last) and then the earlier run's files this run does not write are
/// removed. Refuses, before anything is replaced, a name in @p target that is not a regular file. Removes
/// @p staging in every case. @p shown is the directory as the user gave it (for messages).
void commitStaging(const std::filesystem::path &staging, const std::filesystem::path &target,
                   const std::vector<std::string> &names, const std::vector<std::string> &previous,
                   const std::string &shown);

/// @brief Marks the start and end of writing: while it lasts, SIGINT/SIGTERM/SIGHUP (with
/// installOutputSignalHandlers()) are held and answered at the next file by interruptIfSignalled().
void setStaging(bool on);

/// @brief When a signal arrived while staging: removes @p staging and ends the process by that signal.
void interruptIfSignalled(const std::filesystem::path &staging);

/// @brief Ends the process by a signal that arrived during the commit (after it completed), unless the commit is
/// final: then the signal stays for signalAfterOutputs() and the plans under way are asked to stop.
void raisePendingSignal();

/// @brief For tests: a function called at each named step of writeOutputFiles() ("staged", "committed": the new
/// outputs in place, "final": no longer taken back by a signal).
void setStepHook(void (*hook)(const char *step));
void stepHook(const char *step);
} // namespace ompl_glider::output_detail
