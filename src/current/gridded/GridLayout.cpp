// The grid of the velocities: 1-D longitude/latitude (or x/y) axes or a 2-D curvilinear grid, geographic or
// Cartesian.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
/// u and v, with the same 2 to 4 dimensions.
void findVelocities(const GriddedDataset &f, const GriddedCurrentOptions &opt, Layout &l)
{
    l.uVar = findVelocity(f, opt.uName, true, "uName");
    l.vVar = findVelocity(f, opt.vName, false, "vName");
    l.uName = f.varName(l.uVar);
    l.vName = f.varName(l.vVar);
    const std::vector<int> dims = f.varDims(l.uVar);
    l.uDims = dims;
    l.vDims = f.varDims(l.vVar);
    l.staggered = l.vDims != dims;
    if (l.staggered && (l.vDims.size() != dims.size() || dims.size() < 2 ||
                        !std::equal(dims.begin(), dims.end() - 2, l.vDims.begin())))
        throw f.error("velocity variables '" + l.uName + "' and '" + l.vName +
                      "' differ in more than their two horizontal dimensions; expected the same time and depth "
                      "dimensions (a staggered grid puts only the horizontal points apart)");
    if (dims.size() < 2 || dims.size() > 5) // 5: a file of several forecast runs (run, time, depth, lat, lon)
        throw f.error("variable '" + l.uName + "': expected 2 to 4 dimensions ([time,] [depth,] lat, lon), got " +
                      std::to_string(dims.size()));
}

/// The runs of a file of several forecast runs (Role::Run): before time, time a 2-D time(run, time) (or 1-D for a
/// single run); the run read is GriddedCurrentOptions::runIndex (checked when the times are chosen, checkRunIndex()).
void placeRuns(const GriddedDataset &f, const GriddedCurrentOptions &opt, Layout &l)
{
    const std::size_t others = l.dims.size() - (l.dimRun >= 0 ? 1 : 0);
    if (others > 4)
        throw f.error("variable '" + l.uName + "': expected 2 to 4 dimensions ([time,] [depth,] lat, lon), got " +
                      std::to_string(l.dims.size()) + " (a file of several forecast runs has a run dimension first)");
    if (l.dimRun < 0)
        return;
    l.runVar = l.coordVar[std::size_t(l.dimRun)];
    l.run = opt.runIndex.value_or(0);
    const int runDim = l.dims[std::size_t(l.dimRun)];
    const std::string runName = f.dimName(runDim);
    if (l.dimT < 0 || l.dimT < l.dimRun)
        throw f.error("variable '" + l.uName + "' is on dimension '" + runName +
                      "' of forecast runs but has no time dimension after it; expected (run, time, [depth,] lat, lon)");
    const int tVar = l.coordVar[std::size_t(l.dimT)];
    const std::vector<int> td = f.varDims(tVar);
    const bool twoD = td == std::vector<int>{runDim, l.dims[std::size_t(l.dimT)]};
    if (!twoD && f.dimLen(runDim) > 1)
        throw f.error("variable '" + l.uName + "' is on dimension '" + runName + "' of " +
                      std::to_string(f.dimLen(runDim)) + " forecast runs, but its time '" + f.varName(tVar) +
                      "' is not a 2-D time(" + runName + ", " + f.dimName(l.dims[std::size_t(l.dimT)]) +
                      "); expected a THREDDS FMRC's layout");
}

/// Candidate 2-D coordinate variables on (j, i): those of u's `coordinates` attribute first, then all.
std::vector<int> curvilinearCandidates(const GriddedDataset &f, int uVar, const std::vector<int> &want)
{
    std::vector<int> cands;
    auto consider = [&](int var) {
        if (f.varDims(var) == want)
            cands.push_back(var);
    };
    if (auto c = f.attText(uVar, "coordinates"))
    {
        std::istringstream is(*c);
        std::string tok;
        while (is >> tok)
            if (auto v = f.findVar(tok))
                consider(*v);
    }
    for (int var = 0; var < f.nvars(); ++var)
        consider(var);
    return cands;
}

