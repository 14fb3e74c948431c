#include "ompl_glider/current/NetCdfCurrents.h"

#include <netcdf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string lower(std::string s)
{
    for (char &c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}
std::string trim(const std::string &s)
{
    std::size_t a = 0, b = s.size();
    while (a < b && (std::isspace(static_cast<unsigned char>(s[a])) || s[a] == '\0'))
        ++a;
    while (b > a && (std::isspace(static_cast<unsigned char>(s[b - 1])) || s[b - 1] == '\0'))
        --b;
    return s.substr(a, b - a);
}

/// The open file, closed on scope exit; helpers that name the file in errors.
class NcFile
{
public:
    explicit NcFile(const std::string &path) : path_(path)
    {
        const int st = nc_open(path.c_str(), NC_NOWRITE, &id_);
        if (st != NC_NOERR)
            throw Error("NetCDF file '" + path + "': cannot open: " + nc_strerror(st));
    }
    ~NcFile()
    {
        nc_close(id_);
    }
    NcFile(const NcFile &) = delete;
    NcFile &operator=(const NcFile &) = delete;

    int id() const
    {
        return id_;
    }
    Error error(const std::string &what) const
    {
        return Error("NetCDF file '" + path_ + "': " + what);
    }
    void check(int status, const std::string &what) const
    {
        if (status != NC_NOERR)
            throw error(what + ": " + nc_strerror(status));
    }
    int nvars() const
    {
        int n = 0;
        check(nc_inq_nvars(id_, &n), "inquire variables");
        return n;
    }
    std::string varName(int var) const
    {
        char buf[NC_MAX_NAME + 1];
        check(nc_inq_varname(id_, var, buf), "inquire variable name");
        return buf;
    }
    std::string dimName(int dim) const
    {
        char buf[NC_MAX_NAME + 1];
        check(nc_inq_dimname(id_, dim, buf), "inquire dimension name");
        return buf;
    }
    std::size_t dimLen(int dim) const
    {
        std::size_t n = 0;
        check(nc_inq_dimlen(id_, dim, &n), "inquire dimension length");
        return n;
    }
    std::optional<int> findVar(const std::string &name) const
    {
        int v;
        if (nc_inq_varid(id_, name.c_str(), &v) == NC_NOERR)
            return v;
        return std::nullopt;
    }
    std::vector<int> varDims(int var) const
    {
        int nd = 0;
        check(nc_inq_varndims(id_, var, &nd), "inquire dimensions of '" + varName(var) + "'");
        std::vector<int> d(static_cast<std::size_t>(nd));
        if (nd > 0)
            check(nc_inq_vardimid(id_, var, d.data()), "inquire dimensions of '" + varName(var) + "'");
        return d;
    }
    nc_type varType(int var) const
    {
        nc_type t;
        check(nc_inq_vartype(id_, var, &t), "inquire type of '" + varName(var) + "'");
        return t;
    }
    std::optional<std::string> attText(int var, const char *name) const
    {
        nc_type t;
        std::size_t len;
        if (nc_inq_att(id_, var, name, &t, &len) != NC_NOERR)
            return std::nullopt;
        if (t == NC_CHAR)
        {
            std::string s(len, '\0');
            if (len > 0)
                check(nc_get_att_text(id_, var, name, &s[0]), std::string("read attribute ") + name);
            return trim(s);
        }
        if (t == NC_STRING && len >= 1)
        {
            std::vector<char *> p(len, nullptr);
            check(nc_get_att_string(id_, var, name, p.data()), std::string("read attribute ") + name);
            std::string s = p[0] ? p[0] : "";
            nc_free_string(len, p.data());
            return trim(s);
        }
        return std::nullopt;
    }
    std::vector<double> attDoubles(int var, const char *name) const
    {
        nc_type t;
        std::size_t len;
        if (nc_inq_att(id_, var, name, &t, &len) != NC_NOERR || t == NC_CHAR || t == NC_STRING)
            return {};
        std::vector<double> v(len);
        check(nc_get_att_double(id_, var, name, v.data()), std::string("read attribute ") + name);
        return v;
    }
    std::vector<double> readAll1D(int var) const
    {
        const std::vector<int> d = varDims(var);
        std::size_t n = 1;
        for (int x : d)
            n *= dimLen(x);
        std::vector<double> v(n);
        if (n > 0)
            check(nc_get_var_double(id_, var, v.data()), "read variable '" + varName(var) + "'");
        return v;
    }
    const std::string &path() const
    {
        return path_;
    }

private:
    std::string path_;
    int id_{-1};
};

std::string stdName(const NcFile &f, int var)
{
    return lower(f.attText(var, "standard_name").value_or(""));
}
std::string unitsOf(const NcFile &f, int var)
{
    return f.attText(var, "units").value_or("");
}
bool inList(const std::string &s, std::initializer_list<const char *> l)
{
    for (const char *x : l)
        if (s == x)
            return true;
    return false;
}

bool isLonVar(const NcFile &f, int var)
{
    const std::string u = lower(unitsOf(f, var)), sn = stdName(f, var), n = lower(f.varName(var));
    return inList(u, {"degrees_east", "degree_east", "degrees_e", "degree_e", "degreese", "degreee"}) ||
           sn == "longitude" || inList(n, {"lon", "longitude", "nav_lon", "glamt", "tlong", "lon_rho", "longitudes"});
}
bool isLatVar(const NcFile &f, int var)
{
    const std::string u = lower(unitsOf(f, var)), sn = stdName(f, var), n = lower(f.varName(var));
    return inList(u, {"degrees_north", "degree_north", "degrees_n", "degree_n", "degreesn", "degreen"}) ||
           sn == "latitude" || inList(n, {"lat", "latitude", "nav_lat", "gphit", "tlat", "lat_rho", "latitudes"});
}
bool isXVar(const NcFile &f, int var)
{
    const std::string sn = stdName(f, var), n = lower(f.varName(var));
    return sn == "projection_x_coordinate" || lower(f.attText(var, "axis").value_or("")) == "x" ||
           inList(n, {"x", "xc", "x_rho", "easting"});
}
bool isYVar(const NcFile &f, int var)
{
    const std::string sn = stdName(f, var), n = lower(f.varName(var));
    return sn == "projection_y_coordinate" || lower(f.attText(var, "axis").value_or("")) == "y" ||
           inList(n, {"y", "yc", "y_rho", "northing"});
}
bool isTimeVar(const NcFile &f, int var)
{
    const std::string u = lower(unitsOf(f, var)), sn = stdName(f, var), n = lower(f.varName(var));
    return u.find(" since ") != std::string::npos || sn == "time" ||
           lower(f.attText(var, "axis").value_or("")) == "t" ||
           inList(n, {"time", "t", "time_counter", "ocean_time", "valid_time", "mt"});
}
bool isDepthVar(const NcFile &f, int var)
{
    const std::string sn = stdName(f, var), n = lower(f.varName(var));
    return sn == "depth" || lower(f.attText(var, "axis").value_or("")) == "z" || f.attText(var, "positive") ||
           inList(n, {"depth", "deptht", "depthu", "depthv", "depthw", "z", "lev", "level", "zlev"});
}

/// Scale factor of a velocity unit string to m/s (std::nullopt if unknown).
std::optional<double> velocityScale(const std::string &units)
{
    std::string s;
    for (char c : lower(units))
        if (!std::isspace(static_cast<unsigned char>(c)))
            s += c;
    if (inList(s, {"m/s", "ms-1", "m.s-1", "ms^-1", "m.s^-1", "m*s-1", "m/sec", "meter/second", "meters/second",
                   "metre/second", "metres/second", "meterspersecond", "metrespersecond", "meter/sec", "meters/sec",
                   "mps"}))
        return 1.0;
    if (inList(s, {"cm/s", "cms-1", "cm.s-1", "cms^-1", "cm.s^-1", "cm*s-1", "cm/sec", "centimeter/second",
                   "centimeters/second", "centimetre/second", "centimetres/second", "centimeterspersecond"}))
        return 0.01;
    if (inList(s, {"knots", "knot", "kt", "kts", "kn"}))
        return 1852.0 / 3600.0;
    return std::nullopt;
}

/// Contiguous runs of file indices along one dimension and the internal position of each index read.
struct DimRead
{
    std::vector<std::pair<std::size_t, std::size_t>> runs;  // (start, count) in the file
    std::vector<std::vector<std::size_t>> pos;              // per run, internal position of each element
};

/// Builds the runs from the list "internal position p -> file index fileIdx[p]".
DimRead makeDimRead(const std::vector<std::size_t> &fileIdx)
{
    std::vector<std::pair<std::size_t, std::size_t>> order;  // (file index, internal pos)
    for (std::size_t p = 0; p < fileIdx.size(); ++p)
        order.emplace_back(fileIdx[p], p);
    std::sort(order.begin(), order.end());
    DimRead d;
    for (std::size_t k = 0; k < order.size(); ++k)
    {
        if (k == 0 || order[k].first != order[k - 1].first + 1)
        {
            d.runs.emplace_back(order[k].first, 0);
            d.pos.emplace_back();
        }
        d.runs.back().second++;
        d.pos.back().push_back(order[k].second);
    }
    return d;
}

/// Indices [a, b] (inclusive) of an axis (ascending or descending) whose values lie in [lo, hi], widened by
/// `extra` nodes; nullopt when none.
std::optional<std::pair<std::size_t, std::size_t>> indexRange(const std::vector<double> &ax, double lo, double hi,
                                                              int extra)
{
    std::size_t a = ax.size(), b = 0;
    for (std::size_t i = 0; i < ax.size(); ++i)
        if (ax[i] >= lo && ax[i] <= hi)
        {
            a = std::min(a, i);
            b = std::max(b, i);
        }
    if (a == ax.size())
    {
        // region between two nodes: take the bracketing pair
        for (std::size_t i = 0; i + 1 < ax.size(); ++i)
        {
            const double mn = std::min(ax[i], ax[i + 1]), mx = std::max(ax[i], ax[i + 1]);
            if (mn <= hi && mx >= lo)
            {
                a = i;
                b = i + 1;
                break;
            }
        }
        if (a == ax.size())
            return std::nullopt;
    }
    const std::size_t e = static_cast<std::size_t>(std::max(0, extra));
    a = a >= e ? a - e : 0;
    b = std::min(ax.size() - 1, b + e);
    return std::make_pair(a, b);
}

double wrapTo(double lon, double centre)
{
    double d = std::fmod(lon - centre + 180.0, 360.0);
    if (d < 0)
        d += 360.0;
    return centre + d - 180.0;
}

/// Reads `var` restricted to the per-dimension reads, scattering into `out` at internal offsets
/// sum_d pos * stride[d]. Values are raw (packed) doubles.
void readScatter(const NcFile &f, int var, const std::vector<DimRead> &dims, const std::vector<std::size_t> &stride,
                 std::vector<double> &out)
{
    const std::size_t nd = dims.size();
    std::vector<std::size_t> runIdx(nd, 0);
    std::vector<double> buf;
    while (true)
    {
        std::vector<std::size_t> start(nd), count(nd);
        std::size_t n = 1;
        for (std::size_t d = 0; d < nd; ++d)
        {
            start[d] = dims[d].runs[runIdx[d]].first;
            count[d] = dims[d].runs[runIdx[d]].second;
            n *= count[d];
        }
        buf.resize(n);
        if (n > 0)
            f.check(nc_get_vara_double(f.id(), var, start.data(), count.data(), buf.data()),
                    "read variable '" + f.varName(var) + "'");
        // odometer over the hyperslab in row-major order
        std::vector<std::size_t> c(nd, 0);
        for (std::size_t e = 0; e < n; ++e)
        {
            std::size_t off = 0;
            for (std::size_t d = 0; d < nd; ++d)
                off += dims[d].pos[runIdx[d]][c[d]] * stride[d];
            out[off] = buf[e];
            for (std::size_t d = nd; d-- > 0;)
            {
                if (++c[d] < count[d])
                    break;
                c[d] = 0;
            }
        }
        std::size_t d = nd;
        while (d-- > 0)
        {
            if (++runIdx[d] < dims[d].runs.size())
                break;
            runIdx[d] = 0;
        }
        if (d == static_cast<std::size_t>(-1))
            break;
    }
}

/// Packing and missing-value rules of a variable.
struct Packing
{
    double scale{1.0}, offset{0.0};
    std::vector<double> fills;
    double validMin{-kInf}, validMax{kInf};
    bool isFill(double r) const
    {
        if (std::isnan(r))
            return true;
        for (double f : fills)
            if (r == f)
                return true;
        return r < validMin || r > validMax;
    }
};

Packing packingOf(const NcFile &f, int var)
{
    Packing p;
    const std::string name = f.varName(var);
    const auto sf = f.attDoubles(var, "scale_factor"), ao = f.attDoubles(var, "add_offset");
    if (!sf.empty())
        p.scale = sf[0];
    if (!ao.empty())
        p.offset = ao[0];
    if (!std::isfinite(p.scale) || p.scale == 0.0 || !std::isfinite(p.offset))
        throw f.error("variable '" + name + "': scale_factor/add_offset must be finite and scale_factor non-zero");
    const auto fv = f.attDoubles(var, "_FillValue");
    if (!fv.empty())
        p.fills.push_back(fv[0]);
    else
    {
        switch (f.varType(var))
        {
            case NC_SHORT:
                p.fills.push_back(NC_FILL_SHORT);
                break;
            case NC_INT:
                p.fills.push_back(NC_FILL_INT);
                break;
            case NC_FLOAT:
                p.fills.push_back(static_cast<double>(NC_FILL_FLOAT));
                break;
            case NC_DOUBLE:
                p.fills.push_back(NC_FILL_DOUBLE);
                break;
            default:
                break;
        }
    }
    for (double m : f.attDoubles(var, "missing_value"))
        p.fills.push_back(m);
    const auto vr = f.attDoubles(var, "valid_range");
    if (vr.size() >= 2)
    {
        p.validMin = vr[0];
        p.validMax = vr[1];
    }
    const auto vmin = f.attDoubles(var, "valid_min"), vmax = f.attDoubles(var, "valid_max");
    if (!vmin.empty())
        p.validMin = vmin[0];
    if (!vmax.empty())
        p.validMax = vmax[0];
    return p;
}

std::string joinNames(const std::vector<std::string> &v)
{
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i)
        s += (i ? ", " : "") + v[i];
    return s;
}

