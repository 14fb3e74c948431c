/// @file OutputFormatWriters.cpp
/// @brief The writers' table: each output format's files (summary.json, the route files, the goto list and the
/// Seaglider targets, stints, the map, the execution's files, the reachability files). Adding a format: its row in
/// outputFormats() (src/mission/settings/OutputFormats.cpp) and its writer here.
#include "ompl_glider/output/OutputFormatWriters.h"

#include <functional>
#include <memory>

#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#if OMPL_GLIDER_WITH_MAP
#include "ompl_glider/output/MapHtml.h"
#include "ompl_glider/output/MissionMap.h"
#endif
#include "ompl_glider/output/ExecutionFiles.h"
#include "ompl_glider/output/ReachabilityFiles.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/output/SeagliderTargets.h"
#include "ompl_glider/output/SlocumGoto.h"
#include "ompl_glider/output/SummaryJson.h"
#include "OutputDirectory.h"

namespace ompl_glider
{
namespace
{
using Listed = std::vector<std::string>;

void writeFormatText(const std::string &path, const std::string &text)
{
    output_detail::writeFileChecked(path, text);
}

/// summary.json, listing every file of the run.
std::vector<OutputFile> summaryFormatFiles(const MissionResult &r, const MissionProblem &problem, const Listed &listed)
{
    const MissionResult *res = &r;
    const MissionProblem *prob = &problem;
    return {{"summary.json",
             [res, prob, listed](const std::string &p) { writeFormatText(p, summaryJson(*res, *prob, listed)); }}};
}

std::vector<OutputFile> csvFormatFiles(const MissionResult &r, const MissionProblem &problem, const Listed &)
{
    const MissionResult *res = &r;
    const MissionProblem *prob = &problem;
    return {{"waypoints.csv", [res, prob](const std::string &p) { writeFormatText(p, waypointsCsv(*res, prob)); }}};
}

std::vector<OutputFile> pathFormatFiles(const MissionResult &r, const MissionProblem &, const Listed &)
{
    const MissionResult *res = &r;
    return {{"path.csv", [res](const std::string &p) { writeFormatText(p, pathCsv(*res)); }}};
}

std::vector<OutputFile> geoJsonFormatFiles(const MissionResult &r, const MissionProblem &problem, const Listed &)
{
    const MissionResult *res = &r;
    const MissionProblem *prob = &problem; // projects a heading route's track
    std::vector<OutputFile> files{
        {"path.geojson", [res, prob](const std::string &p) { writeFormatText(p, routeGeoJson(*res, prob)); }}};
    if (problem.isGeographic()) // the same route for Google Earth
        files.push_back({"route.kml", [res, prob](const std::string &p) { writeFormatText(p, routeKml(*res, prob)); }});
    return files;
}

std::vector<OutputFile> isochronesFormatFiles(const MissionResult &r, const MissionProblem &, const Listed &)
{
    if (!r.isochrones)
        return {};
    const MissionResult *res = &r;
    return {{"isochrones.geojson", [res](const std::string &p) { writeFormatText(p, isochronesGeoJson(*res)); }}};
}

std::vector<OutputFile> gotoFormatFiles(const MissionResult &r, const MissionProblem &problem, const Listed &)
{
    if (!problem.isGeographic())
        return {};
    const MissionResult *res = &r;
    const MissionProblem *prob = &problem; // checks the thinned list's legs
    // the Seaglider's targets file of the same turns beside the Slocum's goto list
    return {{gotoFileName(r.spec.outputs.gotoNumber),
             [res, prob](const std::string &p) { writeGotoFile(p, gotoList(*res, prob)); }},
            {"targets", [res, prob](const std::string &p) {
                 writeFormatText(p, formatSeagliderTargets(seagliderTargets(*res, prob), res->spec.name));
             }}};
}

std::vector<OutputFile> stintsFormatFiles(const MissionResult &r, const MissionProblem &problem, const Listed &)
{
    if (!r.plan.stints && !r.plan.headingRoute()) // a heading route's segments are written as stints
        return {};
    const MissionResult *res = &r;
    const MissionProblem *prob = &problem;
    return {{"stints.csv", [res, prob](const std::string &p) { writeFormatText(p, stintsCsv(*res, *prob)); }}};
}

#if OMPL_GLIDER_WITH_MAP
/// The SVG and PNG of one drawing, made once for both files.
std::vector<OutputFile> drawnFormatFiles(const std::string &stem, std::function<MapRenderer()> make)
{
    auto map = std::make_shared<std::unique_ptr<MapRenderer>>();
    auto draw = [map, make]() -> const MapRenderer & {
        if (!*map)
            *map = std::make_unique<MapRenderer>(make());
        return **map;
    };
    return {{stem + ".svg", [draw](const std::string &p) { draw().writeSvg(p); }},
            {stem + ".png", [draw](const std::string &p) { draw().writePng(p); }}};
}

std::vector<OutputFile> mapFormatFiles(const MissionResult &r, const MissionProblem &problem, const Listed &)
{
    const MissionResult *res = &r;
    const MissionProblem *prob = &problem;
    std::vector<OutputFile> files = drawnFormatFiles("map", [res, prob] { return missionMap(*res, *prob); });
    files.push_back({"map.html", [res, prob](const std::string &p) { writeFormatText(p, mapHtml(*res, *prob)); }});
    return files;
}
#else
std::vector<OutputFile> mapFormatFiles(const MissionResult &r, const MissionProblem &, const Listed &)
{
    throw Error(r.spec.file + ": field 'outputs.files': this build of ompl_glider draws no maps "
                              "(OMPL_GLIDER_WITH_MAP=OFF)");
}
#endif

std::vector<OutputFile> executionFormatFiles(const MissionResult &r, const MissionProblem &problem, const Listed &)
{
    if (!r.execution)
        return {};
    const MissionResult *res = &r;
    const MissionProblem *prob = &problem;
    std::vector<OutputFile> files{
        {"execution.csv",
         [res, prob](const std::string &p) { writeFormatText(p, executionCsv(*res->execution, *prob)); }},
        {"execution_tracks.csv",
         [res, prob](const std::string &p) { writeFormatText(p, executionTracksCsv(*res->execution, *prob)); }}};
#if OMPL_GLIDER_WITH_MAP
    for (const bool svg : {true, false})
        files.push_back({svg ? "execution.svg" : "execution.png",
                         [res, svg](const std::string &p) { writeExecutionPlot(p, *res->execution, res->spec, svg); }});
    if (r.spec.execution.truth)
        for (OutputFile &f :
             drawnFormatFiles("model_difference", [res, prob] { return modelDifferenceMap(*res, *prob); }))
            files.push_back(std::move(f));
#endif
    return files;
}

std::vector<OutputFile> reachabilityFormatFiles(const MissionResult &r, const MissionProblem &problem, const Listed &)
{
    if (!r.reachability)
        return {};
    const MissionResult *res = &r;
    const MissionProblem *prob = &problem;
    return {{"reachability.nc", [res, prob](const std::string &p) { writeReachabilityNetCdf(p, *res, *prob); }},
            {"reachability.geojson", [res](const std::string &p) { writeFormatText(p, reachabilityGeoJson(*res)); }}};
}
} // namespace

const std::vector<OutputFormatWriterRow> &outputFormatWriters()
{
    static const std::vector<OutputFormatWriterRow> writers = {
        {OutputFormatId::Summary, summaryFormatFiles},
        {OutputFormatId::Csv, csvFormatFiles},
        {OutputFormatId::Path, pathFormatFiles},
        {OutputFormatId::GeoJson, geoJsonFormatFiles},
        {OutputFormatId::Isochrones, isochronesFormatFiles},
        {OutputFormatId::Goto, gotoFormatFiles},
        {OutputFormatId::Stints, stintsFormatFiles},
        {OutputFormatId::Map, mapFormatFiles},
        {OutputFormatId::Execution, executionFormatFiles},
        {OutputFormatId::Reachability, reachabilityFormatFiles},
    };
    return writers;
}

OutputFormatWriter outputFormatWriter(OutputFormatId id)
{
    for (const OutputFormatWriterRow &row : outputFormatWriters())
        if (row.id == id)
            return row.writer;
    throw Error("output format " + std::to_string(static_cast<int>(id)) + " has no writer");
}

std::vector<std::string> declaredFileNames(const OutputFormat &format, int gotoNumber)
{
    std::vector<std::string> names;
    std::string list = format.files + ",";
    for (std::size_t at = 0, comma; (comma = list.find(',', at)) != std::string::npos; at = comma + 1)
    {
        std::string name = list.substr(at, comma - at);
        name.erase(0, name.find_first_not_of(' '));
        if (name == "goto_lNN.ma")
            name = gotoFileName(gotoNumber);
        const std::size_t slash = name.find('/');
        if (slash != std::string::npos) // "map.svg/png"
        {
            names.push_back(name.substr(0, slash));
            name = name.substr(0, name.rfind('.', slash) + 1) + name.substr(slash + 1);
        }
        names.push_back(name);
    }
    return names;
}
} // namespace ompl_glider