/// The 2-D longitude/latitude (x/y in Cartesian mode) variables of a curvilinear grid on (j, i) = want.
void findCurvilinearCoordinates(const GriddedDataset &f, const GriddedCurrentOptions &opt, const std::vector<int> &want,
                                Layout &l)
{
    const bool cartesian = opt.coordinates == CoordinateMode::Cartesian;
    if (!opt.lonName.empty())
        l.lon2D = *f.findVar(opt.lonName);
    if (!opt.latName.empty())
        l.lat2D = *f.findVar(opt.latName);
    for (int var : curvilinearCandidates(f, l.uVar, want))
    {
        if (l.lon2D < 0 && ((!cartesian && isLonVar(f, var)) || (cartesian && isXVar(f, var))))
            l.lon2D = var;
        if (l.lat2D < 0 && ((!cartesian && isLatVar(f, var)) || (cartesian && isYVar(f, var))))
            l.lat2D = var;
    }
    if (l.lon2D < 0 || l.lat2D < 0)
        throw f.error("variable '" + l.uName + "' is on dimensions (" + f.dimName(want[0]) + ", " + f.dimName(want[1]) +
                      ") without 1-D axes; expected 2-D longitude/latitude variables on them "
                      "(from its 'coordinates' attribute, standard_name or units degrees_east/degrees_north)");
    if (f.varDims(l.lon2D) != want || f.varDims(l.lat2D) != want)
        throw f.error("curvilinear coordinates '" + f.varName(l.lon2D) + "'/'" + f.varName(l.lat2D) +
                      "': expected dimensions (" + f.dimName(want[0]) + ", " + f.dimName(want[1]) + ")");
}

/// The describing text "name = length" of a dimension.
std::string dimText(const GriddedDataset &f, int dim)
{
    return f.dimName(dim) + " = " + std::to_string(f.dimLen(dim));
}

/// The rho (cell centre) dimensions (eta_rho, xi_rho) of a ROMS-like C grid: u on (eta_u, xi_u) with
/// eta_u = eta_rho and xi_u = xi_rho - 1, v on (eta_v, xi_v) with eta_v = eta_rho - 1 and xi_v = xi_rho; found
/// from the 2-D longitude/latitude (x/y) variables of that shape. @throws Error when the staggering is another.
std::vector<int> rhoDimensions(const GriddedDataset &f, const GriddedCurrentOptions &opt, const Layout &l)
{
    const std::size_t n = l.uDims.size();
    const int ueta = l.uDims[n - 2], uxi = l.uDims[n - 1], veta = l.vDims[n - 2], vxi = l.vDims[n - 1];
    const bool cartesian = opt.coordinates == CoordinateMode::Cartesian;
    for (int var = 0; var < f.nvars(); ++var)
    {
        const std::vector<int> d = f.varDims(var);
        if (d.size() != 2 || !(cartesian ? isXVar(f, var) : isLonVar(f, var)))
            continue;
        if (f.dimLen(d[0]) == f.dimLen(ueta) && f.dimLen(d[1]) == f.dimLen(uxi) + 1 &&
            f.dimLen(d[0]) == f.dimLen(veta) + 1 && f.dimLen(d[1]) == f.dimLen(vxi))
            return d;
    }
    throw f.error("velocity variables '" + l.uName + "' (" + dimText(f, ueta) + ", " + dimText(f, uxi) + ") and '" +
                  l.vName + "' (" + dimText(f, veta) + ", " + dimText(f, vxi) +
                  ") are on different grids; a staggered grid is read as an Arakawa C grid as ROMS writes it (u one "
                  "point shorter than the cell centres in x, v one shorter in y, with 2-D longitude/latitude on the "
                  "cell centres), and no such longitude variable was found");
}

