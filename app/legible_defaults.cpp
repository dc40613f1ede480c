#include "app/legible_defaults.h"

#include <algorithm>
#include <cmath>
#include <deque>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "gen/model/feature_registry.h"
#include "gen/model/features/felt_heights.h"
#include "gen/model/features/top_shapes.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"
#include "verify/tactile.h"

namespace tsf::cli {
namespace {

// The checks a setting of height or transfer can fix.
constexpr const char* kFixable[] = {"tactile_finger_reach", "tactile_slender_pillars"};

bool isFixable(const std::string& id) { return std::find(std::begin(kFixable), std::end(kFixable), id) != std::end(kFixable); }

// Lowest height tried, mm: below it a model is a plate.
constexpr double kLowestHeightMm = 2.0;

// The smallest neighbouring step of `s` that is at least a felt step, over
// pairs of data cells of different values (mm); +inf when there is none.
double smallestFeltStep(const Scene& s) {
    double smallest = INFINITY;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (s.kind[k] != CellKind::Data) continue;
        for (int e = 0; e < 3; ++e) {
            const int32_t n = s.keptNeighbour(k, e);
            if (n < 0 || s.kind[size_t(n)] != CellKind::Data || s.value[k] == s.value[size_t(n)]) continue;
            const double dz = std::fabs(s.zMm(centreTop(s, k)) - s.zMm(centreTop(s, size_t(n))));
            if (dz >= kFeltHeightStepMm - 1e-9) smallest = std::min(smallest, dz);
        }
    }
    return smallest;
}

// The first neighbouring pair whose step was felt in `before` and is not in
// `after` (the same grid, other heights); "" when every felt step stays felt.
std::string flattened(const Scene& before, const Scene& after) {
    for (size_t k = 0; k < before.keptCount(); ++k) {
        if (before.kind[k] != CellKind::Data) continue;
        const int32_t a = after.keptAt(before.col[k], before.row[k]);
        for (int e = 0; e < 3; ++e) {
            const int32_t n = before.keptNeighbour(k, e);
            if (n < 0 || before.kind[size_t(n)] != CellKind::Data) continue;
            const double was = std::fabs(before.zMm(centreTop(before, k)) - before.zMm(centreTop(before, size_t(n))));
            if (was < kFeltHeightStepMm - 1e-9) continue;
            const int32_t b = after.keptAt(before.col[size_t(n)], before.row[size_t(n)]);
            const double is = a < 0 || b < 0 ? 0.0
                                             : std::fabs(after.zMm(centreTop(after, size_t(a))) -
                                                         after.zMm(centreTop(after, size_t(b))));
            if (is < kFeltHeightStepMm - 1e-9)
                return "cells (col " + std::to_string(before.col[k]) + ", row " + std::to_string(before.row[k]) +
                       ") and (col " + std::to_string(before.col[size_t(n)]) + ", row " +
                       std::to_string(before.row[size_t(n)]) + ") would be " + formatSignificant(is, 2) + " mm apart, not " +
                       formatSignificant(was, 2);
        }
    }
    return "";
}

struct Trial {
    SceneParams params;
    int bins = 0;               // the field read at this many hexagons across (0: the first field)
    double pitch_mm = 0;        // the model's cell
    int cols = 0;               // its hexagons across
    std::vector<Check> checks;  // the fixable checks, as the verifier found them (only the slender pillars when they fail)
    int64_t failing = 0;        // their offenders together
    std::string flattens;       // why it was refused ("" when it was tried)
};

// Builds, meshes and checks one setting with the verifier's tactile checks;
// `reference` is the model of the same field at the first setting, whose
// felt steps the setting must keep.
Trial tryParams(const HexField& field, const Scene& reference, const SceneParams& p, const VerifyOptions& vo, int bins = 0) {
    Trial t;
    t.params = p;
    t.bins = bins;
    const Scene s = buildScene(field, p);
    t.pitch_mm = s.pitch_mm;
    t.cols = s.grid.cols;
    t.flattens = flattened(reference, s);
    if (!t.flattens.empty()) return t;
    TactileOptions to;
    to.sample_mm = vo.tactile_sample_mm;
    to.layer_mm = vo.layer_mm;
    to.nozzle_mm = vo.nozzle_mm;
    to.max_offenders = 3;
    // A trial passes only with no offender in either check; the slender
    // pillars are read from the Scene alone, so a setting they fail is known
    // to fail without meshing it (at 0.15 mm cells every setting: seconds
    // at 1000 x 1000). Only whether a trial passes is used (the texts come
    // from the first setting's checks).
    if (Check slender = checkSlenderPillars(s, to); slender.status == CheckStatus::Fail) {
        t.failing = slender.count;
        t.checks.push_back(std::move(slender));
        return t;
    }
    TactileResult r = checkLegibility(meshScene(s), s, to);
    for (Check& c : r.checks)
        if (isFixable(c.id)) {
            if (c.status == CheckStatus::Fail) t.failing += c.count;
            t.checks.push_back(std::move(c));
        }
    return t;
}

// The fixable checks of gen's self-check, as checkTactile gave them: gen
// turns a failed tactile check into a warning (both fixable checks only
// ever pass or fail), and lists up to its own number of offenders, worst
// first, of which the summary and key name the first three.
std::vector<Check> fixableChecks(const VerifyReport& report) {
    std::vector<Check> out;
    for (const Check& c : report.checks) {
        if (!isFixable(c.id)) continue;
        Check k = c;
        if (k.status == CheckStatus::Warn) k.status = CheckStatus::Fail;
        if (k.worst.size() > 3) k.worst.resize(3);
        out.push_back(std::move(k));
    }
    return out;
}

std::string settingText(const SceneParams& p) {
    return "--height " + formatSignificant(p.max_height_mm, 3) + " --transfer " + toString(p.transfer);
}

// The options that differ between two settings, as a user would type them.
std::string changedOptions(const SceneParams& from, const Trial& to) {
    std::string out;
    if (to.bins > 0) out += "--bins " + std::to_string(to.bins);
    if (std::fabs(from.max_height_mm - to.params.max_height_mm) > 1e-9)
        out += std::string(out.empty() ? "" : " ") + "--height " + formatSignificant(to.params.max_height_mm, 3);
    if (from.transfer != to.params.transfer) out += std::string(out.empty() ? "" : " ") + "--transfer " + toString(to.params.transfer);
    return out;
}

// The first values of the options `to` changed, as a user would type them.
std::string firstOptions(const Scene& first, const Trial& to) {
    const SceneParams& p0 = first.params;
    std::string out;
    auto add = [&out](const std::string& option) { out += (out.empty() ? "" : " ") + option; };
    if (to.bins > 0) add("--bins " + std::to_string(first.grid.cols));
    if (std::fabs(p0.max_height_mm - to.params.max_height_mm) > 1e-9) add("--height " + formatSignificant(p0.max_height_mm, 3));
    if (p0.transfer != to.params.transfer) add("--transfer " + std::string(toString(p0.transfer)));
    return out;
}

// What larger cells cost and generalise, for the summary.
std::string cellCost(const Scene& first, const Trial& t) {
    const double area = (t.pitch_mm / first.pitch_mm) * (t.pitch_mm / first.pitch_mm);
    return "cells " + formatSignificant(t.pitch_mm, 3) + " mm across instead of " + formatSignificant(first.pitch_mm, 3) +
           " (" + std::to_string(t.cols) + " instead of " + std::to_string(first.grid.cols) +
           " hexagons across, the model's size kept): each hexagon now stands for about " + formatSignificant(area, 2) +
           " times the ground it did";
}

std::string failText(const Check& c) {
    std::string where;
    for (size_t k = 0; k < c.worst.size() && k < 3; ++k)
        where += std::string(k ? "; " : "") + "(" + formatFixed(c.worst[k].at_mm.x, 1) + ", " + formatFixed(c.worst[k].at_mm.y, 1) +
                 ") mm: " + c.worst[k].detail;
    return c.id + " fails at " + std::to_string(c.count) + (c.count == 1 ? " place" : " places") +
           (where.empty() ? "" : " (" + where + ")");
}

// The same for the model's key, in a reader's words: where (mm east and
// north of the grid's south-west corner) and what it means for reading.
std::string readerText(const Check& c) {
    std::string where;
    for (size_t k = 0; k < c.worst.size() && k < 3; ++k)
        where += std::string(k ? "; " : "") + formatFixed(c.worst[k].at_mm.x, 0) + " mm east and " +
                 formatFixed(c.worst[k].at_mm.y, 0) + " mm north, " + formatFixed(c.worst[k].amount, 1) + " mm";
    const std::string n = std::to_string(c.count);
    if (c.id == std::string("tactile_finger_reach"))
        return "At " + n + (c.count == 1 ? " place" : " places") +
               " a fingertip cannot reach the bottom of a narrow low between high pillars, so its value is not read by "
               "touch (east and north of the pillars' south-west corner, and how far the finger stays above the bottom: " + where + ")";
    return n + (c.count == 1 ? " pillar is" : " pillars are") +
           " thin and tall and may break if pressed hard (east and north of the pillars' south-west corner, and how far "
           "each stands above its neighbours: " + where + ")";
}

}  // namespace

