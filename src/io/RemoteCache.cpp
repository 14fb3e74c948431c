// The cache file of a remote (OPeNDAP) dataset (see RemoteDataset.h): checked against the server before it is read
// further, written anew (all or nothing) with every block fetched.
#include "RemoteDataset.h"

#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "DatasetLock.h"
#include "NumberText.h"
#include "RemoteRecord.h"
#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
/// Where the descriptions of two NetCDF datasets differ in their dimensions or in their coordinate variables' units
/// and calendars ("" when they agree).
std::string describedDifferently(int a, int b)
{
    int na = 0, nb = 0;
    nc_inq_ndims(a, &na);
    nc_inq_ndims(b, &nb);
    if (na != nb)
        return std::to_string(na) + " dimensions cached, " + std::to_string(nb) + " now";
    for (int d = 0; d < na; ++d)
    {
        char name[NC_MAX_NAME + 1] = "", other[NC_MAX_NAME + 1] = "";
        std::size_t la = 0, lb = 0;
        nc_inq_dim(a, d, name, &la);
        nc_inq_dim(b, d, other, &lb);
        if (std::string(name) != other || la != lb)
            return std::string("dimension ") + name + " of " + std::to_string(la) + " cached, " + other + " of " +
                   std::to_string(lb) + " now";
        int va = -1, vb = -1;
        if (nc_inq_varid(a, name, &va) != NC_NOERR || nc_inq_varid(b, name, &vb) != NC_NOERR)
            continue;
        for (const char *att : {"units", "calendar"})
        {
            const std::string ta = textAttribute(a, va, att), tb = textAttribute(b, vb, att);
            if (ta != tb)
                return std::string(name) + ":" + att + " '" + ta + "' cached, '" + tb + "' now";
        }
    }
    return {};
}

} // namespace

void RemoteDataset::checkCacheAnswers()
{
    std::string what = describedDifferently(cacheId_, remoteId_);
    // the coordinate values cached (a forecast republished at the same URL keeps its shape and moves its dates)
    for (const Block &b : blocks_)
    {
        if (!what.empty())
            break;
        char name[NC_MAX_NAME + 1] = "";
        int nd = 0, dim = -1;
        if (b.start.size() != 1 || nc_inq_var(cacheId_, b.var, name, nullptr, &nd, &dim, nullptr) != NC_NOERR)
            continue;
        char dimName[NC_MAX_NAME + 1] = "";
        if (nd != 1 || nc_inq_dimname(cacheId_, dim, dimName) != NC_NOERR || std::string(name) != dimName)
            continue; // not a coordinate variable
        std::vector<double> cached(b.count[0]), now(b.count[0]);
        if (nc_get_vara_double(cacheId_, b.var, b.start.data(), b.count.data(), cached.data()) != NC_NOERR)
            continue;
        attempt("reading " + constraintOf(name, b.start, b.count),
                [&] { return nc_get_vara_double(remoteId_, b.var, b.start.data(), b.count.data(), now.data()); });
        for (std::size_t k = 0; k < cached.size() && what.empty(); ++k)
            if (!(cached[k] == now[k]) && !(std::isnan(cached[k]) && std::isnan(now[k])))
                what = std::string(name) + "[" + std::to_string(b.start[0] + k) + "] " + text::number(cached[k]) +
                       " cached, " + text::number(now[k]) + " now";
    }
    if (!what.empty())
        throw Error(who() + " is not the dataset its cache file '" + cachePath_ + "' holds (" + what +
                    "): republished since it was cached? Its cached values cannot be mixed with the new ones: "
                    "remove the cache file, or plan with another cache folder, to fetch the forecast anew");
}

void RemoteDataset::flush()
{
    const DatasetLock netcdf; // before the dataset's own lock (DatasetLock.h: its lock order)
    std::lock_guard<std::mutex> lock(mutex_);
    if (!dirty_)
        return;
    dirty_ = false;
    const std::string tmp = cachePath_ + ".part" + std::to_string(::getpid());
    try
    {
        writeCache(tmp);
        std::error_code ec;
        std::filesystem::rename(tmp, cachePath_, ec);
        if (ec)
            throw Error("cannot rename '" + tmp + "' to '" + cachePath_ + "': " + ec.message());
        remote_detail::updateFetchRecord(record_, [](RemoteFetch &f) { f.cacheProblem.clear(); });
    }
    catch (const std::exception &e)
    {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        remote_detail::updateFetchRecord(record_, [&](RemoteFetch &f) { f.cacheProblem = e.what(); });
    }
}

