// Remote (OPeNDAP) datasets for GriddedDataset: NetCDF-C's HTTP time limits, requests retried a bounded number of
// times, the values fetched kept in memory, what was read noted in the process's record (RemoteRecord.h; see
// RemoteDataset.h, io/RemoteSource.h). The cache file: RemoteCache.cpp.
#include "RemoteDataset.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <unistd.h>

#include "BlockCopy.h"
#include "FetchStop.h"
#include "DatasetLock.h"
#include "NumberText.h"
#include "RemoteRecord.h"
#include "TextUtil.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/StopRequest.h"
#if OMPL_GLIDER_WITH_MISSION
#include "GdalModule.h" // the DAP answer explained (HttpMirror.h), GDAL loaded then
#endif

namespace ompl_glider
{
namespace
{
/// Failures worth another attempt: the network, the server, and an answer that is malformed or cut short (a slow
/// answer cut by the time limit, a server that closes the connection early).
bool transient(int status)
{
    return status == NC_EIO || status == NC_ECURL || status == NC_EDAPSVC || status == NC_EDAS || status == NC_EDDS ||
           status == NC_EDATADDS;
}

/// The text NetCDF-C's DAP client prints for an answer shorter than its description: it then returns the values
/// zero-filled with NC_NOERR, so the text is the only sign.
bool cutShort(const std::string &log)
{
    return log.find("apparently too short") != std::string::npos;
}

/// NetCDF-C's DAP parser on an answer that is not DAP (an HTML page: "syntax error ... context: <!DOCTYPE^ HTML>..."):
/// not echoed (the page), the open's failure explained instead (notDapAnswer()).
bool foreignAnswer(const std::string &log)
{
    return log.find("context: <") != std::string::npos || log.find("context: \n<") != std::string::npos;
}

/// Set by the last failed attempt of this thread: NetCDF-C's parser met an answer that is not DAP.
thread_local bool lastAnswerForeign = false;

/// Runs @p call with the process's standard error taken into a temporary file, which is returned in @p log; what it
/// caught is written on to standard error unless it is NetCDF-C's note of an answer cut short (then the caller says
/// what happened). One call at a time (the error stream is the process's).
int callWatchingLog(const std::function<int()> &call, std::string &log)
{
    static std::mutex m;
    const std::lock_guard<std::mutex> lock(m);
    std::fflush(stderr);
    std::FILE *tmp = std::tmpfile();
    const int saved = tmp ? ::dup(STDERR_FILENO) : -1;
    if (saved < 0 || ::dup2(::fileno(tmp), STDERR_FILENO) < 0)
    {
        if (saved >= 0)
            ::close(saved);
        if (tmp)
            std::fclose(tmp);
        return call(); // no temporary file: unwatched (the complaint reaches the terminal)
    }
    const int st = call();
    std::fflush(stderr);
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    std::rewind(tmp);
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, tmp)) > 0;)
        log.append(buf, n);
    std::fclose(tmp);
    if (!log.empty() && !cutShort(log) && !foreignAnswer(log))
        (void)!::write(STDERR_FILENO, log.data(), log.size());
    return st;
}

/// Reads "ompl_glider_blocks" of a cache file: one block per line, "var start... / count...".
std::vector<std::pair<int, std::pair<std::vector<std::size_t>, std::vector<std::size_t>>>> cachedBlocks(int ncid)
{
    std::vector<std::pair<int, std::pair<std::vector<std::size_t>, std::vector<std::size_t>>>> out;
    std::size_t len = 0;
    if (nc_inq_attlen(ncid, NC_GLOBAL, "ompl_glider_blocks", &len) != NC_NOERR)
        return out;
    std::string text(len, '\0');
    if (len > 0 && nc_get_att_text(ncid, NC_GLOBAL, "ompl_glider_blocks", &text[0]) != NC_NOERR)
        return out;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
    {
        std::istringstream in(line);
        int var = -1, nd = -1;
        if (!(in >> var >> nd) || var < 0 || nd < 0 || nd > NC_MAX_VAR_DIMS)
            continue;
        std::vector<std::size_t> s(static_cast<std::size_t>(nd)), c(static_cast<std::size_t>(nd));
        for (auto &x : s)
            in >> x;
        for (auto &x : c)
            in >> x;
        if (in)
            out.push_back({var, {s, c}});
    }
    return out;
}

