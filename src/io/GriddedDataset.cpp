// The open gridded dataset and its queries (see GriddedDataset.h), and NetCDF-C's reader of files, in-memory datasets
// and OPeNDAP URLs: the one place that holds a NetCDF id.
#include "GriddedDataset.h"

#include <hdf5.h>
#include <netcdf.h>
#include <netcdf_mem.h>

#include "Dataset.h"
#include "DatasetLock.h"
#include "RemoteDataset.h"
#include "RemoteRecord.h"
#include "ompl_glider/io/MemoryDataset.h"
#include "TextUtil.h"
#include "ompl_glider/Config.h"
#if OMPL_GLIDER_WITH_MISSION
#include "GdalModule.h"
#endif

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
/// HDF5 keeps an error stack, and its automatic printing, per thread; NetCDF-C switches the printing off only on the
/// thread that first opens a NetCDF-4 file. Every thread that opens one switches it off for itself: NetCDF-C's
/// probes for optional attributes fail inside HDF5 by design, and the errors that matter reach the user through
/// NetCDF-C's status codes.
void quietHdf5OnThisThread()
{
    thread_local const bool quiet = H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) >= 0;
    (void)quiet;
}
/// A dataset NetCDF-C reads: a file (checked against its classic header first), an in-memory dataset, or an
/// OPeNDAP URL (RemoteDataset: its description from the cache file when there is one).
class NetCdfDataset final : public Dataset
{
public:
    explicit NetCdfDataset(const std::string &path) : path_(path)
    {
        const DatasetLock lock;
        quietHdf5OnThisThread();
        const RemoteAccess access = remoteAccess();
        prepareNetcdfAccess(access);
        if (isRemoteSource(path))
        {
            remote_ = RemoteDataset::open(path, access);
            id_ = remote_->metadataId();
            return;
        }
        if (isMemoryDataset(path))
        {
            memory_ = remote_detail::memoryDataset(path);
            if (!memory_)
                throw Error("NetCDF dataset '" + path + "': no such dataset in memory (released)");
            // NetCDF-C reads the bytes in place (NC_INMEMORY without NC_WRITE): they stay alive while it is open
            char *bytes = const_cast<char *>(memory_->data());
            const int st = nc_open_mem(path.c_str(), NC_NOWRITE, memory_->size(), bytes, &id_);
            if (st != NC_NOERR)
                throw Error("NetCDF dataset '" + path + "': cannot open: " + nc_strerror(st));
            return;
        }
        // A classic file is checked against its header before NetCDF-C opens it: NetCDF-C reads a cut file as if it
        // were complete, and allocates whatever a corrupt header declares (an attribute of 2^31 values) first.
        if (auto cut = classicTruncation(path))
            throw Error("NetCDF file '" + path + "' " + *cut);
        const int st = nc_open(path.c_str(), NC_NOWRITE, &id_);
        if (st != NC_NOERR)
            throw Error("NetCDF file '" + path + "': cannot open: " + nc_strerror(st));
    }
    ~NetCdfDataset() override
    {
        const DatasetLock lock;
        if (remote_)
            remote_->flush(); // the dataset stays open for the process's next reader
        else
            nc_close(id_);
    }
    NetCdfDataset(const NetCdfDataset &) = delete;
    NetCdfDataset &operator=(const NetCdfDataset &) = delete;

