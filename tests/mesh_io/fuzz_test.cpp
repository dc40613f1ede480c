// Fuzz-style robustness: thousands of random and mutated inputs per format.
// The only acceptable outcomes are a tsf::InputError or a mesh whose indices
// are in range and whose coordinates are finite; a crash, a hang or any other
// exception fails. Seeds are fixed, so a failure reproduces.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <sstream>

#include "gen/util/error.h"
#include "gen/mesh_io/obj_reader.h"
#include "gen/mesh_io/obj_writer.h"
#include "gen/mesh_io/off_reader.h"
#include "gen/mesh_io/off_writer.h"
#include "gen/mesh_io/stl_reader.h"
#include "gen/mesh_io/stl_writer.h"
#include "gen/mesh_io/three_mf_reader.h"
#include "mesh_io_test_support.h"

namespace tsf {
namespace {

using Parser = std::function<Mesh(std::string_view, const std::string&, MeshReadReport*)>;

struct Outcome {
    size_t accepted = 0;
    size_t rejected = 0;
};

void expectOnlyInputError(const Parser& parse, const std::string& input, size_t case_index, Outcome& outcome) {
    try {
        MeshReadReport report;
        const Mesh m = parse(input, "fuzz", &report);
        for (const auto& t : m.triangles) {
            for (uint32_t v : t) ASSERT_LT(v, m.vertexCount()) << "case " << case_index;
        }
        for (const Vec3& p : m.positions) {
            ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << "case " << case_index;
        }
        ASSERT_EQ(report.input_triangles, m.triangleCount());
        ++outcome.accepted;
    } catch (const InputError&) {
        ++outcome.rejected;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "case " << case_index << ": unexpected " << typeid(e).name() << ": " << e.what();
    }
}

// Byte-level mutations: flips, overwrites with boundary values, deletions,
// duplications, truncation, insertion of tokens that stress text parsers.
std::string mutate(const std::string& seed, std::mt19937& rng) {
    static const std::vector<std::string> kTokens = {
        "0", "-1", "1e308", "1e-320", "nan", "inf", "-0", "4294967295", "4294967296", "-2147483649", "99999999999999999999",
        "/", "//", "#", "\n", "\r\n", " ", "\0", "facet", "vertex", "endsolid", "solid", "f", "v", "OFF", "3", "<", ">",
        "\"", "=", "&amp;", "<triangle v1=\"0\" v2=\"0\" v3=\"9\"/>", "1.5.5", "+", "e"};
    std::string s = seed;
    auto pick = [&rng](size_t n) { return n == 0 ? size_t{0} : std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
    const int edits = 1 + int(pick(4));
    for (int e = 0; e < edits; ++e) {
        switch (pick(7)) {
            case 0:
                if (!s.empty()) s[pick(s.size())] ^= static_cast<char>(1 << pick(8));
                break;
            case 1:
                if (!s.empty()) s[pick(s.size())] = static_cast<char>(std::array<int, 6>{0, 0x7F, 0x80, 0xFF, ' ', '9'}[pick(6)]);
                break;
            case 2:
                if (!s.empty()) {
                    const size_t at = pick(s.size());
                    s.erase(at, pick(std::min<size_t>(64, s.size() - at) + 1));
                }
                break;
            case 3:
                if (!s.empty()) {
                    const size_t at = pick(s.size());
                    s.insert(pick(s.size() + 1), s.substr(at, pick(64) + 1));
                }
                break;
            case 4: s.resize(pick(s.size() + 1)); break;
            case 5: {
                const std::string& token = kTokens[pick(kTokens.size())];
                s.insert(pick(s.size() + 1), token);
                break;
            }
            default:
                if (s.size() >= 4) {  // corrupt a little-endian count-like field
                    const size_t at = pick(s.size() - 3);
                    for (int k = 0; k < 4; ++k) s[at + k] = static_cast<char>(pick(256));
                }
                break;
        }
    }
    return s;
}

std::string randomBytes(std::mt19937& rng, size_t max_size) {
    std::string s(std::uniform_int_distribution<size_t>(0, max_size)(rng), '\0');
    for (char& c : s) c = static_cast<char>(rng());
    return s;
}

Outcome fuzz(const Parser& parse, const std::vector<std::string>& seeds, unsigned seed, size_t mutated, size_t random) {
    std::mt19937 rng(seed);
    Outcome outcome;
    size_t index = 0;
    for (const std::string& s : seeds) expectOnlyInputError(parse, s, index++, outcome);
    for (size_t i = 0; i < mutated; ++i) {
        expectOnlyInputError(parse, mutate(seeds[i % seeds.size()], rng), index++, outcome);
    }
    for (size_t i = 0; i < random; ++i) expectOnlyInputError(parse, randomBytes(rng, 400), index++, outcome);
    ::testing::Test::RecordProperty("accepted", int(outcome.accepted));
    ::testing::Test::RecordProperty("rejected", int(outcome.rejected));
    return outcome;
}

template <typename Writer>
std::string written(const Mesh& mesh, Writer write) {
    std::ostringstream out;
    write(mesh, out, "seed");
    return out.str();
}

TEST(Fuzz, StlBinaryAndAscii) {
    const Parser parse = [](std::string_view b, const std::string& n, MeshReadReport* r) { return parseStl(b, n, r); };
    const std::vector<std::string> seeds = {
        written(test::tetrahedron(), writeStlBinary), written(test::cube(3.0), writeStlBinary),
        written(test::tetrahedron(), writeStlAscii), written(test::cube(3.0), writeStlAscii)};
    const Outcome o = fuzz(parse, seeds, 101, 4000, 1000);
    EXPECT_GT(o.accepted, 4u);   // the seeds at least
    EXPECT_GT(o.rejected, 100u);  // the mutations really reach the checks
}

TEST(Fuzz, Off) {
    const Parser parse = [](std::string_view b, const std::string& n, MeshReadReport* r) { return parseOff(b, n, r); };
    const std::vector<std::string> seeds = {written(test::tetrahedron(), [](auto& m, auto& o, auto& t) { writeOff(m, o, t); }),
                                            written(test::cube(3.0), [](auto& m, auto& o, auto& t) { writeOff(m, o, t); }),
                                            "COFF\n4 2 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n1 1 0 1 1 1 1\n0 1 0 1 1 1 1\n"
                                            "4 0 1 2 3 255 0 0\n3 0 2 3\n"};
    const Outcome o = fuzz(parse, seeds, 202, 4000, 1000);
    EXPECT_GT(o.accepted, 3u);
    EXPECT_GT(o.rejected, 100u);
}

TEST(Fuzz, Obj) {
    const Parser parse = [](std::string_view b, const std::string& n, MeshReadReport* r) { return parseObj(b, n, r); };
    const std::vector<std::string> seeds = {written(test::tetrahedron(), [](auto& m, auto& o, auto& t) { writeObj(m, o, t); }),
                                            written(test::cube(3.0), [](auto& m, auto& o, auto& t) { writeObj(m, o, t); }),
                                            "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 -1/1/1\n"
                                            "f 1//1 2//1 3//1\nl 1 2\n"};
    const Outcome o = fuzz(parse, seeds, 303, 4000, 1000);
    EXPECT_GT(o.accepted, 3u);
    EXPECT_GT(o.rejected, 100u);
}

TEST(Fuzz, ThreeMf) {
    const Parser parse = [](std::string_view b, const std::string& n, MeshReadReport* r) { return parse3mf(b, n, r); };
    const std::string model_xml =
        R"(<?xml version="1.0" encoding="UTF-8"?>
<model unit="millimeter" xml:lang="en-US" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">
 <resources>
  <object id="1" type="model"><mesh>
   <vertices><vertex x="0" y="0" z="0"/><vertex x="4" y="0" z="0"/><vertex x="0" y="3" z="0"/><vertex x="0" y="0" z="5"/></vertices>
   <triangles><triangle v1="0" v2="2" v3="1"/><triangle v1="0" v2="1" v3="3"/><triangle v1="0" v2="3" v3="2"/><triangle v1="1" v2="2" v3="3"/></triangles>
  </mesh></object>
  <object id="2" type="model"><components><component objectid="1" transform="1 0 0 0 1 0 0 0 1 0 0 1"/></components></object>
 </resources>
 <build><item objectid="2"/><item objectid="1" transform="1 0 0 0 1 0 0 0 1 9 0 0"/></build>
</model>)";
    std::mt19937 rng(404);
    Outcome o;
    size_t index = 0;
    expectOnlyInputError(parse, test::threeMfPackage(model_xml), index++, o);
    ASSERT_EQ(o.accepted, 1u);
    // Mutated XML in a valid ZIP reaches lib3mf's model parser; mutated ZIP
    // bytes reach libzip.
    for (int i = 0; i < 1500; ++i) expectOnlyInputError(parse, test::threeMfPackage(mutate(model_xml, rng)), index++, o);
    const std::string package = test::threeMfPackage(model_xml);
    for (int i = 0; i < 500; ++i) expectOnlyInputError(parse, mutate(package, rng), index++, o);
    for (int i = 0; i < 200; ++i) expectOnlyInputError(parse, "PK\x03\x04" + randomBytes(rng, 400), index++, o);
    RecordProperty("accepted", int(o.accepted));
    RecordProperty("rejected", int(o.rejected));
    EXPECT_GT(o.accepted, 10u);  // some mutations still parse: the model parser was reached
    EXPECT_GT(o.rejected, 100u);
}

}  // namespace
}  // namespace tsf
