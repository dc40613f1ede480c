#include "gen/util/atomic_file.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <pthread.h>
#include <stdexcept>
#include <streambuf>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>
#include <utility>
#include <vector>

#include "gen/util/error.h"
#include "gen/util/temp_files.h"

namespace tsf {
namespace {

// Keeps the temporary name within NAME_MAX (255) whatever the target's name.
constexpr size_t kMaxNameStemChars = 200;

std::atomic<unsigned> g_temp_counter{0};

std::string osMessage(int error_number) { return std::strerror(error_number); }

// Folder part of a path, "." for a bare file name.
std::string folderOf(const std::string& path) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

void syncFolder(const std::string& folder) {
    // Makes the rename itself durable. Failure here is not reported: the new
    // file is already complete and in place, only its durability across a
    // power cut is in doubt, and some file systems refuse fsync on folders.
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    (void)::fsync(fd);
    ::close(fd);
}

// The target's file name as its temporary files start with it (cut to
// kMaxNameStemChars, so the temporary name fits NAME_MAX).
std::string nameStem(const std::string& target_path) {
    std::string stem = std::filesystem::path(target_path).filename().string();
    if (stem.size() > kMaxNameStemChars) stem.resize(kMaxNameStemChars);
    return stem;
}

// "<digits>-<digits>" as a pid (0 if the text is not exactly that).
pid_t pidOfSuffix(const std::string& suffix) {
    const size_t dash = suffix.find('-');
    if (dash == 0 || dash == std::string::npos || dash + 1 == suffix.size() || dash > 9) return 0;
    for (size_t k = 0; k < suffix.size(); ++k)
        if (k != dash && (suffix[k] < '0' || suffix[k] > '9')) return 0;
    return pid_t(std::stol(suffix.substr(0, dash)));
}

// True when `name` is a temporary file of a target named `stem`, made by
// process `pid`: ".<stem>.tmp-<pid>-<n>", or the temporary file of such a
// temporary file (a file staged inside another, as tsf render does).
bool isTempNameOf(const std::string& name, const std::string& stem, pid_t& pid) {
    const size_t at = name.rfind(".tmp-");
    if (name.empty() || name[0] != '.' || at == std::string::npos || at == 0) return false;
    pid = pidOfSuffix(name.substr(at + 5));
    if (pid <= 0) return false;
    const std::string base = name.substr(1, at - 1);
    pid_t inner = 0;
    return base == stem || isTempNameOf(base, stem, inner);
}

bool processExists(pid_t pid) { return ::kill(pid, 0) == 0 || errno == EPERM; }

// The set of the command that is writing, if any (see OutputSet).
OutputSet* g_output_set = nullptr;

// SIGINT, SIGTERM and SIGHUP held off for a scope; delivered when it ends.
struct TerminationSignalsHeld {
    sigset_t old{};
    TerminationSignalsHeld() {
        sigset_t held;
        sigemptyset(&held);
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&held, sig);
        ::pthread_sigmask(SIG_BLOCK, &held, &old);
    }
    ~TerminationSignalsHeld() { ::pthread_sigmask(SIG_SETMASK, &old, nullptr); }
};

// The stream writers write a file through: buffered, straight to the file
// descriptor. Every byte is stamped (file_stamp.h) on its way, so the file's
// stamp is known when it is written, not read back (82 ms for a 519 MB
// model). Every kWritebackBytes written, the kernel is asked to start
// writing those pages to disk (sync_file_range, Linux): the disk then works
// while the writer still converts and writes, and the fsync of commit()
// waits for the tail alone instead of the whole file (at 519 MB, 0.2 s of
// close and fsync after the last write). Small writes gather in a buffer;
// large ones go straight to the file.
class FileWriteBuf : public std::streambuf {
public:
    explicit FileWriteBuf(int fd) : fd_(fd), buffer_(kBufferBytes) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
    FileStamp stamp() const { return hasher_.stamp(); }
    /// errno of the first write that failed, 0 if none did.
    int error() const { return error_; }

protected:
    int_type overflow(int_type c) override {
        if (!flushBuffer()) return traits_type::eof();
        if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
        *pptr() = traits_type::to_char_type(c);
        pbump(1);
        return c;
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        if (n < epptr() - pptr()) {
            std::copy(s, s + n, pptr());
            pbump(int(n));
            return n;
        }
        if (!flushBuffer() || !writeAll(s, size_t(n))) return 0;
        return n;
    }
    int sync() override { return flushBuffer() ? 0 : -1; }

private:
    static constexpr size_t kBufferBytes = size_t(1) << 16;
    static constexpr off_t kWritebackBytes = off_t(32) << 20;

