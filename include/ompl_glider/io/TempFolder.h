#pragma once
/// @file TempFolder.h
/// @brief The folder for temporary files, checked: a missing TMPDIR is said as such, not as a library's
/// "filesystem error: temp_directory_path".

#include <filesystem>

namespace ompl_glider
{
/// @brief $TMPDIR when it is set and not empty, else /tmp; it must be an existing folder.
/// @throws Error naming the folder (and TMPDIR when it came from there) when it is not.
std::filesystem::path temporaryFolder();
} // namespace ompl_glider
