// What a mission reads about land and depth (ProblemInputs.h): the coastline's land polygons about the planning box,
// the bathymetry of the depth limit (MissionSpec::safety) and of the dive profiles (MissionSpec::dive); the problem
// turns them into forbidden regions (src/mission/problem/Land.cpp, Safety.cpp).
#include "InputsInternal.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "../../io/NumberText.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Bathymetry.h"
#include "ompl_glider/io/Coastline.h"
#include "ompl_glider/io/DepthGrid.h"
#include "ompl_glider/io/GeoBox.h"

namespace ompl_glider::inputs_detail
{
namespace
{
/// The lon/lat box a bathymetry grid is read over: the box with a margin of 5 %; the whole grid when the mission is
/// not geographic.
GeoBox bathymetryRegion(const PlanningFrame &frame)
{
    GeoBox region = GeoBox::world();
    if (frame.isGeographic())
    {
        const Region &b = frame.box;
        const GeoBox gb =
            frameBounds(Box{b.xMin, b.xMax, b.yMin, b.yMax}, [&frame](Point2 p) { return frame.toGeographic(p); });
        const double pad = 0.05 * std::max(gb.lonMax - gb.lonMin, gb.latMax - gb.latMin);
        region = {gb.lonMin - pad, gb.lonMax + pad, std::max(-90.0, gb.latMin - pad), std::min(90.0, gb.latMax + pad)};
    }
    return region;
}
} // namespace

void readCoastline(ProblemInputs &in)
{
    // the coastline's land polygons that meet the box (with a margin of a tenth of its size)
    const MissionSpec &m = in.spec;
    if (m.forbidden.coastline.empty())
        return;
    const SourceMark &mk = m.forbidden.coastlineMark;
    const std::string at = mk.namesItself() ? mk.file + ": " : sourcePlace(m, mk);
    if (!in.frame.isGeographic())
        throw Error(at + "forbidden.coastline: the coastline is in lon/lat; give a 'projection' in the mission");
    const PlanningFrame &frame = in.frame;
    const Region &b0 = frame.box;
    const GeoBox gb =
        frameBounds(Box{b0.xMin, b0.xMax, b0.yMin, b0.yMax}, [&frame](Point2 p) { return frame.toGeographic(p); });
    const double lon0 = gb.lonMin, lon1 = gb.lonMax, lat0 = gb.latMin, lat1 = gb.latMax;
    const double pad = 0.1 * std::max(lon1 - lon0, lat1 - lat0);
    std::vector<LandPolygon> &land = in.coastline;
    try
    {
        // the box in -180..180; across the antimeridian, its two sides
        const double a = lon0 - pad, b = lon1 + pad, s = std::max(-90.0, lat0 - pad), n = std::min(90.0, lat1 + pad);
        std::vector<std::pair<double, double>> spans;
        if (b - a >= 360.0)
            spans = {{-180.0, 180.0}};
        else if (a < -180.0)
            spans = {{a + 360.0, 180.0}, {-180.0, b}};
        else if (b > 180.0)
            spans = {{a, 180.0}, {-180.0, b - 360.0}};
        else
            spans = {{a, b}};
        std::vector<std::string> repairs;
        CoastlineCount count;
        std::set<std::string> usedFeatures; // a feature across the antimeridian meets both spans: counted once
        for (const auto &[w, e] : spans)
        {
            count = {};
            for (LandPolygon &p : readLandPolygons(m.forbidden.coastline, GeoBox{w, e, s, n}, &repairs, &count))
                land.push_back(std::move(p));
            usedFeatures.insert(count.usedFeatures.begin(), count.usedFeatures.end());
        }
        const int used = static_cast<int>(usedFeatures.size());
        // none used: open water in a larger file, or a file nowhere near the trip (lon and lat swapped, another
        // region): the latter is refused, with where the file's features lie
        const double near = std::max(lon1 - lon0, lat1 - lat0);
        auto nearBox = [&](double shift) {
            return count.lonMax + shift >= lon0 - near && count.lonMin + shift <= lon1 + near &&
                   count.latMax >= lat0 - near && count.latMin <= lat1 + near;
        };
        if (count.features > 0 && used == 0 && !nearBox(0.0) && !nearBox(360.0) && !nearBox(-360.0))
            throw Error("coastline file '" + m.forbidden.coastline + "': none of its " +
                        std::to_string(count.features) + " features lies in or near the trip's box (" + gb.text() +
                        "); they lie within lon " + text::number(count.lonMin) + ".." + text::number(count.lonMax) +
                        ", lat " + text::number(count.latMin) + ".." + text::number(count.latMax) +
                        " (lon and lat swapped? another region?)");
        in.coastlineNote = std::to_string(land.size()) + " land polygons from " + std::to_string(used) + " of " +
                           std::to_string(count.features) + " features of '" + m.forbidden.coastline + "'";
        for (const std::string &r : repairs)
            in.coastlineNote += "; " + r;
    }
    catch (const Error &e)
    {
        throw Error(at + e.what());
    }
}

void readDepthLimit(ProblemInputs &in)
{
    const MissionSpec &m = in.spec;
    const bool limit = m.marks.count("safety.min_depth") > 0 || !m.safety.bathymetry.empty();
    if (!limit)
        return;
    const std::string field = m.safety.bathymetry.empty() ? "safety.min_depth" : "safety.bathymetry";
    std::string file = m.safety.bathymetry;
    if (file.empty())
    {
        if (in.forecastFiles.empty())
            throw Error(m.place(field) + ": a depth limit needs a bathymetry file (" + m.term("safety.bathymetry") +
                        ")");
        file = in.forecastFiles.front(); // the model's own bathymetry (ROMS h)
    }
#if OMPL_GLIDER_WITH_NETCDF
    try
    {
        DepthGrid g = readDepthGrid(file, m.safety.bathymetryVariable, bathymetryRegion(in.frame));
        if (g.geographic && !in.frame.isGeographic())
            throw Error("the bathymetry is on longitude/latitude: the mission needs a projection");
        in.depthGrid = std::make_shared<const DepthGrid>(std::move(g));
        in.depthGridFile = file;
    }
    catch (const Error &e)
    {
        throw Error(m.place(field) + ": " + e.what());
    }
#else
    throw Error(m.place(field) + ": this build of ompl_glider has no NetCDF support");
#endif
}

void readDiveBathymetry(ProblemInputs &in)
{
    const MissionSpec &m = in.spec;
    if (!m.dive.enabled)
        return;
    if (m.dive.bathymetry == DiveSpec::Bathymetry::Constant)
    {
        const double d = m.dive.bathymetryDepth;
        in.diveBathymetry = std::make_shared<FunctionBathymetry>([d](double, double) { return d; });
    }
    else if (m.dive.bathymetry == DiveSpec::Bathymetry::File)
    {
#if !OMPL_GLIDER_WITH_NETCDF
        throw Error(m.file + ": field 'dive_profile.bathymetry': this build has no NetCDF support");
#else
        std::function<LonLat(double, double)> geo;
        if (in.frame.isGeographic())
            geo = [frame = in.frame](double x, double y) { return frame.toGeographic({x, y}); };
        try
        {
            in.diveBathymetry =
                readBathymetry(m.dive.bathymetryFile, m.dive.bathymetryVariable, geo, bathymetryRegion(in.frame));
        }
        catch (const Error &e)
        {
            throw Error(m.file + ": field 'dive_profile.bathymetry': " + e.what());
        }
#endif
    }
}
} // namespace ompl_glider::inputs_detail
