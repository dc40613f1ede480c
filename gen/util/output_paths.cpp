#include "gen/util/output_paths.h"

#include <filesystem>

#include "gen/util/error.h"

namespace fs = std::filesystem;

namespace tsf {
namespace {

// The absolute path with "." and ".." and the existing part's links resolved.
fs::path resolved(const std::string& p) {
    std::error_code ec;
    fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return ec ? fs::absolute(p).lexically_normal() : r;
}

}  // namespace

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec)) {
        const bool same = fs::equivalent(a, b, ec);  // hard links too
        if (!ec) return same;
    }
    return resolved(a) == resolved(b);
}

void checkOutputPaths(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
    for (size_t k = 0; k < outputs.size(); ++k) {
        const NamedPath& out = outputs[k];
        if (out.path.empty()) continue;
        for (const NamedPath& in : inputs)
            if (!in.path.empty() && sameFile(out.path, in.path))
                throw InputError(out.path, 0, 0,
                                 "is " + in.role + " and would be overwritten by " + out.role +
                                     "; choose another output name");
        for (size_t e = 0; e < k; ++e)
            if (!outputs[e].path.empty() && sameFile(out.path, outputs[e].path))
                throw InputError(out.path, 0, 0,
                                 "is named twice as an output (" + outputs[e].role + " and " + out.role +
                                     "); give each output its own name");
    }
}

}  // namespace tsf
