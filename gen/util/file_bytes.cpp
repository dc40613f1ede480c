#include "gen/mesh_io/file_bytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sys/stat.h>

#include "gen/error.h"

namespace tsf::mesh_io {

std::string readFileBytes(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        throw InputError(path, 0, 0, std::string("cannot open: ") + std::strerror(errno));
    }
    if (S_ISDIR(st.st_mode)) throw InputError(path, 0, 0, "cannot read: this is a folder, a mesh file is expected");

    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) throw InputError(path, 0, 0, std::string("cannot open: ") + std::strerror(errno));
    std::string bytes;
    if (S_ISREG(st.st_mode)) bytes.reserve(static_cast<size_t>(st.st_size));
    char buffer[1 << 16];
    for (;;) {
        const size_t got = std::fread(buffer, 1, sizeof buffer, file.get());
        bytes.append(buffer, got);
        if (got < sizeof buffer) break;
    }
    if (std::ferror(file.get())) throw InputError(path, 0, 0, std::string("cannot read: ") + std::strerror(errno));
    return bytes;
}

std::string quoteForMessage(std::string_view text, size_t max_chars) {
    std::string out = "'";
    for (size_t i = 0; i < text.size() && i < max_chars; ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        out += (byte >= 0x20 && byte < 0x7F) ? static_cast<char>(byte) : '?';
    }
    if (text.size() > max_chars) out += "...";
    return out + "'";
}

}  // namespace tsf::mesh_io
