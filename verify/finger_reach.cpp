#include "verify/finger_reach.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

#include "gen/util/number_format.h"
#include "gen/util/workers.h"

namespace tsf {
namespace {

// Heights that differ by float32's rounding of a model's z (about 2e-6 mm at
// 20 mm) are the same height: a step of exactly the threshold stays on the
// same side of it in gen's mesh and in the file read back.
constexpr double kSameHeightMm = 1e-4;

// The ball's offsets chord by chord: for each row offset |dj| (0..n), the
// rises sqrt(r^2 - d^2) of the column offsets di = -m..m inside the disc,
// computed exactly as a sample-by-sample loop over the disc would (so the
// closing below gives the same numbers, bit for bit). A row offset and its
// negation have the same chord.
struct Chord {
    int dj = 0, m = 0;
    std::vector<double> rise;  // rise[di + m]
};

std::vector<Chord> discChords(double r, double step, int n) {
    std::vector<Chord> out;
    for (int dj = 0; dj <= n; ++dj) {
        Chord c;
        c.dj = dj;
        for (int di = -n; di <= n; ++di) {
            const double d2 = (di * step) * (di * step) + (dj * step) * (dj * step);
            if (d2 <= r * r) c.rise.push_back(std::sqrt(r * r - d2));
        }
        if (c.rise.empty()) continue;
        c.m = int(c.rise.size() / 2);  // (di * step)^2 grows with |di|: a chord is -m..m
        out.push_back(std::move(c));
    }
    return out;
}

// Rows are worked on in blocks of kLanes samples, with restrict pointers: g++
// at -O2 vectorises a loop only when it needs neither a check that its
// arrays do not overlap nor a scalar loop for the last few samples, and a
// loop over whole blocks needs neither. The samples past a row's end in its
// last block are scratch, never read back.
constexpr size_t kLanes = 4;

// The two kernels below are built twice with g++ on x86-64 glibc: for AVX2
// (four doubles a vector) and for the baseline's SSE2 (two), the one the
// processor runs chosen when the program loads. An add and a max or min
// per sample: the same IEEE operations at either width, so the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && defined(__GLIBC__)
#define TSF_WIDE_VECTORS __attribute__((target_clones("avx2", "default")))
#else
#define TSF_WIDE_VECTORS
#endif

size_t wholeBlocks(int nx) { return (size_t(nx) + kLanes - 1) / kLanes; }

// d[i] = take(d[i], src[i] + add) for the blocks' samples.
template <bool kMax>
TSF_WIDE_VECTORS void takeShifted(double* __restrict d, const double* __restrict src, double add, size_t blocks) {
    for (size_t b = 0; b < blocks; ++b)
        for (size_t k = 0; k < kLanes; ++k) {
            const size_t i = b * kLanes + k;
            d[i] = kMax ? std::max(d[i], src[i] + add) : std::min(d[i], src[i] + add);
        }
}

// out[i] = take(out[i], take(below[i], above[i])) for the blocks' samples.
template <bool kMax>
TSF_WIDE_VECTORS void takeEither(double* __restrict out, const double* below, const double* above, size_t blocks) {
    for (size_t b = 0; b < blocks; ++b)
        for (size_t k = 0; k < kLanes; ++k) {
            const size_t i = b * kLanes + k;
            out[i] = kMax ? std::max(out[i], std::max(below[i], above[i]))
                          : std::min(out[i], std::min(below[i], above[i]));
        }
}

// out(j)[i] for every sample (i, j) of an nx x ny top: the largest (kMax) of
// in[j + dj][i + di] + rise, or the smallest of in[j + dj][i + di] - rise,
// over the disc's offsets. `in` is padded by n samples on every side (w
// wide, at least wholeBlocks(nx) * kLanes + 2n), so an offset never leaves
// its row.
//
// The disc is taken apart into its chords: a row of `in` is dilated along
// x by the chord of |dj| once, and that row serves the rows dj above and
// below it, which halves the work of a sample-by-sample loop over the disc
// (the 16 mm fingertip at 0.5 mm is 800 offsets). Max and min are exact, so
// the order they are taken in does not change a bit of the result. Each
// worker owns a band of rows and the dilated rows it needs.
template <bool kMax, class OutRow>
void overDisc(const std::vector<double>& in, size_t w, int n, int nx, int ny, const std::vector<Chord>& chords,
              OutRow out_row) {
    const unsigned workers = std::min<unsigned>(detail::workerCount(0), unsigned(std::max(1, ny)));
    const double start = kMax ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    const size_t blocks = wholeBlocks(nx), wide = blocks * kLanes;
    detail::runOnWorkers(workers, [&](unsigned worker, const auto&) {
        const int j0 = int(int64_t(ny) * worker / workers), j1 = int(int64_t(ny) * (worker + 1) / workers);
        if (j0 >= j1) return;
        // acc[(j - j0) * wide + i]: the band's results so far.
        std::vector<double> acc(size_t(j1 - j0) * wide, start);
        // dilated[(p - j0 + n) * wide + i]: row p (in the top's rows,
        // -n..ny+n) dilated along x by the current chord.
        std::vector<double> dilated(size_t(j1 - j0 + 2 * n) * wide);
        for (const Chord& c : chords) {
            for (int p = j0 - c.dj; p < j1 + c.dj; ++p) {
                double* d = &dilated[size_t(p - j0 + n) * wide];
                std::fill(d, d + wide, start);
                const double* row = &in[size_t(p + n) * w + size_t(n)];
                for (int k = 0; k <= 2 * c.m; ++k)
                    takeShifted<kMax>(d, row + (k - c.m), kMax ? c.rise[size_t(k)] : -c.rise[size_t(k)], blocks);
            }
            for (int j = j0; j < j1; ++j)
                takeEither<kMax>(&acc[size_t(j - j0) * wide], &dilated[size_t(j - c.dj - j0 + n) * wide],
                                 &dilated[size_t(j + c.dj - j0 + n) * wide], blocks);
        }
        for (int j = j0; j < j1; ++j) std::copy_n(&acc[size_t(j - j0) * wide], nx, out_row(j));
    });
}

}  // namespace

std::vector<double> closedByBall(const TopHeightField& h, double r, double table) {
    const int n = int(std::ceil(r / h.step));
    const std::vector<Chord> chords = discChords(r, h.step, n);
    const size_t w = wholeBlocks(h.nx) * kLanes + 2 * size_t(n), rows = size_t(h.ny) + 2 * size_t(n);
    std::vector<double> padded(w * rows, table);  // the surface; the table where nothing is
    for (int j = 0; j < h.ny; ++j)
        for (int i = 0; i < h.nx; ++i) {
            const double z = h.at(i, j);
            padded[(size_t(j) + size_t(n)) * w + size_t(i) + size_t(n)] = std::isfinite(z) ? z : table;
        }
    // The lowest each ball centre can go; a centre beyond the sampled area
    // stands on the table.
    std::vector<double> centre(w * rows, table + r), reach(h.z.size());
    overDisc<true>(padded, w, n, h.nx, h.ny, chords,
                   [&](int j) { return &centre[(size_t(j) + size_t(n)) * w + size_t(n)]; });
    // The lowest point of the balls over each sample.
    overDisc<false>(centre, w, n, h.nx, h.ny, chords, [&](int j) { return &reach[size_t(j) * size_t(h.nx)]; });
    return reach;
}

namespace {

// Union-find over samples with the fingers that reach each set (a bit per finger).
struct Sets {
    std::vector<int32_t> parent;
    std::vector<uint32_t> reached;
    int32_t find(int32_t s) {
        while (parent[size_t(s)] != s) {
            parent[size_t(s)] = parent[size_t(parent[size_t(s)])];
            s = parent[size_t(s)];
        }
        return s;
    }
    void join(int32_t a, int32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return;
        parent[size_t(b)] = a;
        reached[size_t(a)] |= reached[size_t(b)];
    }
};

// For every sample deep for some finger, the fingers that read it anyway: the
// surface continues from it, never more than kUnreachedDepthMm above it, to a
// sample that finger reaches. Found in one sweep up the heights: samples join
// the sets of their lower neighbours in order of height, and a deep sample is
// asked about once every sample up to its height + kUnreachedDepthMm has joined.
std::vector<uint32_t> readAnyway(const TopHeightField& h, const std::vector<uint32_t>& reached_by,
                                 const std::vector<uint32_t>& deep_for) {
    const size_t n = h.z.size();
    // Sorted by height with the height beside the sample (not looked up at
    // every comparison). How samples of one height are ordered does not
    // matter: every one of them has joined before a sample is asked about.
    std::vector<std::pair<double, int32_t>> by_z, asked_by_z;
    for (size_t s = 0; s < n; ++s)
        if (std::isfinite(h.z[s])) {
            by_z.push_back({h.z[s], int32_t(s)});
            if (deep_for[s]) asked_by_z.push_back({h.z[s], int32_t(s)});
        }
    std::sort(by_z.begin(), by_z.end());
    std::sort(asked_by_z.begin(), asked_by_z.end());
    std::vector<int32_t> order(by_z.size()), asked(asked_by_z.size());
    for (size_t k = 0; k < by_z.size(); ++k) order[k] = by_z[k].second;
    for (size_t k = 0; k < asked_by_z.size(); ++k) asked[k] = asked_by_z[k].second;
    Sets sets{std::vector<int32_t>(n, -1), std::vector<uint32_t>(n, 0)};
    std::vector<uint32_t> answer(n, 0);
    size_t next = 0;
    for (const int32_t p : asked) {
        const double up_to = h.z[size_t(p)] + kUnreachedDepthMm + kSameHeightMm;
        for (; next < order.size() && h.z[size_t(order[next])] <= up_to; ++next) {
            const int32_t s = order[next];
            sets.parent[size_t(s)] = s;
            sets.reached[size_t(s)] = reached_by[size_t(s)];
            const int i = int(size_t(s) % size_t(h.nx)), j = int(size_t(s) / size_t(h.nx));
            for (const auto& [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                const int qi = i + di, qj = j + dj;
                if (qi < 0 || qj < 0 || qi >= h.nx || qj >= h.ny) continue;
                const size_t q = size_t(qj) * size_t(h.nx) + size_t(qi);
                if (sets.parent[q] >= 0) sets.join(s, int32_t(q));
            }
        }
        answer[size_t(p)] = sets.reached[size_t(sets.find(p))];
    }
    return answer;
}

// The places of one finger: connected groups of its unreached samples.
FingerReach placesOf(const TopHeightField& h, const std::vector<double>& reach, const std::vector<uint8_t>& unreached,
                     double radius) {
    FingerReach f;
    f.radius_mm = radius;
    const double cell = h.step * h.step;
    std::vector<uint8_t> seen(h.z.size(), 0);
    std::vector<size_t> stack;
    for (size_t s = 0; s < h.z.size(); ++s) {
        if (!unreached[s] || seen[s]) continue;
        Offender worst{{0, 0, 0}, -1, ""};
        int64_t samples = 0;
        stack.assign(1, s);
        seen[s] = 1;
        while (!stack.empty()) {
            const size_t p = stack.back();
            stack.pop_back();
            ++samples;
            const int pi = int(p % size_t(h.nx)), pj = int(p / size_t(h.nx));
            const double depth = reach[p] - h.z[p];
            if (depth > worst.amount) worst = {{h.x0 + pi * h.step, h.y0 + pj * h.step, h.z[p]}, depth, ""};
            for (const auto& [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                const int qi = pi + di, qj = pj + dj;
                if (qi < 0 || qj < 0 || qi >= h.nx || qj >= h.ny) continue;
                const size_t q = size_t(qj) * size_t(h.nx) + size_t(qi);
                if (!unreached[q] || seen[q]) continue;
                seen[q] = 1;
                stack.push_back(q);
            }
        }
        ++f.places;
        f.deepest_mm = std::max(f.deepest_mm, worst.amount);
        f.area_mm2 += double(samples) * cell;
        worst.detail = "the fingertip (" + formatFixed(2 * radius, 0) + " mm) stops " + formatFixed(worst.amount, 1) +
                       " mm above the surface, over " + formatFixed(double(samples) * cell, 1) + " mm^2";
        f.worst.push_back(std::move(worst));
    }
    std::stable_sort(f.worst.begin(), f.worst.end(), [](const Offender& a, const Offender& b) { return a.amount > b.amount; });
    return f;
}

}  // namespace

TopHeightField sampledTop(const Mesh& mesh, double sample_mm, double margin_mm) {
    TopHeightField h;
    const Bounds b = meshBounds(mesh);
    if (mesh.triangles.empty() || !std::isfinite(b.min.z)) return h;
    const double w = b.max.x - b.min.x + 2 * margin_mm, d = b.max.y - b.min.y + 2 * margin_mm;
    // At most about a million samples (a 500 mm model at 0.5 mm); the
    // coarser step is rounded up to 0.01 mm so that float32's rounding of the
    // bounds does not move it.
    h.step = std::max(sample_mm, std::ceil(std::sqrt(w * d / 1.0e6) * 100) / 100);
    h.x0 = std::floor((b.min.x - margin_mm) / h.step) * h.step;
    h.y0 = std::floor((b.min.y - margin_mm) / h.step) * h.step;
    h.nx = int(std::ceil((b.max.x + margin_mm - h.x0) / h.step)) + 1;
    h.ny = int(std::ceil((b.max.y + margin_mm - h.y0) / h.step)) + 1;
    rasteriseTop(mesh, h);
    return h;
}

FingerReachResult fingerReach(const TopHeightField& h, double table_mm, const std::vector<double>& radii_mm,
                              const std::vector<uint8_t>& no_value) {
    FingerReachResult r;
    r.step_mm = h.step;
    const size_t n = h.z.size();
    const size_t fingers = std::min<size_t>(radii_mm.size(), 32);
    std::vector<std::vector<double>> reach;
    std::vector<uint32_t> reached_by(n, 0), deep_for(n, 0);
    for (size_t f = 0; f < fingers; ++f) {
        reach.push_back(closedByBall(h, radii_mm[f], table_mm));
        // A smaller ball fits wherever the larger one before it touched.
        if (f > 0 && radii_mm[f] <= radii_mm[f - 1])
            for (size_t s = 0; s < n; ++s) reach[f][s] = std::min(reach[f][s], reach[f - 1][s]);
        for (size_t s = 0; s < n; ++s) {
            if (!std::isfinite(h.z[s])) continue;
            if (reach[f][s] - h.z[s] > kUnreachedDepthMm + kSameHeightMm) deep_for[s] |= 1u << f;
            else reached_by[s] |= 1u << f;
        }
    }
    const std::vector<uint32_t> anyway = readAnyway(h, reached_by, deep_for);
    std::vector<uint8_t> unreached(n, 0);
    for (size_t f = 0; f < fingers; ++f) {
        const uint32_t bit = 1u << f;
        int64_t left_out = 0;
        for (size_t s = 0; s < n; ++s) {
            unreached[s] = (deep_for[s] & bit) && !(anyway[s] & bit);
            if (unreached[s] && s < no_value.size() && no_value[s]) {
                unreached[s] = 0;
                ++left_out;
            }
        }
        r.fingers.push_back(placesOf(h, reach[f], unreached, radii_mm[f]));
        r.fingers.back().no_value_area_mm2 = double(left_out) * h.step * h.step;
    }
    return r;
}

FingerReachResult fingerReach(const Mesh& mesh, double sample_mm, const std::vector<double>& radii_mm) {
    const double margin = radii_mm.empty() ? 0.0 : *std::max_element(radii_mm.begin(), radii_mm.end());
    const TopHeightField h = sampledTop(mesh, sample_mm, margin);
    if (h.z.empty()) return {};
    return fingerReach(h, meshBounds(mesh).min.z, radii_mm);
}

}  // namespace tsf
