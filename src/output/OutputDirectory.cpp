// The output directory's transaction: checked writes, the lock, the staging directory, its commit by one
// exchange of directories, and the signals that arrive while files are written (OutputWriter.h).
#include "OutputDirectory.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <set>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/output/OutputWriter.h"

namespace ompl_glider
{
namespace fs = std::filesystem;

namespace
{
/// Where the process is in writing its outputs, one value read at once by the signal handler (which may run on any
/// thread while the main one moves on): no write under way (a signal ends the process), files being staged or
/// swapped in (a signal is held and takes the write back), or the last write's outputs standing for good (a signal
/// stops the run but no longer undoes them). Two separate flags let a handler on another thread see "not final" then
/// "not staging" around the commit, and end the process after the new outputs stood.
enum class WriteState : int
{
    Idle,
    Staging,
    Final
};
std::atomic<WriteState> g_state{WriteState::Idle};
std::atomic<int> g_pending{0};
std::atomic<void (*)(const char *)> g_hook{nullptr};

/// Ends the process by @p sig as its default action would; the CPU time limit (SIGXCPU, whose default dumps
/// core) with a message and exit status 128 + SIGXCPU. Async-signal-safe.
void endBySignal(int sig)
{
    if (sig == SIGXCPU)
    {
        static const char msg[] = ": the CPU time limit (ulimit -t) was reached: stopped, no output written or "
                                  "replaced\n";
        const char *name = program_invocation_short_name;
        (void)!::write(STDERR_FILENO, name, std::strlen(name));
        (void)!::write(STDERR_FILENO, msg, sizeof msg - 1);
        ::_exit(128 + SIGXCPU);
    }
    ::signal(sig, SIG_DFL);
    ::raise(sig);
}

extern "C" void onTerminatingSignal(int sig)
{
    const WriteState state = g_state.load();
    if (state == WriteState::Final)
    {
        // the new outputs stand: the run is stopped, not undone (the caller must not read "nothing was written")
        g_pending.store(sig);
        requestStop();
        return;
    }
    if (state == WriteState::Idle)
    {
        endBySignal(sig); // end the process as the signal would have (nothing is half written)
        return;
    }
    g_pending.store(sig); // answered at the next file (interruptIfSignalled), or after the commit if it is final
}

std::string systemReason(int err)
{
    return std::strerror(err);
}

/// fsync() of a directory, so that the names in it survive a crash; errors are not fatal (some file systems
/// refuse fsync on directories).
void syncDirectory(const fs::path &dir)
{
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0)
    {
        (void)::fsync(fd);
        ::close(fd);
    }
}

std::string baseName(const fs::path &target)
{
    const std::string base = target.filename().string();
    return base.empty() ? std::string("out") : base;
}

/// ".BASE.tmp-" followed by digits, '-', digits: the staging directories of BASE (and nothing else's).
bool isStagingName(const std::string &name, const std::string &base)
{
    const std::string head = "." + base + ".tmp-";
    if (name.compare(0, head.size(), head) != 0)
        return false;
    const std::string rest = name.substr(head.size());
    const std::size_t dash = rest.find('-');
    auto digits = [](const std::string &s) {
        return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
    };
    return dash != std::string::npos && digits(rest.substr(0, dash)) && digits(rest.substr(dash + 1));
}

/// Whether @p target holds only an earlier run's outputs (regular files listed in its summary.json) and is not
/// the working directory: then it may be exchanged as a whole.
bool holdsOnlyOutputs(const fs::path &target, const std::vector<std::string> &previous)
{
    std::error_code ec;
    if (fs::equivalent(target, fs::current_path(ec), ec))
        return false;
    const std::set<std::string> listed(previous.begin(), previous.end());
    for (const fs::directory_entry &e : fs::directory_iterator(target, ec))
    {
        const std::string name = e.path().filename().string();
        const fs::file_type type = fs::symlink_status(e.path(), ec).type();
        if (type == fs::file_type::directory) // a fleet glider's folder: every file in it listed as NAME/FILE
        {
            bool any = false;
            for (const fs::directory_entry &f : fs::directory_iterator(e.path(), ec))
            {
                if (!listed.count(name + "/" + f.path().filename().string()) ||
                    fs::symlink_status(f.path(), ec).type() != fs::file_type::regular)
                    return false;
                any = true;
            }
            if (!any)
                return false;
            continue;
        }
        if (!listed.count(name) || type != fs::file_type::regular)
            return false;
    }
    return !ec;
}

/// The folder part of a name in a fleet's output ("alpha" of "alpha/summary.json"); empty for a plain name.
std::string folderOf(const std::string &name)
{
    const std::size_t slash = name.find('/');
    return slash == std::string::npos ? std::string() : name.substr(0, slash);
}

struct HeldLock
{
    int fd = -1;
    int count = 0;
};

std::mutex &lockMutex()
{
    static std::mutex m;
    return m;
}

std::map<std::string, HeldLock> &heldLocks()
{
    static std::map<std::string, HeldLock> held;
    return held;
}
} // namespace

