// Reading a check out of a verification report in JSON (tsf verify --json,
// or the "verify" object of tsf gen --json): the one way the tests look a
// check up by its id.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace tsf::test {

/// The check `id` of `report` (an object with "checks"), or null when it
/// has none.
inline nlohmann::json checkOf(const nlohmann::json& report, const std::string& id) {
    if (!report.is_object() || !report.contains("checks")) return nullptr;
    for (const auto& c : report["checks"])
        if (c.value("id", "") == id) return c;
    return nullptr;
}

/// The status ("pass", "warn", "fail", "skip") of check `id` in `report`;
/// "" when it has no such check.
inline std::string checkStatusIn(const nlohmann::json& report, const std::string& id) {
    const nlohmann::json c = checkOf(report, id);
    return c.is_object() ? c.value("status", "") : "";
}

/// The same in the report's JSON text; "" when the text is not JSON.
inline std::string checkStatus(const std::string& json_text, const std::string& id) {
    return checkStatusIn(nlohmann::json::parse(json_text, nullptr, false), id);
}

}  // namespace tsf::test
