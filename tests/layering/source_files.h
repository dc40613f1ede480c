// The project's C++ sources as the layering tests read them: every .h and
// .cpp under the given top-level folders, as paths relative to the source
// tree, leaving out what a package manager installed (node_modules).
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace tsf::test {

inline std::vector<std::string> sourceFiles(const std::filesystem::path& root, std::initializer_list<const char*> tops) {
    namespace fs = std::filesystem;
    std::vector<std::string> out;
    for (const char* top : tops)
        for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
            const std::string ext = entry.path().extension().string();
            if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
            const std::string rel = fs::relative(entry.path(), root).string();
            if (rel.find("node_modules") == std::string::npos) out.push_back(rel);
        }
    return out;
}

/// The libraries' and the application's folders (no tests, no benchmarks).
inline constexpr std::initializer_list<const char*> kProjectTops = {"gen", "verify", "runners", "pipeline", "haptics", "app"};

}  // namespace tsf::test
