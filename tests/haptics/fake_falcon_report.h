// The fake Falcon's report (TSF_FAKE_FALCON_REPORT): key=value lines the
// libusb stand-in rewrites after every command, read by it (the state a
// later process inherits) and by the tests (what the device holds).
#pragma once

#include <fstream>
#include <map>
#include <string>

namespace tsf::haptics::testing {

/// The report's key=value lines; empty when there is no report.
inline std::map<std::string, std::string> readFakeFalconReport(const std::string& path) {
    std::map<std::string, std::string> m;
    std::ifstream f(path);
    std::string line;
    while (std::getline(f, line))
        if (const auto eq = line.find('='); eq != std::string::npos) m[line.substr(0, eq)] = line.substr(eq + 1);
    return m;
}

}  // namespace tsf::haptics::testing
