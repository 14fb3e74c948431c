// A gridded dataset through GDAL's multidimensional API (see GdalGrid.h).
#include "GdalGrid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <mutex>

#include <gdal_priv.h>

#include "BlockCopy.h"
#include "NumberText.h"
#include "TextUtil.h"
#include "GdalFaults.h"
#include "HttpMirror.h"
#include "NetCdfLock.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/FileList.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
namespace netcdf_detail
{
namespace
{
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


/// The http(s) URL of a Zarr store given as a URL (ending in .zarr) or as GDAL's `ZARR:URL` / `ZARR:"URL"`; "" for
/// anything else.
std::string zarrUrl(const std::string &path)
{
    std::string s = path;
    if (s.rfind("ZARR:", 0) == 0)
    {
        s = s.substr(5);
        if (s.size() >= 2 && s.front() == '"' && s.back() == '"')
            s = s.substr(1, s.size() - 2);
        return isUrl(s) ? s : "";
    }
    return isUrl(s) && isZarrStore(s) ? s : "";
}

/// The folder of a store given as a folder or as GDAL's `ZARR:folder` / `ZARR:"folder"`.
std::string zarrFolder(const std::string &path)
{
    std::string s = path.rfind("ZARR:", 0) == 0 ? path.substr(5) : path;
    if (s.size() >= 2 && s.front() == '"' && s.back() == '"')
        s = s.substr(1, s.size() - 2);
    return s;
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
    // (declared before the dataset: destroyed after it)
    std::unique_ptr<ZarrMirror> mirror;      // a store over HTTP: what was fetched of it (GDAL reads the mirror)
    std::unique_ptr<FileMirror> file;        // a GRIB file over HTTP: its copy (GDAL reads the copy)
    std::unique_ptr<GDALDataset> dataset;
    std::unique_ptr<GDALDataset> timeHolder;  // the in-memory dataset of an added time coordinate (addFileTime())
    std::shared_ptr<GDALGroup> root;
    std::vector<std::shared_ptr<GDALMDArray>> vars;
    /// A GRIB field: a 2-D array (record -1), or record `record` of a 3-D array over GDAL's TIME dimension.
    struct Field
    {
        std::shared_ptr<GDALMDArray> array;
        long record{-1};
    };
    /// per var: the GRIB fields of one parameter and level, one per time of the added time dimension (empty: the
    /// array as GDAL gives it)
    std::vector<std::vector<Field>> series;
    int timeDim{-1};              // that dimension, -1 without
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

    std::vector<std::string> unreadable;  // "array 'uo': <GDAL's reason>", the arrays GDAL lists but cannot open

    void addGroup(const std::shared_ptr<GDALGroup> &g, CollectGdalErrors &errors)
    {
        for (const std::string &name : g->GetMDArrayNames())
        {
            const std::size_t before = errors.count();
            if (auto a = g->OpenMDArray(name))
                vars.push_back(a);
            else
            {
                const std::string why = errors.since(before);
                unreadable.push_back("array '" + (g->GetFullName() == "/" ? "" : g->GetFullName().substr(1) + "/") +
                                     name + "' cannot be opened" + (why.empty() ? std::string() : ": " + why));
            }
        }
        for (const std::string &name : g->GetGroupNames())  // GRIB: none; a store's subgroups
            if (auto sub = g->OpenGroup(name))
                addGroup(sub, errors);
    }

    /// The fields of a GRIB file over one time dimension, where GDAL gives some field of some time its own 2-D array
    /// with the time only in attributes: a file of one forecast time (RTOFS writes one per forecast hour), or several
    /// times with the parameters interleaved (U, V of one time, then of the next: ERA5-like downloads), which GDAL
    /// gives as 2-D arrays and, where records of one parameter follow each other, 3-D arrays over a TIME dimension.
    /// The fields of one parameter and level (attributes `name`, `first_level`), wherever GDAL put them, become one
    /// variable over the file's times (`validity_time`, or the TIME coordinate: seconds of the Unix epoch); several
    /// files of one time each then read as one forecast. A velocity parameter missing at one of the times is refused
    /// (its fields alone would plan on one time in silence); another parameter missing somewhere stays as GDAL gives
    /// it. A file whose fields GDAL gave all as TIME arrays is read as GDAL gives it.
    void addFileTime()
    {
        std::map<std::string, std::map<double, Field>> fields;  // name|level -> time -> field
        std::vector<std::string> order;                          // the parameters in the file's order
        std::set<std::size_t> used;                              // the vars that hold fields
        std::set<double> times;
        bool loose = false;  // some field is a 2-D array of its own
        for (std::size_t k = 0; k < vars.size(); ++k)
        {
            const auto &a = vars[k];
            std::string key;
            for (const char *name : {"name", "first_level"})
                if (auto text = a->GetAttribute(name); text && text->GetDataType().GetClass() == GEDTC_STRING)
                    key += std::string(text->ReadAsString() ? text->ReadAsString() : "") + "|";
            std::vector<std::pair<double, long>> at;  // (time, record; -1: the 2-D array itself)
            const auto &d = a->GetDimensions();
            if (!d.empty() && d[0]->GetType() == GDAL_DIM_TYPE_TEMPORAL && d.size() == 3)
            {
                const auto axis = d[0]->GetIndexingVariable();
                const std::vector<double> values = axis ? readAll(*axis) : std::vector<double>{};
                if (values.size() != d[0]->GetSize())
                    return;
                for (std::size_t r = 0; r < values.size(); ++r)
                    at.emplace_back(values[r], static_cast<long>(r));
            }
            else if (const auto t = a->GetAttribute("validity_time"); t && d.size() == 2)
            {
                at.emplace_back(t->ReadAsDouble(), -1);
                loose = true;
            }
            if (at.empty() || key.empty())
                continue;
            if (!fields.count(key))
                order.push_back(key);
            for (const auto &[time, record] : at)
            {
                if (!fields[key].emplace(time, Field{a, record}).second)
                    return;  // two fields of one parameter, level and time: GDAL's arrays as they are
                times.insert(time);
            }
            used.insert(k);
        }
        if (!loose)
            return;
        for (auto it = fields.begin(); it != fields.end();)
        {
            if (it->second.size() == times.size())
            {
                ++it;
                continue;
            }
            refuseGap(it->first, it->second, times);
            for (const auto &[time, f] : it->second)  // not a velocity: its arrays as GDAL gives them
                for (std::size_t k = 0; k < vars.size(); ++k)
                    if (vars[k] == f.array)
                        used.erase(k);
            order.erase(std::find(order.begin(), order.end(), it->first));
            it = fields.erase(it);
        }
        GDALDriver *mem = GetGDALDriverManager()->GetDriverByName("MEM");
        if (fields.empty() || !mem)
            return;
        const std::vector<double> values(times.begin(), times.end());
        timeHolder.reset(mem->CreateMultiDimensional("time", nullptr, nullptr));
        auto group = timeHolder ? timeHolder->GetRootGroup() : nullptr;
        auto dim = group ? group->CreateDimension("time", GDAL_DIM_TYPE_TEMPORAL, "", values.size()) : nullptr;
        auto array = dim ? group->CreateMDArray("time", {dim}, GDALExtendedDataType::Create(GDT_Float64)) : nullptr;
        const GUInt64 first = 0;
        const std::size_t n = values.size();
        if (!array || !array->Write(&first, &n, nullptr, nullptr, GDALExtendedDataType::Create(GDT_Float64),
                                    values.data()) || !array->SetUnit("sec UTC"))
            return;
        // one variable per parameter and level, its earliest field standing for it (name, attributes, type); the
        // arrays of other parameters as GDAL gives them
        std::vector<std::shared_ptr<GDALMDArray>> kept;
        std::vector<std::vector<Field>> keptSeries;
        for (std::size_t k = 0; k < vars.size(); ++k)
            if (!used.count(k))
            {
                kept.push_back(vars[k]);
                keptSeries.emplace_back();
            }
        for (const std::string &key : order)
        {
            std::vector<Field> one;
            for (const auto &[time, f] : fields.at(key))
                one.push_back(f);
            kept.push_back(one.front().array);
            keptSeries.push_back(one);
        }
        timeDim = dimOf(dim);
        kept.push_back(array);
        keptSeries.emplace_back();
        vars = kept;
        series = keptSeries;
    }

    /// A velocity parameter (UOGRD, VOGRD, UGRD, VGRD) missing at one of @p times is refused, naming the time.
    void refuseGap(const std::string &key, const std::map<double, Field> &byTime, const std::set<double> &times) const
    {
        const std::string parameter = key.substr(0, key.find('|'));
        if (!gribStandardName(parameter))
            return;
        double missing = 0.0;
        for (const double t : times)
            if (!byTime.count(t))
            {
                missing = t;
                break;
            }
        const std::time_t when = static_cast<std::time_t>(missing);
        char date[32] = "?";
        if (const std::tm *tm = std::gmtime(&when))
            std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", tm);
        throw Error(kind + " '" + withoutCredentials(path) + "': " + parameter + " has fields at " +
                    std::to_string(byTime.size()) + " of the " + std::to_string(times.size()) +
                    " times of the file (none at " + date + "): a forecast needs its currents at every time");
    }

    /// The arrays of the store's consolidated metadata at @p folder that GDAL left out, with @p why.
    void addDropped(const std::string &folder, const std::string &why)
    {
        std::set<std::string> opened;
        for (const auto &a : vars)
            opened.insert(a->GetFullName().substr(1));
        for (const std::string &name : droppedArrays(folder, opened))
            if (std::none_of(unreadable.begin(), unreadable.end(),
                             [&](const std::string &u) { return u.rfind("array '" + name + "'", 0) == 0; }))
                unreadable.push_back("array '" + name + "' of its consolidated metadata cannot be opened" +
                                     (why.empty() ? std::string() : ": " + why));
    }

    static std::vector<double> readAll(const GDALMDArray &a)
    {
        std::vector<double> v(a.GetTotalElementsCount());
        const GUInt64 first = 0;
        const std::size_t n = v.size();
        if (a.GetDimensionCount() != 1 ||
            !a.Read(&first, &n, nullptr, nullptr, GDALExtendedDataType::Create(GDT_Float64), v.data()))
            return {};
        return v;
    }

    bool hasAddedTime(int var) const
    {
        return static_cast<std::size_t>(var) < series.size() && !series[static_cast<std::size_t>(var)].empty();
    }

    std::shared_ptr<GDALAttribute> attribute(int var, const char *name) const
    {
        return var == NC_GLOBAL ? root->GetAttribute(name) : vars.at(static_cast<std::size_t>(var))->GetAttribute(name);
    }
};

GdalGrid::GdalGrid(const std::string &path) : impl_(std::make_unique<Impl>())
{
    const NetCdfLock lock;  // GDAL's datasets, and its netCDF driver's NetCDF-C calls (NetCdfLock.h)
    Impl &d = *impl_;
    d.path = path;
    d.kind = isZarrStore(path) ? "Zarr store" : "GRIB file";
    GDALAllRegister();
    std::string open = path;
    const std::string url = zarrUrl(path);
    if (!url.empty())
    {
        // the store's metadata and chunks fetched into a mirror as the reader asks for them (the cache's, or
        // GDAL's memory): each once, with the time limit and retries; a second run with the cache asks nothing
        d.mirror = std::make_unique<ZarrMirror>(url);
        open = d.mirror->folder();
    }
    else if (isUrl(path))
    {
        // a GRIB file over HTTP: fetched whole, once (its messages are decoded whole anyway), into the cache
        d.file = std::make_unique<FileMirror>(path, ".grib2", "GRIB file");
        open = d.file->file();
    }
    const std::string local = open;  // the store's folder or the file GDAL reads
    if (d.kind == "Zarr store" && open.rfind("ZARR:", 0) != 0)
        open = "ZARR:\"" + withoutSlash(open) + "\"";
    CollectGdalErrors errors;
    d.dataset.reset(GDALDataset::Open(open.c_str(), GDAL_OF_MULTIDIM_RASTER | GDAL_OF_READONLY));
    if (!d.dataset || !(d.root = d.dataset->GetRootGroup()))
    {
        const std::string cut = d.kind == "GRIB file" ? gribTruncation(local) : "";
        const std::string why = !cut.empty() ? cut : errors.since(0);
        throw Error(who() + ": cannot open" + (why.empty() ? std::string() : ": " + why));
    }
    const std::string opening = errors.since(0);  // GDAL's messages on the store as a whole
    d.addGroup(d.root, errors);
    if (d.kind == "Zarr store")
        d.addDropped(zarrFolder(local), opening);
    for (const auto &a : d.vars)
        if (auto srs = a->GetSpatialRef())
            d.geographic = d.geographic || srs->IsGeographic();
    for (const auto &g : d.root->GetDimensions())
        d.dimOf(g);
    for (const auto &a : d.vars)
        for (const auto &g : a->GetDimensions())
            d.dimOf(g);
    if (d.kind == "GRIB file")
    {
        d.addFileTime();
        if (const std::string lone = loneVelocityComponent(d.vars, local); !lone.empty())
            throw Error(who() + ": " + lone);
    }
    if (d.vars.empty())
        throw Error(who() + ": holds no arrays" + (d.unreadable.empty() ? "" : " that can be read: " + unreadable()));
}

std::string GdalGrid::unreadable() const
{
    std::string out;
    for (const std::string &u : impl_->unreadable)
        out += (out.empty() ? "" : "; ") + u;
    return out;
}

GdalGrid::~GdalGrid()
{
    const NetCdfLock lock;  // the dataset closed under the lock too
    impl_.reset();
}

std::shared_ptr<GdalGrid> GdalGrid::open(const std::string &path)
{
    const NetCdfLock netcdf;  // before this function's own lock (NetCdfLock.h: its lock order)
    if (!isUrl(path) && zarrUrl(path).empty())
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
    const NetCdfLock lock;
    return static_cast<int>(impl_->vars.size());
}

std::string GdalGrid::varName(int var) const
{
    const NetCdfLock lock;
    return impl_->vars.at(static_cast<std::size_t>(var))->GetName();
}

std::string GdalGrid::dimName(int dim) const
{
    const NetCdfLock lock;
    return impl_->dims.at(static_cast<std::size_t>(dim))->GetName();
}

std::size_t GdalGrid::dimLen(int dim) const
{
    const NetCdfLock lock;
    return static_cast<std::size_t>(impl_->dims.at(static_cast<std::size_t>(dim))->GetSize());
}

std::optional<int> GdalGrid::findVar(const std::string &name) const
{
    const NetCdfLock lock;
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
    const NetCdfLock lock;
    std::vector<int> out;
    if (impl_->hasAddedTime(var))
        out.push_back(impl_->timeDim);
    for (const auto &g : impl_->vars.at(static_cast<std::size_t>(var))->GetDimensions())
        out.push_back(impl_->dimIndex.at(g->GetFullName()));
    return out;
}

nc_type GdalGrid::varType(int var) const
{
    const NetCdfLock lock;
    const GDALExtendedDataType &t = impl_->vars.at(static_cast<std::size_t>(var))->GetDataType();
    if (t.GetClass() == GEDTC_STRING)
        return NC_STRING;
    return ncTypeOf(t.GetNumericDataType());
}

std::optional<std::string> GdalGrid::attText(int var, const char *name) const
{
    const NetCdfLock netcdf;  // before the dataset's own lock (NetCdfLock.h: its lock order)
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
    const NetCdfLock netcdf;  // before the dataset's own lock (NetCdfLock.h: its lock order)
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
    const NetCdfLock netcdf;  // before the dataset's own lock (NetCdfLock.h: its lock order)
    const std::lock_guard<std::mutex> lock(impl_->mutex);
    for (const Impl::Block &b : impl_->blocks)
        if (b.var == var && inside(start, count, b.start, b.count))
        {
            copyOut(b.values, b.start, b.count, start, count, out);
            return;
        }
    const GDALMDArray &array = *impl_->vars.at(static_cast<std::size_t>(var));
    // a GRIB field given the file's time dimension: each record from its own 2-D array
    const std::size_t skip = impl_->hasAddedTime(var) ? 1 : 0;
    static const std::vector<Impl::Field> none;
    const auto &series = skip ? impl_->series[static_cast<std::size_t>(var)] : none;
    if (skip && (start.empty() || count[0] == 0 || start[0] + count[0] > series.size()))
        throw Error(who() + ": " + array.GetName() + " has " + std::to_string(series.size()) + " times");
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
    bool read = true;
    if (!skip)
        read = array.Read(first.data(), size.data(), nullptr, nullptr, GDALExtendedDataType::Create(GDT_Float64), out);
    else
    {
        std::size_t plane = 1;
        for (const std::size_t c : size)
            plane *= c;
        for (std::size_t t = 0; t < count[0] && read; ++t)
        {
            const Impl::Field &f = series[start[0] + t];
            std::vector<GUInt64> at = first;
            std::vector<std::size_t> span = size;
            if (f.record >= 0)  // a record of GDAL's TIME array
            {
                at.insert(at.begin(), static_cast<GUInt64>(f.record));
                span.insert(span.begin(), 1);
            }
            read = f.array->Read(at.data(), span.data(), nullptr, nullptr, GDALExtendedDataType::Create(GDT_Float64),
                                 out + t * plane);
        }
    }
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
