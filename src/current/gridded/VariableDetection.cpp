// Which variables are the velocities and what each of their dimensions is (CF standard_name, axis attribute,
// units, then usual names).
#include <algorithm>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{
std::string stdName(const GriddedDataset &f, int var)
{
    return lower(f.attText(var, "standard_name").value_or(""));
}

std::string unitsOf(const GriddedDataset &f, int var)
{
    return f.attText(var, "units").value_or("");
}

namespace
{
std::string axisOf(const GriddedDataset &f, int var)
{
    return lower(f.attText(var, "axis").value_or(""));
}
} // namespace

bool isLonVar(const GriddedDataset &f, int var)
{
    const std::string u = lower(unitsOf(f, var)), sn = stdName(f, var), n = lower(f.varName(var));
    return inList(u, {"degrees_east", "degree_east", "degrees_e", "degree_e", "degreese", "degreee"}) ||
           sn == "longitude" || inList(n, {"lon", "longitude", "nav_lon", "glamt", "tlong", "lon_rho", "longitudes"});
}

bool isLatVar(const GriddedDataset &f, int var)
{
    const std::string u = lower(unitsOf(f, var)), sn = stdName(f, var), n = lower(f.varName(var));
    return inList(u, {"degrees_north", "degree_north", "degrees_n", "degree_n", "degreesn", "degreen"}) ||
           sn == "latitude" || inList(n, {"lat", "latitude", "nav_lat", "gphit", "tlat", "lat_rho", "latitudes"});
}

bool isXVar(const GriddedDataset &f, int var)
{
    const std::string sn = stdName(f, var), n = lower(f.varName(var));
    return sn == "projection_x_coordinate" || axisOf(f, var) == "x" || inList(n, {"x", "xc", "x_rho", "easting"});
}

bool isYVar(const GriddedDataset &f, int var)
{
    const std::string sn = stdName(f, var), n = lower(f.varName(var));
    return sn == "projection_y_coordinate" || axisOf(f, var) == "y" || inList(n, {"y", "yc", "y_rho", "northing"});
}

bool isTimeVar(const GriddedDataset &f, int var)
{
    const std::string u = lower(unitsOf(f, var)), sn = stdName(f, var), n = lower(f.varName(var));
    return u.find(" since ") != std::string::npos || sn == "time" || axisOf(f, var) == "t" ||
           inList(n, {"time", "t", "time_counter", "ocean_time", "valid_time", "mt"});
}

bool isRunVar(const GriddedDataset &f, int var)
{
    const std::string n = lower(f.varName(var));
    const bool numbered = n.rfind("reftime", 0) == 0 && n.find_first_not_of("0123456789", 7) == std::string::npos;
    return stdName(f, var) == "forecast_reference_time" ||
           lower(f.attText(var, "_CoordinateAxisType").value_or("")) == "runtime" || numbered ||
           inList(n, {"run", "runtime", "forecast_reference_time"});
}

bool isDepthVar(const GriddedDataset &f, int var)
{
    const std::string sn = stdName(f, var), n = lower(f.varName(var));
    return sn == "depth" || axisOf(f, var) == "z" || f.attText(var, "positive") ||
           inList(n, {"depth", "deptht", "depthu", "depthv", "depthw", "z", "lev", "level", "zlev"});
}

namespace
{
/// "name(dim,dim,...) [units]" of every variable with 2 or more dimensions: what the user may mean by u and v.
std::string candidateList(const GriddedDataset &f)
{
    std::string out;
    for (int var = 0; var < f.nvars(); ++var)
    {
        const std::vector<int> dims = f.varDims(var);
        if (dims.size() < 2)
            continue;
        std::string item = f.varName(var) + "(";
        for (std::size_t d = 0; d < dims.size(); ++d)
            item += (d ? "," : "") + f.dimName(dims[d]);
        const std::string units = trim(unitsOf(f, var));
        item += ") [" + (units.empty() ? std::string("no units") : units) + "]";
        out += (out.empty() ? "" : ", ") + item;
    }
    return out.empty() ? "none (no variable has 2 or more dimensions)" : out;
}
} // namespace

