#include "ompl_glider/output/OutputWriter.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#if OMPL_GLIDER_WITH_MAP
#include "ompl_glider/output/MapHtml.h"
#include "ompl_glider/output/MissionMap.h"
#endif
#include "ompl_glider/output/ExecutionFiles.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/output/SlocumGoto.h"
#include "ompl_glider/output/SeagliderTargets.h"
#include "ompl_glider/output/SummaryJson.h"
#include "OutputDirectory.h"

namespace ompl_glider
{
namespace fs = std::filesystem;

namespace
{
void writeText(const std::string &path, const std::string &text)
{
    output_detail::writeFileChecked(path, text);
}

/// The route and map files of one format (summary.json is added by outputFiles()).
std::vector<OutputFile> formatFiles(OutputFormatId format, const MissionResult &r, const MissionProblem &problem)
{
    const MissionResult *res = &r;
    if (format == OutputFormatId::Csv)
        return {{"waypoints.csv", [res](const std::string &p) { writeText(p, waypointsCsv(*res)); }}};
    if (format == OutputFormatId::Path)
        return {{"path.csv", [res](const std::string &p) { writeText(p, pathCsv(*res)); }}};
    if (format == OutputFormatId::GeoJson)
    {
        const MissionProblem *prob = &problem;  // projects a heading route's track
        std::vector<OutputFile> files{
            {"path.geojson", [res, prob](const std::string &p) { writeText(p, routeGeoJson(*res, prob)); }}};
        if (problem.isGeographic())  // the same route for Google Earth
            files.push_back({"route.kml", [res, prob](const std::string &p) { writeText(p, routeKml(*res, prob)); }});
        return files;
    }
    if (format == OutputFormatId::Isochrones)
    {
        if (!r.isochrones)
            return {};
        return {{"isochrones.geojson", [res](const std::string &p) { writeText(p, isochronesGeoJson(*res)); }}};
    }
    if (format == OutputFormatId::Stints)
    {
        if (!r.plan.stints && !r.plan.headingRoute())  // a heading route's segments are written as stints
            return {};
        const MissionProblem *prob = &problem;
        return {{"stints.csv", [res, prob](const std::string &p) { writeText(p, stintsCsv(*res, *prob)); }}};
    }
    if (format == OutputFormatId::Goto)
    {
        if (!problem.isGeographic())
            return {};
        const MissionProblem *prob = &problem;  // checks the thinned list's legs
        // the Seaglider's targets file of the same turns beside the Slocum's goto list
        return {{gotoFileName(r.spec.outputs.gotoNumber),
                 [res, prob](const std::string &p) { writeGotoFile(p, gotoList(*res, prob)); }},
                {"targets", [res, prob](const std::string &p) {
                     writeText(p, formatSeagliderTargets(seagliderTargets(*res, prob), res->spec.name));
                 }}};
    }
    if (format == OutputFormatId::Execution)
    {
        if (!r.execution)
            return {};
        const MissionProblem *prob = &problem;
        std::vector<OutputFile> files{
            {"execution.csv", [res, prob](const std::string &p) { writeText(p, executionCsv(*res->execution, *prob)); }},
            {"execution_tracks.csv",
             [res, prob](const std::string &p) { writeText(p, executionTracksCsv(*res->execution, *prob)); }}};
#if OMPL_GLIDER_WITH_MAP
        for (const bool svg : {true, false})
            files.push_back({svg ? "execution.svg" : "execution.png", [res, svg](const std::string &p) {
                                 writeExecutionPlot(p, *res->execution, res->spec, svg);
                             }});
        if (r.spec.execution.truth)
        {
            auto map = std::make_shared<std::unique_ptr<MapRenderer>>();
            auto draw = [map, res, prob]() -> const MapRenderer & {
                if (!*map)
                    *map = std::make_unique<MapRenderer>(modelDifferenceMap(*res, *prob));
                return **map;
            };
            files.push_back({"model_difference.svg", [draw](const std::string &p) { draw().writeSvg(p); }});
            files.push_back({"model_difference.png", [draw](const std::string &p) { draw().writePng(p); }});
        }
#endif
        return files;
    }
#if OMPL_GLIDER_WITH_MAP
    if (format == OutputFormatId::Map)
    {
        // One drawing for both files.
        auto map = std::make_shared<std::unique_ptr<MapRenderer>>();
        const MissionProblem *prob = &problem;
        auto draw = [map, res, prob]() -> const MapRenderer & {
            if (!*map)
                *map = std::make_unique<MapRenderer>(missionMap(*res, *prob));
            return **map;
        };
        return {{"map.svg", [draw](const std::string &p) { draw().writeSvg(p); }},
                {"map.png", [draw](const std::string &p) { draw().writePng(p); }},
                {"map.html", [res, prob](const std::string &p) { writeText(p, mapHtml(*res, *prob)); }}};
    }
#else
    if (format == OutputFormatId::Map)
        throw Error(r.spec.file + ": field 'outputs.files': this build of ompl_glider draws no maps "
                                  "(OMPL_GLIDER_WITH_MAP=OFF)");
#endif
    return {};
}

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

}  // namespace

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
        for (OutputFile &f : formatFiles(format.id, r, problem))
            files.push_back(std::move(f));
    }
    const std::string &prefix = r.spec.outputs.prefix;
    std::vector<std::string> names = {"summary.json"};
    for (const OutputFile &f : files)
        names.push_back(f.name);
    if (!prefix.empty())
        for (std::size_t i = 0, n = names.size(); i < n; ++i)
            names.push_back(prefix + "_" + names[i]);
    const MissionResult *res = &r;
    const MissionProblem *prob = &problem;
    files.insert(files.begin(), OutputFile{"summary.json", [res, prob, names](const std::string &p) {
                                               writeText(p, summaryJson(*res, *prob, names));
                                           }});
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
    // Every name a run can write (outputFormats()' file lists: "a.csv, b.svg/png, goto_lNN.ma"), with the prefix.
    std::vector<std::string> names;
    for (const OutputFormat &format : outputFormats())
    {
        std::string list = format.files + ",";
        for (std::size_t at = 0, comma; (comma = list.find(',', at)) != std::string::npos; at = comma + 1)
        {
            std::string name = list.substr(at, comma - at);
            name.erase(0, name.find_first_not_of(' '));
            if (name == "goto_lNN.ma")
                name = gotoFileName(outputs.gotoNumber);
            const std::size_t slash = name.find('/');
            if (slash != std::string::npos)  // "map.svg/png"
            {
                names.push_back(name.substr(0, slash));
                name = name.substr(0, name.rfind('.', slash) + 1) + name.substr(slash + 1);
            }
            names.push_back(name);
        }
    }
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
        std::string what = e.what();  // name the file where it was meant to go, not in the staging directory
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
}  // namespace ompl_glider
