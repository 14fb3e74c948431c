/// @file TempFolder.cpp
/// @brief The checked folder for temporary files (TempFolder.h).

#include "ompl_glider/io/TempFolder.h"

#include <cstdlib>
#include <string>
#include <system_error>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
std::filesystem::path temporaryFolder()
{
    const char *env = std::getenv("TMPDIR");
    const bool fromEnv = env && *env;
    const std::filesystem::path dir = fromEnv ? std::filesystem::path(env) : std::filesystem::path("/tmp");
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
        throw Error("the folder for temporary files '" + dir.string() + "'" +
                    (fromEnv ? " (the environment variable TMPDIR)" : std::string()) +
                    " does not exist or is not a folder: set TMPDIR to a writable folder");
    return dir;
}
} // namespace ompl_glider
