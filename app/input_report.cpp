#include "app/input_report.h"

#include <sstream>

namespace tsf::cli {
namespace {

nlohmann::json numberOrNull(double v) { return std::isnan(v) ? nlohmann::json() : nlohmann::json(v); }

}  // namespace

std::string formatFieldInput(const FieldInput& in) {
    std::ostringstream s;
    s << "  read      " << in.kind;
    if (in.cols > 0) s << ", " << in.cols << " x " << in.rows << " values";
    else s << ", " << in.values << " points";
    for (const ReadFact& f : in.facts) s << "; " << f.name << ": " << f.value;
    // What the values are in the file's own words (the key opens with them).
    if (!in.description.empty() || !in.step.empty()) {
        s << "\n  data      " << (in.description.empty() ? in.variable : in.description);
        if (!in.units.empty()) s << ", in " << in.units;
        if (!in.step.empty()) s << ", for " << in.step;
    }
    s << "\n  values    ";
    if (in.kind == "points" && in.cols == 0 && std::isnan(in.min) && in.nodata == 0) {
        s << "count of points per hexagon\n";
        return s.str();
    }
    if (std::isnan(in.min)) s << "none with data";
    else s << "min " << in.min << ", max " << in.max << ", mean " << in.mean << " (as read)";
    s << "; " << in.nodata << " of " << in.values << " without data\n";
    return s.str();
}

nlohmann::json fieldInputJson(const FieldInput& in) {
    nlohmann::json detected = nlohmann::json::object();
    for (const ReadFact& f : in.facts) detected[f.name] = f.value;
    return {{"kind", in.kind},         {"cols", in.cols},          {"rows", in.rows},
            {"values", in.values},     {"nodata_values", in.nodata}, {"min", numberOrNull(in.min)},
            {"max", numberOrNull(in.max)}, {"mean", numberOrNull(in.mean)}, {"detected", detected},
            {"description", in.description}, {"variable", in.variable}, {"step", in.step}, {"units", in.units}};
}

}  // namespace tsf::cli
