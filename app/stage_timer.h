// Wall-clock timing of the stages of a command, with optional progress lines
// on stderr ("tsf: meshing ... 0.84 s") so long runs are never silent.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace tsf::cli {

class StageTimer {
public:
    explicit StageTimer(bool verbose) : verbose_(verbose) {}

    /// Starts a stage; the previous one (if any) ends now.
    void begin(const std::string& name) {
        end();
        name_ = name;
        start_ = std::chrono::steady_clock::now();
        if (verbose_) std::fprintf(stderr, "tsf: %s ...\n", name.c_str());
    }
    void end() {
        if (name_.empty()) return;
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
        stages_.emplace_back(name_, ms);
        if (verbose_) std::fprintf(stderr, "tsf: %s done in %.2f s\n", name_.c_str(), ms / 1000.0);
        name_.clear();
    }
    const std::vector<std::pair<std::string, double>>& stagesMs() const { return stages_; }

private:
    bool verbose_;
    std::string name_;
    std::chrono::steady_clock::time_point start_;
    std::vector<std::pair<std::string, double>> stages_;
};

}  // namespace tsf::cli
