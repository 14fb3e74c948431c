#include "ompl_glider/output/OutputWriter.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "ompl_glider/Exception.h"
#include "ompl_glider/output/OutputFormatWriters.h"
#include "OutputDirectory.h"

namespace ompl_glider
{
namespace fs = std::filesystem;

namespace
{
/// The names an earlier run listed in DIR/summary.json (empty when there is none or it cannot be read).
std::vector<std::string> previousManifest(const fs::path &dir)
{
    std::error_code ec;
    if (!fs::is_regular_file(dir / "summary.json", ec))
        return {};
    std::ifstream in(dir / "summary.json");
    if (!in)
        return {};
    try
    {
        const nlohmann::json j = nlohmann::json::parse(in);
        if (j.is_object() && j.contains("files") && j["files"].is_array())
        {
            std::vector<std::string> names;
            for (const auto &f : j["files"])
                if (f.is_string())
                    names.push_back(f.get<std::string>());
            return names;
        }
    }
    catch (const nlohmann::json::exception &)
    {
    }
    return {};
}

/// A plain file name (no directory part, not "." or ".."), or one in a folder ("alpha/summary.json": a fleet's
/// glider): only such names are ever removed.
bool plainName(const std::string &name)
{
    const auto plain = [](const std::string &n) {
        return !n.empty() && n != "." && n != ".." && n.find('/') == std::string::npos &&
               n.find('\\') == std::string::npos;
    };
    const std::size_t slash = name.find('/');
    return slash == std::string::npos ? plain(name) : plain(name.substr(0, slash)) && plain(name.substr(slash + 1));
}

} // namespace

std::vector<OutputFile> outputFiles(const MissionResult &r, const MissionProblem &problem)
{
    std::vector<OutputFile> files;
    for (const OutputFormat &format : outputFormats())
    {
        if (format.id == OutputFormatId::Summary)
            continue;
        const bool wanted = (format.id == OutputFormatId::Execution && r.execution) || r.spec.outputs.wants(format.id);
        if (!wanted || (format.route && !r.plan.solved))
            continue;
        for (OutputFile &f : outputFormatWriter(format.id)(r, problem, {}))
            files.push_back(std::move(f));
    }
    const std::string &prefix = r.spec.outputs.prefix;
    std::vector<std::string> names = {"summary.json"};
    for (const OutputFile &f : files)
        names.push_back(f.name);
    if (!prefix.empty())
        for (std::size_t i = 0, n = names.size(); i < n; ++i)
            names.push_back(prefix + "_" + names[i]);
    // summary.json first, listing every file (its own name and the prefixed copies included)
    std::vector<OutputFile> summary = outputFormatWriter(OutputFormatId::Summary)(r, problem, names);
    files.insert(files.begin(), summary.begin(), summary.end());
    if (!prefix.empty())
        for (std::size_t i = 0, n = files.size(); i < n; ++i)
            files.push_back({prefix + "_" + files[i].name, files[i].write});
    return files;
}

void checkOutputDirectory(const std::string &directory)
{
    const fs::path target = output_detail::resolveOutputDirectory(directory);
    std::error_code ec;
    if (fs::exists(target, ec) && !fs::is_directory(target, ec))
        throw Error("output directory '" + directory + "' exists and is not a directory");
    // The staging directory is made beside the target (its parent, or the nearest existing ancestor, must be a
    // writable directory), or inside the target when only the target may be written.
    fs::path parent = target.parent_path();
    while (!parent.empty() && !fs::exists(parent, ec) && parent != parent.root_path())
        parent = parent.parent_path();
    if (!fs::is_directory(parent, ec))
        throw Error("output directory '" + directory + "': '" + parent.string() + "' is not a directory");
    const bool targetExists = fs::exists(target, ec);
    if (targetExists && ::access(target.c_str(), W_OK | X_OK) != 0)
        throw Error("output directory '" + directory + "' is not writable (" + std::strerror(errno) + ")");
    const fs::path work = targetExists ? output_detail::workDirOf(target) : parent;
    if (::access(work.c_str(), W_OK | X_OK) != 0)
        throw Error("output directory '" + directory + "' is not writable (" + std::strerror(errno) + ")");
    // access() says yes to root everywhere (even in /proc or on a read-only mount): make and remove a directory
    // where the staging directory will go.
    // (a unique name: threads of one process may check sibling directories at once)
    std::string probe = (work / ".ompl_glider-probe-XXXXXX").string();
    if (!::mkdtemp(&probe[0]))
        throw Error("output directory '" + directory + "' cannot be written: no directory can be made in '" +
                    work.string() + "' (" + std::strerror(errno) + ")");
    fs::remove(probe, ec);
}

void checkOutputNames(const OutputSpec &outputs)
{
    const fs::path target = output_detail::resolveOutputDirectory(outputs.directory);
    std::error_code ec;
    if (!fs::is_directory(target, ec))
        return;
    // Every name a run can write (outputFormats()' file lists), with the prefix.
    std::vector<std::string> names;
    for (const OutputFormat &format : outputFormats())
        for (std::string &name : declaredFileNames(format, outputs.gotoNumber))
            names.push_back(std::move(name));
    for (std::size_t i = 0, n = names.size(); i < n && !outputs.prefix.empty(); ++i)
        names.push_back(outputs.prefix + "_" + names[i]);
    for (const std::string &name : names)
        if (fs::symlink_status(target / name, ec).type() == fs::file_type::directory)
            throw Error("output directory '" + outputs.directory + "' holds a directory '" + name +
                        "' where glider_plan writes a file; nothing was replaced (remove it or choose another "
                        "output directory)");
}

std::vector<std::string> writeOutputFiles(const std::string &directory, const std::vector<OutputFile> &files)
{
    checkOutputDirectory(directory);
    const std::string shown = directory.empty() ? "." : directory;
    std::vector<std::string> names;
    std::set<std::string> unique;
    for (const OutputFile &f : files)
    {
        if (!plainName(f.name) || !unique.insert(f.name).second)
            throw Error("output file name '" + f.name + "' is not a plain, unique file name");
        names.push_back(f.name);
    }
    const OutputLock lock(directory);
    const fs::path target = output_detail::resolveOutputDirectory(directory);
    output_detail::removeStaleStaging(target);
    const fs::path staging = output_detail::makeStaging(target);
    output_detail::setStaging(true);
    try
    {
        for (const OutputFile &f : files)
        {
            output_detail::interruptIfSignalled(staging);
            if (f.name.find('/') != std::string::npos)
                fs::create_directory((staging / f.name).parent_path());
            f.write((staging / f.name).string());
        }
        output_detail::interruptIfSignalled(staging);
        output_detail::stepHook("staged");
        output_detail::commitStaging(staging, target, names, previousManifest(target), shown);
    }
    catch (const Error &e)
    {
        std::error_code ec;
        fs::remove_all(staging, ec);
        output_detail::setStaging(false);
        output_detail::raisePendingSignal();
        std::string what = e.what(); // name the file where it was meant to go, not in the staging directory
        const std::string from = staging.string() + "/";
        for (std::size_t at = what.find(from); at != std::string::npos; at = what.find(from))
            what.replace(at, from.size(), (fs::path(shown) / "").string());
        throw Error(what + "; the output directory '" + shown + "' was left as it was");
    }
    catch (...)
    {
        std::error_code ec;
        fs::remove_all(staging, ec);
        output_detail::setStaging(false);
        throw;
    }
    output_detail::setStaging(false);
    output_detail::raisePendingSignal();
    std::vector<std::string> written;
    for (const std::string &name : names)
        written.push_back((fs::path(shown) / name).string());
    return written;
}

std::vector<std::string> writeOutputs(const MissionResult &result, const MissionProblem &problem)
{
    return writeOutputFiles(result.spec.outputs.directory, outputFiles(result, problem));
}
} // namespace ompl_glider