int findVelocity(const NcFile &f, const std::string &given, bool east, const std::string &optionName)
{
    if (!given.empty())
    {
        auto v = f.findVar(given);
        if (!v)
            throw f.error("no variable '" + given + "' (given with NetCdfCurrentOptions::" + optionName + ")");
        return *v;
    }
    const std::vector<std::string> stdNames =
        east ? std::vector<std::string>{"eastward_sea_water_velocity", "surface_eastward_sea_water_velocity",
                                        "eastward_sea_water_velocity_assuming_no_tide",
                                        "baroclinic_eastward_sea_water_velocity",
                                        "barotropic_eastward_sea_water_velocity",
                                        "surface_geostrophic_eastward_sea_water_velocity", "eastward_current",
                                        "sea_water_x_velocity"}
             : std::vector<std::string>{"northward_sea_water_velocity", "surface_northward_sea_water_velocity",
                                        "northward_sea_water_velocity_assuming_no_tide",
                                        "baroclinic_northward_sea_water_velocity",
                                        "barotropic_northward_sea_water_velocity",
                                        "surface_geostrophic_northward_sea_water_velocity", "northward_current",
                                        "sea_water_y_velocity"};
    const std::vector<std::string> names =
        east ? std::vector<std::string>{"uo", "u", "water_u", "uvel", "vozocrtx", "ucur", "U", "u_current"}
             : std::vector<std::string>{"vo", "v", "water_v", "vvel", "vomecrty", "vcur", "V", "v_current"};
    const int nv = f.nvars();
    for (const std::string &sn : stdNames)
        for (int var = 0; var < nv; ++var)
            if (stdName(f, var) == sn)
                return var;
    for (const std::string &n : names)
        if (auto v = f.findVar(n))
            return *v;
    throw f.error(std::string("no ") + (east ? "eastward (u)" : "northward (v)") +
                  " velocity variable: expected a variable with standard_name one of {" + joinNames(stdNames) +
                  "} or named one of {" + joinNames(names) + "}; give its name with NetCdfCurrentOptions::" +
                  optionName);
}

