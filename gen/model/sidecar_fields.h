// Reading and writing the scene sidecar's members (gen/model/scene_json.h),
// shared by the sidecar and the features' own records
// (gen/model/feature_records.h): every reading error names the JSON path of
// the member ("legend.plate_mm.north: expected a finite number"), as an
// InputError without a file or line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "gen/util/error.h"

namespace tsf::sidecar {

using nlohmann::json;

/// v, or null for NaN.
json numberOrNull(double v);

/// Throws the InputError "PATH: what" ("(top level)" for an empty path).
[[noreturn]] void fail(const std::string& path, const std::string& what);

/// The JSON type's name ("object", "number", ...), for messages.
const char* typeName(const json& v);

/// path + "." + key (or key at the top level).
std::string join(const std::string& path, const char* key);

/// obj[key]; fails when obj is no object or has no such member.
const json& member(const json& obj, const std::string& path, const char* key);

int64_t toInt(const json& v, const std::string& path);
int64_t getInt(const json& obj, const std::string& path, const char* key);
/// An integer in [lo, hi].
int32_t getInt32(const json& obj, const std::string& path, const char* key, int64_t lo, int64_t hi);
double toNumber(const json& v, const std::string& path);
double getNumber(const json& obj, const std::string& path, const char* key);
/// A finite number > 0.
double getPositive(const json& obj, const std::string& path, const char* key);
/// A finite number.
double getFinite(const json& obj, const std::string& path, const char* key);
/// [x, y], both finite.
std::pair<double, double> getFinitePair(const json& obj, const std::string& path, const char* key);
std::string getString(const json& obj, const std::string& path, const char* key);
const json& getArray(const json& obj, const std::string& path, const char* key);

/// One of `all`, by the name toString gives it.
template <class E, size_t N>
E getEnum(const json& obj, const std::string& path, const char* key, const E (&all)[N]) {
    const std::string s = getString(obj, path, key);
    std::string names;
    for (E e : all) {
        if (s == toString(e)) return e;
        names += std::string(names.empty() ? "" : ", ") + toString(e);
    }
    fail(join(path, key), "unknown value \"" + s + "\" (expected one of: " + names + ")");
}

}  // namespace tsf::sidecar