/// A NetCDF-4 file whose variables lie in groups: only the root group is read, so a velocity not found there is
/// refused naming the groups (not as a missing variable). "" without groups.
std::string groupNote(const GriddedDataset &f)
{
    std::string names;
    for (const std::string &name : f.groupNames())
        names += (names.empty() ? "'" : ", '") + name + "'";
    if (names.empty())
        return "";
    return "the velocities are not in the root group, and the file has NetCDF-4 groups (" + names +
           "): only the root group is read; copy the group's variables out first (nccopy -G or ncks -G : -g NAME)";
}

int findVelocity(const GriddedDataset &f, const std::string &given, bool east, const std::string &optionName)
{
    const std::string groups = groupNote(f);
    if (!given.empty())
    {
        auto v = f.findVar(given);
        if (!v && !groups.empty())
            throw f.error("no variable '" + given + "' in the root group: " + groups,
                          "GriddedCurrentOptions::" + optionName);
        if (!v)
            throw f.error("no variable '" + given + "' (given with GriddedCurrentOptions::" + optionName +
                              "); candidates: " + candidateList(f) +
                              (f.unreadable().empty() ? std::string() : "; and " + f.unreadable()),
                          "GriddedCurrentOptions::" + optionName);
        return *v;
    }
    const std::vector<std::string> stdNames =
        east ? std::vector<std::string>{"eastward_sea_water_velocity",
                                        "surface_eastward_sea_water_velocity",
                                        "eastward_sea_water_velocity_assuming_no_tide",
                                        "baroclinic_eastward_sea_water_velocity",
                                        "barotropic_eastward_sea_water_velocity",
                                        "surface_geostrophic_eastward_sea_water_velocity",
                                        "eastward_current",
                                        "sea_water_x_velocity",
                                        "eastward_wind"}
             : std::vector<std::string>{"northward_sea_water_velocity",
                                        "surface_northward_sea_water_velocity",
                                        "northward_sea_water_velocity_assuming_no_tide",
                                        "baroclinic_northward_sea_water_velocity",
                                        "barotropic_northward_sea_water_velocity",
                                        "surface_geostrophic_northward_sea_water_velocity",
                                        "northward_current",
                                        "sea_water_y_velocity",
                                        "northward_wind"};
    // Usual names of files without CF standard names, matched without regard to case (UVEL, UWND, U10): Copernicus
    // and NEMO (uo, vozocrtx), HYCOM (water_u), POP (uvel; urot rotated to east/north), ROMS post-processed
    // (u_eastward), winds of reanalyses and weather models (uwnd, u10) for vehicles in wind.
    const std::vector<std::string> names =
        east ? std::vector<std::string>{"uo",       "u",    "water_u",   "uvel", "urot", "u_eastward",
                                        "vozocrtx", "ucur", "u_current", "uwnd", "u10"}
             : std::vector<std::string>{"vo",       "v",    "water_v",   "vvel", "vrot", "v_northward",
                                        "vomecrty", "vcur", "v_current", "vwnd", "v10"};
    const int nv = f.nvars();
    for (const std::string &sn : stdNames)
        for (int var = 0; var < nv; ++var)
            if (stdName(f, var) == sn)
                return var;
    for (const std::string &n : names)
    {
        if (auto v = f.findVar(n)) // as listed first (a file may hold both u and U)
            return *v;
        for (int var = 0; var < nv; ++var)
            if (lower(f.varName(var)) == n)
                return var;
    }
    if (!groups.empty())
        throw f.error(groups);
    if (const std::string broken = f.unreadable(); !broken.empty()) // the velocity may be the array that is broken
        throw f.error(std::string("no ") + (east ? "eastward (u)" : "northward (v)") +
                      " velocity among the arrays "
                      "that can be read, and " +
                      broken + "; candidates: " + candidateList(f));
    throw f.error(std::string("no ") + (east ? "eastward (u)" : "northward (v)") +
                  " velocity found: no variable with standard_name one of {" + joinNames(stdNames) +
                  "} or named one of {" + joinNames(names) + "} (in any case); candidates: " + candidateList(f) +
                  "; name them with GriddedCurrentOptions::uName/vName");
}

