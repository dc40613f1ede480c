// Temporary files that must not outlive the process, whatever ends it.
//
// AtomicFile (atomic_file.h) registers each temporary file here while it
// exists. installTempFileCleanup() (called once by main) makes the process
// remove every registered file when it is ended by SIGINT, SIGTERM or SIGHUP
// (the handler unlinks the files, then the signal's default action runs, so
// the exit status still says which signal it was), and ignores SIGXFSZ so
// that writing past a file-size limit (ulimit -f) fails like a full disk:
// write() returns EFBIG, the stream reports the failure, and the writer's
// normal cleanup removes its temporary file.
//
// Limits: at most kMaxTempFiles files registered at once, paths up to
// kMaxTempPathBytes bytes; a file beyond either is simply not cleaned up by
// the signal handler (normal exits still remove it). SIGKILL cannot be
// caught.
#pragma once

#include <string>

namespace tsf {

inline constexpr int kMaxTempFiles = 64;
inline constexpr size_t kMaxTempPathBytes = 4096;

/// Registers `path`; returns a slot for unregisterTempFile, or -1 when full.
int registerTempFile(const std::string& path);

/// Forgets a slot from registerTempFile (-1 is ignored). Does not touch the file.
void unregisterTempFile(int slot);

/// Installs the signal handling described above. Idempotent.
void installTempFileCleanup();

/// A fresh, empty file "$TMPDIR/<prefix>XXXXXX<suffix>" (TMPDIR unset: /tmp),
/// registered for cleanup while it exists and removed by the destructor.
/// Throws std::runtime_error when it cannot be created.
class ScopedTempFile {
public:
    ScopedTempFile(const std::string& prefix, const std::string& suffix);
    ~ScopedTempFile();
    ScopedTempFile(const ScopedTempFile&) = delete;
    ScopedTempFile& operator=(const ScopedTempFile&) = delete;
    const std::string& path() const { return path_; }

private:
    std::string path_;
    int slot_ = -1;
};

}  // namespace tsf
