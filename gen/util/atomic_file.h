// AtomicFile: write a file so that readers see either the old file or the
// complete new one, never a half-written file (docs/design.md, "Outputs are
// written atomically").
//
// Behaviour: the constructor reserves a fresh, empty temporary file in the
// SAME folder as the target (".<name>.tmp-<pid>-<n>", created exclusively, so
// two writers never share one). The caller writes the temporary file by path
// (any library that takes a file name can do it), then calls commit(), which
// fsyncs the temporary file, renames it over the target (atomic on POSIX file
// systems because both are in one folder) and fsyncs the folder. If commit()
// is never reached (an exception, an early return), the destructor removes
// the temporary file and an existing target is left untouched. While it
// exists the temporary file is registered with temp_files.h, so SIGINT,
// SIGTERM and SIGHUP remove it too, and a file-size limit (SIGXFSZ) is an
// ordinary write failure.
//
// A run ended by SIGKILL (or a power cut) cannot remove its temporary file.
// The next AtomicFile for the same target removes such leftovers: files named
// exactly ".<name>.tmp-<pid>-<n>" for this target (or a temporary file of such
// a file: tsf render stages the engine's output inside its own) whose process
// <pid> no longer exists (removeStaleTempFiles). Nothing else is touched: not
// another target's, not a live process's, not a file of another naming.
//
// Caveats: the new file gets default permissions (0666 minus umask), not the
// old target's; a symbolic link at the target is replaced by the file rather
// than written through.
#pragma once

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "gen/util/file_stamp.h"

namespace tsf {

class AtomicFile {
public:
    /// Reserves the temporary file next to target_path.
    /// Throws tsf::InputError naming target_path when its folder does not
    /// exist, is not writable, or target_path is an existing folder.
    explicit AtomicFile(const std::string& target_path);
    /// Removes the temporary file unless commit() succeeded. Never throws.
    ~AtomicFile();

    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    const std::string& targetPath() const { return target_path_; }
    /// The reserved temporary file to write (exists, empty, same folder).
    const std::string& tempPath() const { return temp_path_; }
    bool committed() const { return committed_; }

    /// fsync the temporary file, rename it over the target, fsync the folder
    /// (with an OutputSet alive: fsync and hand the file to the set).
    /// Throws tsf::OutputError with the OS message when the sync or the
    /// rename fails (the temporary file is then still removed by the
    /// destructor). Calling it twice is a bug. `stamp`, the stamp of what
    /// was written when the writer took it (writeFileAtomically does), is
    /// kept by the OutputSet for stampOf().
    void commit(std::optional<FileStamp> stamp = std::nullopt);

private:
    std::string target_path_;
    std::string temp_path_;
    bool committed_ = false;
    int cleanup_slot_ = -1;  ///< registerTempFile slot while the temporary file exists
};

/// OutputSet: every file one command writes, replaced together.
///
/// While an OutputSet exists, AtomicFile::commit() (and so
/// writeFileAtomically) only makes its temporary file durable and hands it
/// to the set; the targets are left as they were. OutputSet::commit() then
/// renames every temporary file over its target with SIGINT, SIGTERM and
/// SIGHUP held off, so a signal a person or a service manager sends (Ctrl-C,
/// kill, a closed terminal) leaves the old files or the new set, never a
/// mix: before the renames the handler removes the temporary files, after
/// them it finds none. SIGKILL or a power cut during the renames can still
/// leave a mix; what tsf verify checks (the sidecar's model stamp) names it.
/// If the set is destroyed without commit() (an error while writing), its
/// temporary files are removed and no target changes. A target handed to
/// the set twice keeps its newer file (the older is removed at once). One
/// set at a time; files are handed to it by one thread at a time (a writer
/// thread may, while the thread that owns the set waits for it).
class OutputSet {
public:
    OutputSet();
    ~OutputSet();
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    /// Renames every file handed to the set over its target, in the order
    /// they were written. Throws tsf::OutputError when a rename fails (the
    /// files renamed before it stay renamed; the rest are removed).
    void commit();
    /// Where the bytes of `target` are now: its temporary file while it
    /// waits in the set, else `target` itself.
    std::string currentPath(const std::string& target) const;
    /// The stamp of `target`'s new bytes as taken while they were written
    /// (writeFileAtomically), without reading the file back; none for a
    /// file written otherwise or not in the set.
    std::optional<FileStamp> stampOf(const std::string& target) const;

    struct Pending {
        std::string temp_path, target_path;
        int cleanup_slot = -1;
        std::optional<FileStamp> stamp;
    };

private:
    friend class AtomicFile;
    /// Hands a committed temporary file to the set, in place of the one
    /// handed earlier for the same target (removed at once).
    void take(Pending file);
    /// The file waiting in the set for `target`, if any (one at most).
    const Pending* pendingFor(const std::string& target) const;
    std::vector<Pending> pending_;
    bool committed_ = false;
};

/// Removes the temporary files a killed run left for target_path (see the
/// file comment): ".<name>.tmp-<pid>-<n>" in its folder, <pid> not a running
/// process. Returns how many were removed. Never throws.
int removeStaleTempFiles(const std::string& target_path);

/// Writes path atomically through a stream: opens the temporary file as a
/// binary std::ofstream, calls write(stream), checks the stream state (a full
/// disk shows up here), then commits. The bytes are stamped (XXH3, as
/// stampFile) on their way to the file: see OutputSet::stampOf. If write throws, the exception
/// propagates and no file appears at path (an existing one is untouched).
/// Throws tsf::InputError for an unusable folder (see AtomicFile) and
/// tsf::OutputError (also an InputError) for I/O failures: a full disk, a
/// file-size limit.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace tsf
