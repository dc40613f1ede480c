// Feeds random and mutated bytes to every reader: the only acceptable outcomes
// are a Raster/PointTable or a tsf::InputError - never a crash, a hang, or
// another exception type.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "gen/util/error.h"
#include "gen/readers/csv_grid_reader.h"
#include "gen/readers/esri_ascii_reader.h"
#include "gen/readers/pgm_reader.h"
#include "gen/readers/png_reader.h"
#include "gen/readers/point_reader.h"
#include "gen/readers/raster_reader.h"
#include "png_test_writer.h"

namespace tsf {
namespace {

constexpr int kIterations = 5000;  // per reader; the whole file runs in well under a second

using Parser = std::function<void(const std::string&)>;

// PNG chunks carry a CRC; recomputing it after a mutation lets the bytes
// reach libpng's decoder instead of stopping at the checksum.
uint32_t crc32Png(const unsigned char* p, size_t n) {
    uint32_t c = 0xFFFFFFFFu;
    for (size_t k = 0; k < n; ++k) {
        c ^= p[k];
        for (int b = 0; b < 8; ++b) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return c ^ 0xFFFFFFFFu;
}

void fixPngCrcs(std::string& png) {
    size_t pos = 8;
    while (pos + 12 <= png.size()) {
        const auto* u = reinterpret_cast<const unsigned char*>(png.data());
        const uint32_t len = (uint32_t(u[pos]) << 24) | (uint32_t(u[pos + 1]) << 16) | (uint32_t(u[pos + 2]) << 8) | u[pos + 3];
        if (len > png.size() - pos - 12) return;
        const uint32_t crc = crc32Png(u + pos + 4, len + 4);
        for (int k = 0; k < 4; ++k) png[pos + 8 + len + size_t(k)] = char((crc >> (24 - 8 * k)) & 0xFF);
        pos += 12 + len;
    }
}

std::string mutate(const std::string& seed, std::mt19937& rng, const std::string& alphabet) {
    std::string s = seed;
    const int edits = 1 + int(rng() % 4);
    for (int e = 0; e < edits; ++e) {
        const size_t at = s.empty() ? 0 : rng() % s.size();
        const char c = (rng() % 2) ? alphabet[rng() % alphabet.size()] : char(rng() & 0xFF);
        switch (rng() % 5) {
            case 0: if (!s.empty()) s[at] = c; break;
            case 1: s.insert(s.begin() + long(at), c); break;
            case 2: if (!s.empty()) s.erase(at, 1 + rng() % 4); break;
            case 3: s.resize(at); break;  // truncate
            default: if (!s.empty()) s.insert(at, s.substr(rng() % s.size(), 1 + rng() % 16)); break;  // duplicate a slice
        }
    }
    return s;
}

std::string randomBytes(std::mt19937& rng, const std::string& alphabet) {
    std::string s(rng() % 200, '\0');
    for (char& c : s) c = (rng() % 4) ? alphabet[rng() % alphabet.size()] : char(rng() & 0xFF);
    return s;
}

void fuzz(const char* name, const Parser& parse, const std::vector<std::string>& seeds, const std::string& alphabet,
          bool fix_png_crc = false) {
    std::mt19937 rng(12345);
    int accepted = 0, rejected = 0;
    for (int it = 0; it < kIterations; ++it) {
        std::string input = (it % 5 == 0) ? randomBytes(rng, alphabet) : mutate(seeds[size_t(it) % seeds.size()], rng, alphabet);
        if (fix_png_crc && it % 2 == 0) fixPngCrcs(input);
        try {
            parse(input);
            ++accepted;
        } catch (const InputError&) {
            ++rejected;
        } catch (const std::exception& e) {
            FAIL() << name << " iteration " << it << ": unexpected exception " << e.what();
        } catch (...) {
            FAIL() << name << " iteration " << it << ": unexpected non-standard exception";
        }
    }
    std::printf("[ fuzz     ] %s: %d accepted, %d rejected\n", name, accepted, rejected);
    // Both outcomes occur: the mutations are neither all fatal nor all
    // harmless (a parser that rejects everything, or accepts everything,
    // would pass a test of exceptions alone).
    EXPECT_GT(rejected, 0) << name;
    EXPECT_GT(accepted, 0) << name;
}

TEST(ReaderFuzz, CsvGrid) {
    fuzz("csv", [](const std::string& s) { parseCsvGrid(s, "fuzz.csv"); },
         {"a,b,c\n1,2,3\n4,5,6\n", "1;2,5\r\n3;4\r\n", "\"1\",\"2\"\n\"3\",\"\"\n", "1 2 3\n4 5 6\n", "\xEF\xBB\xBF" "1\t2\n"},
         "0123456789.,;\t \n\r\"eE+-naNAif");
}

TEST(ReaderFuzz, Pgm) {
    std::string p5 = "P5\n# c\n4 3\n255\n";
    for (int k = 0; k < 12; ++k) p5 += char(k * 20);
    std::string p5w = "P5 2 2 65535\n";
    for (int k = 0; k < 8; ++k) p5w += char(k * 31);
    fuzz("pgm", [](const std::string& s) { parsePgm(s, "fuzz.pgm"); },
         {"P2\n# comment\n3 2\n255\n0 1 2\n3 4 5\n", p5, p5w}, "P25 0123456789#\n\r\t");
}

TEST(ReaderFuzz, Png) {
    std::vector<std::string> seeds;
    test::PngSpec grey;
    grey.width = 5;
    grey.height = 4;
    for (int k = 0; k < 20; ++k) grey.samples.push_back(unsigned(k * 12));
    seeds.push_back(test::makePng(grey));
    test::PngSpec g16 = grey;
    g16.bit_depth = 16;
    for (auto& v : g16.samples) v *= 200;
    g16.interlaced = true;
    seeds.push_back(test::makePng(g16));
    test::PngSpec ga;
    ga.width = 3;
    ga.height = 2;
    ga.color_type = PNG_COLOR_TYPE_GRAY_ALPHA;
    ga.samples = {1, 255, 2, 0, 3, 9, 4, 255, 5, 0, 6, 1};
    seeds.push_back(test::makePng(ga));
    test::PngSpec pal;
    pal.width = 3;
    pal.color_type = PNG_COLOR_TYPE_PALETTE;
    pal.palette = {{1, 1, 1}, {2, 3, 4}};
    pal.samples = {0, 1, 0};
    seeds.push_back(test::makePng(pal));
    fuzz("png", [](const std::string& s) { parsePng(s, "fuzz.png"); }, seeds, std::string("\x00\x01\xFF IHDRIDATPNG", 16),
         /*fix_png_crc=*/true);
}

TEST(ReaderFuzz, EsriAscii) {
    fuzz("esri", [](const std::string& s) { parseEsriAscii(s, "fuzz.asc"); },
         {"ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -9999\n1 2 3\n4 -9999 6\n",
          "NCOLS 2\r\nNROWS 2\r\nXLLCENTER 1\r\nYLLCENTER 1\r\nCELLSIZE 0.5\r\n1 2 3 4\r\n"},
         "ncolsrwxyl NODATAvue_0123456789.-\n");
}

TEST(ReaderFuzz, Points) {
    fuzz("points",
         [](const std::string& s) {
             PointColumns cols;
             cols.x.name = "lon";
             cols.y.name = "lat";
             cols.weight.index = 2;
             parsePointsCsv(s, "fuzz.csv", cols);
         },
         {"lon,lat,w\n1,2,3\n4,5,\n", "\"a,b\";lon;lat\n1;2;3\n"}, "lonat,;\"w0123456789.-\n");
}

TEST(ReaderFuzz, AutoDetection) {
    fuzz("auto", [](const std::string& s) { parseRaster(s, "fuzz"); },
         {"P2 2 1 9 1 2", "ncols 1\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n5\n", "1,2\n3,4\n",
          std::string("\x89PNG\r\n\x1a\n", 8)},
         "P25ncols 0123456789,\n");
}

}  // namespace
}  // namespace tsf
