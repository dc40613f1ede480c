#include "gen/scad/scad_library.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace tsf {
namespace fs = std::filesystem;

namespace {

bool holdsLibrary(const fs::path& dir) {
    std::error_code ec;
    return fs::is_regular_file(dir / kScadLibraryEntry, ec);
}

fs::path executableDir() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe.parent_path();
}

}  // namespace

std::string scadLibraryDir() {
    if (const char* env = std::getenv("TSF_SCAD_LIB"); env && *env) {
        if (holdsLibrary(env)) return fs::path(env).lexically_normal().string();
        throw std::runtime_error(std::string("TSF_SCAD_LIB is set to '") + env + "', but that folder has no " +
                                 kScadLibraryEntry + " (unset it to use the library installed with tsf)");
    }
    std::vector<fs::path> tried;
    if (const fs::path exe_dir = executableDir(); !exe_dir.empty())
        tried.push_back((exe_dir / ".." / "share" / "tsf" / "scad_lib").lexically_normal());
#ifdef TSF_SOURCE_DIR
    tried.push_back(fs::path(TSF_SOURCE_DIR) / "scad_lib");
#endif
    for (const fs::path& dir : tried)
        if (holdsLibrary(dir)) return dir.string();
    std::string where;
    for (const fs::path& dir : tried) where += "\n  " + dir.string();
    throw std::runtime_error("cannot find tsf's OpenSCAD library (" + std::string(kScadLibraryEntry) +
                             "); looked in:" + where + "\nset TSF_SCAD_LIB to the scad_lib folder of the tsf sources");
}

std::vector<std::string> scadLibraryFiles(const std::string& library_dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(library_dir, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file() && it->path().extension() == ".scad") names.push_back(it->path().filename().string());
    if (ec) throw std::runtime_error("cannot read the OpenSCAD library folder " + library_dir + ": " + ec.message());
    std::sort(names.begin(), names.end());
    return names;
}

std::string readScadLibraryFile(const std::string& library_dir, const std::string& name) {
    const fs::path path = fs::path(library_dir) / name;
    std::ifstream in(path, std::ios::binary);
    if (!in.is_open()) throw std::runtime_error("cannot open the OpenSCAD library file " + path.string());
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw std::runtime_error("cannot read the OpenSCAD library file " + path.string());
    return text.str();
}

}  // namespace tsf
