// Where cells lie, in words. See places_in_words.h.
#include "gen/key/places_in_words.h"

#include <algorithm>
#include <array>

namespace tsf {
namespace {

/// The three by three regions, [row third][column third], north first.
constexpr std::array<std::array<const char*, 3>, 3> kRegions = {{
    {"the north-west corner", "the north", "the north-east corner"},
    {"the west", "the centre", "the east"},
    {"the south-west corner", "the south", "the south-east corner"},
}};

std::string listed(const std::vector<std::string>& names) {
    std::string out;
    for (size_t k = 0; k < names.size(); ++k)
        out += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
    return out;
}

}  // namespace

std::string placesInWords(int32_t cols, int32_t rows, const std::vector<std::pair<int32_t, int32_t>>& cells) {
    if (cells.empty() || cols <= 0 || rows <= 0) return "";
    const double n = double(cells.size());
    // The border: a tenth of each side, at least one cell, on grids big
    // enough to have an inside (4 x 4 and larger).
    if (cols >= 4 && rows >= 4) {
        const int32_t bc = std::max(1, cols / 10), br = std::max(1, rows / 10);
        int64_t on_border = 0;
        std::array<int64_t, 4> side{};  // north, east, south, west
        for (const auto& [c, r] : cells) {
            const bool n_ = r < br, s_ = r >= rows - br, w_ = c < bc, e_ = c >= cols - bc;
            if (n_ || s_ || w_ || e_) ++on_border;
            side[0] += n_, side[1] += e_, side[2] += s_, side[3] += w_;
        }
        if (double(on_border) >= 0.8 * n && cells.size() >= 4) {
            constexpr std::array<const char*, 4> kSide = {"north", "east", "south", "west"};
            std::vector<std::string> along;
            for (size_t k = 0; k < 4; ++k)
                if (double(side[k]) >= 0.1 * n) along.push_back(kSide[k]);
            if (along.size() == 4) return "around the border";
            if (along.size() == 3) return "along the " + listed(along) + " edges";
        }
    }
    std::array<int64_t, 9> count{};
    for (const auto& [c, r] : cells) {
        const int32_t cc = std::min(2, int32_t(int64_t(c) * 3 / cols)), rr = std::min(2, int32_t(int64_t(r) * 3 / rows));
        ++count[size_t(rr * 3 + cc)];
    }
    std::array<size_t, 9> order{};
    for (size_t k = 0; k < 9; ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return count[a] > count[b]; });
    std::vector<std::string> names;
    int64_t held = 0;
    for (size_t k : order) {
        if (count[k] == 0 || double(held) >= 0.75 * n) break;
        names.push_back(kRegions[k / 3][k % 3]);
        held += count[k];
    }
    if (names.size() > 3) return "scattered across the model";
    return (double(held) >= n ? "in " : "mostly in ") + listed(names);
}

}  // namespace tsf