enum class Role
{
    None,
    Time,
    Depth,
    X,
    Y
};
}  // namespace

double NetCdfCurrents::fieldTime(const std::string &text) const
{
    const std::string s = trim(text);
    char *end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (!s.empty() && end && *end == '\0' && std::isfinite(v))
        return v;
    if (!dated)
        throw Error("time '" + text + "': the forecast has no dated time axis; give a number (field time units)");
    return secondsSinceCalendarEpoch(parseDateTime(s), calendar) - originSeconds;
}

std::string NetCdfCurrents::isoTime(double t) const
{
    if (!dated)
    {
        std::ostringstream os;
        os << t;
        return os.str();
    }
    return formatDateTime(dateFromCalendarEpoch(originSeconds + t, calendar));
}

void NetCdfCurrents::toGeographic(double x, double y, double &lon, double &lat) const
{
    if (projection)
        projection->inverse(x, y, lon, lat);
    else
    {
        lon = x;
        lat = y;
    }
}

void NetCdfCurrents::toLocal(double lon, double lat, double &x, double &y) const
{
    if (projection)
        projection->forward(lon, lat, x, y);
    else
    {
        x = lon;
        y = lat;
    }
}

NetCdfCurrents loadNetCdfCurrents(const std::string &path, const NetCdfCurrentOptions &opt)
{
    NcFile f(path);
    NetCdfCurrents out;
    const int uVar = findVelocity(f, opt.uName, true, "uName");
    const int vVar = findVelocity(f, opt.vName, false, "vName");
    out.uVariable = f.varName(uVar);
    out.vVariable = f.varName(vVar);
    const std::vector<int> dims = f.varDims(uVar);
    if (f.varDims(vVar) != dims)
        throw f.error("velocity variables '" + out.uVariable + "' and '" + out.vVariable +
                      "' must have the same dimensions (staggered grids are not supported)");
    if (dims.size() < 2 || dims.size() > 4)
        throw f.error("variable '" + out.uVariable + "': expected 2 to 4 dimensions ([time,] [depth,] lat, lon), got " +
                      std::to_string(dims.size()));

    // ---- classify the dimensions of u ----
    const std::size_t nd = dims.size();
    std::vector<Role> role(nd, Role::None);
    std::vector<int> coordVar(nd, -1);
    bool geoAxes = false, cartAxes = false;
    auto given = [&](const std::string &name, Role r) {
        if (name.empty())
            return;
        auto v = f.findVar(name);
        if (!v)
            throw f.error("no coordinate variable '" + name + "' (given in NetCdfCurrentOptions)");
        const std::vector<int> vd = f.varDims(*v);
        if (vd.size() != 1)
            return;  // 2-D coordinates are handled with the curvilinear grid
        for (std::size_t d = 0; d < nd; ++d)
            if (dims[d] == vd[0])
            {
                role[d] = r;
                coordVar[d] = *v;
                return;
            }
        throw f.error("coordinate variable '" + name + "' is not on a dimension of '" + out.uVariable + "'");
    };
    given(opt.timeName, Role::Time);
    given(opt.depthName, Role::Depth);
    given(opt.lonName, Role::X);
    given(opt.latName, Role::Y);
    for (std::size_t d = 0; d < nd; ++d)
    {
        if (role[d] != Role::None)
            continue;
        const std::string dn = f.dimName(dims[d]);
        auto cv = f.findVar(dn);
        if (!cv || f.varDims(*cv).size() != 1 || f.varDims(*cv)[0] != dims[d])
        {
            const std::string l = lower(dn);
            if (inList(l, {"time", "t", "time_counter", "ocean_time"}))
                throw f.error("dimension '" + dn + "' of '" + out.uVariable +
                              "' looks like time but has no coordinate variable '" + dn + "'");
            continue;
        }
        if (isTimeVar(f, *cv))
            role[d] = Role::Time;
        else if (opt.coordinates != CoordinateMode::Cartesian && isLonVar(f, *cv))
            role[d] = Role::X, geoAxes = true;
        else if (opt.coordinates != CoordinateMode::Cartesian && isLatVar(f, *cv))
            role[d] = Role::Y, geoAxes = true;
        else if (isDepthVar(f, *cv))
            role[d] = Role::Depth;
        else if (isXVar(f, *cv) || (opt.coordinates == CoordinateMode::Cartesian && isLonVar(f, *cv)))
            role[d] = Role::X, cartAxes = true;
        else if (isYVar(f, *cv) || (opt.coordinates == CoordinateMode::Cartesian && isLatVar(f, *cv)))
            role[d] = Role::Y, cartAxes = true;
        if (role[d] != Role::None)
            coordVar[d] = *cv;
    }
    for (std::size_t d = 0; d < nd; ++d)
    {
        // axes named by the user: geographic when their attributes say degrees, else Cartesian
        const bool named = (role[d] == Role::X && !opt.lonName.empty()) || (role[d] == Role::Y && !opt.latName.empty());
        if (!named || coordVar[d] < 0)
            continue;
        const bool deg = role[d] == Role::X ? isLonVar(f, coordVar[d]) : isLatVar(f, coordVar[d]);
        (deg && opt.coordinates != CoordinateMode::Cartesian ? geoAxes : cartAxes) = true;
    }
    auto count = [&](Role r) { return std::count(role.begin(), role.end(), r); };
    for (Role r : {Role::Time, Role::Depth, Role::X, Role::Y})
        if (count(r) > 1)
            throw f.error("variable '" + out.uVariable + "' has two dimensions of the same kind; name the coordinates "
                          "with NetCdfCurrentOptions::timeName/depthName/lonName/latName");
    int dimT = -1, dimZ = -1, dimX = -1, dimY = -1;
    for (std::size_t d = 0; d < nd; ++d)
    {
        if (role[d] == Role::Time)
            dimT = int(d);
        if (role[d] == Role::Depth)
            dimZ = int(d);
        if (role[d] == Role::X)
            dimX = int(d);
        if (role[d] == Role::Y)
            dimY = int(d);
    }
    bool curvilinear = false;
    int lon2D = -1, lat2D = -1;
    if (dimX < 0 || dimY < 0)
    {
        // curvilinear: the two remaining dimensions of length > 1 are (j, i) in file order
        std::vector<int> rest;
        for (std::size_t d = 0; d < nd; ++d)
            if (role[d] == Role::None && f.dimLen(dims[d]) > 1)
                rest.push_back(int(d));
        if (rest.size() != 2 || dimX >= 0 || dimY >= 0)
            throw f.error("variable '" + out.uVariable +
                          "': expected longitude/latitude (or x/y) axes or a 2-D curvilinear grid; found no horizontal "
                          "coordinate variables (name them with NetCdfCurrentOptions::lonName/latName)");
        dimY = rest[0];
        dimX = rest[1];
        role[std::size_t(dimY)] = Role::Y;
        role[std::size_t(dimX)] = Role::X;
        curvilinear = true;
        const std::vector<int> want{dims[std::size_t(dimY)], dims[std::size_t(dimX)]};
        std::vector<int> cands;
        auto consider = [&](int var) {
            if (f.varDims(var) == want)
                cands.push_back(var);
        };
        if (!opt.lonName.empty())
            lon2D = *f.findVar(opt.lonName);
        if (!opt.latName.empty())
            lat2D = *f.findVar(opt.latName);
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
        for (int var : cands)
        {
            if (lon2D < 0 && ((opt.coordinates != CoordinateMode::Cartesian && isLonVar(f, var)) ||
                              (opt.coordinates == CoordinateMode::Cartesian && isXVar(f, var))))
                lon2D = var;
            if (lat2D < 0 && ((opt.coordinates != CoordinateMode::Cartesian && isLatVar(f, var)) ||
                              (opt.coordinates == CoordinateMode::Cartesian && isYVar(f, var))))
                lat2D = var;
        }
        if (lon2D < 0 || lat2D < 0)
            throw f.error("variable '" + out.uVariable + "' is on dimensions (" + f.dimName(want[0]) + ", " +
                          f.dimName(want[1]) + ") without 1-D axes; expected 2-D longitude/latitude variables on them "
                          "(from its 'coordinates' attribute, standard_name or units degrees_east/degrees_north)");
        if (f.varDims(lon2D) != want || f.varDims(lat2D) != want)
            throw f.error("curvilinear coordinates '" + f.varName(lon2D) + "'/'" + f.varName(lat2D) +
                          "': expected dimensions (" + f.dimName(want[0]) + ", " + f.dimName(want[1]) + ")");
        geoAxes = opt.coordinates != CoordinateMode::Cartesian && isLonVar(f, lon2D) && isLatVar(f, lat2D);
        cartAxes = !geoAxes;
    }
    for (std::size_t d = 0; d < nd; ++d)
        if (role[d] == Role::None && f.dimLen(dims[d]) > 1)
            throw f.error("variable '" + out.uVariable + "' has dimension '" + f.dimName(dims[d]) + "' (length " +
                          std::to_string(f.dimLen(dims[d])) +
                          ") that is neither time, depth, latitude nor longitude; expected (time, depth, lat, lon)");
    bool geographic;
    if (opt.coordinates == CoordinateMode::Geographic)
    {
        if (!geoAxes)
            throw f.error("expected longitude/latitude coordinates (units degrees_east/degrees_north or standard_name "
                          "longitude/latitude) for variable '" + out.uVariable + "' (CoordinateMode::Geographic)");
        geographic = true;
    }
    else if (opt.coordinates == CoordinateMode::Cartesian)
        geographic = false;
    else
        geographic = geoAxes && !cartAxes;
    out.geographic = geographic;
    const std::string xName = curvilinear ? f.varName(lon2D) : f.varName(coordVar[std::size_t(dimX)]);
    const std::string yName = curvilinear ? f.varName(lat2D) : f.varName(coordVar[std::size_t(dimY)]);

    // ---- velocity units ----
    double velScale = 1.0;
    {
        const std::string uu = opt.velocityUnits.empty() ? unitsOf(f, uVar) : opt.velocityUnits;
        const std::string vu = opt.velocityUnits.empty() ? unitsOf(f, vVar) : opt.velocityUnits;
        auto su = velocityScale(uu), sv = velocityScale(vu);
        const bool dimensionless = !geographic && (uu.empty() || uu == "1") && (vu.empty() || vu == "1");
        if (dimensionless)
            velScale = 1.0;
        else
        {
            if (!su)
                throw f.error("variable '" + out.uVariable + "': units '" + uu +
                              "' not understood; expected m/s (m s-1), cm/s (cm s-1) or knots");
            if (!sv)
                throw f.error("variable '" + out.vVariable + "': units '" + vu +
                              "' not understood; expected m/s (m s-1), cm/s (cm s-1) or knots");
            if (*su != *sv)
                throw f.error("variables '" + out.uVariable + "' and '" + out.vVariable + "' have different units");
            velScale = *su;
        }
    }

    // ---- horizontal subset ----
    const bool haveRegion = std::isfinite(opt.lonMin) && std::isfinite(opt.lonMax) && std::isfinite(opt.latMin) &&
                            std::isfinite(opt.latMax);
    if (!haveRegion && (std::isfinite(opt.lonMin) || std::isfinite(opt.lonMax) || std::isfinite(opt.latMin) ||
                        std::isfinite(opt.latMax)))
        throw Error("NetCdfCurrentOptions: give all four of lonMin, lonMax, latMin, latMax, or none");
    if (haveRegion && opt.latMin > opt.latMax)
        throw Error("NetCdfCurrentOptions: latMin > latMax");
    double rLon0 = opt.lonMin, rLon1 = opt.lonMax;
    if (haveRegion && geographic && rLon1 < rLon0)
        rLon1 += 360.0;  // across the antimeridian
    if (haveRegion && !geographic && rLon1 < rLon0)
        throw Error("NetCdfCurrentOptions: lonMin (x) > lonMax (x) in Cartesian mode");
    const double m = opt.margin;
    const std::size_t fileNx = f.dimLen(dims[std::size_t(dimX)]), fileNy = f.dimLen(dims[std::size_t(dimY)]);
    std::vector<std::size_t> xIdx, yIdx;      // file index per internal i / j
    std::vector<double> lon1D, lat1D;        // internal i / j coordinate values (rectilinear)
    std::vector<double> nodeLon, nodeLat;    // curvilinear (internal j*nx+i)
    double centreLon = kNaN, centreLat = kNaN;
    if (!curvilinear)
    {
        const std::vector<double> xs = f.readAll1D(coordVar[std::size_t(dimX)]);
        const std::vector<double> ys = f.readAll1D(coordVar[std::size_t(dimY)]);
        for (double v : xs)
            if (!std::isfinite(v))
                throw f.error("coordinate '" + xName + "' has non-finite values");
        for (double v : ys)
            if (!std::isfinite(v))
                throw f.error("coordinate '" + yName + "' has non-finite values");
        // y: ascending or descending; store ascending
        std::size_t ya = 0, yb = ys.size() - 1;
        if (haveRegion)
        {
            auto r = indexRange(ys, opt.latMin - m, opt.latMax + m, opt.marginNodes);
            if (!r)
                throw f.error("region " + std::string(geographic ? "latitude" : "y") + " [" +
                              std::to_string(opt.latMin) + ", " + std::to_string(opt.latMax) + "] is outside '" +
                              yName + "' [" + std::to_string(*std::min_element(ys.begin(), ys.end())) + ", " +
                              std::to_string(*std::max_element(ys.begin(), ys.end())) + "]");
            ya = r->first;
            yb = r->second;
        }
        const bool yDesc = ys.size() > 1 && ys[1] < ys[0];
        for (std::size_t k = 0; k <= yb - ya; ++k)
        {
            const std::size_t fi = yDesc ? yb - k : ya + k;
            yIdx.push_back(fi);
            lat1D.push_back(ys[fi]);
        }
        // x: ascending or descending; geographic global axes wrap
        const bool xDesc = xs.size() > 1 && xs[1] < xs[0];
        std::vector<double> xa = xs;
        std::vector<std::size_t> xmap(xs.size());
        for (std::size_t k = 0; k < xs.size(); ++k)
            xmap[k] = xDesc ? xs.size() - 1 - k : k;
        for (std::size_t k = 0; k < xs.size(); ++k)
            xa[k] = xs[xmap[k]];
        const std::size_t n = xa.size();
        const double step = n > 1 ? (xa[n - 1] - xa[0]) / double(n - 1) : 360.0;
        const bool cyclic = geographic && n > 2 && (xa[n - 1] - xa[0] + step) >= 360.0 - 1e-6 * std::abs(step) &&
                            (xa[n - 1] - xa[0]) < 360.0;
        if (!haveRegion)
        {
            for (std::size_t k = 0; k < n; ++k)
            {
                xIdx.push_back(xmap[k]);
                lon1D.push_back(xa[k]);
            }
        }
        else if (!geographic || !cyclic)
        {
            double lo = rLon0 - m, hi = rLon1 + m;
            if (geographic)
            {
                // express the region in the axis's convention (0..360 or -180..180): shift by whole turns
                const double mid = 0.5 * (xa.front() + xa.back());
                const double c = 0.5 * (lo + hi);
                const double k = std::round((mid - c) / 360.0);
                lo += 360.0 * k;
                hi += 360.0 * k;
            }
            auto r = indexRange(xa, lo, hi, opt.marginNodes);
            if (!r)
                throw f.error("region " + std::string(geographic ? "longitude" : "x") + " [" +
                              std::to_string(opt.lonMin) + ", " + std::to_string(opt.lonMax) + "] is outside '" +
                              xName + "' [" + std::to_string(xa.front()) + ", " + std::to_string(xa.back()) + "]");
            for (std::size_t k = r->first; k <= r->second; ++k)
            {
                xIdx.push_back(xmap[k]);
                lon1D.push_back(xa[k]);
            }
        }
        else
        {
            // cyclic axis: virtual index v, file position v mod n, value xa[v mod n] + 360 floor(v / n)
            const double lo = rLon0 - m, hi = rLon1 + m;
            const double lo0 = xa[0] + std::fmod(std::fmod(lo - xa[0], 360.0) + 360.0, 360.0);  // in [xa0, xa0+360)
            const double hiV = lo0 + (hi - lo);
            long vs = long(std::floor((lo0 - xa[0]) / step)) - opt.marginNodes;
            long ve = long(std::ceil((hiV - xa[0]) / step)) + opt.marginNodes;
            if (ve - vs + 1 > long(n))
                ve = vs + long(n) - 1;
            const long ln = long(n);
            for (long v = vs; v <= ve; ++v)
            {
                const long q = ((v % ln) + ln) % ln;
                const long wraps = (v - q) / ln;
                xIdx.push_back(xmap[std::size_t(q)]);
                lon1D.push_back(xa[std::size_t(q)] + 360.0 * double(wraps));
            }
            // ensure strictly increasing (it is unless the axis is irregular at the seam)
            for (std::size_t k = 1; k < lon1D.size(); ++k)
                if (!(lon1D[k] > lon1D[k - 1]))
                    throw f.error("longitude axis '" + xName + "' is not increasing across its seam");
        }
        if (xIdx.size() < 2 || yIdx.size() < 2)
            throw f.error("the region covers fewer than 2 grid nodes along '" + xName + "' or '" + yName + "'");
        centreLon = 0.5 * (lon1D.front() + lon1D.back());
        centreLat = 0.5 * (lat1D.front() + lat1D.back());
    }
    else
    {
        // curvilinear: scan the 2-D coordinates in row blocks for the index box of the region
        std::size_t j0 = 0, j1 = fileNy - 1, i0 = 0, i1 = fileNx - 1;
        const double cLon = haveRegion ? 0.5 * (rLon0 + rLon1) : 0.0;
        if (haveRegion)
        {
            j0 = fileNy;
            i0 = fileNx;
            j1 = i1 = 0;
            const std::size_t block = std::max<std::size_t>(1, 1000000 / std::max<std::size_t>(1, fileNx));
            std::vector<double> la, lo;
            for (std::size_t r0 = 0; r0 < fileNy; r0 += block)
            {
                const std::size_t rc = std::min(block, fileNy - r0);
                std::size_t st[2] = {r0, 0}, ct[2] = {rc, fileNx};
                la.resize(rc * fileNx);
                lo.resize(rc * fileNx);
                f.check(nc_get_vara_double(f.id(), lat2D, st, ct, la.data()), "read '" + yName + "'");
                f.check(nc_get_vara_double(f.id(), lon2D, st, ct, lo.data()), "read '" + xName + "'");
                for (std::size_t r = 0; r < rc; ++r)
                    for (std::size_t i = 0; i < fileNx; ++i)
                    {
                        const double y = la[r * fileNx + i];
                        double x = lo[r * fileNx + i];
                        if (geographic)
                            x = wrapTo(x, cLon);
                        if (y >= opt.latMin - m && y <= opt.latMax + m && x >= rLon0 - m && x <= rLon1 + m)
                        {
                            j0 = std::min(j0, r0 + r);
                            j1 = std::max(j1, r0 + r);
                            i0 = std::min(i0, i);
                            i1 = std::max(i1, i);
                        }
                    }
            }
            if (j0 == fileNy)
                throw f.error("no node of the curvilinear grid ('" + xName + "', '" + yName +
                              "') lies in the region [" + std::to_string(opt.lonMin) + ", " +
                              std::to_string(opt.lonMax) + "] x [" + std::to_string(opt.latMin) + ", " +
                              std::to_string(opt.latMax) + "]");
            const std::size_t e = std::size_t(std::max(0, opt.marginNodes));
            j0 = j0 >= e ? j0 - e : 0;
            i0 = i0 >= e ? i0 - e : 0;
            j1 = std::min(fileNy - 1, j1 + e);
            i1 = std::min(fileNx - 1, i1 + e);
        }
        for (std::size_t j = j0; j <= j1; ++j)
            yIdx.push_back(j);
        for (std::size_t i = i0; i <= i1; ++i)
            xIdx.push_back(i);
        if (xIdx.size() < 2 || yIdx.size() < 2)
            throw f.error("the region covers fewer than 2 grid nodes along a dimension of '" + xName + "'");
        std::size_t st[2] = {j0, i0}, ct[2] = {yIdx.size(), xIdx.size()};
        nodeLat.resize(ct[0] * ct[1]);
        nodeLon.resize(ct[0] * ct[1]);
        f.check(nc_get_vara_double(f.id(), lat2D, st, ct, nodeLat.data()), "read '" + yName + "'");
        f.check(nc_get_vara_double(f.id(), lon2D, st, ct, nodeLon.data()), "read '" + xName + "'");
        for (std::size_t k = 0; k < nodeLat.size(); ++k)
            if (!std::isfinite(nodeLat[k]) || !std::isfinite(nodeLon[k]))
                throw f.error("curvilinear coordinates '" + xName + "'/'" + yName + "' have non-finite values");
        const std::size_t mid = (ct[0] / 2) * ct[1] + ct[1] / 2;
        const double ref = haveRegion ? cLon : nodeLon[mid];
        double a = kInf, b = -kInf, c = kInf, d = -kInf;
        for (std::size_t k = 0; k < nodeLat.size(); ++k)
        {
            const double x = geographic ? wrapTo(nodeLon[k], ref) : nodeLon[k];
            a = std::min(a, x);
            b = std::max(b, x);
            c = std::min(c, nodeLat[k]);
            d = std::max(d, nodeLat[k]);
        }
        centreLon = 0.5 * (a + b);
        centreLat = 0.5 * (c + d);
    }

    // ---- depth ----
    std::vector<std::size_t> zIdx{0};
    std::vector<double> depth{0.0};
    if (dimZ >= 0)
    {
        const int zv = coordVar[std::size_t(dimZ)];
        const std::string zn = f.varName(zv);
        std::vector<double> zs = f.readAll1D(zv);
        const std::string zsn = stdName(f, zv);
        if (zsn.rfind("ocean_s", 0) == 0 || zsn.rfind("ocean_sigma", 0) == 0 || zsn.rfind("ocean_double_sigma", 0) == 0)
            throw f.error("depth '" + zn + "' is a terrain-following coordinate (standard_name " + zsn +
                          "); expected depth in metres: interpolate the file to z levels first");
        const std::string pos = lower(f.attText(zv, "positive").value_or("down"));
        if (pos != "down" && pos != "up")
            throw f.error("depth '" + zn + "': attribute positive = '" + pos + "', expected 'down' or 'up'");
        const std::string zu = lower(unitsOf(f, zv));
        double zscale = 1.0;
        if (zu == "cm" || zu == "centimeters")
            zscale = 0.01;
        else if (zu == "km")
            zscale = 1000.0;
        else if (!(zu.empty() || inList(zu, {"m", "meter", "meters", "metre", "metres", "1", "level"})))
            throw f.error("depth '" + zn + "': units '" + zu + "', expected m");
        for (double &z : zs)
        {
            if (!std::isfinite(z))
                throw f.error("depth '" + zn + "' has non-finite values");
            z *= (pos == "up" ? -zscale : zscale);
        }
        std::vector<std::size_t> order(zs.size());
        for (std::size_t k = 0; k < zs.size(); ++k)
            order[k] = k;
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return zs[a] < zs[b]; });
        std::size_t last = order.size() - 1;
        if (std::isfinite(opt.maxDepth))
        {
            last = 0;
            while (last + 1 < order.size() && zs[order[last]] < opt.maxDepth)
                ++last;
            last = std::min(order.size() - 1, last + 2);
        }
        zIdx.clear();
        depth.clear();
        for (std::size_t k = 0; k <= last; ++k)
        {
            zIdx.push_back(order[k]);
            depth.push_back(zs[order[k]]);
        }
    }

    // ---- time ----
    std::vector<std::size_t> tIdx{0};
    std::vector<double> times{0.0};
    if (dimT >= 0)
    {
        const int tv = coordVar[std::size_t(dimT)];
        const std::string tn = f.varName(tv);
        const std::vector<double> raw = f.readAll1D(tv);
        const std::string units = unitsOf(f, tv);
        const std::string cal = f.attText(tv, "calendar").value_or("standard");
        std::vector<double> ts(raw.size());
        if (lower(units).find(" since ") != std::string::npos)
        {
            CfTimeUnits cu;
            try
            {
                cu = parseCfTimeUnits(units, cal);
            }
            catch (const Error &e)
            {
                throw f.error("time variable '" + tn + "': " + e.what());
            }
            out.dated = true;
            out.calendar = cu.calendar;
            out.originSeconds = cu.reference + raw.at(0) * cu.secondsPerUnit;
            for (std::size_t k = 0; k < raw.size(); ++k)
                ts[k] = (raw[k] - raw[0]) * cu.secondsPerUnit;
        }
        else if (!geographic)
            ts = raw;
        else
            throw f.error("time variable '" + tn + "': units '" + units +
                          "', expected '<seconds|minutes|hours|days> since <date>'");
        for (std::size_t k = 0; k < ts.size(); ++k)
        {
            if (!std::isfinite(ts[k]))
                throw f.error("time variable '" + tn + "' has non-finite values");
            if (k > 0 && !(ts[k] > ts[k - 1]))
                throw f.error("time variable '" + tn + "': expected strictly increasing values");
        }
        out.forecastBegin = ts.front();
        out.forecastEnd = ts.back();
        double dep = ts.front();
        if (!opt.departure.empty())
        {
            try
            {
                dep = out.fieldTime(opt.departure);
            }
            catch (const Error &e)
            {
                throw f.error(std::string("departure: ") + e.what());
            }
            if (dep < ts.front() || dep > ts.back())
                throw f.error("departure " + opt.departure + " (" + out.isoTime(dep) +
                              ") is outside the forecast of variable '" + tn + "' [" + out.isoTime(ts.front()) + ", " +
                              out.isoTime(ts.back()) + "]");
        }
        out.departureTime = dep;
        const double end = std::isfinite(opt.horizon) ? dep + std::max(0.0, opt.horizon) : ts.back();
        const Axis ax(ts, "time '" + tn + "'");
        std::size_t a = ax.interval(dep), b = ax.size() > 1 ? ax.interval(std::min(end, ts.back())) + 1 : 0;
        a = a >= 2 ? a - 2 : 0;
        b = std::min(ts.size() - 1, b + 2);
        tIdx.clear();
        times.clear();
        for (std::size_t k = a; k <= b; ++k)
        {
            tIdx.push_back(k);
            times.push_back(ts[k]);
        }
    }
    else if (!opt.departure.empty())
        out.departureTime = out.fieldTime(opt.departure);

    // ---- read u, v ----
    const std::size_t nx = xIdx.size(), ny = yIdx.size(), nz = zIdx.size(), nt = tIdx.size();
    const std::size_t nh = nx * ny, total = nt * nz * nh;
    std::vector<DimRead> reads(nd);
    std::vector<std::size_t> stride(nd, 0);
    out.fileValues = 1;
    for (std::size_t d = 0; d < nd; ++d)
    {
        out.fileValues *= f.dimLen(dims[d]);
        switch (role[d])
        {
            case Role::Time:
                reads[d] = makeDimRead(tIdx);
                stride[d] = nz * nh;
                break;
            case Role::Depth:
                reads[d] = makeDimRead(zIdx);
                stride[d] = nh;
                break;
            case Role::Y:
                reads[d] = makeDimRead(yIdx);
                stride[d] = nx;
                break;
            case Role::X:
                reads[d] = makeDimRead(xIdx);
                stride[d] = 1;
                break;
            case Role::None:
                reads[d] = makeDimRead({0});
                stride[d] = 0;
                break;
        }
    }
    std::vector<double> ru(total), rv(total);
    readScatter(f, uVar, reads, stride, ru);
    readScatter(f, vVar, reads, stride, rv);
    const Packing pu = packingOf(f, uVar), pv = packingOf(f, vVar);
    GriddedData g;
    g.nx = nx;
    g.ny = ny;
    g.depth = depth;
    g.time = times;
    g.u.resize(total);
    g.v.resize(total);
    g.water.assign(nz * nh, 1);
    for (std::size_t it = 0; it < nt; ++it)
        for (std::size_t n = 0; n < nz * nh; ++n)
        {
            const std::size_t idx = it * nz * nh + n;
            if (pu.isFill(ru[idx]) || pv.isFill(rv[idx]))
            {
                g.water[n] = 0;
                continue;
            }
            g.u[idx] = static_cast<float>((ru[idx] * pu.scale + pu.offset) * velScale);
            g.v[idx] = static_cast<float>((rv[idx] * pv.scale + pv.offset) * velScale);
        }
    std::vector<double>().swap(ru);
    std::vector<double>().swap(rv);

    // ---- coordinates: projection or Cartesian ----
    if (geographic)
    {
        const double refLon = std::isfinite(opt.refLon) ? opt.refLon : (haveRegion ? 0.5 * (rLon0 + rLon1) : centreLon);
        const double refLat = std::isfinite(opt.refLat) ? opt.refLat : (haveRegion ? 0.5 * (opt.latMin + opt.latMax) : centreLat);
        auto proj = std::make_shared<LocalProjection>(refLon, refLat);
        out.projection = proj;
        g.nodeX.resize(nh);
        g.nodeY.resize(nh);
        for (std::size_t j = 0; j < ny; ++j)
            for (std::size_t i = 0; i < nx; ++i)
            {
                const std::size_t n = j * nx + i;
                const double lon = curvilinear ? nodeLon[n] : lon1D[i];
                const double lat = curvilinear ? nodeLat[n] : lat1D[j];
                if (std::abs(lat) > 89.9)
                    throw f.error("grid node at latitude " + std::to_string(lat) +
                                  " is too close to a pole for a local projection; restrict the region");
                proj->forward(lon, lat, g.nodeX[n], g.nodeY[n]);
                double ex, ey, nx_, ny_;
                proj->eastDirection(lon, lat, ex, ey);
                proj->northDirection(lon, lat, nx_, ny_);
                for (std::size_t it = 0; it < nt; ++it)
                    for (std::size_t k = 0; k < nz; ++k)
                    {
                        const std::size_t idx = (it * nz + k) * nh + n;
                        const double ue = g.u[idx], vn = g.v[idx];
                        g.u[idx] = static_cast<float>(ue * ex + vn * nx_);
                        g.v[idx] = static_cast<float>(ue * ey + vn * ny_);
                    }
            }
    }
    else
    {
        auto axisScale = [&](int var) {
            const std::string u = lower(unitsOf(f, var));
            if (u == "km" || u == "kilometer" || u == "kilometers" || u == "kilometre" || u == "kilometres")
                return 1000.0;
            return 1.0;
        };
        if (curvilinear)
        {
            const double sx = axisScale(lon2D), sy = axisScale(lat2D);
            g.nodeX.resize(nh);
            g.nodeY.resize(nh);
            for (std::size_t n = 0; n < nh; ++n)
            {
                g.nodeX[n] = nodeLon[n] * sx;
                g.nodeY[n] = nodeLat[n] * sy;
            }
        }
        else
        {
            const double sx = axisScale(coordVar[std::size_t(dimX)]), sy = axisScale(coordVar[std::size_t(dimY)]);
            for (double v : lon1D)
                g.x.push_back(v * sx);
            for (double v : lat1D)
                g.y.push_back(v * sy);
        }
    }
    GriddedFieldOptions fo = opt.field;
    if (fo.name == "gridded" || fo.name.empty())
        fo.name = "netcdf:" + path;
    try
    {
        out.field = std::make_shared<GriddedCurrentField>(std::move(g), fo);
    }
    catch (const Error &e)
    {
        throw f.error(std::string("variables '") + out.uVariable + "'/'" + out.vVariable + "': " + e.what());
    }
    out.loadedShape = {nt, nz, ny, nx};
    out.loadedValues = total;
    return out;
}
}  // namespace ompl_glider
