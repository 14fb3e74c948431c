#include "ompl_glider/output/OutputWriter.h"

#include <atomic>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#if OMPL_GLIDER_WITH_MAP
#include "ompl_glider/output/MissionMap.h"
#endif
#include "ompl_glider/output/ExecutionFiles.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/output/SlocumGoto.h"
#include "ompl_glider/output/SummaryJson.h"

namespace ompl_glider
{
namespace fs = std::filesystem;

namespace
{
void writeText(const std::string &path, const std::string &text)
{
    std::ofstream out(path, std::ios::binary);
    if (!out || !(out << text) || !out.flush())
        throw Error("cannot write '" + path + "'");
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
        return {{"path.geojson", [res, prob](const std::string &p) { writeText(p, routeGeoJson(*res, prob)); }}};
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
        return {{gotoFileName(r.spec.outputs.gotoNumber),
                 [res](const std::string &p) { writeGotoFile(p, gotoList(*res)); }}};
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
                {"map.png", [draw](const std::string &p) { draw().writePng(p); }}};
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

/// A plain file name (no directory part, not "." or ".."): only such names are ever removed.
bool plainName(const std::string &name)
{
    return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos &&
           name.find('\\') == std::string::npos;
}

fs::path normalised(const std::string &directory)
{
    fs::path p = fs::absolute(directory.empty() ? fs::path(".") : fs::path(directory)).lexically_normal();
    if (p.filename().empty() && p.has_parent_path() && p != p.root_path())
        p = p.parent_path();  // trailing slash
    return p;
}

fs::path stagingDirectory(const fs::path &target)
{
    static std::atomic<unsigned> counter{0};
    const std::string base = target.filename().string();
    return target.parent_path() /
           ("." + (base.empty() ? std::string("out") : base) + ".tmp-" + std::to_string(::getpid()) + "-" +
            std::to_string(counter++));
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
    const fs::path target = normalised(directory);
    std::error_code ec;
    if (fs::exists(target, ec) && !fs::is_directory(target, ec))
        throw Error("output directory '" + directory + "' exists and is not a directory");
    // The staging directory is made beside the target: its parent (or the nearest existing ancestor) must be a
    // writable directory.
    fs::path parent = target.parent_path();
    while (!parent.empty() && !fs::exists(parent, ec) && parent != parent.root_path())
        parent = parent.parent_path();
    if (!fs::is_directory(parent, ec))
        throw Error("output directory '" + directory + "': '" + parent.string() + "' is not a directory");
    if (::access(parent.c_str(), W_OK | X_OK) != 0 ||
        (fs::exists(target, ec) && ::access(target.c_str(), W_OK | X_OK) != 0))
        throw Error("output directory '" + directory + "' is not writable");
    // access() says yes to root everywhere (even in /proc): make and remove a directory where the staging
    // directory will go.
    const fs::path probe = parent / (".ompl_glider-probe-" + std::to_string(::getpid()));
    if (!fs::create_directory(probe, ec))
        throw Error("output directory '" + directory + "' cannot be created: no directory can be made in '" +
                    parent.string() + "'" + (ec ? " (" + ec.message() + ")" : std::string()));
    fs::remove(probe, ec);
}

std::vector<std::string> writeOutputFiles(const std::string &directory, const std::vector<OutputFile> &files)
{
    checkOutputDirectory(directory);
    const fs::path target = normalised(directory);
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
    const fs::path staging = stagingDirectory(target);
    if (!fs::create_directory(staging, ec))
        throw Error("cannot create the temporary directory '" + staging.string() + "'" +
                    (ec ? ": " + ec.message() : std::string()));
    std::set<std::string> names;
    try
    {
        for (const OutputFile &f : files)
        {
            if (!plainName(f.name) || !names.insert(f.name).second)
                throw Error("output file name '" + f.name + "' is not a plain, unique file name");
            f.write((staging / f.name).string());
        }
    }
    catch (...)
    {
        fs::remove_all(staging, ec);
        throw;
    }
    // Everything was written: move it into place.
    std::vector<std::string> written;
    if (!fs::exists(target, ec))
    {
        fs::rename(staging, target, ec);
        if (ec)
        {
            fs::remove_all(staging, ec);
            throw Error("cannot create the output directory '" + directory + "': " + ec.message());
        }
    }
    else
    {
        const std::vector<std::string> old = previousManifest(target);
        for (const OutputFile &f : files)
        {
            fs::rename(staging / f.name, target / f.name, ec);
            if (ec)
            {
                fs::remove_all(staging, ec);
                throw Error("cannot move '" + f.name + "' into '" + directory + "': " + ec.message());
            }
        }
        for (const std::string &name : old)
            if (plainName(name) && !names.count(name))
                fs::remove(target / name, ec);
        fs::remove_all(staging, ec);
    }
    for (const OutputFile &f : files)
        written.push_back((fs::path(directory.empty() ? "." : directory) / f.name).string());
    return written;
}

std::vector<std::string> writeOutputs(const MissionResult &result, const MissionProblem &problem)
{
    return writeOutputFiles(result.spec.outputs.directory, outputFiles(result, problem));
}
}  // namespace ompl_glider
