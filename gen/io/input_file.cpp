#include "gen/io/input_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "gen/error.h"

namespace tsf {

std::string readInputFile(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st)) throw InputError(path, 0, 0, "file not found");
    if (fs::is_directory(st)) throw InputError(path, 0, 0, "is a folder, expected a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, 0, std::string("cannot open: ") + std::strerror(errno));
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0, std::ios::beg);
    if (size < 0) throw InputError(path, 0, 0, "cannot determine the file size");
    if (int64_t(size) > kMaxInputFileBytes)
        throw InputError(path, 0, 0,
                         "file is " + std::to_string(int64_t(size) >> 20) + " MiB; the largest input tsf reads is " +
                             std::to_string(kMaxInputFileBytes >> 20) + " MiB");
    std::string bytes(size_t(size), '\0');
    if (size > 0 && !in.read(bytes.data(), size)) throw InputError(path, 0, 0, "read error");
    return bytes;
}

}  // namespace tsf
