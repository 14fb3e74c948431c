// The files of a forecast list: paths, glob patterns, URLs (FileList.h).
#include "ompl_glider/io/FileList.h"

#include <glob.h>

#include <filesystem>

#include "TextUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/MemoryDataset.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
std::vector<std::string> expandForecastFiles(const std::vector<std::string> &items, const std::string &baseDir)
{
    namespace fs = std::filesystem;
    std::vector<std::string> out;
    for (const std::string &item0 : items)
    {
        const std::string item = text::trim(item0);
        if (item.empty())
            throw Error("forecast files: an empty name in the list (expected file names or glob patterns, "
                        "separated by commas)");
        if (isRemoteSource(item) || isMemoryDataset(item))
        {  // an OPeNDAP URL, a dataset in memory: one dataset each, read as a file is (io/RemoteSource.h)
            out.push_back(item);
            continue;
        }
        const std::string path =
            baseDir.empty() || fs::path(item).is_absolute() ? item : (fs::path(baseDir) / item).string();
        std::error_code ec;
        if (item.find_first_of("*?[") == std::string::npos || fs::is_regular_file(path, ec))
        {  // (a file that exists is that file, even when its name holds brackets: a[1].nc)
            out.push_back(path);
            continue;
        }
        // wildcards in the file name only: a pattern reads one directory, never walks a tree
        if (fs::path(item).parent_path().string().find_first_of("*?[") != std::string::npos)
            throw Error("forecast files: the pattern '" + item + "' has wildcards in its directory; put them in the "
                        "file name only (e.g. forecasts/hycom_*.nc)");
        glob_t g{};
        const int rc = ::glob(path.c_str(), 0, nullptr, &g);
        if (rc == GLOB_NOMATCH)
        {
            globfree(&g);
            throw Error("forecast files: no file matches the pattern '" + path + "'");
        }
        if (rc != 0)
        {
            globfree(&g);
            throw Error("forecast files: cannot expand the pattern '" + path + "' (" +
                        (rc == GLOB_NOSPACE ? "out of memory" : "a directory cannot be read") + ")");
        }
        const std::size_t kMaxFiles = 100000;
        if (g.gl_pathc > kMaxFiles)
        {
            const std::size_t n = g.gl_pathc;
            globfree(&g);
            throw Error("forecast files: the pattern '" + path + "' matches " + std::to_string(n) +
                        " files, more than " + std::to_string(kMaxFiles) + "; narrow it");
        }
        for (std::size_t k = 0; k < g.gl_pathc; ++k)
            out.emplace_back(g.gl_pathv[k]);
        globfree(&g);
    }
    if (out.empty())
        throw Error("forecast files: none given");
    return out;
}

std::vector<std::string> forecastFileList(const std::string &text, const std::string &baseDir)
{
    std::vector<std::string> items;
    std::size_t from = 0;
    for (std::size_t at = text.find(','); ; at = text.find(',', from))
    {
        items.push_back(text.substr(from, at == std::string::npos ? std::string::npos : at - from));
        if (at == std::string::npos)
            break;
        from = at + 1;
    }
    return expandForecastFiles(items, baseDir);
}
}  // namespace ompl_glider