    std::string who() const override { return remote_ ? remote_->who() : "NetCDF file '" + path_ + "'"; }
    int nvars() const override
    {
        const DatasetLock lock;
        int n = 0;
        check(nc_inq_nvars(id_, &n), "inquire variables");
        return n;
    }
    std::string varName(int var) const override
    {
        const DatasetLock lock;
        char buf[NC_MAX_NAME + 1];
        check(nc_inq_varname(id_, var, buf), "inquire variable name");
        return buf;
    }
    std::string dimName(int dim) const override
    {
        const DatasetLock lock;
        char buf[NC_MAX_NAME + 1];
        check(nc_inq_dimname(id_, dim, buf), "inquire dimension name");
        return buf;
    }
    std::size_t dimLen(int dim) const override
    {
        const DatasetLock lock;
        std::size_t n = 0;
        check(nc_inq_dimlen(id_, dim, &n), "inquire dimension length");
        return n;
    }
    std::optional<int> findVar(const std::string &name) const override
    {
        const DatasetLock lock;
        int v;
        if (nc_inq_varid(id_, name.c_str(), &v) == NC_NOERR)
            return v;
        return std::nullopt;
    }
    std::vector<int> varDims(int var) const override
    {
        const DatasetLock lock;
        int nd = 0;
        check(nc_inq_varndims(id_, var, &nd), "inquire dimensions of '" + varName(var) + "'");
        std::vector<int> d(static_cast<std::size_t>(nd));
        if (nd > 0)
            check(nc_inq_vardimid(id_, var, d.data()), "inquire dimensions of '" + varName(var) + "'");
        return d;
    }
    ValueType varType(int var) const override
    {
        const DatasetLock lock;
        nc_type t;
        check(nc_inq_vartype(id_, var, &t), "inquire type of '" + varName(var) + "'");
        return valueTypeOf(t);
    }
    std::optional<std::string> attText(int var, const char *name) const override
    {
        const DatasetLock lock;
        nc_type t;
        std::size_t len;
        if (nc_inq_att(id_, var, name, &t, &len) != NC_NOERR)
            return std::nullopt;
        if (t == NC_CHAR)
        {
            std::string s(len, '\0');
            if (len > 0)
                check(nc_get_att_text(id_, var, name, &s[0]), std::string("read attribute ") + name);
            return text::trim(s);
        }
        if (t == NC_STRING && len >= 1)
        {
            std::vector<char *> p(len, nullptr);
            check(nc_get_att_string(id_, var, name, p.data()), std::string("read attribute ") + name);
            std::string s = p[0] ? p[0] : "";
            nc_free_string(len, p.data());
            return text::trim(s);
        }
        return std::nullopt;
    }
    std::vector<double> attDoubles(int var, const char *name, bool &isText) const override
    {
        const DatasetLock lock;
        nc_type t = NC_DOUBLE;
        std::size_t len = 0;
        isText = false;
        if (nc_inq_att(id_, var, name, &t, &len) != NC_NOERR)
            return {};
        if (t == NC_CHAR || t == NC_STRING)
        {
            isText = true;
            return {};
        }
        std::vector<double> v(len);
        check(nc_get_att_double(id_, var, name, v.data()), std::string("read attribute ") + name);
        return v;
    }
    void readBlock(int var, const std::vector<std::size_t> &start, const std::vector<std::size_t> &count,
                   double *out) const override
    {
        const DatasetLock lock;
        if (remote_)
            remote_->read(var, start, count, out);
        else
            check(nc_get_vara_double(id_, var, start.data(), count.data(), out),
                  "read variable '" + varName(var) + "'");
    }

    std::vector<std::string> groupNames() const override
    {
        const DatasetLock lock;
        int n = 0;
        if (nc_inq_grps(id_, &n, nullptr) != NC_NOERR || n <= 0)
            return {};
        std::vector<int> ids(static_cast<std::size_t>(n));
        nc_inq_grps(id_, &n, ids.data());
        std::vector<std::string> names;
        for (int g : ids)
        {
            char name[NC_MAX_NAME + 1] = {0};
            nc_inq_grpname(g, name);
            names.emplace_back(name);
        }
        return names;
    }
    std::string readChars(int var) const override
    {
        const DatasetLock lock;
        std::size_t n = 1;
        for (int d : varDims(var))
            n *= dimLen(d);
        std::vector<char> chars(n + 1, '\0');
        check(nc_get_var_text(id_, var, chars.data()), "read '" + varName(var) + "'");
        return std::string(chars.data(), n);
    }

private:
    static ValueType valueTypeOf(nc_type t)
    {
        switch (t)
        {
        case NC_BYTE:
            return ValueType::Byte;
        case NC_UBYTE:
            return ValueType::UByte;
        case NC_SHORT:
            return ValueType::Short;
        case NC_USHORT:
            return ValueType::UShort;
        case NC_INT:
            return ValueType::Int;
        case NC_UINT:
            return ValueType::UInt;
        case NC_INT64:
            return ValueType::Int64;
        case NC_UINT64:
            return ValueType::UInt64;
        case NC_FLOAT:
            return ValueType::Float;
        case NC_DOUBLE:
            return ValueType::Double;
        case NC_CHAR:
            return ValueType::Char;
        case NC_STRING:
            return ValueType::String;
        default:
            return ValueType::Other;
        }
    }
    void check(int status, const std::string &what) const
    {
        const DatasetLock lock;
        if (status != NC_NOERR)
            throw Error(who() + ": " + what + ": " + nc_strerror(status));
    }