int signalAfterOutputs()
{
    return g_state.load() == WriteState::Final ? g_pending.exchange(0) : 0;
}

void installOutputSignalHandlers()
{
    for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGXCPU})
    {
        struct sigaction old
        {
        };
        if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN)
            continue; // an ignored signal (nohup) stays ignored
        struct sigaction sa
        {
        };
        sa.sa_handler = onTerminatingSignal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESTART;
        ::sigaction(sig, &sa, nullptr);
    }
}

OutputLock::OutputLock(const std::string &directory)
{
    const fs::path target = output_detail::resolveOutputDirectory(directory);
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
    path_ = (output_detail::workDirOf(target) / ("." + baseName(target) + ".lock")).string();
    const std::lock_guard<std::mutex> guard(lockMutex());
    HeldLock &held = heldLocks()[path_];
    if (held.count > 0)
    {
        ++held.count; // this process holds it already (glider_plan locks before planning, then writes)
        return;
    }
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0)
    {
        const int err = errno;
        heldLocks().erase(path_);
        throw Error("output directory '" + directory + "': cannot create its lock file '" + path_ +
                    "': " + systemReason(err));
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
    {
        const int err = errno;
        ::close(fd);
        heldLocks().erase(path_);
        if (err == EWOULDBLOCK)
            throw Error("output directory '" + directory + "' is in use by another glider_plan run (it holds '" +
                        path_ + "'); wait for that run to end or choose another output directory");
        throw Error("output directory '" + directory + "': cannot lock '" + path_ + "': " + systemReason(err));
    }
    held.fd = fd;
    held.count = 1;
}

OutputLock::~OutputLock()
{
    const std::lock_guard<std::mutex> guard(lockMutex());
    auto it = heldLocks().find(path_);
    if (it == heldLocks().end() || --it->second.count > 0)
        return;
    ::close(it->second.fd); // releases the flock; the lock file stays (removing it would race a waiting run)
    heldLocks().erase(it);
}

namespace output_detail
{
void writeFileChecked(const std::string &path, const std::string &bytes)
{
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0)
        throw Error("cannot write '" + path + "': " + systemReason(errno));
    std::size_t done = 0;
    while (done < bytes.size())
    {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
        {
            const int err = n < 0 ? errno : ENOSPC;
            ::close(fd);
            throw Error("cannot write '" + path + "': " + systemReason(err) + " (" + std::to_string(done) + " of " +
                        std::to_string(bytes.size()) + " bytes written)");
        }
        done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS)
    {
        const int err = errno;
        ::close(fd);
        throw Error("cannot write '" + path + "': " + systemReason(err));
    }
    if (::close(fd) != 0)
        throw Error("cannot write '" + path + "': " + systemReason(errno) + " (when closing it)");
}

fs::path resolveOutputDirectory(const std::string &directory)
{
    fs::path p = fs::absolute(directory.empty() ? fs::path(".") : fs::path(directory)).lexically_normal();
    if (p.filename().empty() && p.has_parent_path() && p != p.root_path())
        p = p.parent_path(); // trailing slash
    std::error_code ec;
    if (fs::is_symlink(p, ec))
    {
        if (!fs::exists(p, ec))
            throw Error("output directory '" + directory + "' is a symbolic link to '" +
                        fs::read_symlink(p, ec).string() +
                        "', which does not exist; create that directory or choose another output directory");
        p = fs::canonical(p, ec); // the exchange must move the directory, not the link
    }
    return p;
}

void removeStaleStaging(const fs::path &target)
{
    std::error_code ec;
    const std::string base = baseName(target);
    std::vector<fs::path> stale;
    for (const fs::directory_entry &e : fs::directory_iterator(workDirOf(target), ec))
        if (isStagingName(e.path().filename().string(), base) &&
            fs::symlink_status(e.path(), ec).type() == fs::file_type::directory)
            stale.push_back(e.path());
    for (const fs::path &p : stale)
        fs::remove_all(p, ec);
}

fs::path workDirOf(const fs::path &target)
{
    const fs::path parent = target.parent_path();
    if (::access(parent.c_str(), W_OK | X_OK) == 0)
        return parent;
    std::error_code ec;
    return fs::is_directory(target, ec) && ::access(target.c_str(), W_OK | X_OK) == 0 ? target : parent;
}

fs::path makeStaging(const fs::path &target)
{
    static std::atomic<unsigned> counter{0};
    const fs::path staging = workDirOf(target) / ("." + baseName(target) + ".tmp-" + std::to_string(::getpid()) + "-" +
                                                  std::to_string(counter++));
    std::error_code ec;
    if (!fs::create_directory(staging, ec))
        throw Error("cannot create the temporary directory '" + staging.string() + "'" +
                    (ec ? ": " + ec.message() : std::string()));
    return staging;
}

