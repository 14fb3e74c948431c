#pragma once
/// @file Coastline.h
/// @brief Land polygons from a vector GIS file (GeoJSON, ESRI Shapefile, KML, GeoPackage, GMT/OGR...), read with
/// GDAL/OGR: the coastline a pilot has (GSHHG, Natural Earth, a national chart's land area), forbidden to the
/// glider and drawn on the map.

#include <set>
#include <string>
#include <vector>

#include "ompl_glider/io/GeoBox.h"
#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
/// @brief One land polygon in lon/lat (degrees, WGS 84), rings not closed (the first vertex is not repeated).
struct LandPolygon
{
    std::vector<LonLat> outer;
    std::vector<std::vector<LonLat>> holes; ///< lakes
    std::string name;                       ///< the feature's `name` attribute, else "feature <FID>"
};

/// @brief What a coastline file held: its features with a geometry, those that met the box, and their extent in
/// lon/lat (after the transformation), so that a file lying nowhere near the trip can be told from open water.
struct CoastlineCount
{
    int features{0};                    ///< features with a geometry
    int used{0};                        ///< features that met the box
    std::set<std::string> usedFeatures; ///< those features (layer/FID): a feature met by two reads counts once
    double lonMin{1e300}, lonMax{-1e300}, latMin{1e300}, latMax{-1e300}; ///< the features' extent
};

/// @brief The land polygons of every layer of @p path that meet @p box ([lonMin, lonMax] x [latMin, latMax]),
/// clipped to it (GEOS intersection through OGR), so that only what the trip can meet is kept.
///
/// Polygons and multi-polygons are read as they are; closed line strings (a shoreline written as a line, as GMT's
/// `coast -M` and some charts do) are taken as the outline of land. Coordinates are transformed to WGS 84 lon/lat
/// from the layer's spatial reference when it has another one (a file without one is taken as lon/lat). The box
/// must not cross the antimeridian (lonMin < lonMax within -180..180).
/// Every polygon GEOS calls valid is taken as it is (a hole may touch its outer ring or another hole at a point,
/// as GSHHG's do); the others are repaired by OGR's MakeValid, and each repair is described in @p repairs (when
/// given): the feature, GEOS's reason and its place in lon/lat.
/// @throws Error naming the file, the layer and the feature (its `name`, else its index) and giving places in lon/lat,
/// when it cannot be opened, holds no layer, holds an open line or a point where land is expected, or has
/// coordinates that cannot be transformed to lon/lat, or coordinates (after the transformation) outside lon
/// -180..360, lat -90..90 (a projected file without a spatial reference: a GeoJSON without a `crs` member, a
/// shapefile without its `.prj`). @p count (when given) is added to.
std::vector<LandPolygon> readLandPolygons(const std::string &path, const GeoBox &box,
                                          std::vector<std::string> *repairs = nullptr, CoastlineCount *count = nullptr);

/// @brief Why GEOS (through OGR) calls the polygon with outer ring @p outer and @p holes invalid ("Self-intersection
/// at or near point 1 2", in the rings' own coordinates), or "" when it is valid.
std::string polygonFault(const std::vector<Point2> &outer, const std::vector<std::vector<Point2>> &holes);
} // namespace ompl_glider
