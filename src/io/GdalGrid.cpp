// A gridded dataset through GDAL's multidimensional API (see GdalGrid.h): opening a store or a GRIB file, the
// queries, reading blocks; a GRIB file's time dimension in GribTimes.cpp (GdalGridImpl.h).
#include "GdalGrid.h"

#include <cstring>
#include <map>
#include <mutex>

#include <gdal_priv.h>

#include "BlockCopy.h"
#include "GdalGridImpl.h"
#include "TextUtil.h"
#include "DatasetLock.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/FileList.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
namespace gridded_detail
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
    ~QuietGdal() { CPLPopErrorHandler(); }
    QuietGdal(const QuietGdal &) = delete;
    QuietGdal &operator=(const QuietGdal &) = delete;
};

ValueType valueTypeOf(GDALDataType t)
{
    switch (t)
    {
    case GDT_Byte:
        return ValueType::UByte;
    case GDT_UInt16:
        return ValueType::UShort;
    case GDT_Int16:
        return ValueType::Short;
    case GDT_UInt32:
        return ValueType::UInt;
    case GDT_Int32:
        return ValueType::Int;
    case GDT_UInt64:
        return ValueType::UInt64;
    case GDT_Int64:
        return ValueType::Int64;
    case GDT_Float32:
        return ValueType::Float;
    default:
        return ValueType::Double;
    }
}
} // namespace

GdalGrid::GdalGrid(const std::string &path) : impl_(std::make_unique<Impl>())
{
    const DatasetLock lock; // GDAL's datasets, and its netCDF driver's NetCDF-C calls (DatasetLock.h)
    Impl &d = *impl_;
    d.path = path;
    d.kind = isZarrStore(path) ? DatasetKind::ZarrStore : DatasetKind::GribFile;
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
        d.file = std::make_unique<FileMirror>(path, ".grib2", DatasetKind::GribFile);
        open = d.file->file();
    }
    const std::string local = open; // the store's folder or the file GDAL reads
    if (d.kind == DatasetKind::ZarrStore && open.rfind("ZARR:", 0) != 0)
        open = "ZARR:\"" + withoutSlash(open) + "\"";
    CollectGdalErrors errors;
    d.dataset.reset(GDALDataset::Open(open.c_str(), GDAL_OF_MULTIDIM_RASTER | GDAL_OF_READONLY));
    if (!d.dataset || !(d.root = d.dataset->GetRootGroup()))
    {
        const std::string cut = d.kind == DatasetKind::GribFile ? gribTruncation(local) : "";
        const std::string why = !cut.empty() ? cut : errors.since(0);
        throw Error(who() + ": cannot open" + (why.empty() ? std::string() : ": " + why));
    }
    const std::string opening = errors.since(0); // GDAL's messages on the store as a whole
    d.addGroup(d.root, errors);
    if (d.kind == DatasetKind::ZarrStore)
        d.addDropped(zarrFolder(local), opening);
    for (const auto &a : d.vars)
        if (auto srs = a->GetSpatialRef())
            d.geographic = d.geographic || srs->IsGeographic();
    for (const auto &g : d.root->GetDimensions())
        d.dimOf(g);
    for (const auto &a : d.vars)
        for (const auto &g : a->GetDimensions())
            d.dimOf(g);
    if (d.kind == DatasetKind::GribFile)
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
    const DatasetLock lock; // the dataset closed under the lock too
    impl_.reset();
}

std::shared_ptr<GdalGrid> GdalGrid::open(const std::string &path)
{
    const DatasetLock netcdf; // before this function's own lock (DatasetLock.h: its lock order)
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
    return datasetWho(impl_->kind, withoutCredentials(impl_->path));
}

int GdalGrid::nvars() const
{
    const DatasetLock lock;
    return static_cast<int>(impl_->vars.size());
}

std::string GdalGrid::varName(int var) const
{
    const DatasetLock lock;
    return impl_->vars.at(static_cast<std::size_t>(var))->GetName();
}

std::string GdalGrid::dimName(int dim) const
{
    const DatasetLock lock;
    return impl_->dims.at(static_cast<std::size_t>(dim))->GetName();
}

std::size_t GdalGrid::dimLen(int dim) const
{
    const DatasetLock lock;
    return static_cast<std::size_t>(impl_->dims.at(static_cast<std::size_t>(dim))->GetSize());
}

std::optional<int> GdalGrid::findVar(const std::string &name) const
{
    const DatasetLock lock;
    for (std::size_t k = 0; k < impl_->vars.size(); ++k)
        if (impl_->vars[k]->GetName() == name)
            return static_cast<int>(k);
    // a GRIB parameter by its short name (UOGRD for the array UOGRD_0-DBSL), where one array has it
    std::optional<int> found;
    for (std::size_t k = 0; k < impl_->vars.size(); ++k)
        if (auto a = impl_->vars[k]->GetAttribute("name");
            a && a->GetDataType().GetClass() == GEDTC_STRING && a->ReadAsString() && name == a->ReadAsString())
        {
            if (found)
                return std::nullopt; // several levels or times: the array's own name is needed
            found = static_cast<int>(k);
        }
    return found;
}

std::vector<int> GdalGrid::varDims(int var) const
{
    const DatasetLock lock;
    std::vector<int> out;
    if (impl_->hasAddedTime(var))
        out.push_back(impl_->timeDim);
    for (const auto &g : impl_->vars.at(static_cast<std::size_t>(var))->GetDimensions())
        out.push_back(impl_->dimIndex.at(g->GetFullName()));
    return out;
}

ValueType GdalGrid::varType(int var) const
{
    const DatasetLock lock;
    const GDALExtendedDataType &t = impl_->vars.at(static_cast<std::size_t>(var))->GetDataType();
    if (t.GetClass() == GEDTC_STRING)
        return ValueType::String;
    return valueTypeOf(t.GetNumericDataType());
}

std::optional<std::string> GdalGrid::attText(int var, const char *name) const
{
    const DatasetLock netcdf; // before the dataset's own lock (DatasetLock.h: its lock order)
    const std::lock_guard<std::mutex> lock(impl_->mutex);
    if (auto a = impl_->attribute(var, name))
    {
        if (a->GetDataType().GetClass() != GEDTC_STRING)
            return std::nullopt;
        const char *s = a->ReadAsString();
        return text::trim(s ? s : "");
    }
    if (var == kGlobalAttributes)
        return std::nullopt;
    const GDALMDArray &array = *impl_->vars.at(static_cast<std::size_t>(var));
    if (std::strcmp(name, "units") == 0)
    {
        const std::string unit = text::trim(array.GetUnit());
        if (unit == "sec UTC") // GDAL's GRIB times: seconds of the Unix epoch
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
    const DatasetLock netcdf; // before the dataset's own lock (DatasetLock.h: its lock order)
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
    if (var == kGlobalAttributes)
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
    const DatasetLock netcdf; // before the dataset's own lock (DatasetLock.h: its lock order)
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
            if (f.record >= 0) // a record of GDAL's TIME array
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
} // namespace gridded_detail
} // namespace ompl_glider