int DimensionRoles::find(Role r) const
{
    for (std::size_t d = 0; d < role.size(); ++d)
        if (role[d] == r)
            return int(d);
    return -1;
}

namespace
{
/// A coordinate variable named in the options: its dimension gets the role (2-D coordinates are left to the
/// curvilinear grid).
void assignGiven(const GriddedDataset &f, const std::string &name, Role r, const std::string &uName, DimensionRoles &dr)
{
    if (name.empty())
        return;
    auto v = f.findVar(name);
    if (!v)
        throw f.error("no coordinate variable '" + name + "' (given in GriddedCurrentOptions)");
    std::vector<int> vd = f.varDims(*v);
    if (r == Role::Time && vd.size() == 2 && dr.find(Role::Run) >= 0 &&
        vd[0] == dr.dims[std::size_t(dr.find(Role::Run))])
        vd.erase(vd.begin()); // a 2-D time(run, time) of a file of several runs: on its time dimension
    if (vd.size() != 1)
        return; // 2-D coordinates are handled with the curvilinear grid
    for (std::size_t d = 0; d < dr.dims.size(); ++d)
        if (dr.dims[d] == vd[0])
        {
            dr.role[d] = r;
            dr.coordVar[d] = *v;
            return;
        }
    throw f.error("coordinate variable '" + name + "' is not on a dimension of '" + uName + "'");
}

/// The role of a 1-D coordinate variable from its attributes and name (time first).
Role roleOf(const GriddedDataset &f, int cv, CoordinateMode mode, bool &geoAxes, bool &cartAxes)
{
    const bool cartesian = mode == CoordinateMode::Cartesian;
    if (isTimeVar(f, cv))
        return Role::Time;
    if (!cartesian && isLonVar(f, cv))
        return geoAxes = true, Role::X;
    if (!cartesian && isLatVar(f, cv))
        return geoAxes = true, Role::Y;
    if (isDepthVar(f, cv))
        return Role::Depth;
    if (isXVar(f, cv) || (cartesian && isLonVar(f, cv)))
        return cartAxes = true, Role::X;
    if (isYVar(f, cv) || (cartesian && isLatVar(f, cv)))
        return cartAxes = true, Role::Y;
    return Role::None;
}

/// The runs of a file of several forecast runs (a THREDDS FMRC): a dimension of u before the others whose
/// coordinate variable (same name, 1-D on it) isRunVar(); else one on which a 1-D variable with standard_name
/// forecast_reference_time lies (an auxiliary coordinate: reftime(run)), or which is named so (run, reftime,
/// runtime) without either.
void assignRuns(const GriddedDataset &f, DimensionRoles &dr)
{
    for (std::size_t d = 0; d + 2 < dr.dims.size() && dr.find(Role::Run) < 0; ++d)
    {
        const std::vector<int> on{dr.dims[d]};
        const std::string dn = f.dimName(dr.dims[d]);
        const auto cv = f.findVar(dn);
        int coordinate = cv && f.varDims(*cv) == on ? *cv : -1;
        if (coordinate >= 0 && !isRunVar(f, coordinate))
            continue;
        for (int var = 0; coordinate < 0 && var < f.nvars(); ++var)
            if (f.varDims(var) == on && stdName(f, var) == "forecast_reference_time")
                coordinate = var;
        if (coordinate < 0 && !inList(lower(dn), {"run", "reftime", "runtime"}))
            continue;
        dr.role[d] = Role::Run;
        dr.coordVar[d] = coordinate;
    }
}

/// The 2-D time(run, time) of dimension @p d (same name, on u's run dimension and d), else -1.
int twoDimensionalTime(const GriddedDataset &f, const DimensionRoles &dr, std::size_t d)
{
    const int run = dr.find(Role::Run);
    const auto cv = f.findVar(f.dimName(dr.dims[d]));
    if (run < 0 || !cv || f.varDims(*cv) != std::vector<int>{dr.dims[std::size_t(run)], dr.dims[d]} ||
        !isTimeVar(f, *cv))
        return -1;
    return *cv;
}

/// Dimensions not named in the options, classified by their coordinate variable (same name, 1-D on it).
void assignDetected(const GriddedDataset &f, CoordinateMode mode, const std::string &uName, DimensionRoles &dr)
{
    for (std::size_t d = 0; d < dr.dims.size(); ++d)
    {
        if (dr.role[d] != Role::None)
            continue;
        const std::string dn = f.dimName(dr.dims[d]);
        auto cv = f.findVar(dn);
        if (const int t2 = twoDimensionalTime(f, dr, d); t2 >= 0)
        {
            dr.role[d] = Role::Time;
            dr.coordVar[d] = t2;
            continue;
        }
        if (!cv || f.varDims(*cv).size() != 1 || f.varDims(*cv)[0] != dr.dims[d])
        {
            if (inList(lower(dn), {"time", "t", "time_counter", "ocean_time"}))
                throw f.error("dimension '" + dn + "' of '" + uName +
                              "' looks like time but has no coordinate variable '" + dn + "'");
            continue;
        }
        dr.role[d] = roleOf(f, *cv, mode, dr.geoAxes, dr.cartAxes);
        if (dr.role[d] != Role::None)
            dr.coordVar[d] = *cv;
    }
}

/// Axes named by the user: geographic when their attributes say degrees, else Cartesian.
void markNamedAxes(const GriddedDataset &f, const GriddedCurrentOptions &opt, DimensionRoles &dr)
{
    for (std::size_t d = 0; d < dr.dims.size(); ++d)
    {
        const Role r = dr.role[d];
        const bool named = (r == Role::X && !opt.lonName.empty()) || (r == Role::Y && !opt.latName.empty());
        if (!named || dr.coordVar[d] < 0)
            continue;
        const bool deg = r == Role::X ? isLonVar(f, dr.coordVar[d]) : isLatVar(f, dr.coordVar[d]);
        (deg && opt.coordinates != CoordinateMode::Cartesian ? dr.geoAxes : dr.cartAxes) = true;
    }
}
} // namespace

DimensionRoles classifyDimensions(const GriddedDataset &f, const GriddedCurrentOptions &opt, int uVar)
{
    DimensionRoles dr;
    dr.dims = f.varDims(uVar);
    dr.role.assign(dr.dims.size(), Role::None);
    dr.coordVar.assign(dr.dims.size(), -1);
    const std::string uName = f.varName(uVar);
    assignRuns(f, dr);
    assignGiven(f, opt.timeName, Role::Time, uName, dr);
    assignGiven(f, opt.depthName, Role::Depth, uName, dr);
    assignGiven(f, opt.lonName, Role::X, uName, dr);
    assignGiven(f, opt.latName, Role::Y, uName, dr);
    assignDetected(f, opt.coordinates, uName, dr);
    markNamedAxes(f, opt, dr);
    for (Role r : {Role::Run, Role::Time, Role::Depth, Role::X, Role::Y})
        if (std::count(dr.role.begin(), dr.role.end(), r) > 1)
            throw f.error("variable '" + uName +
                          "' has two dimensions of the same kind; name the coordinates "
                          "with GriddedCurrentOptions::timeName/depthName/lonName/latName");
    return dr;
}
} // namespace gridded_detail
} // namespace ompl_glider
