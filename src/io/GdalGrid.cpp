// A gridded dataset through GDAL's multidimensional API (see GdalGrid.h).
#include "GdalGrid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>

#include <gdal_priv.h>

#include "BlockCopy.h"
#include "NumberText.h"
#include "TextUtil.h"
#include "ZarrMirror.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
namespace netcdf_detail
{
namespace
{
bool endsWith(const std::string &s, const std::string &tail)
{
    return s.size() >= tail.size() && text::lower(s.substr(s.size() - tail.size())) == tail;
}

bool isUrl(const std::string &s)
{
    return s.rfind("http://", 0) == 0 || s.rfind("https://", 0) == 0;
}

std::string withoutSlash(std::string s)
{
    while (s.size() > 1 && s.back() == '/')
        s.pop_back();
    return s;
}

bool isGribFile(const std::string &path)
{
    for (const char *ext : {".grib2", ".grb2", ".grib", ".grb"})
        if (endsWith(path, ext))
            return true;
    std::error_code ec;
    if (isUrl(path) || !std::filesystem::is_regular_file(path, ec))
        return false;
    char magic[4] = {};
    std::ifstream in(path, std::ios::binary);
    return in.read(magic, 4) && std::memcmp(magic, "GRIB", 4) == 0;
}

/// GDAL's HTTP settings from the process's remote access (RemoteSource.h): the request time limit and the retries.
void applyRemoteAccess()
{
    const RemoteAccess a = remoteAccess();
    const std::string limit = std::to_string(std::max(1L, std::lround(a.requestTimeout)));
    CPLSetConfigOption("GDAL_HTTP_TIMEOUT", limit.c_str());
    CPLSetConfigOption("GDAL_HTTP_CONNECTTIMEOUT", limit.c_str());
    CPLSetConfigOption("GDAL_HTTP_MAX_RETRY", std::to_string(a.retries).c_str());
    CPLSetConfigOption("GDAL_HTTP_RETRY_DELAY", "1");
    CPLSetConfigOption("GDAL_DISABLE_READDIR_ON_OPEN", "EMPTY_DIR");  // a store's listing is its .zmetadata
}

/// GDAL's own printing of its errors off for the life of the object: they reach the user in this reader's messages
/// (CPLGetLastErrorMsg()), which name the source.
struct QuietGdal
{
    QuietGdal()
    {
        CPLPushErrorHandler(CPLQuietErrorHandler);
        CPLErrorReset();
    }
    ~QuietGdal()
    {
        CPLPopErrorHandler();
    }
    QuietGdal(const QuietGdal &) = delete;
    QuietGdal &operator=(const QuietGdal &) = delete;
};

nc_type ncTypeOf(GDALDataType t)
{
    switch (t)
    {
        case GDT_Byte: return NC_UBYTE;
        case GDT_UInt16: return NC_USHORT;
        case GDT_Int16: return NC_SHORT;
        case GDT_UInt32: return NC_UINT;
        case GDT_Int32: return NC_INT;
        case GDT_UInt64: return NC_UINT64;
        case GDT_Int64: return NC_INT64;
        case GDT_Float32: return NC_FLOAT;
        default: return NC_DOUBLE;
    }
}
}  // namespace

bool isZarrStore(const std::string &path)
{
    if (path.rfind("ZARR:", 0) == 0 || endsWith(withoutSlash(path), ".zarr"))
        return true;
    if (isUrl(path))
        return false;
    std::error_code ec;
    for (const char *marker : {".zgroup", ".zmetadata", ".zarray"})
        if (std::filesystem::is_regular_file(std::filesystem::path(path) / marker, ec))
            return true;
    return false;
}

bool isGdalSource(const std::string &path)
{
    return isZarrStore(path) || isGribFile(path);
}

/// CF's standard name of a GRIB2 parameter (its short name, as GDAL's "name" attribute gives it): the currents of
/// ocean models (RTOFS) and the winds of weather models (for vehicles in wind).
std::optional<std::string> gribStandardName(const std::string &shortName)
{
    static const std::map<std::string, std::string> names = {{"UOGRD", "eastward_sea_water_velocity"},
                                                             {"VOGRD", "northward_sea_water_velocity"},
                                                             {"UGRD", "eastward_wind"},
                                                             {"VGRD", "northward_wind"}};
    const auto it = names.find(shortName);
    return it == names.end() ? std::nullopt : std::optional<std::string>(it->second);
}

struct GdalGrid::Impl
{
    std::string path, kind;
    bool geographic{false};  // GRIB: the arrays' grid is in longitude and latitude
    std::unique_ptr<GDALDataset> dataset;
    std::unique_ptr<ZarrMirror> mirror;      // a store over HTTP: what was fetched of it (GDAL reads the mirror)
    std::unique_ptr<GDALDataset> timeHolder;  // the in-memory dataset of an added time coordinate (addFileTime())
    std::shared_ptr<GDALGroup> root;
    std::vector<std::shared_ptr<GDALMDArray>> vars;
    std::vector<bool> timeAdded;  // per var: a GRIB field of one time, given the file's time dimension first
    int timeDim{-1};              // that dimension (length 1), -1 without
    std::vector<std::shared_ptr<GDALDimension>> dims;
    std::map<std::string, int> dimIndex;  // by full name
    mutable std::mutex mutex;             // GDAL's datasets are not thread-safe
    struct Block
    {
        int var;
        std::vector<std::size_t> start, count;
        std::vector<double> values;
    };
    std::vector<Block> blocks;  // the blocks read so far (a URL's chunks fetched, a GRIB message decoded, once)