    bool writeAll(const char* s, size_t n) {
        if (error_ != 0) return false;
        while (n > 0) {
            const ssize_t put = ::write(fd_, s, n);
            if (put < 0) {
                if (errno == EINTR) continue;
                error_ = errno;
                return false;
            }
            hasher_.update(s, size_t(put));
            s += put;
            n -= size_t(put);
            written_ += put;
        }
#ifdef SYNC_FILE_RANGE_WRITE
        // Started, not waited for; a file system without it says EINVAL or
        // ENOSYS, and then fsync does all of it as before.
        for (; written_ - started_ >= kWritebackBytes; started_ += kWritebackBytes)
            (void)::sync_file_range(fd_, started_, kWritebackBytes, SYNC_FILE_RANGE_WRITE);
#endif
        return true;
    }
    bool flushBuffer() {
        const size_t n = size_t(pptr() - pbase());
        const bool ok = n == 0 || writeAll(pbase(), n);
        setp(buffer_.data(), buffer_.data() + buffer_.size());
        return ok;
    }

    const int fd_;
    std::vector<char> buffer_;
    StampHasher hasher_;
    off_t written_ = 0, started_ = 0;
    int error_ = 0;
};

}  // namespace

int removeStaleTempFiles(const std::string& target_path) {
    if (target_path.empty()) return 0;
    const std::string stem = nameStem(target_path);
    int removed = 0;
    std::error_code ec;
    std::filesystem::directory_iterator it(folderOf(target_path), ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        pid_t pid = 0;
        if (!isTempNameOf(name, stem, pid) || pid == ::getpid() || processExists(pid)) continue;
        std::error_code file_ec;
        if (!it->is_regular_file(file_ec) || file_ec) continue;
        if (::unlink(it->path().c_str()) == 0) ++removed;
    }
    return removed;
}

AtomicFile::AtomicFile(const std::string& target_path) : target_path_(target_path) {
    if (target_path.empty()) throw InputError("output path is empty");
    const std::string folder = folderOf(target_path);
    struct stat st {};
    if (::stat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
        throw InputError(target_path, 0, 0, "cannot write: folder '" + folder + "' does not exist");
    }
    if (::stat(target_path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
        throw InputError(target_path, 0, 0, "cannot write: this is a folder, a file name is expected");
    }
    const std::string prefix = (folder == "." && target_path.find('/') == std::string::npos ? std::string() : folder + "/");
    const std::string stem = nameStem(target_path);
    // What a killed run of this command left (SIGKILL cannot be caught).
    removeStaleTempFiles(target_path);

    for (;;) {
        const unsigned n = g_temp_counter.fetch_add(1);
        std::string candidate = prefix + "." + stem + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(n);
        // Created and registered with termination signals held off: a signal
        // between the two would leave the file behind.
        const TerminationSignalsHeld held;
        const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            temp_path_ = std::move(candidate);
            cleanup_slot_ = registerTempFile(temp_path_);
            return;
        }
        if (errno == EEXIST) continue;  // a leftover from a crashed run with a recycled pid
        throw InputError(target_path, 0, 0, "cannot write in folder '" + folder + "': " + osMessage(errno));
    }
}

AtomicFile::~AtomicFile() {
    if (!committed_ && !temp_path_.empty()) ::unlink(temp_path_.c_str());
    unregisterTempFile(cleanup_slot_);
}

