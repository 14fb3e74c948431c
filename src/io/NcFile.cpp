// The open NetCDF file and its queries (see NcFile.h).
#include "NcFile.h"

#include <hdf5.h>
#include <netcdf_mem.h>

#include "RemoteDataset.h"
#include "RemoteRecord.h"
#include "ompl_glider/io/MemoryDataset.h"
#include "TextUtil.h"
#include "ompl_glider/Config.h"
#if OMPL_GLIDER_WITH_MISSION
#include "GdalGrid.h"
#endif

namespace ompl_glider
{
namespace netcdf_detail
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
}  // namespace

NcFile::NcFile(const std::string &path) : path_(path)
{
#if OMPL_GLIDER_WITH_MISSION
    if (isGdalSource(path))
    {
        gdal_ = GdalGrid::open(path);
        return;
    }
#endif
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
        // NetCDF-C reads the bytes in place (NC_INMEMORY without NC_WRITE): they stay alive while the file is open
        char *bytes = const_cast<char *>(memory_->data());
        const int st = nc_open_mem(path.c_str(), NC_NOWRITE, memory_->size(), bytes, &id_);
        if (st != NC_NOERR)
            throw Error("NetCDF dataset '" + path + "': cannot open: " + nc_strerror(st));
        return;
    }
    // A classic file is checked against its header before NetCDF-C opens it: NetCDF-C reads a cut file as if it
    // were complete, and allocates whatever a corrupt header declares (an attribute of 2^31 values) before reading.
    if (auto cut = classicTruncation(path))
        throw Error("NetCDF file '" + path + "' " + *cut);
    const int st = nc_open(path.c_str(), NC_NOWRITE, &id_);
    if (st != NC_NOERR)
        throw Error("NetCDF file '" + path + "': cannot open: " + nc_strerror(st));
}

NcFile::~NcFile()
{
    if (gdal_)
        return;
    if (remote_)
        remote_->flush();  // the dataset stays open for the process's next reader
    else
        nc_close(id_);
}

Error NcFile::error(const std::string &what) const
{
    return Error((gdal_ ? gdal_->who() : remote_ ? remote_->who() : "NetCDF file '" + path_ + "'") + ": " + what);
}

void NcFile::check(int status, const std::string &what) const
{
    if (status != NC_NOERR)
        throw error(what + ": " + nc_strerror(status));
}

int NcFile::nvars() const
{
    if (gdal_)
        return gdal_->nvars();
    int n = 0;
    check(nc_inq_nvars(id_, &n), "inquire variables");
    return n;
}

std::string NcFile::varName(int var) const
{
    if (gdal_)
        return gdal_->varName(var);
    char buf[NC_MAX_NAME + 1];
    check(nc_inq_varname(id_, var, buf), "inquire variable name");
    return buf;
}

std::string NcFile::dimName(int dim) const
{
    if (gdal_)
        return gdal_->dimName(dim);
    char buf[NC_MAX_NAME + 1];
    check(nc_inq_dimname(id_, dim, buf), "inquire dimension name");
    return buf;
}

std::size_t NcFile::dimLen(int dim) const
{
    if (gdal_)
        return gdal_->dimLen(dim);
    std::size_t n = 0;
    check(nc_inq_dimlen(id_, dim, &n), "inquire dimension length");
    return n;
}

std::optional<int> NcFile::findVar(const std::string &name) const
{
    if (gdal_)
        return gdal_->findVar(name);
    int v;
    if (nc_inq_varid(id_, name.c_str(), &v) == NC_NOERR)
        return v;
    return std::nullopt;
}

std::vector<int> NcFile::varDims(int var) const
{
    if (gdal_)
        return gdal_->varDims(var);
    int nd = 0;
    check(nc_inq_varndims(id_, var, &nd), "inquire dimensions of '" + varName(var) + "'");
    std::vector<int> d(static_cast<std::size_t>(nd));
    if (nd > 0)
        check(nc_inq_vardimid(id_, var, d.data()), "inquire dimensions of '" + varName(var) + "'");
    return d;
}

nc_type NcFile::varType(int var) const
{
    if (gdal_)
        return gdal_->varType(var);
    nc_type t;
    check(nc_inq_vartype(id_, var, &t), "inquire type of '" + varName(var) + "'");
    return t;
}

std::optional<std::string> NcFile::attText(int var, const char *name) const
{
    if (gdal_)
        return gdal_->attText(var, name);
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

std::vector<double> NcFile::attDoubles(int var, const char *name) const
{
    nc_type t = NC_DOUBLE;
    std::size_t len = 0;
    bool gdalText = false;
    if (gdal_)
    {
        std::vector<double> v = gdal_->attDoubles(var, name, gdalText);
        if (!gdalText)
            return v;
    }
    else if (nc_inq_att(id_, var, name, &t, &len) != NC_NOERR)
        return {};
    if (gdalText || t == NC_CHAR || t == NC_STRING)  // CF: these attributes are numbers; text would be ignored
        throw error((var == NC_GLOBAL ? std::string("global") : "variable '" + varName(var) + "':") +
                    " attribute '" + name + "' is text ('" + attText(var, name).value_or("") +
                    "'); it must be numeric");
    std::vector<double> v(len);
    check(nc_get_att_double(id_, var, name, v.data()), std::string("read attribute ") + name);
    return v;
}

std::vector<double> NcFile::readAll1D(int var) const
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

void NcFile::readBlock(int var, const std::vector<std::size_t> &start, const std::vector<std::size_t> &count,
                       double *out) const
{
    if (gdal_)
        gdal_->readBlock(var, start, count, out);
    else if (remote_)
        remote_->read(var, start, count, out);
    else
        check(nc_get_vara_double(id_, var, start.data(), count.data(), out), "read variable '" + varName(var) + "'");
}
}  // namespace netcdf_detail
}  // namespace ompl_glider