    int dimOf(const std::shared_ptr<GDALDimension> &d)
    {
        const auto [it, added] = dimIndex.emplace(d->GetFullName(), static_cast<int>(dims.size()));
        if (added)
            dims.push_back(d);
        return it->second;
    }

    void addGroup(const std::shared_ptr<GDALGroup> &g)
    {
        for (const std::string &name : g->GetMDArrayNames())
            if (auto a = g->OpenMDArray(name))
                vars.push_back(a);
        for (const std::string &name : g->GetGroupNames())  // GRIB: none; a store's subgroups
            if (auto sub = g->OpenGroup(name))
                addGroup(sub);
    }

    /// A GRIB file of one forecast time (RTOFS writes one file per forecast hour): GDAL gives its fields as 2-D
    /// arrays with the time only in attributes. They get a time dimension of length 1 and a time coordinate (the
    /// fields' common validity time, seconds of the Unix epoch), so that several such files read as one forecast.
    void addFileTime()
    {
        std::optional<double> valid;
        for (const auto &a : vars)
        {
            for (const auto &dim : a->GetDimensions())
                if (dim->GetType() == GDAL_DIM_TYPE_TEMPORAL)
                    return;  // GDAL grouped the records along a TIME dimension already
            if (auto t = a->GetAttribute("validity_time"))
            {
                const double v = t->ReadAsDouble();
                if (valid && *valid != v)
                    return;  // fields of several times, each its own array: GDAL's arrays as they are
                valid = v;
            }
        }
        GDALDriver *mem = GetGDALDriverManager()->GetDriverByName("MEM");
        if (!valid || !mem)
            return;
        timeHolder.reset(mem->CreateMultiDimensional("time", nullptr, nullptr));
        auto group = timeHolder ? timeHolder->GetRootGroup() : nullptr;
        auto dim = group ? group->CreateDimension("time", GDAL_DIM_TYPE_TEMPORAL, "", 1) : nullptr;
        auto array = dim ? group->CreateMDArray("time", {dim}, GDALExtendedDataType::Create(GDT_Float64)) : nullptr;
        const GUInt64 first = 0;
        const std::size_t one = 1;
        if (!array || !array->Write(&first, &one, nullptr, nullptr, GDALExtendedDataType::Create(GDT_Float64),
                                    &*valid) || !array->SetUnit("sec UTC"))
            return;
        timeAdded.assign(vars.size(), false);
        for (std::size_t k = 0; k < vars.size(); ++k)
            timeAdded[k] = vars[k]->GetAttribute("validity_time") != nullptr;
        timeDim = dimOf(dim);
        vars.push_back(array);
        timeAdded.push_back(false);
    }

    bool hasAddedTime(int var) const
    {
        return static_cast<std::size_t>(var) < timeAdded.size() && timeAdded[static_cast<std::size_t>(var)];
    }