/// The grid angle variable: the given one (which must be 2-D on the grid), else one named "angle" on the grid,
/// unless u is named eastward; its unit (radians or degrees). -1 when none: then a curvilinear grid's angle is
/// derived from its coordinates (Layout::deriveAngle) unless u is named eastward or the angle is "none".
void findAngle(const GriddedDataset &f, const GriddedCurrentOptions &opt, Layout &l)
{
    const std::vector<int> grid = {l.dims[std::size_t(l.dimY)], l.dims[std::size_t(l.dimX)]};
    if (lower(opt.angleName) == "none")
        return;
    if (!opt.angleName.empty())
    {
        const auto v = f.findVar(opt.angleName);
        if (!v)
            throw f.error("no grid angle variable '" + opt.angleName + "' (given as GriddedCurrentOptions::angleName)",
                          "GriddedCurrentOptions::angleName");
        if (f.varDims(*v) != grid)
            throw f.error("grid angle variable '" + opt.angleName +
                              "' (GriddedCurrentOptions::angleName) is not on "
                              "the grid of the velocities (" +
                              dimText(f, grid[0]) + ", " + dimText(f, grid[1]) + ")",
                          "GriddedCurrentOptions::angleName");
        l.angleVar = *v;
    }
    else
    {
        // velocities that say they are eastward (standard_name, a name such as ROMS' u_eastward, or a long_name
        // "zonal"/"eastward" where no standard_name calls them grid-relative, as POP's rotated urot) are not turned
        const std::string sn = stdName(f, l.uVar);
        const std::string longName = lower(f.attText(l.uVar, "long_name").value_or(""));
        const bool gridRelative = sn.find("x_velocity") != std::string::npos || sn.find("grid") != std::string::npos;
        if (sn.find("eastward") != std::string::npos || lower(l.uName).find("east") != std::string::npos ||
            (!gridRelative &&
             (longName.find("zonal") != std::string::npos || longName.find("eastward") != std::string::npos)))
            return;
        for (int var = 0; var < f.nvars() && l.angleVar < 0; ++var)
            if (lower(f.varName(var)) == "angle")
            {
                if (f.varDims(var) != grid) // (a 1-D angle on a 2-D grid would turn nothing, in silence)
                    throw f.error("grid angle variable '" + f.varName(var) +
                                  "' is not on the grid of the "
                                  "velocities (" +
                                  dimText(f, grid[0]) + ", " + dimText(f, grid[1]) +
                                  "): give the grid's angle with GriddedCurrentOptions::angleName, or 'none' when "
                                  "the velocities are east/north");
                l.angleVar = var;
            }
        if (l.angleVar < 0)
        {
            // nothing says the velocities are eastward: on a curvilinear grid they may run along it (ROMS, NEMO)
            l.deriveAngle = l.curvilinear;
            return;
        }
    }
    const std::string units = lower(trim(unitsOf(f, l.angleVar)));
    if (inList(units, {"radian", "radians", "rad"}))
        l.angleToRadians = 1.0;
    else if (inList(units, {"degree", "degrees", "deg", "degrees_east", "degrees_north"}))
        l.angleToRadians = M_PI / 180.0;
    else
        throw f.error("grid angle variable '" + f.varName(l.angleVar) + "' has units '" + units +
                      "'; expected radians or degrees");
}

/// Without 1-D x/y axes: the two remaining dimensions of length > 1 are (j, i) in file order, with 2-D
/// coordinates. Updates the roles and geoAxes/cartAxes.
void makeCurvilinear(const GriddedDataset &f, const GriddedCurrentOptions &opt, Layout &l, bool &geoAxes,
                     bool &cartAxes)
{
    std::vector<int> rest;
    for (std::size_t d = 0; d < l.dims.size(); ++d)
        if (l.role[d] == Role::None && f.dimLen(l.dims[d]) > 1)
            rest.push_back(int(d));
    if (rest.size() != 2 || l.dimX >= 0 || l.dimY >= 0)
        throw f.error("variable '" + l.uName +
                      "': expected longitude/latitude (or x/y) axes or a 2-D curvilinear grid; found no horizontal "
                      "coordinate variables (name them with GriddedCurrentOptions::lonName/latName)");
    l.dimY = rest[0];
    l.dimX = rest[1];
    l.role[std::size_t(l.dimY)] = Role::Y;
    l.role[std::size_t(l.dimX)] = Role::X;
    l.curvilinear = true;
    if (l.staggered)
    {
        const std::vector<int> rho = rhoDimensions(f, opt, l);
        l.dims[std::size_t(l.dimY)] = rho[0];
        l.dims[std::size_t(l.dimX)] = rho[1];
    }
    findCurvilinearCoordinates(f, opt, {l.dims[std::size_t(l.dimY)], l.dims[std::size_t(l.dimX)]}, l);
    geoAxes = opt.coordinates != CoordinateMode::Cartesian && isLonVar(f, l.lon2D) && isLatVar(f, l.lat2D);
    cartAxes = !geoAxes;
}

