// readGdalRaster, parseGdalRaster: through the GDAL module, loaded on first
// use. See gdal_reader.h and gdal/gdal_module_abi.h.
#include "gen/readers/gdal_reader.h"

#include <cctype>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "gen/util/error.h"
#include "gen/readers/gdal/gdal_module_abi.h"

namespace tsf {
namespace {

using ReadFn = int (*)(const GdalCall*);
using TransformFn = int (*)(const GdalTransformCall*);
using AbiFn = int (*)();

struct Module {
    ReadFn read = nullptr;
    TransformFn transform = nullptr;
    std::string problem;  // why there is no module, when read is null
};

// Where the module may be: $TSF_GDAL_MODULE alone when set; else beside the
// running binary (the build tree), in <prefix>/lib/tsf beside <prefix>/bin
// (installed), and where this build put it (tests, tools run from elsewhere).
std::vector<std::string> candidates() {
    if (const char* env = std::getenv("TSF_GDAL_MODULE"); env && *env) return {env};
    std::vector<std::string> out;
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        out.push_back((exe.parent_path() / kGdalModuleName).string());
        out.push_back((exe.parent_path().parent_path() / "lib" / "tsf" / kGdalModuleName).string());
    }
#ifdef TSF_GDAL_MODULE_BUILD_PATH
    out.push_back(TSF_GDAL_MODULE_BUILD_PATH);
#endif
    return out;
}

Module load() {
    Module m;
    std::string tried;
    for (const std::string& path : candidates()) {
        tried += (tried.empty() ? "" : ", ") + path;
        if (::access(path.c_str(), F_OK) != 0) continue;
        void* h = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!h) {
            const char* why = ::dlerror();
            m.problem = path + " cannot be loaded: " + (why ? why : "unknown reason");
            return m;
        }
        const auto abi = reinterpret_cast<AbiFn>(::dlsym(h, "tsf_gdal_module_abi"));
        const auto read = reinterpret_cast<ReadFn>(::dlsym(h, "tsf_gdal_read"));
        const auto transform = reinterpret_cast<TransformFn>(::dlsym(h, "tsf_gdal_transform"));
        if (!abi || !read || !transform || abi() != kGdalModuleAbi) {
            m.problem = path + " is from another build of tsf (reinstall tsf)";
            ::dlclose(h);
            return m;
        }
        m.read = read;  // kept loaded for the life of the process
        m.transform = transform;
        return m;
    }
    m.problem = std::string(kGdalModuleName) + " was not found (looked in: " + tried +
                "); reinstall tsf, or name it in TSF_GDAL_MODULE";
    return m;
}

const Module& module() {
    static const Module m = load();
    return m;
}

Raster call(const std::string& path, const std::string_view* bytes, int band, const std::string& variable,
            bool ignore_georef) {
    const Module& m = module();
    if (!m.read)
        throw std::runtime_error(path + ": this raster is read through GDAL, and tsf's GDAL module " + m.problem);
    Raster r;
    GdalModuleError e;
    const GdalCall c{&path, bytes, &r, &e, band, &variable, ignore_georef};
    const int status = m.read(&c);
    if (status == kGdalInputError) throw InputError(e.path, e.line, e.column, e.detail);
    if (status != kGdalOk) throw std::runtime_error(path + ": GDAL failed: " + e.detail);
    return r;
}

}  // namespace

Raster readGdalRaster(const std::string& path, int band, const std::string& variable, bool ignore_georef) {
    return call(path, nullptr, band, variable, ignore_georef);
}

Raster parseGdalRaster(std::string_view bytes, const std::string& path, int band, const std::string& variable,
                       bool ignore_georef) {
    return call(path, &bytes, band, variable, ignore_georef);
}

bool isGdalDatasetName(const std::string& path) {
    const size_t colon = path.find(':');
    if (colon < 2 || colon == std::string::npos || colon + 1 >= path.size()) return false;
    for (size_t k = 0; k < colon; ++k)
        if (!std::isalnum(static_cast<unsigned char>(path[k])) && path[k] != '_') return false;
    // DRIVER:"file":var, or DRIVER:file:var (a second colon after the file).
    return path[colon + 1] == '"' || path.find(':', colon + 1) != std::string::npos;
}

std::string transformCoordinates(const std::string& from, const std::string& to, std::vector<double>& x,
                                 std::vector<double>& y) {
    const Module& m = module();
    if (!m.transform) throw std::runtime_error("points are projected through GDAL and PROJ, and tsf's GDAL module " + m.problem);
    std::string name;
    GdalModuleError e;
    const GdalTransformCall c{&from, &to, &x, &y, &name, &e};
    const int status = m.transform(&c);
    if (status == kGdalInputError) throw InputError(e.path, e.line, e.column, e.detail);
    if (status != kGdalOk) throw std::runtime_error("projecting points failed: " + e.detail);
    return name;
}

}  // namespace tsf
