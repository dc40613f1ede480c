#include "gen/util/error.h"

namespace tsf {
namespace {
std::string formatLocation(const std::string& path, int line, int column, const std::string& what) {
    std::string out;
    if (!path.empty()) {
        out += path;
        if (line > 0) {
            out += ":" + std::to_string(line);
            if (column > 0) out += ":" + std::to_string(column);
        }
        out += ": ";
    }
    return out + what;
}
}  // namespace

InputError::InputError(std::string path, int line, int column, const std::string& what)
    : std::runtime_error(formatLocation(path, line, column, what)),
      path_(std::move(path)), line_(line), column_(column), detail_(what) {}

InputError::InputError(const std::string& what) : std::runtime_error(what), detail_(what) {}

}  // namespace tsf