/// @throws Error when a dimension of the velocities has length 0 (an UNLIMITED dimension without records, say):
/// naming its coordinate variable when it has one.
void checkNoEmptyDimension(const GriddedDataset &f, const Layout &l)
{
    for (std::size_t d = 0; d < l.dims.size(); ++d)
    {
        if (f.dimLen(l.dims[d]) > 0)
            continue;
        const std::string dim = "'" + f.dimName(l.dims[d]) + "' has length 0";
        if (l.coordVar[d] < 0)
            throw f.error("variable '" + l.uName + "' has no values: its dimension " + dim);
        const std::string kind = l.role[d] == Role::Time ? "time variable '" : "coordinate '";
        throw f.error(kind + f.varName(l.coordVar[d]) + "' has no values: its dimension " + dim);
    }
}

/// Geographic or Cartesian, from the options and what the axes looked like.
bool decideGeographic(const GriddedDataset &f, const GriddedCurrentOptions &opt, const Layout &l, bool geoAxes,
                      bool cartAxes)
{
    if (opt.coordinates == CoordinateMode::Geographic)
    {
        if (!geoAxes)
            throw f.error("expected longitude/latitude coordinates (units degrees_east/degrees_north or standard_name "
                          "longitude/latitude) for variable '" +
                          l.uName + "' (CoordinateMode::Geographic)");
        return true;
    }
    if (opt.coordinates == CoordinateMode::Cartesian)
        return false;
    return geoAxes && !cartAxes;
}
} // namespace

Layout detectLayout(const GriddedDataset &f, const GriddedCurrentOptions &opt)
{
    Layout l;
    findVelocities(f, opt, l);
    DimensionRoles dr = classifyDimensions(f, opt, l.uVar);
    l.dimT = dr.find(Role::Time);
    l.dimZ = dr.find(Role::Depth);
    l.dimX = dr.find(Role::X);
    l.dimY = dr.find(Role::Y);
    l.dimRun = dr.find(Role::Run);
    l.dims = std::move(dr.dims);
    l.role = std::move(dr.role);
    l.coordVar = std::move(dr.coordVar);
    bool geoAxes = dr.geoAxes, cartAxes = dr.cartAxes;
    checkNoEmptyDimension(f, l);
    placeRuns(f, opt, l);
    if (l.staggered && (l.dimX >= 0 || l.dimY >= 0))
        throw f.error("velocity variables '" + l.uName + "' and '" + l.vName +
                      "' are on different grids with 1-D axes; only a ROMS-like C grid with 2-D coordinates on "
                      "its cell centres is read as a staggered grid");
    if (l.dimX < 0 || l.dimY < 0)
        makeCurvilinear(f, opt, l, geoAxes, cartAxes);
    for (std::size_t d = 0; d < l.dims.size(); ++d)
        if (l.role[d] == Role::None && f.dimLen(l.dims[d]) > 1)
            throw f.error("variable '" + l.uName + "' has dimension '" + f.dimName(l.dims[d]) + "' (length " +
                          std::to_string(f.dimLen(l.dims[d])) +
                          ") that is neither time, depth, latitude nor longitude; expected (time, depth, lat, lon)");
    l.geographic = decideGeographic(f, opt, l, geoAxes, cartAxes);
    l.xName = l.curvilinear ? f.varName(l.lon2D) : f.varName(l.coordVar[std::size_t(l.dimX)]);
    l.yName = l.curvilinear ? f.varName(l.lat2D) : f.varName(l.coordVar[std::size_t(l.dimY)]);
    findAngle(f, opt, l);
    return l;
}
} // namespace gridded_detail
} // namespace ompl_glider