    std::shared_ptr<GDALAttribute> attribute(int var, const char *name) const
    {
        return var == NC_GLOBAL ? root->GetAttribute(name) : vars.at(static_cast<std::size_t>(var))->GetAttribute(name);
    }
};

GdalGrid::GdalGrid(const std::string &path) : impl_(std::make_unique<Impl>())
{
    Impl &d = *impl_;
    d.path = path;
    d.kind = isZarrStore(path) ? "Zarr store" : "GRIB file";
    GDALAllRegister();
    std::string open = path;
    if (isUrl(path) && d.kind == "Zarr store")
    {
        // the store's metadata and chunks fetched into a mirror as the reader asks for them (the cache's, or
        // GDAL's memory): each once, with the time limit and retries; a second run with the cache asks nothing
        d.mirror = std::make_unique<ZarrMirror>(path);
        open = d.mirror->folder();
    }
    else if (isUrl(path))
    {
        applyRemoteAccess();
        open = "/vsicurl/" + path;
    }
    if (d.kind == "Zarr store" && open.rfind("ZARR:", 0) != 0)
        open = "ZARR:\"" + withoutSlash(open) + "\"";
    const QuietGdal quiet;
    d.dataset.reset(GDALDataset::Open(open.c_str(), GDAL_OF_MULTIDIM_RASTER | GDAL_OF_READONLY));
    if (!d.dataset || !(d.root = d.dataset->GetRootGroup()))
    {
        std::string why = CPLGetLastErrorMsg();
        if (isUrl(path))  // GDAL says only what it did not find
            why += std::string(why.empty() ? "" : " ") + "(no answer within the request time limit of " +
                   std::to_string(std::max(1L, std::lround(remoteAccess().requestTimeout))) + " s, after " +
                   std::to_string(remoteAccess().retries) + " retries; the server cannot be reached; or no " +
                   (d.kind == "Zarr store" ? "Zarr store" : "GRIB file") + " there)";
        throw Error(who() + ": cannot open" + (why.empty() ? std::string() : ": " + why));
    }
    d.addGroup(d.root);
    for (const auto &a : d.vars)
        if (auto srs = a->GetSpatialRef())
            d.geographic = d.geographic || srs->IsGeographic();
    for (const auto &g : d.root->GetDimensions())
        d.dimOf(g);
    for (const auto &a : d.vars)
        for (const auto &g : a->GetDimensions())
            d.dimOf(g);
    if (d.kind == "GRIB file")
        d.addFileTime();
    if (d.vars.empty())
        throw Error(who() + ": holds no arrays");
}

GdalGrid::~GdalGrid() = default;

std::shared_ptr<GdalGrid> GdalGrid::open(const std::string &path)
{
    if (!isUrl(path))
        return std::make_shared<GdalGrid>(path);
    static std::mutex m;
    // kept for the process, as the OPeNDAP datasets are (RemoteDataset::open()), one per URL and cache folder
    static auto &opened = *new std::map<std::string, std::shared_ptr<GdalGrid>>();
    const std::lock_guard<std::mutex> lock(m);
    auto &g = opened[path + '\n' + remoteAccess().cacheDir];
    if (!g)
        g = std::make_shared<GdalGrid>(path);
    return g;
}

std::string GdalGrid::who() const
{
    return impl_->kind + " '" + withoutCredentials(impl_->path) + "'";
}

int GdalGrid::nvars() const
{
    return static_cast<int>(impl_->vars.size());
}

std::string GdalGrid::varName(int var) const
{
    return impl_->vars.at(static_cast<std::size_t>(var))->GetName();
}

std::string GdalGrid::dimName(int dim) const
{
    return impl_->dims.at(static_cast<std::size_t>(dim))->GetName();
}

std::size_t GdalGrid::dimLen(int dim) const
{
    return static_cast<std::size_t>(impl_->dims.at(static_cast<std::size_t>(dim))->GetSize());
}

std::optional<int> GdalGrid::findVar(const std::string &name) const
{
    for (std::size_t k = 0; k < impl_->vars.size(); ++k)
        if (impl_->vars[k]->GetName() == name)
            return static_cast<int>(k);
    // a GRIB parameter by its short name (UOGRD for the array UOGRD_0-DBSL), where one array has it
    std::optional<int> found;
    for (std::size_t k = 0; k < impl_->vars.size(); ++k)
        if (auto a = impl_->vars[k]->GetAttribute("name"); a && a->GetDataType().GetClass() == GEDTC_STRING &&
                                                           a->ReadAsString() && name == a->ReadAsString())
        {
            if (found)
                return std::nullopt;  // several levels or times: the array's own name is needed
            found = static_cast<int>(k);
        }
    return found;
}

std::vector<int> GdalGrid::varDims(int var) const
{
    std::vector<int> out;
    if (impl_->hasAddedTime(var))
        out.push_back(impl_->timeDim);
    for (const auto &g : impl_->vars.at(static_cast<std::size_t>(var))->GetDimensions())
        out.push_back(impl_->dimIndex.at(g->GetFullName()));
    return out;
}

nc_type GdalGrid::varType(int var) const
{
    const GDALExtendedDataType &t = impl_->vars.at(static_cast<std::size_t>(var))->GetDataType();
    if (t.GetClass() == GEDTC_STRING)
        return NC_STRING;
    return ncTypeOf(t.GetNumericDataType());
}

std::optional<std::string> GdalGrid::attText(int var, const char *name) const
{
    const std::lock_guard<std::mutex> lock(impl_->mutex);
    if (auto a = impl_->attribute(var, name))
    {
        if (a->GetDataType().GetClass() != GEDTC_STRING)
            return std::nullopt;
        const char *s = a->ReadAsString();
        return text::trim(s ? s : "");
    }
    if (var == NC_GLOBAL)
        return std::nullopt;
    const GDALMDArray &array = *impl_->vars.at(static_cast<std::size_t>(var));
    if (std::strcmp(name, "units") == 0)
    {
        const std::string unit = text::trim(array.GetUnit());
        if (unit == "sec UTC")  // GDAL's GRIB times: seconds of the Unix epoch
            return std::string("seconds since 1970-01-01 00:00:00");
        if (!unit.empty())
            return unit;
        // GDAL's GRIB gives the axes of a longitude/latitude grid without units
        const auto &dims = array.GetDimensions();
        if (impl_->geographic && dims.size() == 1 && dims[0]->GetName() == array.GetName())
        {
            if (dims[0]->GetType() == GDAL_DIM_TYPE_HORIZONTAL_X)
                return std::string("degrees_east");
            if (dims[0]->GetType() == GDAL_DIM_TYPE_HORIZONTAL_Y)
                return std::string("degrees_north");
        }
    }
    if (std::strcmp(name, "standard_name") == 0)
        if (auto a = array.GetAttribute("name"); a && a->GetDataType().GetClass() == GEDTC_STRING && a->ReadAsString())
            return gribStandardName(a->ReadAsString());
    return std::nullopt;
}

std::vector<double> GdalGrid::attDoubles(int var, const char *name, bool &isText) const
{
    const std::lock_guard<std::mutex> lock(impl_->mutex);
    isText = false;
    if (auto a = impl_->attribute(var, name))
    {
        if (a->GetDataType().GetClass() == GEDTC_STRING)
        {
            isText = true;
            return {};
        }
        return a->ReadAsDoubleArray();
    }
    if (var == NC_GLOBAL)
        return {};
    const GDALMDArray &array = *impl_->vars.at(static_cast<std::size_t>(var));
    bool has = false;
    if (std::strcmp(name, "_FillValue") == 0)
    {
        const double v = array.GetNoDataValueAsDouble(&has);
        return has ? std::vector<double>{v} : std::vector<double>{};
    }
    if (std::strcmp(name, "scale_factor") == 0)
    {
        const double v = array.GetScale(&has);
        return has ? std::vector<double>{v} : std::vector<double>{};
    }
    if (std::strcmp(name, "add_offset") == 0)
    {
        const double v = array.GetOffset(&has);
        return has ? std::vector<double>{v} : std::vector<double>{};
    }
    return {};
}

void GdalGrid::readBlock(int var, const std::vector<std::size_t> &start, const std::vector<std::size_t> &count,
                         double *out) const
{
    const std::lock_guard<std::mutex> lock(impl_->mutex);
    for (const Impl::Block &b : impl_->blocks)
        if (b.var == var && inside(start, count, b.start, b.count))
        {
            copyOut(b.values, b.start, b.count, start, count, out);
            return;
        }
    const GDALMDArray &array = *impl_->vars.at(static_cast<std::size_t>(var));
    // a field given the file's time dimension: its one record, the rest of the block from the 2-D array
    const std::size_t skip = impl_->hasAddedTime(var) ? 1 : 0;
    if (skip && (start.empty() || start[0] != 0 || count[0] != 1))
        throw Error(who() + ": " + array.GetName() + " has one time (the file's)");
    std::vector<GUInt64> first(start.begin() + static_cast<std::ptrdiff_t>(skip), start.end());
    const std::vector<std::size_t> size(count.begin() + static_cast<std::ptrdiff_t>(skip), count.end());
    if (impl_->mirror)
    {
        std::string path = array.GetFullName();
        if (!path.empty() && path.front() == '/')
            path.erase(0, 1);
        impl_->mirror->ensure(path, std::vector<std::size_t>(first.begin(), first.end()), size);
    }
    const QuietGdal quiet;
    const bool read =
        array.Read(first.data(), size.data(), nullptr, nullptr, GDALExtendedDataType::Create(GDT_Float64), out);
    if (read)
    {
        std::size_t n = 1;
        for (const std::size_t c : count)
            n *= c;
        impl_->blocks.push_back({var, start, count, std::vector<double>(out, out + n)});
    }
    if (!read)
    {
        std::string block;
        for (std::size_t k = 0; k < start.size(); ++k)
            block += "[" + std::to_string(start[k]) + ":" + std::to_string(start[k] + count[k] - 1) + "]";
        const std::string why = CPLGetLastErrorMsg();
        throw Error(who() + ": cannot read " + array.GetName() + block + (why.empty() ? std::string() : ": " + why));
    }
}
}  // namespace netcdf_detail
}  // namespace ompl_glider
