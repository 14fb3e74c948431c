// loadGriddedCurrents(): the stages of the NetCDF reader (src/current/gridded/, see GriddedInternal.h) composed,
// and the coordinate/time conversions of GriddedCurrents.
#include "ompl_glider/current/GriddedCurrents.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "gridded/ForecastFiles.h"
#include "gridded/GriddedInternal.h"
#include "ompl_glider/Exception.h"

namespace ompl_glider
{
bool netCdfIsGeographic(const std::string &path, const GriddedCurrentOptions &opt)
{
    gridded_detail::GriddedDataset f(path);
    return gridded_detail::detectLayout(f, opt).geographic;
}

ForecastExtent readForecastExtent(const std::string &path, const GriddedCurrentOptions &opt)
{
    using namespace gridded_detail;
    GriddedDataset f(path);
    const Layout l = detectLayout(f, opt);
    ForecastExtent e;
    e.geographic = l.geographic;
    e.xName = l.xName;
    e.yName = l.yName;
    const int xv = l.curvilinear ? l.lon2D : l.coordVar[std::size_t(l.dimX)];
    const int yv = l.curvilinear ? l.lat2D : l.coordVar[std::size_t(l.dimY)];
    std::vector<double> x = f.readAll1D(xv);
    std::vector<double> y = f.readAll1D(yv);
    if (x.empty() || y.empty())
        throw f.error("coordinates '" + l.xName + "'/'" + l.yName + "' have no values");
    checkAxisValues(f, yv, y, "coordinate"); // (latitude first, as the loader checks them)
    checkAxisValues(f, xv, x, "coordinate");
    unpackCoordinates(f, xv, x);
    unpackCoordinates(f, yv, y);
    if (l.geographic)
    {
        // each longitude the shorter way from the first: a regional grid's span, wherever its seam
        const double ref = x.front();
        for (double &v : x)
            v = wrapTo(v, ref);
    }
    const auto [x0, x1] = std::minmax_element(x.begin(), x.end());
    const auto [y0, y1] = std::minmax_element(y.begin(), y.end());
    e.lonMin = *x0;
    e.lonMax = *x1;
    e.latMin = *y0;
    e.latMax = *y1;
    if (l.geographic)
    {
        e.allLongitudes = e.lonMax - e.lonMin >= 358.0; // (a global grid, its spacing of up to 2 degrees)
        const double w = e.lonMax - e.lonMin;
        e.lonMin = normalizeLongitude(e.lonMin);
        e.lonMax = e.lonMin + w;
    }
    return e;
}

GriddedCurrents loadGriddedCurrents(const std::string &path, const GriddedCurrentOptions &opt)
{
    gridded_detail::ForecastPiece p = gridded_detail::readForecastPiece(path, opt);
    return gridded_detail::buildForecast(p, opt, "netcdf:" + path);
}

// The stages of one file up to its land (the forecast in several files reads each file with it: ForecastFiles.cpp),
// then the field (buildForecast()).
gridded_detail::ForecastPiece gridded_detail::readForecastPiece(const std::string &path,
                                                                const GriddedCurrentOptions &opt,
                                                                const AxisSelection *times, std::size_t totalTimes)
{
    using namespace gridded_detail;
    ForecastPiece p;
    p.file = std::make_unique<GriddedDataset>(path);
    const GriddedDataset &f = *p.file;
    GriddedCurrents &out = p.out;
    out.files = {path};
    // what is in the file: velocities, their grid, units
    const Layout &l = p.layout = detectLayout(f, opt);
    out.uVariable = l.uName;
    out.depthAxis = l.dimZ >= 0;
    out.vVariable = l.vName;
    out.geographic = l.geographic;
    const LinearConversion vel = velocityConversionOf(f, l, opt);
    // what to load: depth layers, forecast times, region (its memory checked before the nodes are read)
    const RegionOfInterest &region = p.region = regionOfInterest(opt, l.geographic);
    if (opt.depthAverage && !(opt.depthAverage->first >= 0.0 && opt.depthAverage->first <= opt.depthAverage->second &&
                              std::isfinite(opt.depthAverage->second)))
        throw f.error("depth average over " + std::to_string(opt.depthAverage->first) + ".." +
                      std::to_string(opt.depthAverage->second) + " m: expected 0 <= top <= bottom, finite");
    if (opt.depthAverage && (l.dimZ < 0 || f.dimLen(l.dims[std::size_t(l.dimZ)]) < 2))
        throw f.error("a depth average (GriddedCurrentOptions::depthAverage) needs several depth levels, but '" +
                      l.uName + "' has " + (l.dimZ < 0 ? std::string("no depth dimension") : "a single depth level") +
                      ": remove the depth average to plan on this level");
    const AxisSelection &z = p.z = selectDepths(f, l, opt.depthAverage ? opt.depthAverage->second : opt.maxDepth);
    // the records: chosen here (one file), or given (one file of a forecast in several files)
    if (times && l.dimT < 0)
        throw f.error("variable '" + l.uName +
                      "' has no time dimension: it cannot be part of a forecast in several "
                      "files");
    const AxisSelection &t = p.t = times ? *times : selectTimes(f, l, opt, out);
    const HorizontalSubset &h = p.h =
        l.curvilinear ? curvilinearSubset(f, l, region, z, t) : rectilinearSubset(f, l, region, z, t);
    if (totalTimes > t.idx.size())
        checkTripMemory(f, h.xIdx.size(), h.yIdx.size(), totalTimes, z.idx.size());
    // read u, v and build the grid
    const HyperslabPlan plan = planHyperslab(f, l, h, z, t);
    out.fileValues = plan.fileValues;
    GriddedData &g = p.g;
    g.nx = h.xIdx.size();
    g.ny = h.yIdx.size();
    g.depth = z.values;
    g.time = t.values;
    GriddedCurrentOptions unpack = opt;
    unpack.zeroVelocityLand = false; // decided after every other signal of land (zeroVelocityLand())
    if (l.staggered)
        readStaggeredVelocities(f, l, h, z, t, vel, unpack, g, out);
    else
        readVelocities(f, l, plan, t, vel, unpack, g, out);
    rotateGridToEastNorth(f, l, h, g, out);
    // land is the union of every signal the file gives, each node counted for the first that marks it
    p.fillWater = g.water;
    applyLandMask(f, l, h, z, t, opt, g, out);
    p.maskWater = g.water;
    applyTracerLand(f, l, h, z, t, opt, g, out);
    p.cornerGrid = out.cornerGrid;
    if (opt.zeroVelocityLand && !times) // (a forecast in several files decides it on all its records)
    {
        const Packing pu = packingOf(f, l.uVar), pv = packingOf(f, l.vVar);
        const bool packed = pu.scale != 1.0 || pu.offset != 0.0 || pv.scale != 1.0 || pv.offset != 0.0;
        const bool otherLand = out.fillLandNodes + out.maskLandNodes + out.tracerLandNodes > 0;
        out.zeroLandNodes = zeroVelocityLand(g, t, packed, zeroLandRule(f, l, h, otherLand, out.cornerGrid));
    }
    zeroLandVelocities(g);
    checkVelocityMagnitudes(f, l, h, t, opt, g);
    out.landNodes = static_cast<std::size_t>(std::count(g.water.begin(), g.water.end(), 0));
    if (z.sigma)
    {
        const double deepest = opt.depthAverage ? opt.depthAverage->second : opt.maxDepth;
        std::vector<double> requested{opt.maxDepth};
        if (opt.depthAverage)
            requested = {opt.depthAverage->first, opt.depthAverage->second};
        remapSigmaToDepths(f, l, h, z, t, deepest, requested, g);
        out.landNodes = static_cast<std::size_t>(std::count(g.water.begin(), g.water.end(), 0));
    }
    if (p.fillWater.size() != g.water.size())
        p.fillWater = p.maskWater = g.water; // layers remapped: land from fill values is not told apart from the
                                             // mask's and the tracer's
    return p;
}

GriddedCurrents gridded_detail::buildForecast(ForecastPiece &p, const GriddedCurrentOptions &opt,
                                              const std::string &fieldName)
{
    const GriddedDataset &f = *p.file;
    const gridded_detail::Layout &l = p.layout;
    const gridded_detail::HorizontalSubset &h = p.h;
    const gridded_detail::RegionOfInterest &region = p.region;
    const gridded_detail::AxisSelection &z = p.z, &t = p.t;
    GriddedData &g = p.g;
    GriddedCurrents out = std::move(p.out);
    if (opt.depthAverage)
        averageOverDepth(opt.depthAverage->first, opt.depthAverage->second, g);
    out.projection = setNodeCoordinates(f, l, h, region, opt, g);
    if (!l.geographic && l.dimX >= 0)
        out.xyMetres = gridded_detail::axisConversion(f, l.coordVar[std::size_t(l.dimX)]).factor;
    out.lonMin = l.geographic ? normalizeLongitude(h.lonLo) : h.lonLo;
    out.lonMax = out.lonMin + (h.lonHi - h.lonLo);
    out.latMin = h.latLo;
    out.latMax = h.latHi;
    GriddedFieldOptions fo = opt.field;
    if (fo.name == "gridded" || fo.name.empty())
        fo.name = fieldName;
    out.loadedShape = {t.idx.size(), z.idx.size(), g.ny, g.nx};
    out.loadedValues = g.u.size();
    try
    {
        out.field = std::make_shared<GriddedCurrentField>(std::move(g), fo);
    }
    catch (const Error &e)
    {
        throw f.error(std::string("variables '") + out.uVariable + "'/'" + out.vVariable + "': " + e.what());
    }
    return out;
}
} // namespace ompl_glider