void RemoteDataset::writeCache(const std::string &tmp)
{
    const int src = metadataId();
    int out = -1;
    auto check = [&](int st, const std::string &what) {
        if (st != NC_NOERR)
        {
            if (out >= 0)
                nc_close(out);
            throw Error("cache file '" + tmp + "': " + what + ": " + nc_strerror(st));
        }
    };
    // a whole block held only by the old cache file is read before the new file replaces it
    for (Block &b : blocks_)
        if (b.values.empty())
        {
            std::size_t n = 1;
            for (const std::size_t c : b.count)
                n *= c;
            b.values.resize(n);
            check(nc_get_vara_double(cacheId_, b.var, b.start.data(), b.count.data(), b.values.data()),
                  "reading the old cache file");
        }
    check(nc_create(tmp.c_str(), NC_NETCDF4 | NC_CLOBBER, &out), "create");
    int ndims = 0, nvars = 0, natts = 0;
    check(nc_inq(src, &ndims, &nvars, &natts, nullptr), "inquire the source");
    for (int d = 0; d < ndims; ++d) // fixed sizes: the cache holds the remote lengths whatever was fetched
    {
        char name[NC_MAX_NAME + 1];
        std::size_t len = 0;
        int id = -1;
        check(nc_inq_dim(src, d, name, &len), "inquire a dimension");
        check(nc_def_dim(out, name, len, &id), std::string("define dimension ") + name);
    }
    auto copyAtts = [&](int var, int n) {
        for (int a = 0; a < n; ++a)
        {
            char name[NC_MAX_NAME + 1];
            check(nc_inq_attname(src, var, a, name), "inquire an attribute");
            if (std::string(name).rfind("ompl_glider_", 0) == 0)
                continue;
            check(nc_copy_att(src, var, name, out, var), std::string("copy attribute ") + name);
        }
    };
    copyAtts(NC_GLOBAL, natts);
    for (int v = 0; v < nvars; ++v)
    {
        char name[NC_MAX_NAME + 1];
        nc_type type;
        int nd = 0, dims[NC_MAX_VAR_DIMS], na = 0, id = -1;
        check(nc_inq_var(src, v, name, &type, &nd, dims, &na), "inquire a variable");
        check(nc_def_var(out, name, type, nd, dims, &id), std::string("define variable ") + name);
        if (nd > 0)
            check(nc_def_var_deflate(out, id, 1, 1, 1), std::string("compress variable ") + name);
        copyAtts(v, na);
    }
    std::string blocks, fetched;
    for (const Block &b : blocks_)
    {
        blocks += std::to_string(b.var) + " " + std::to_string(b.start.size());
        for (const std::size_t x : b.start)
            blocks += " " + std::to_string(x);
        for (const std::size_t x : b.count)
            blocks += " " + std::to_string(x);
        blocks += "\n";
        char name[NC_MAX_NAME + 1] = "";
        nc_inq_varname(src, b.var, name);
        fetched += constraintOf(name, b.start, b.count) + "\n";
    }
    const std::string shown = withoutCredentials(url_);
    check(nc_put_att_text(out, NC_GLOBAL, "ompl_glider_source", shown.size(), shown.c_str()), "write the source");
    check(nc_put_att_text(out, NC_GLOBAL, "ompl_glider_fetched", fetched.size(), fetched.c_str()),
          "write the constraints");
    check(nc_put_att_text(out, NC_GLOBAL, "ompl_glider_blocks", blocks.size(), blocks.c_str()), "write the blocks");
    check(nc_enddef(out), "end the definitions");
    for (const Block &b : blocks_)
        check(nc_put_vara_double(out, b.var, b.start.data(), b.count.data(), b.values.data()), "write values");
    check(nc_close(out), "close");
    out = -1;
}
} // namespace gridded_detail
} // namespace ompl_glider