void AtomicFile::commit(std::optional<FileStamp> stamp) {
    if (committed_) throw std::logic_error("AtomicFile::commit called twice for " + target_path_);
    const int fd = ::open(temp_path_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        throw OutputError(target_path_, "cannot reopen the temporary file '" + temp_path_ + "': " + osMessage(errno));
    }
    if (::fsync(fd) != 0) {
        const int error_number = errno;
        ::close(fd);
        throw OutputError(target_path_, "cannot flush '" + temp_path_ + "' to disk: " + osMessage(error_number));
    }
    ::close(fd);
    if (g_output_set != nullptr) {
        // Renamed with the rest of the set; until then the set owns the file.
        g_output_set->take({temp_path_, target_path_, cleanup_slot_, stamp});
        cleanup_slot_ = -1;
        committed_ = true;
        return;
    }
    if (::rename(temp_path_.c_str(), target_path_.c_str()) != 0) {
        throw OutputError(target_path_, "cannot replace the file: " + osMessage(errno));
    }
    committed_ = true;
    unregisterTempFile(cleanup_slot_);
    cleanup_slot_ = -1;
    syncFolder(folderOf(target_path_));
}

OutputSet::OutputSet() {
    if (g_output_set != nullptr) throw std::logic_error("OutputSet: one set at a time");
    g_output_set = this;
}

OutputSet::~OutputSet() {
    if (g_output_set == this) g_output_set = nullptr;
    for (const Pending& p : pending_) {
        if (!committed_) ::unlink(p.temp_path.c_str());
        unregisterTempFile(p.cleanup_slot);
    }
}

void OutputSet::take(Pending file) {
    // A target written again in the same run (a model made again) keeps
    // only its newest bytes: the earlier file is removed, so the commit
    // never shows the target's superseded version, not even between two
    // renames.
    for (auto it = pending_.begin(); it != pending_.end(); ++it)
        if (it->target_path == file.target_path) {
            ::unlink(it->temp_path.c_str());
            unregisterTempFile(it->cleanup_slot);
            pending_.erase(it);
            break;
        }
    pending_.push_back(std::move(file));
}

const OutputSet::Pending* OutputSet::pendingFor(const std::string& target) const {
    for (const Pending& p : pending_)
        if (p.target_path == target) return &p;
    return nullptr;
}

std::string OutputSet::currentPath(const std::string& target) const {
    const Pending* p = pendingFor(target);
    return p ? p->temp_path : target;
}

std::optional<FileStamp> OutputSet::stampOf(const std::string& target) const {
    const Pending* p = pendingFor(target);
    return p ? p->stamp : std::nullopt;
}

void OutputSet::commit() {
    if (committed_) throw std::logic_error("OutputSet::commit called twice");
    g_output_set = nullptr;
    std::vector<std::string> folders;
    {
        const TerminationSignalsHeld held;
        for (size_t k = 0; k < pending_.size(); ++k) {
            Pending& p = pending_[k];
            if (::rename(p.temp_path.c_str(), p.target_path.c_str()) != 0) {
                const int error_number = errno;
                const std::string target = p.target_path;
                // What is not renamed is removed by the destructor.
                pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(k));
                throw OutputError(target, "cannot replace the file: " + osMessage(error_number));
            }
            unregisterTempFile(p.cleanup_slot);
            p.cleanup_slot = -1;
            folders.push_back(folderOf(p.target_path));
        }
        committed_ = true;
    }
    std::sort(folders.begin(), folders.end());
    folders.erase(std::unique(folders.begin(), folders.end()), folders.end());
    for (const std::string& folder : folders) syncFolder(folder);
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    AtomicFile file(path);
    std::optional<FileStamp> stamp;
    {
        // The temporary file exists and is empty (AtomicFile made it).
        const int fd = ::open(file.tempPath().c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0) throw OutputError(path, "cannot open '" + file.tempPath() + "' for writing: " + osMessage(errno));
        struct Closer {
            int fd;
            ~Closer() {
                if (fd >= 0) ::close(fd);
            }
        } closer{fd};
        FileWriteBuf buf(fd);
        std::ostream out(&buf);
        write(out);
        out.flush();
        int error_number = buf.error();
        const bool closed = ::close(std::exchange(closer.fd, -1)) == 0;
        if (closed && error_number == 0 && !out.fail()) {
            stamp = buf.stamp();
        } else {
            if (error_number == 0 && !closed) error_number = errno;
            const std::string reason =
                error_number != 0 ? osMessage(error_number) : std::string("write error (is the disk full?)");
            throw OutputError(path, "writing failed: " + reason);
        }
    }
    file.commit(stamp);
}

}  // namespace tsf