namespace
{
/// File by file into a directory that holds other things too (summary.json last), then the earlier run's files
/// this run does not write are removed.
void moveFileByFile(const fs::path &staging, const fs::path &target, const std::vector<std::string> &names,
                    const std::vector<std::string> &previous, const std::string &shown)
{
    std::vector<std::string> order;
    for (const bool summaries : {false, true})
        for (const std::string &n : names)
            if ((n.size() >= 12 && n.compare(n.size() - 12, 12, "summary.json") == 0) == summaries)
                order.push_back(n);
    std::error_code ec;
    for (const std::string &n : order)
    {
        const std::string folder = folderOf(n);
        if (!folder.empty())
            fs::create_directory(target / folder, ec);
        if (::rename((staging / n).c_str(), (target / n).c_str()) != 0)
            throw Error("cannot move '" + n + "' into '" + shown + "': " + systemReason(errno));
    }
    stepHook("committed");
    const std::set<std::string> now(names.begin(), names.end());
    std::set<std::string> folders;
    for (const std::string &name : previous)
    {
        const std::string folder = folderOf(name);
        const std::string file = folder.empty() ? name : name.substr(folder.size() + 1);
        if (now.count(name) || file.find('/') != std::string::npos || file.empty() || file == "." || file == ".." ||
            folder == "." || folder == ".." || fs::symlink_status(target / name, ec).type() != fs::file_type::regular)
            continue;
        fs::remove(target / name, ec);
        if (!folder.empty())
            folders.insert(folder);
    }
    for (const std::string &folder : folders) // an earlier fleet's glider that this run has not
        if (fs::is_empty(target / folder, ec))
            fs::remove(target / folder, ec);
}
} // namespace

void commitStaging(const fs::path &staging, const fs::path &target, const std::vector<std::string> &names,
                   const std::vector<std::string> &previous, const std::string &shown)
{
    std::error_code ec;
    for (const std::string &n : names)
    {
        const std::string folder = folderOf(n);
        const fs::file_type held =
            folder.empty() ? fs::file_type::directory : fs::symlink_status(target / folder, ec).type();
        if (held != fs::file_type::directory && held != fs::file_type::not_found && held != fs::file_type::none)
            throw Error("output directory '" + shown + "' holds '" + folder +
                        "', which is not a directory, where glider_plan writes a glider's folder; nothing was "
                        "replaced (remove it or choose another output directory)");
        const fs::file_type type = fs::symlink_status(target / n, ec).type();
        if (type == fs::file_type::directory)
            throw Error("output directory '" + shown + "' holds a directory '" + n +
                        "' where glider_plan writes a file; nothing was replaced (remove it or choose another "
                        "output directory)");
        if (type != fs::file_type::not_found && type != fs::file_type::none && type != fs::file_type::regular &&
            type != fs::file_type::symlink)
            throw Error("output directory '" + shown + "' holds '" + n +
                        "', which is not a regular file, where glider_plan writes a file; nothing was replaced");
    }
    for (const std::string &n : names)
        if (!folderOf(n).empty())
            syncDirectory(staging / folderOf(n));
    syncDirectory(staging);
    // A signal that arrived while the files were staged or swapped in (held until now) takes the swap back in one
    // more rename, before the earlier files are removed: the earlier outputs stay, as for a signal while staging.
    if (!fs::exists(fs::symlink_status(target, ec)))
    {
        if (::rename(staging.c_str(), target.c_str()) != 0)
            throw Error("cannot create the output directory '" + shown + "': " + systemReason(errno));
        stepHook("committed");
        if (g_pending.load() != 0 && ::rename(target.c_str(), staging.c_str()) == 0)
            interruptIfSignalled(staging);
    }
    else if (holdsOnlyOutputs(target, previous) &&
             (fs::permissions(staging, fs::status(target, ec).permissions(), ec), true) &&
             ::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0)
    {
        stepHook("committed"); // the staging directory now holds the earlier run's files
        if (g_pending.load() != 0 &&
            ::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0)
            interruptIfSignalled(staging);
    }
    else
        moveFileByFile(staging, target, names, previous, shown);
    g_state.store(WriteState::Final); // a signal from here on no longer takes the new outputs back
    stepHook("final");
    syncDirectory(target.parent_path());
    fs::remove_all(staging, ec);
}

void setStaging(bool on)
{
    if (on)
        g_state.store(WriteState::Staging);
    else
    {
        WriteState staging = WriteState::Staging; // a final write stays final
        g_state.compare_exchange_strong(staging, WriteState::Idle);
    }
}

void raisePendingSignal()
{
    if (g_state.load() == WriteState::Final)
    {
        if (g_pending.load() != 0)
            requestStop(); // kept for signalAfterOutputs(); the outputs stand
        return;
    }
    if (const int sig = g_pending.exchange(0))
        endBySignal(sig);
}

void interruptIfSignalled(const fs::path &staging)
{
    if (g_pending.load() == 0)
        return;
    std::error_code ec;
    fs::remove_all(staging, ec);
    g_state.store(WriteState::Idle);
    raisePendingSignal();
}

void setStepHook(void (*hook)(const char *))
{
    g_hook.store(hook);
}

void stepHook(const char *step)
{
    if (auto *hook = g_hook.load())
        hook(step);
}
} // namespace output_detail
} // namespace ompl_glider
