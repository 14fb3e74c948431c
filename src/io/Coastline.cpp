// Land polygons from a vector GIS file through GDAL/OGR (see Coastline.h).
#include "ompl_glider/io/Coastline.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <mutex>

#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include "ompl_glider/Exception.h"
#include "GdalModule.h"
#include "DatasetLock.h"
#include "NumberText.h"

namespace ompl_glider
{
namespace
{
void registerDrivers()
{
    static std::once_flag once;
    std::call_once(once, [] {
        GDALAllRegister();
        CPLSetErrorHandler(CPLQuietErrorHandler); // errors reach the user through our messages
    });
}

std::vector<LonLat> ringOf(const OGRLinearRing &r)
{
    std::vector<LonLat> v;
    for (int k = 0; k < r.getNumPoints(); ++k)
        v.push_back({r.getX(k), r.getY(k)});
    if (v.size() > 1 && v.front().lon == v.back().lon && v.front().lat == v.back().lat)
        v.pop_back();
    return v;
}

void addPolygon(const OGRPolygon &p, std::vector<LandPolygon> &out)
{
    if (p.IsEmpty() || !p.getExteriorRing())
        return;
    LandPolygon lp;
    lp.outer = ringOf(*p.getExteriorRing());
    for (int k = 0; k < p.getNumInteriorRings(); ++k)
        lp.holes.push_back(ringOf(*p.getInteriorRing(k)));
    if (lp.outer.size() >= 3)
        out.push_back(std::move(lp));
}

/// Polygons of a (clipped) geometry; lines and points left by the clipping (land touching the box's edge) are
/// dropped.
void collect(const OGRGeometry &g, std::vector<LandPolygon> &out)
{
    switch (wkbFlatten(g.getGeometryType()))
    {
    case wkbPolygon:
        addPolygon(*g.toPolygon(), out);
        break;
    case wkbMultiPolygon:
    case wkbGeometryCollection: {
        const auto &c = *g.toGeometryCollection();
        for (int k = 0; k < c.getNumGeometries(); ++k)
            collect(*c.getGeometryRef(k), out);
        break;
    }
    default:
        break;
    }
}

/// "lon -80.1, lat 25.2"
std::string lonLat(double lon, double lat)
{
    return "lon " + text::number(lon) + ", lat " + text::number(lat);
}

/// The land of one feature's geometry as a multipolygon: polygons as they are, closed lines (a shoreline written as
/// lines) as the outline of land, and the members of a geometry collection likewise, at any depth. An open line, a
/// point or any other kind is refused, naming the member: a shoreline is never dropped in silence.
std::unique_ptr<OGRGeometry> landGeometry(std::unique_ptr<OGRGeometry> g, const std::string &which)
{
    auto out = std::make_unique<OGRMultiPolygon>();
    const std::function<void(const OGRGeometry &, const std::string &)> add = [&](const OGRGeometry &m,
                                                                                  const std::string &where) {
        switch (wkbFlatten(m.getGeometryType()))
        {
        case wkbPolygon:
            out->addGeometry(&m);
            break;
        case wkbLineString: {
            const OGRLineString &l = *m.toLineString();
            const int n = l.getNumPoints();
            if (n < 4 || !l.get_IsClosed())
                throw Error(
                    which + where + ": an open line" +
                    (n > 0 ? " from " + lonLat(l.getX(0), l.getY(0)) + " to " + lonLat(l.getX(n - 1), l.getY(n - 1))
                           : std::string()) +
                    "; expected land polygons (or closed shorelines)");
            OGRLinearRing r;
            r.addSubLineString(&l);
            OGRPolygon p;
            p.addRing(&r);
            out->addGeometry(&p);
            break;
        }
        case wkbMultiPolygon:
        case wkbMultiLineString:
        case wkbGeometryCollection: {
            const auto &c = *m.toGeometryCollection();
            const bool collection = wkbFlatten(m.getGeometryType()) == wkbGeometryCollection;
            for (int k = 0; k < c.getNumGeometries(); ++k)
                if (!c.getGeometryRef(k)->IsEmpty())
                    add(*c.getGeometryRef(k),
                        collection ? where + ", member " + std::to_string(k + 1) + " of its collection" : where);
            break;
        }
        default:
            throw Error(which + where + ": a " + OGRGeometryTypeToName(m.getGeometryType()) +
                        "; expected land polygons (or closed shorelines)");
        }
    };
    add(*g, "");
    return out;
}

/// GEOS's reason why @p g is invalid (OGR reports it as a warning), or "" when it is valid.
std::string invalidity(const OGRGeometry &g)
{
    CPLErrorReset();
    if (g.IsValid())
        return "";
    const std::string reason = CPLGetLastErrorMsg();
    return reason.empty() ? "invalid (GEOS)" : reason;
}

/// The feature as messages name it: its `name` attribute, else its index.
std::string featureName(const OGRFeature &f)
{
    const int k = f.GetFieldIndex("name");
    if (k >= 0 && f.IsFieldSetAndNotNull(k) && *f.GetFieldAsString(k))
        return std::string("'") + f.GetFieldAsString(k) + "'";
    return std::to_string(f.GetFID());
}

/// The rectangle (@p lonMin, @p latMin) to (@p lonMax, @p latMax) a turn of @p shift degrees east: a layer written
/// in 0..360 (or beyond -180) holds the land of -180..180 a turn away; what it clips is brought back by the turn.
OGRPolygon boxPolygon(double lonMin, double latMin, double lonMax, double latMax, double shift)
{
    OGRPolygon box;
    OGRLinearRing r;
    r.addPoint(lonMin + shift, latMin);
    r.addPoint(lonMax + shift, latMin);
    r.addPoint(lonMax + shift, latMax);
    r.addPoint(lonMin + shift, latMax);
    r.closeRings();
    box.addRing(&r);
    return box;
}

/// The transformation of @p layer's coordinates to lon/lat (@p wgs84); null where they are lon/lat already or the
/// layer has no spatial reference. @p who names the file in an error.
std::unique_ptr<OGRCoordinateTransformation> transformToLonLat(OGRLayer &layer, const OGRSpatialReference &wgs84,
                                                               const std::string &who)
{
    std::unique_ptr<OGRCoordinateTransformation> toLonLat;
    if (const OGRSpatialReference *srs = layer.GetSpatialRef())
    {
        OGRSpatialReference src(*srs);
        src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        if (!src.IsSame(&wgs84))
        {
            toLonLat.reset(OGRCreateCoordinateTransformation(&src, &wgs84));
            if (!toLonLat)
                throw Error(who + ", layer '" + layer.GetName() +
                            "': its spatial reference cannot be transformed to lon/lat (WGS 84)");
        }
    }
    return toLonLat;
}

/// The envelope of @p g, refused (for @p which) where it is not lon/lat: a projected file without its spatial
/// reference.
OGREnvelope lonLatEnvelope(const OGRGeometry &g, const std::string &which)
{
    OGREnvelope e;
    g.getEnvelope(&e);
    if (!(e.MinX >= -180.0 && e.MaxX <= 360.0 && e.MinY >= -90.0 && e.MaxY <= 90.0))
        throw Error(which + ": coordinates up to " +
                    lonLat(std::abs(e.MinX) > std::abs(e.MaxX) ? e.MinX : e.MaxX,
                           std::abs(e.MinY) > std::abs(e.MaxY) ? e.MinY : e.MaxY) +
                    " are not lon/lat (longitude -180..360, latitude -90..90): a projected file (web-mercator "
                    "metres?) needs its spatial reference (a GeoJSON 'crs' member, a shapefile's .prj)");
    return e;
}
} // namespace

std::string gdal_detail::polygonFault(const std::vector<Point2> &outer, const std::vector<std::vector<Point2>> &holes)
{
    registerDrivers();
    OGRPolygon p;
    auto add = [&p](const std::vector<Point2> &ring) {
        OGRLinearRing r;
        for (const Point2 &q : ring)
            r.addPoint(q.x, q.y);
        r.closeRings();
        p.addRing(&r);
    };
    add(outer);
    for (const auto &h : holes)
        add(h);
    return invalidity(p);
}

std::vector<LandPolygon> gdal_detail::readLandPolygons(const std::string &path, const GeoBox &box,
                                                       std::vector<std::string> *repairs, CoastlineCount *count)
{
    // the GDAL dataset, from its opening to its closing at the end of this function, under the process's one lock
    // of GDAL's datasets and NetCDF-C (DatasetLock.h: GDAL's netCDF driver reads vector NetCDF files too)
    const gridded_detail::DatasetLock lock;
    const double lonMin = box.lonMin, latMin = box.latMin, lonMax = box.lonMax, latMax = box.latMax;
    registerDrivers();
    const std::string who = "coastline file '" + path + "'";
    if (!(lonMin < lonMax) || !(latMin < latMax))
        throw Error(who + ": empty box");
    std::unique_ptr<GDALDataset> ds(
        GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    if (!ds)
        throw Error(who + ": cannot open it as a vector GIS file (GeoJSON, Shapefile, KML, GeoPackage...): " +
                    CPLGetLastErrorMsg());
    if (ds->GetLayerCount() == 0)
        throw Error(who + ": holds no layer");
    OGRSpatialReference wgs84;
    if (wgs84.importFromEPSG(4326) != OGRERR_NONE)
        throw Error(who + ": cannot set up lon/lat (EPSG:4326): is PROJ's database (proj-data) installed?");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::vector<LandPolygon> out;
    for (OGRLayer *layer : ds->GetLayers())
    {
        const std::unique_ptr<OGRCoordinateTransformation> toLonLat = transformToLonLat(*layer, wgs84, who);
        layer->ResetReading();
        for (auto &feature : *layer)
        {
            const OGRGeometry *g0 = feature->GetGeometryRef();
            if (!g0 || g0->IsEmpty())
                continue;
            std::unique_ptr<OGRGeometry> g(g0->clone());
            const std::string name = featureName(*feature);
            const std::string which = who + ", layer '" + layer->GetName() + "', feature " + name;
            if (toLonLat && g->transform(toLonLat.get()) != OGRERR_NONE)
                throw Error(which + ": its coordinates cannot be transformed to lon/lat");
            g = landGeometry(std::move(g), which);
            const OGREnvelope e = lonLatEnvelope(*g, which);
            if (count)
            {
                ++count->features;
                count->lonMin = std::min(count->lonMin, e.MinX);
                count->lonMax = std::max(count->lonMax, e.MaxX);
                count->latMin = std::min(count->latMin, e.MinY);
                count->latMax = std::max(count->latMax, e.MaxY);
            }
            bool valid = false;
            for (double shift : {0.0, 360.0, -360.0})
            {
                if (e.MaxX < lonMin + shift || e.MinX > lonMax + shift || e.MaxY < latMin || e.MinY > latMax)
                    continue;
                const std::string fault = valid ? std::string() : invalidity(*g);
                if (!fault.empty())
                {
                    std::unique_ptr<OGRGeometry> fixed(g->MakeValid());
                    if (!fixed || !fixed->IsValid())
                        throw Error(which + ": an invalid polygon (" + fault +
                                    ", in lon lat) that OGR's MakeValid cannot repair");
                    g = std::move(fixed);
                    if (repairs)
                        repairs->push_back("feature " + name + ": " + fault +
                                           " (lon lat): repaired by OGR's MakeValid");
                }
                if (count && !valid)
                {
                    ++count->used;
                    count->usedFeatures.insert(std::string(layer->GetName()) + "/" + std::to_string(feature->GetFID()));
                }
                valid = true;
                const OGRPolygon box = boxPolygon(lonMin, latMin, lonMax, latMax, shift);
                std::unique_ptr<OGRGeometry> clipped(g->Intersection(&box));
                if (!clipped)
                    throw Error(which + ": cannot be clipped to the trip's box (GEOS)");
                const std::size_t first = out.size();
                collect(*clipped, out);
                for (std::size_t k = first; k < out.size(); ++k)
                {
                    out[k].name = feature->GetFieldIndex("name") >= 0 && name.front() == '\''
                                      ? name.substr(1, name.size() - 2)
                                      : "feature " + name;
                    for (LonLat &p : out[k].outer)
                        p.lon -= shift;
                    for (auto &hole : out[k].holes)
                        for (LonLat &p : hole)
                            p.lon -= shift;
                }
            }
        }
    }
    return out;
}
} // namespace ompl_glider