    std::string path_;
    int id_{-1};
    std::shared_ptr<RemoteDataset> remote_;     ///< a URL's dataset (null for a file)
    std::shared_ptr<const std::string> memory_; ///< an in-memory dataset's bytes (MemoryDataset.h)
};
} // namespace

GriddedDataset::GriddedDataset(const std::string &path) : path_(path)
{
#if OMPL_GLIDER_WITH_MISSION
    if (isGdalSource(path))
    {
        data_ = gdal_detail::gdalPart().openGrid(path); // GDAL loaded here (GdalModule.h)
        return;
    }
#endif
    data_ = std::make_shared<NetCdfDataset>(path);
}

GriddedDataset::~GriddedDataset() = default;

Error GriddedDataset::error(const std::string &what) const
{
    return Error(data_->who() + ": " + what);
}

Error GriddedDataset::error(const std::string &what, const std::string &field) const
{
    return Error(data_->who() + ": " + what, field);
}

std::string GriddedDataset::unreadable() const
{
    return data_->unreadable();
}

std::vector<std::string> GriddedDataset::groupNames() const
{
    return data_->groupNames();
}

std::string GriddedDataset::readChars(int var) const
{
    return data_->readChars(var);
}

int GriddedDataset::nvars() const
{
    return data_->nvars();
}

std::string GriddedDataset::varName(int var) const
{
    return data_->varName(var);
}

std::string GriddedDataset::dimName(int dim) const
{
    return data_->dimName(dim);
}

std::size_t GriddedDataset::dimLen(int dim) const
{
    return data_->dimLen(dim);
}

std::optional<int> GriddedDataset::findVar(const std::string &name) const
{
    return data_->findVar(name);
}

std::vector<int> GriddedDataset::varDims(int var) const
{
    return data_->varDims(var);
}

ValueType GriddedDataset::varType(int var) const
{
    return data_->varType(var);
}

std::optional<std::string> GriddedDataset::attText(int var, const char *name) const
{
    return data_->attText(var, name);
}

std::vector<double> GriddedDataset::attDoubles(int var, const char *name) const
{
    bool isText = false;
    std::vector<double> v = data_->attDoubles(var, name, isText);
    if (isText) // CF: these attributes are numbers; text would be ignored
        throw error((var == kGlobalAttributes ? std::string("global") : "variable '" + varName(var) + "':") +
                    " attribute '" + name + "' is text ('" + attText(var, name).value_or("") +
                    "'); it must be numeric");
    return v;
}

std::vector<double> GriddedDataset::readAll1D(int var) const
{
    const std::vector<int> d = varDims(var);
    std::size_t n = 1;
    for (int x : d)
        n *= dimLen(x);
    std::vector<double> v(n);
    if (n > 0)
    {
        std::vector<std::size_t> start(d.size(), 0), count(d.size());
        for (std::size_t k = 0; k < d.size(); ++k)
            count[k] = dimLen(d[k]);
        readBlock(var, start, count, v.data());
    }
    return v;
}

void GriddedDataset::readBlock(int var, const std::vector<std::size_t> &start, const std::vector<std::size_t> &count,
                               double *out) const
{
    data_->readBlock(var, start, count, out);
}
} // namespace gridded_detail
} // namespace ompl_glider
