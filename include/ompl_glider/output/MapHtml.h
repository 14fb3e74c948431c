#pragma once
/// @file MapHtml.h
/// @brief map.html: the plan on an interactive map that works offline (Leaflet from Debian's libjs-leaflet, built
/// into the page): the route and its waypoints (a popup with the arrival date, the heading to hold, the current
/// there), start and goal, isochrones, the model's land and the coastline, forbidden regions and the keep-off band,
/// the current as arrows at the times of the plan with a time slider, the flown tracks of an execution run; a lon/lat
/// graticule, a scale and a legend; OpenStreetMap tiles only when the browser reaches them.

#include <string>
#include <vector>

namespace ompl_glider
{
struct MissionResult;
class MissionProblem;

/// @brief The map's data of one plan (a JSON object: the frame, land, regions, currents and its route), what
/// mapHtml() draws; a fleet's gliders each give theirs where they are planned (FleetFiles.h).
std::string mapHtmlData(const MissionResult &result, const MissionProblem &problem);

/// @brief The page of one or more plans' data (mapHtmlData()): the first gives the frame, land, regions and
/// currents, every one its route and waypoints in its own colour (a fleet); @p title names the page.
/// @throws Error when @p data is empty or not what mapHtmlData() writes.
std::string mapHtmlPage(const std::vector<std::string> &data, const std::string &title);

/// @brief The data of a page mapHtml() or mapHtmlPage() wrote (what a fleet's glider rendered where it was planned);
/// empty when @p page is not such a page.
std::string mapHtmlDataOf(const std::string &page);

/// @brief mapHtmlPage() of one plan, titled by its mission.
std::string mapHtml(const MissionResult &result, const MissionProblem &problem);
} // namespace ompl_glider
