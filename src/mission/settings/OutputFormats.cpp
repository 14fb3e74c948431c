#include "ompl_glider/mission/OutputFormats.h"

// Adding a format: its value of OutputFormatId, its row here, and its writer in src/output/OutputFormatWriters.cpp.

namespace ompl_glider
{
const std::vector<OutputFormat> &outputFormats()
{
    static const std::vector<OutputFormat> formats = {
        {OutputFormatId::Summary, "summary", "summary.json", "what was planned and how (always written)", false},
        {OutputFormatId::Csv, "csv", "waypoints.csv", "waypoints with times, lon/lat and dive profiles", true},
        {OutputFormatId::Path, "path", "path.csv", "the final path: t,x,y,lon,lat", true},
        {OutputFormatId::GeoJson, "geojson", "path.geojson, route.kml",
         "the path and its waypoints as GeoJSON, and for Google Earth as KML (route.kml: geographic missions)", true},
        {OutputFormatId::Isochrones, "isochrones", "isochrones.geojson",
         "reachable-set contours (level set) at times after the departure, as GeoJSON, also drawn on the map", false},
        {OutputFormatId::Goto, "goto", "goto_lNN.ma, targets",
         "Slocum goto list and Seaglider targets file of the route's turns (geographic missions)", true},
        {OutputFormatId::Stints, "stints", "stints.csv",
         "heading per surfacing: time, position, heading, expected drift (missions with stints)", true},
        {OutputFormatId::Map, "map", "map.svg, map.png, map.html",
         "map of the current, regions and paths; map.html: the same to explore in a browser", false},
        {OutputFormatId::Execution, "execution",
         "execution.csv, execution_tracks.csv, execution.svg/png, model_difference.svg/png",
         "the plan flown in the truth per strategy, and the box plot of a batch (written whenever the mission has "
         "an execution section)",
         false},
        {OutputFormatId::Reachability, "reachability", "reachability.nc, reachability.geojson",
         "the probability of reach over the ensemble's members (level set per member): fields per time as NetCDF "
         "(CF), contours per time and level as GeoJSON, the goal's arrival quantiles in summary.json",
         false},
    };
    return formats;
}

std::optional<OutputFormatId> outputFormatByName(const std::string &name)
{
    for (const OutputFormat &format : outputFormats())
        if (format.name == name)
            return format.id;
    return std::nullopt;
}
} // namespace ompl_glider