std::string readText(const std::filesystem::path &p)
{
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}
} // namespace

namespace gridded_detail
{
std::string constraintOf(const std::string &name, const std::vector<std::size_t> &s, const std::vector<std::size_t> &c)
{
    std::string out = name;
    for (std::size_t d = 0; d < s.size(); ++d)
        out += "[" + std::to_string(s[d]) + ":" + std::to_string(s[d] + c[d] - 1) + "]";
    return out;
}

std::string textAttribute(int ncid, int var, const char *name)
{
    std::size_t len = 0;
    nc_type type = NC_NAT;
    if (nc_inq_att(ncid, var, name, &type, &len) != NC_NOERR || type != NC_CHAR)
        return {};
    std::string text(len, '\0');
    if (len > 0 && nc_get_att_text(ncid, var, name, &text[0]) != NC_NOERR)
        return {};
    while (!text.empty() && text.back() == '\0')
        text.pop_back();
    return text;
}

namespace
{
/// The request time limit NetCDF-C was given (seconds; 0: the user's own NCRCENV_RC file, or not set yet).
std::atomic<long> &limitInForce()
{
    static std::atomic<long> seconds{0};
    return seconds;
}

/// Why the time limit could not be given to NetCDF-C (empty: it was, or the user's own NCRCENV_RC file rules).
std::string &limitProblem()
{
    static std::string why;
    return why;
}
} // namespace

void prepareNetcdfAccess(const RemoteAccess &access)
{
    const DatasetLock lock; // NetCDF-C reads the environment at its first call
    static std::once_flag once;
    std::call_once(once, [&] {
        if (std::getenv("NCRCENV_RC"))
            return; // the user's own rc file
        namespace fs = std::filesystem;
        std::error_code ec;
        fs::path tmp;
        try
        {
            tmp = temporaryFolder();
        }
        catch (const Error &e)
        {
            limitProblem() = e.what();
            return;
        }
        const fs::path dir = tmp / ("ompl_glider_ncrc_" + std::to_string(::getpid()));
        fs::create_directories(dir, ec);
        // what NetCDF-C would have read without NCRCENV_RC (credentials, proxies), then the time limits
        std::string text;
        const char *home = std::getenv("HOME");
        for (const fs::path &base : {home ? fs::path(home) : fs::path(), fs::current_path(ec)})
            for (const char *name : {".ncrc", ".daprc", ".dodsrc"})
                if (!base.empty() && fs::is_regular_file(base / name, ec))
                    text += readText(base / name) + "\n";
        const long seconds = std::max(1L, static_cast<long>(std::ceil(access.requestTimeout)));
        text += "HTTP.TIMEOUT=" + std::to_string(seconds) + "\nHTTP.CONNECTTIMEOUT=" + std::to_string(seconds) + "\n";
        const fs::path rc = dir / "ncrc";
        std::ofstream(rc) << text;
        if (!fs::is_regular_file(rc, ec))
            limitProblem() = "cannot write '" + rc.string() + "' (set TMPDIR to a writable folder)";
        else
        {
            ::setenv("NCRCENV_RC", rc.c_str(), 0);
            limitInForce() = seconds;
            static const std::string removeAtExit = dir.string();
            std::atexit([] {
                std::error_code e;
                std::filesystem::remove_all(removeAtExit, e);
            });
        }
    });
}

long requestLimitInForce()
{
    return limitInForce();
}

std::shared_ptr<RemoteDataset> RemoteDataset::open(const std::string &url, const RemoteAccess &access)
{
    const DatasetLock netcdf; // before this function's own lock (DatasetLock.h: its lock order)
    static std::mutex m;
    // kept for the process (never destroyed: no NetCDF call after NetCDF-C's own end at exit)
    static auto &open = *new std::map<std::string, std::shared_ptr<RemoteDataset>>();
    std::lock_guard<std::mutex> lock(m);
    const std::string key = url + '\n' + access.cacheDir;
    if (auto it = open.find(key); it != open.end())
        return it->second;
    const std::size_t k = remote_detail::newFetchRecord(withoutCredentials(url)); // what the outputs show
    std::shared_ptr<RemoteDataset> d(new RemoteDataset(url, access, k));
    open[key] = d;
    return d;
}

RemoteDataset::RemoteDataset(std::string url, RemoteAccess access, std::size_t record)
    : url_(std::move(url)), access_(std::move(access)), record_(record)
{
    if (!access_.cacheDir.empty())
    {
        namespace fs = std::filesystem;
        std::error_code ec;
        fs::create_directories(access_.cacheDir, ec);
        if (!fs::is_directory(access_.cacheDir, ec))
            throw Error(who() + ": the cache folder '" + access_.cacheDir + "' cannot be made");
        cachePath_ = (fs::path(access_.cacheDir) / remote_detail::cacheName(withoutCredentials(url_), ".nc")).string();
        remote_detail::updateFetchRecord(record_, [&](RemoteFetch &f) { f.cacheFile = cachePath_; });
        if (fs::is_regular_file(cachePath_, ec))
        {
            if (nc_open(cachePath_.c_str(), NC_NOWRITE, &cacheId_) != NC_NOERR)
                cacheId_ = -1; // an unreadable cache file is fetched anew and replaced
            else if (const std::string held = textAttribute(cacheId_, NC_GLOBAL, "ompl_glider_source");
                     held != withoutCredentials(url_))
            {
                // another source's cache file (copied into place, or a name shared by two URLs): not this forecast
                nc_close(cacheId_);
                cacheId_ = -1;
                const std::string why = "the file found at the cache file's place holds " +
                                        (held.empty() ? std::string("no source name") : "'" + held + "'") +
                                        ": fetched anew, the file replaced";
                remote_detail::updateFetchRecord(record_, [&](RemoteFetch &f) { f.cacheIgnored = why; });
            }
            else
                for (const auto &[var, sc] : cachedBlocks(cacheId_))
                    blocks_.push_back(Block{var, sc.first, sc.second, {}});
        }
    }
    if (cacheId_ < 0)
        remoteId();
}

RemoteDataset::~RemoteDataset()
{
    const DatasetLock lock;
    if (cacheId_ >= 0)
        nc_close(cacheId_);
    if (remoteId_ >= 0)
        nc_close(remoteId_);
}

std::string RemoteDataset::who() const
{
    return "OPeNDAP source '" + withoutCredentials(url_) + "'";
}

int RemoteDataset::attempt(const std::string &what, const std::function<int()> &call)
{
    for (int k = 0;; ++k)
    {
        remote_detail::updateFetchRecord(record_, [](RemoteFetch &f) { ++f.requests; });
        std::string log;
        int st = NC_NOERR;
        {
            const FetchStopWatch watch(url_);
            st = callWatchingLog(call, log);
        }
        if (stopRequested()) // the request cut by the stop request, or ended as it came: its values are not used
            throw Error(who() + ": " + what + ": stopped (a stop was requested) during attempt " +
                        std::to_string(k + 1));
        const bool cut = cutShort(log);
        lastAnswerForeign = foreignAnswer(log);
        if (cut)
            st = NC_EDATADDS; // zero-filled values, never planned on
        if (st == NC_NOERR)
            return st;
        if (!transient(st) || k >= access_.retries)
        {
            std::string why = cut ? "the server's answer was cut short (NetCDF-C: \"" + text::trim(log) +
                                        "\"): its values are not used"
                                  : nc_strerror(st);
            if (st == NC_EIO || st == NC_ECURL || st == NC_EDAS || st == NC_EDDS || (st == NC_EDATADDS && !cut))
                why += limitInForce() > 0
                           ? " (no answer within the request time limit of " + std::to_string(limitInForce().load()) +
                                 " s, or the server cannot be reached)"
                           : " (no answer in time, or the server cannot be reached)";
            if (transient(st))
                why += "; " + std::to_string(k + 1) + (k == 0 ? " attempt" : " attempts");
            throw Error(who() + ": " + what + ": " + why);
        }
        // the pause before the next attempt, cut short by a stop request (Python's Ctrl-C)
        const auto resume = std::chrono::steady_clock::now() + std::chrono::seconds(k + 1);
        while (std::chrono::steady_clock::now() < resume && !stopRequested())
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        if (stopRequested())
            throw Error(who() + ": " + what + ": stopped (a stop was requested) after " + std::to_string(k + 1) +
                        (k == 0 ? " attempt: " : " attempts: ") + nc_strerror(st));
    }
}

int RemoteDataset::remoteId()
{
    if (remoteId_ < 0)
    {
        prepareNetcdfAccess(access_);
        if (limitInForce() == 0 && !std::getenv("NCRCENV_RC")) // a server must not hold the plan without a limit
            throw Error(
                withoutCredentials(url_) + ": the request time limit cannot be given to NetCDF-C: " +
                (limitProblem().empty() ? std::string("its settings file could not be written") : limitProblem()));
        try
        {
            attempt("cannot open", [&] { return nc_open(url_.c_str(), NC_NOWRITE, &remoteId_); });
        }
        catch (const Error &)
        {
#if OMPL_GLIDER_WITH_MISSION
            // an answer that is not DAP: what the server is instead (a web page, a Zarr store), the page unquoted
            if (lastAnswerForeign)
                if (const std::string why = gdal_detail::gdalPart().notDapAnswer(url_); !why.empty())
                    throw Error(who() + ": cannot open: " + why);
#endif
            if (lastAnswerForeign)
                throw Error(who() + ": cannot open: the server's answer is not OPeNDAP (NetCDF-C's DAP parser could "
                                    "not read it): expected an OPeNDAP dataset URL (THREDDS dodsC, Hyrax, ERDDAP "
                                    "griddap), a Zarr store's URL ending in .zarr (or ZARR:URL), or a GRIB file's URL");
            throw;
        }
        remote_detail::updateFetchRecord(record_, [](RemoteFetch &f) { f.opened = true; });
        if (cacheId_ >= 0)
            checkCacheAnswers();
    }
    return remoteId_;
}

std::uint64_t RemoteDataset::valueBytes(int var, std::size_t values) const
{
    nc_type t = NC_DOUBLE;
    std::size_t size = 8;
    if (nc_inq_vartype(metadataId(), var, &t) == NC_NOERR)
        nc_inq_type(metadataId(), t, nullptr, &size);
    return static_cast<std::uint64_t>(values) * size;
}

void RemoteDataset::read(int var, const std::vector<std::size_t> &start, const std::vector<std::size_t> &count,
                         double *out)
{
    const DatasetLock netcdf; // before the dataset's own lock (DatasetLock.h: its lock order)
    std::lock_guard<std::mutex> lock(mutex_);
    std::size_t n = 1;
    for (const std::size_t c : count)
        n *= c;
    if (n == 0)
        return;
    for (const Block &b : blocks_)
        if (b.var == var && inside(start, count, b.start, b.count))
        {
            if (!b.values.empty())
                copyOut(b.values, b.start, b.count, start, count, out);
            else if (nc_get_vara_double(cacheId_, var, start.data(), count.data(), out) != NC_NOERR)
                continue; // a cache file that does not hold what it says: fetched anew below
            else
            {
                const std::uint64_t bytes = valueBytes(var, n);
                remote_detail::updateFetchRecord(record_, [&](RemoteFetch &f) { f.bytesFromCache += bytes; });
            }
            return;
        }
    Block b{var, start, count, std::vector<double>(n)};
    char name[NC_MAX_NAME + 1] = "";
    nc_inq_varname(metadataId(), var, name);
    const int id = remoteId();
    attempt("reading " + constraintOf(name, start, count),
            [&] { return nc_get_vara_double(id, var, start.data(), count.data(), b.values.data()); });
    std::copy(b.values.begin(), b.values.end(), out);
    remote_detail::updateFetchRecord(record_, [&](RemoteFetch &f) { f.bytesFetched += valueBytes(var, n); });
    blocks_.push_back(std::move(b));
    dirty_ = !cachePath_.empty();
}

} // namespace gridded_detail
} // namespace ompl_glider