std::vector<std::string> failedLegibility(const VerifyReport& report) {
    std::vector<std::string> out;
    for (const char* id : kFixable) {
        const Check* c = report.find(id);
        // gen's self-check turns a failed tactile check into a warning.
        if (c && (c->status == CheckStatus::Fail || c->status == CheckStatus::Warn)) out.push_back(id);
    }
    return out;
}

LegibleDefaults legibleDefaults(const HexField& field, const Scene& first, const VerifyReport& first_report,
                                const LegibilityGiven& given, const VerifyOptions& vo, const FieldAtBins& field_at) {
    LegibleDefaults out;
    const std::vector<std::string> failed = failedLegibility(first_report);
    // A feature that stands every value at one height (a class map's
    // textures) leaves no heights to change.
    if (failed.empty() || featureOneHeight(first)) return out;
    const SceneParams& p0 = first.params;
    // The first setting as gen's own self-check found it: the model as
    // written (float32 in an STL) at verify's sampling, so what this pass
    // says fails is what tsf verify --tactile says, and it is not built,
    // meshed and checked a second time (at 1000 x 1000, seconds).
    Trial at_first;
    at_first.params = p0;
    at_first.pitch_mm = first.pitch_mm;
    at_first.cols = first.grid.cols;
    at_first.checks = fixableChecks(first_report);
    for (const Check& c : at_first.checks)
        if (c.status != CheckStatus::Pass && c.status != CheckStatus::Skipped) at_first.failing += c.count;
    if (at_first.failing == 0) return out;

    // Every trial is a build (and, unless its pillars fail, a mesh and the
    // fingertip's reach): each setting once.
    std::deque<Trial> tried;  // a deque: the trials found stay where they are
    std::string refused;
    auto passes = [](const Trial* t) { return t && t->flattens.empty() && t->failing == 0; };
    // One field to search: the first, or the input read again at other --bins.
    struct Field {
        const HexField& field;
        const Scene& reference;  // at the first setting: the felt steps to keep
        int bins;                // 0: the first field
        std::vector<double> heights;  // below the first, highest first, in half millimetres
    };
    // Lower heights scale every step alike (and a gentler transfer shrinks
    // the steps between high values): heights are tried down to the lowest
    // that keeps every felt step felt.
    auto lowerHeights = [&p0](const Scene& reference) {
        const double felt = smallestFeltStep(reference);
        const double lowest = std::max(kLowestHeightMm, std::isfinite(felt) ? p0.max_height_mm * kFeltHeightStepMm / felt : 0.0);
        std::vector<double> heights;
        for (double f : {0.75, 0.5, 0.35, 0.25, 0.15, 0.1}) {
            const double h = std::round(p0.max_height_mm * f * 2) / 2;
            if (h >= lowest - 1e-9 && h < (heights.empty() ? p0.max_height_mm : heights.back()) - 1e-9) heights.push_back(h);
        }
        if (const double h = std::ceil(lowest * 2 - 1e-9) / 2; h < (heights.empty() ? p0.max_height_mm : heights.back()) - 1e-9)
            heights.push_back(h);
        return heights;
    };
    auto trial = [&](const Field& f, double height, Transfer transfer) -> const Trial* {
        for (const Trial& t : tried)
            if (t.bins == f.bins && t.params.max_height_mm == height && t.params.transfer == transfer) return &t;
        SceneParams p = p0;
        p.max_height_mm = height;
        p.transfer = transfer;
        try {
            tried.push_back(tryParams(f.field, f.reference, p, vo, f.bins));
        } catch (const InputError&) {
            return nullptr;  // a setting the field cannot take
        }
        const Trial& t = tried.back();
        if (!t.flattens.empty() && refused.empty() && f.bins == 0) refused = settingText(p) + ": " + t.flattens;
        return &t;
    };
    // The setting that changes least and passes: the first height and
    // transfer (on another field), a gentler transfer, else the highest
    // height that passes (a lower one makes pits shallower and pillars
    // shorter: found by bisection, once the lowest passes).
    auto search = [&](const Field& f, bool transfers, bool lower) -> const Trial* {
        if (f.bins > 0)
            if (const Trial* x = trial(f, p0.max_height_mm, p0.transfer); passes(x)) return x;
        if (transfers)
            for (const Transfer t : {Transfer::Sqrt, Transfer::Log})
                if (t != p0.transfer)
                    if (const Trial* x = trial(f, p0.max_height_mm, t); passes(x)) return x;
        if (!lower || f.heights.empty()) return nullptr;
        const Trial* low = trial(f, f.heights.back(), p0.transfer);
        if (!passes(low)) return nullptr;
        size_t pass_at = f.heights.size() - 1, fail_at = size_t(-1);  // heights[fail_at] fails (-1: the first height)
        while (pass_at - (fail_at + 1) > 0) {
            const size_t mid = (fail_at + 1 + pass_at) / 2;
            if (passes(trial(f, f.heights[mid], p0.transfer))) pass_at = mid;
            else fail_at = mid;
        }
        return trial(f, f.heights[pass_at], p0.transfer);
    };
    const Field at_first_field{field, first, 0, lowerHeights(first)};
    const std::vector<double>& heights = at_first_field.heights;
    const Trial* pass = search(at_first_field, !given.transfer, !given.height);
    const Trial* pass_given = pass || (!given.height && !given.transfer) ? nullptr : search(at_first_field, true, true);

    // Larger cells, last: a coarser generalisation of what tsf already
    // resampled (or binned) to fit. Fewer hexagons across the same box,
    // each the mean of more pixels: narrow lows widen (a fingertip reaches
    // about w^2 / (8 r) down a pit w wide) and single-pixel noise evens out.
    // At each cell the same search (what the user gave kept), keeping that
    // field's felt steps. A field of one pillar per value is not resampled
    // for it: the --bins that would pass is named.
    const Trial* by_cell = nullptr;
    int coarsest = 0;  // the fewest hexagons across tried
    if (!pass && !pass_given && field_at) {
        int last_bins = first.grid.cols;
        for (const double factor : {4.0 / 3.0, 5.0 / 3.0, 2.0}) {
            const int bins = int(std::floor(first.grid.cols / factor + 1e-9));
            if (bins < 2 || bins >= last_bins) continue;
            last_bins = bins;
            const std::optional<HexField> coarser = field_at(bins);
            if (!coarser) continue;
            coarsest = bins;
            try {
                const Scene reference = buildScene(*coarser, p0);
                by_cell = search(Field{*coarser, reference, bins, lowerHeights(reference)}, !given.transfer, !given.height);
            } catch (const InputError&) {
                continue;  // a setting the field cannot take
            }
            if (by_cell) break;
        }
        if (by_cell && !given.cell && !field.one_to_one) pass = by_cell;
    }

    nlohmann::json j = {{"failed_at_first", failed}};
    if (pass) {
        out.params = pass->params;
        out.bins = pass->bins;
        const std::string what = changedOptions(p0, *pass);
        const std::string was = firstOptions(first, *pass);
        std::string reader;
        if (pass->bins)
            reader += "hexagons " + formatSignificant(pass->pitch_mm, 3) + " millimetres across instead of " +
                      formatSignificant(first.pitch_mm, 3) + ", each standing for more ground";
        if (pass->params.max_height_mm != p0.max_height_mm)
            reader += std::string(reader.empty() ? "" : ", ") + "the highest value " +
                      formatSignificant(pass->params.max_height_mm, 3) + " millimetres high instead of " +
                      formatSignificant(p0.max_height_mm, 3);
        if (pass->params.transfer != p0.transfer)
            reader += std::string(reader.empty() ? "" : ", ") + "heights following the " +
                      (pass->params.transfer == Transfer::Log ? "logarithm" : "square root") +
                      " of the values, so steps between high values are gentler";
        out.key_note = "So that a fingertip reaches the bottom of every low, this model differs from tsf's defaults: " +
                       reader + " (" + what + ")";
        std::string why;
        for (const Check& c : at_first.checks)
            if (c.status == CheckStatus::Fail) why += (why.empty() ? "" : "; ") + failText(c);
        out.lines.push_back("changed " + what + " (was " + was + "): " + why + ". With it every check passes" +
                            (pass->bins ? "; " + cellCost(first, *pass) + ", and" : " and") + " every neighbouring step of " +
                            formatSignificant(kFeltHeightStepMm, 2) + " mm or more stays one; give " + was +
                            " to keep the first");
        j["changed"] = what;
        j["was"] = was;
        j["why"] = why;
        if (pass->bins) j["generalised"] = cellCost(first, *pass);
        out.json = j;
        return out;
    }
    if (const Trial* would = pass_given ? pass_given : by_cell) {
        const std::string what = changedOptions(p0, *would);
        out.lines.push_back("tried: " + what + " passes every tactile check (tried, and no felt step lost" +
                            (would->bins ? "; " + cellCost(first, *would) : std::string()) + "); " +
                            (would->bins && field.one_to_one && !given.cell
                                 ? "one pillar per value is kept (the data as read)"
                                 : "the options given are kept"));
        j["would_pass"] = what;
    }
    const Trial& kept = at_first;
    for (const Check& c : kept.checks)
        if (c.status == CheckStatus::Fail) {
            j["key"].push_back(readerText(c));
            std::string why = failText(c);
            if (c.id == std::string("tactile_finger_reach"))
                why += ". A pit w mm wide is reached to about w^2 / (8 r) + " + formatSignificant(kUnreachedDepthMm, 2) +
                       " mm by a fingertip of radius r = " + formatSignificant(kAdultFingertipRadiusMm, 2) +
                       " mm: a single-cell low " + formatSignificant(first.pitch_mm, 3) + " mm wide is reached " +
                       formatSignificant(first.pitch_mm * first.pitch_mm / (8 * kAdultFingertipRadiusMm) + kUnreachedDepthMm, 2) +
                       " mm deep";
            out.lines.push_back("still " + why);
            j["fails"].push_back(why);
        }
    std::string given_list;
    for (const auto& [is, name] : {std::pair{given.height, "--height"}, {given.transfer, "--transfer"}, {given.cell, "--cell or --bins"}})
        if (is) given_list += std::string(given_list.empty() ? "" : ", ") + name;
    std::string reason = !given_list.empty()
                             ? "no setting passes that keeps the options given (" + given_list + ")"
                         : heights.empty()
                             ? "no transfer passes, and no height below " + formatSignificant(p0.max_height_mm, 3) +
                                   " mm keeps every neighbour step now at least " + formatSignificant(kFeltHeightStepMm, 2) +
                                   " mm felt"
                             : "no height from " + formatSignificant(p0.max_height_mm, 3) + " down to " +
                                   formatSignificant(heights.back(), 3) + " mm and no transfer passes";
    if (by_cell && field.one_to_one && !given.cell)
        reason += "; larger cells pass, but they would resample a raster that stands one pillar per value";
    else if (!by_cell && coarsest > 0)
        reason += "; nor do larger cells, tried down to --bins " + std::to_string(coarsest);
    if (!refused.empty()) reason += "; others would flatten the data (" + refused + ")";
    out.lines.push_back(reason);
    j["why"] = reason;
    out.json = j;
    return out;
}

}  // namespace tsf::cli
