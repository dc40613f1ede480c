#include "gen/util/file_bytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sys/stat.h>

#include "gen/util/error.h"

namespace tsf {
namespace {

[[noreturn]] void tooLarge(const std::string& path, int64_t size, int64_t max_bytes) {
    throw InputError(path, 0, 0,
                     "file is " + std::to_string(size >> 20) + " MiB; the largest input tsf reads is " +
                         std::to_string(max_bytes >> 20) + " MiB");
}

// stat()s path; throws InputError when it is missing, unreadable or a folder.
struct stat statInput(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        if (errno == ENOENT) throw InputError(path, 0, 0, std::string("file not found (") + std::strerror(errno) + ")");
        throw InputError(path, 0, 0, std::string("cannot open: ") + std::strerror(errno));
    }
    if (S_ISDIR(st.st_mode)) throw InputError(path, 0, 0, "is a folder, expected a file");
    // A device (/dev/zero, /dev/urandom, a disk) can be endless: refused
    // before a byte is read. Pipes are read, up to the caller's limit.
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode))
        throw InputError(path, 0, 0, "is a device, not a file: give a file (or a pipe)");
    return st;
}

}  // namespace

std::string readFileHead(const std::string& path, size_t head_bytes) {
    statInput(path);
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) throw InputError(path, 0, 0, std::string("cannot open: ") + std::strerror(errno));
    std::string bytes(head_bytes, '\0');
    bytes.resize(std::fread(bytes.data(), 1, head_bytes, file.get()));
    if (std::ferror(file.get())) throw InputError(path, 0, 0, std::string("cannot read: ") + std::strerror(errno));
    return bytes;
}

std::string readFileBytes(const std::string& path, int64_t max_bytes) {
    const struct stat st = statInput(path);
    if (max_bytes > 0 && S_ISREG(st.st_mode) && int64_t(st.st_size) > max_bytes) tooLarge(path, st.st_size, max_bytes);

    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) throw InputError(path, 0, 0, std::string("cannot open: ") + std::strerror(errno));
    std::string bytes;
    if (S_ISREG(st.st_mode)) bytes.reserve(static_cast<size_t>(st.st_size));
    char buffer[1 << 16];
    for (;;) {
        const size_t got = std::fread(buffer, 1, sizeof buffer, file.get());
        bytes.append(buffer, got);
        if (max_bytes > 0 && int64_t(bytes.size()) > max_bytes) tooLarge(path, int64_t(bytes.size()), max_bytes);
        if (got < sizeof buffer) break;
    }
    if (std::ferror(file.get())) throw InputError(path, 0, 0, std::string("cannot read: ") + std::strerror(errno));
    return bytes;
}

}  // namespace tsf
