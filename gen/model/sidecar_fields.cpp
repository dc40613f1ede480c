#include "gen/model/sidecar_fields.h"

#include <cmath>
#include <limits>

namespace tsf::sidecar {

json numberOrNull(double v) { return std::isnan(v) ? json(nullptr) : json(v); }

// --- reading helpers: every error names the JSON path ---------------------

void fail(const std::string& path, const std::string& what) {
    throw InputError((path.empty() ? std::string("(top level)") : path) + ": " + what);
}

const char* typeName(const json& v) { return v.type_name(); }

const json& member(const json& obj, const std::string& path, const char* key) {
    if (!obj.is_object()) fail(path, std::string("expected an object, found ") + typeName(obj));
    const auto it = obj.find(key);
    const std::string p = path.empty() ? key : path + "." + key;
    if (it == obj.end()) fail(p, "missing");
    return *it;
}

std::string join(const std::string& path, const char* key) { return path.empty() ? key : path + "." + key; }

int64_t toInt(const json& v, const std::string& path) {
    if (v.is_number_unsigned()) {
        if (v.get<uint64_t>() > uint64_t(std::numeric_limits<int64_t>::max())) fail(path, "integer out of range");
        return int64_t(v.get<uint64_t>());
    }
    if (v.is_number_integer()) return v.get<int64_t>();
    fail(path, std::string("expected an integer, found ") + typeName(v));
}

int64_t getInt(const json& obj, const std::string& path, const char* key) {
    return toInt(member(obj, path, key), join(path, key));
}

int32_t getInt32(const json& obj, const std::string& path, const char* key, int64_t lo, int64_t hi) {
    const int64_t v = getInt(obj, path, key);
    if (v < lo || v > hi)
        fail(join(path, key), "must be between " + std::to_string(lo) + " and " + std::to_string(hi) + " (got " +
                                  std::to_string(v) + ")");
    return int32_t(v);
}

double toNumber(const json& v, const std::string& path) {
    if (!v.is_number()) fail(path, std::string("expected a number, found ") + typeName(v));
    return v.get<double>();
}

double getNumber(const json& obj, const std::string& path, const char* key) {
    return toNumber(member(obj, path, key), join(path, key));
}

double getPositive(const json& obj, const std::string& path, const char* key) {
    const double v = getNumber(obj, path, key);
    if (!(v > 0) || !std::isfinite(v)) fail(join(path, key), "must be a number > 0");
    return v;
}

std::string getString(const json& obj, const std::string& path, const char* key) {
    const json& v = member(obj, path, key);
    if (!v.is_string()) fail(join(path, key), std::string("expected a string, found ") + typeName(v));
    return v.get<std::string>();
}

const json& getArray(const json& obj, const std::string& path, const char* key) {
    const json& v = member(obj, path, key);
    if (!v.is_array()) fail(join(path, key), std::string("expected an array, found ") + typeName(v));
    return v;
}

double getFinite(const json& obj, const std::string& path, const char* key) {
    const double v = getNumber(obj, path, key);
    if (!std::isfinite(v)) fail(join(path, key), "expected a finite number");
    return v;
}

std::pair<double, double> getFinitePair(const json& obj, const std::string& path, const char* key) {
    const json& a = getArray(obj, path, key);
    const std::string p = join(path, key);
    if (a.size() != 2) fail(p, "expected two numbers");
    const double x = toNumber(a[0], p + "[0]"), y = toNumber(a[1], p + "[1]");
    if (!std::isfinite(x) || !std::isfinite(y)) fail(p, "expected finite numbers");
    return {x, y};
}

}  // namespace tsf::sidecar
