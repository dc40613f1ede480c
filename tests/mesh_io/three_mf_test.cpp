// 3MF: files we write open with lib3mf itself, in millimetres, with title
// and application metadata; hand-written packages with units, components
// and transforms read back where an independent calculation says.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "Model/COM/NMR_DLLInterfaces.h"
#include "gen/util/error.h"
#include "gen/mesh_io/mesh_reader.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/mesh_io/three_mf_reader.h"
#include "gen/mesh_io/three_mf_writer.h"
#include "mesh_io_test_support.h"

namespace tsf {
namespace {

using test::scratchDir;
using ::testing::HasSubstr;

// Opens path with lib3mf directly (not through our reader) and returns the
// model; fails the test if lib3mf cannot read it.
struct Lib3mfModel {
    NMR::PLib3MFModel* model = nullptr;
    explicit Lib3mfModel(const std::string& path) {
        EXPECT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
        NMR::PLib3MFModelReader* reader = nullptr;
        EXPECT_EQ(NMR::lib3mf_model_queryreader(model, "3mf", &reader), LIB3MF_OK);
        EXPECT_EQ(NMR::lib3mf_reader_setstrictmodeactive(reader, true), LIB3MF_OK);
        EXPECT_EQ(NMR::lib3mf_reader_readfromfileutf8(reader, path.c_str()), LIB3MF_OK) << path;
        NMR::lib3mf_release(reader);
    }
    ~Lib3mfModel() { NMR::lib3mf_release(model); }

    std::string metadata(const std::string& key) const {
        DWORD count = 0;
        NMR::lib3mf_model_getmetadatacount(model, &count);
        for (DWORD i = 0; i < count; ++i) {
            char buffer[256] = {};
            ULONG needed = 0;
            NMR::lib3mf_model_getmetadatakeyutf8(model, i, buffer, sizeof buffer, &needed);
            if (key == buffer) {
                NMR::lib3mf_model_getmetadatavalueutf8(model, i, buffer, sizeof buffer, &needed);
                return buffer;
            }
        }
        return "(missing)";
    }
};

TEST(ThreeMfWriter, FileOpensWithLib3mfInMillimetresWithMetadata) {
    const auto dir = scratchDir();
    const std::string path = (dir / "cube.3mf").string();
    MeshWriteOptions opts;
    opts.title = "Rainfall 2023";
    writeMesh(test::cube(20.0), path, opts);

    Lib3mfModel lib(path);
    DWORD unit = 99;
    ASSERT_EQ(NMR::lib3mf_model_getunit(lib.model, &unit), LIB3MF_OK);
    EXPECT_EQ(unit, DWORD{NMR::MODELUNIT_MILLIMETER});
    EXPECT_EQ(lib.metadata("Title"), "Rainfall 2023");
    EXPECT_THAT(lib.metadata("Application"), HasSubstr("tsf"));

    NMR::PLib3MFModelBuildItemIterator* items = nullptr;
    ASSERT_EQ(NMR::lib3mf_model_getbuilditems(lib.model, &items), LIB3MF_OK);
    BOOL has = false;
    ASSERT_EQ(NMR::lib3mf_builditemiterator_movenext(items, &has), LIB3MF_OK);
    ASSERT_TRUE(has);
    NMR::PLib3MFModelBuildItem* item = nullptr;
    NMR::lib3mf_builditemiterator_getcurrent(items, &item);
    NMR::PLib3MFModelObjectResource* object = nullptr;
    NMR::lib3mf_builditem_getobjectresource(item, &object);
    DWORD vertices = 0, triangles = 0;
    NMR::lib3mf_meshobject_getvertexcount(object, &vertices);
    NMR::lib3mf_meshobject_gettrianglecount(object, &triangles);
    EXPECT_EQ(vertices, 8u);
    EXPECT_EQ(triangles, 12u);
    BOOL manifold = false;
    NMR::lib3mf_meshobject_ismanifoldandoriented(object, &manifold);
    EXPECT_TRUE(manifold);
    ASSERT_EQ(NMR::lib3mf_builditemiterator_movenext(items, &has), LIB3MF_OK);
    EXPECT_FALSE(has);  // exactly one build item
    NMR::lib3mf_release(object);
    NMR::lib3mf_release(item);
    NMR::lib3mf_release(items);
}

// A package whose ZIP directory claims an entry unpacks to gigabytes from a
// few kilobytes is refused before anything reads it (lib3mf would allocate
// the claim), naming the entry; the honest package reads.
TEST(ThreeMfReader, ADirectoryClaimingMoreThanCompressionCanGiveIsRefusedBeforeReading) {
    const auto dir = scratchDir();
    const std::string path = (dir / "honest.3mf").string();
    writeMesh(test::cube(10.5, {0.5, -2.25, 1.125}), path);
    std::string bytes = test::readText(path);
    ASSERT_NO_THROW(parse3mfParts(bytes, "honest.3mf"));
    // Every central directory entry claims 0xF0000000 bytes unpacked: in
    // its ZIP64 extra field when it has one (lib3mf writes them), else in
    // the entry itself.
    size_t patched = 0;
    auto put32 = [&bytes](size_t at, uint32_t v) {
        for (int k = 0; k < 4; ++k) bytes[at + size_t(k)] = char((v >> (8 * k)) & 0xFF);
    };
    auto le16 = [&bytes](size_t at) { return size_t(uint8_t(bytes[at])) | size_t(uint8_t(bytes[at + 1])) << 8; };
    for (size_t at = 0; at + 46 <= bytes.size(); ++at)
        if (bytes.compare(at, 4, "PK\x01\x02") == 0) {
            const bool zip64 = uint8_t(bytes[at + 24]) == 0xFF && uint8_t(bytes[at + 27]) == 0xFF;
            if (zip64) {
                const size_t extra = at + 46 + le16(at + 28);
                ASSERT_EQ(le16(extra), 1u);  // the ZIP64 field first
                put32(extra + 4, 0xF0000000u);  // unpacked, low half
                put32(extra + 8, 0);            // high half
            } else {
                put32(at + 24, 0xF0000000u);
            }
            ++patched;
        }
    ASSERT_GT(patched, 0u);
    try {
        (void)parse3mfParts(bytes, "liar.3mf");
        FAIL() << "a 4 GB claim was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unpacks to 4026531840 bytes"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("liar.3mf"), std::string::npos) << e.what();
    }
}

TEST(ThreeMfRoundTrip, ShortDecimalPositionsComeBackExactly) {
    // Values with at most 6 decimals that float32 holds exactly survive
    // lib3mf's 6-decimal text, and the indexed topology is kept as is.
    const auto dir = scratchDir();
    const std::string path = (dir / "exact.3mf").string();
    const Mesh original = test::cube(10.5, {0.5, -2.25, 1.125});
    writeMesh(original, path);
    MeshReadReport report;
    const Mesh read = readMesh(path, &report);
    EXPECT_EQ(report.format, "3mf");
    EXPECT_EQ(report.merged_vertices, 0u);
    EXPECT_EQ(read.positions, original.positions);
    EXPECT_EQ(read.triangles, original.triangles);
}

TEST(ThreeMfRoundTrip, ArbitraryPositionsComeBackWithinLib3mfPrecision) {
    // lib3mf 1.8.1 prints coordinates with 6 decimals through its own float
    // formatting; the documented bound is 1e-6 mm + 2 float32 ulps.
    const auto dir = scratchDir();
    const std::string path = (dir / "random.3mf").string();
    Mesh original;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coordinate(-300.0, 300.0);
    for (int i = 0; i < 3000; ++i) original.positions.push_back({coordinate(rng), coordinate(rng), coordinate(rng)});
    for (uint32_t i = 0; i < 3000; i += 3) original.triangles.push_back({i, i + 1, i + 2});
    write3mf(original, path);
    const Mesh read = read3mf(path);
    ASSERT_EQ(read.vertexCount(), original.vertexCount());
    EXPECT_EQ(read.triangles, original.triangles);
    double worst = 0;
    for (size_t i = 0; i < original.positions.size(); ++i) {
        const double a[3] = {original.positions[i].x, original.positions[i].y, original.positions[i].z};
        const double b[3] = {read.positions[i].x, read.positions[i].y, read.positions[i].z};
        for (int k = 0; k < 3; ++k) {
            const float f = float(a[k]);
            const double ulp = std::nextafter(std::fabs(f), INFINITY) - std::fabs(f);
            const double error = std::fabs(b[k] - f);
            EXPECT_LE(error, 1e-6 + 2 * ulp) << a[k] << " read back as " << b[k];
            worst = std::max(worst, error);
        }
    }
    RecordProperty("worst_error_mm", std::to_string(worst));
}

TEST(ThreeMfWriter, TriangleRepeatingAVertexIsRefusedBeforeWriting) {
    const auto dir = scratchDir();
    Mesh m = test::tetrahedron();
    m.triangles.push_back({2, 2, 3});
    try {
        write3mf(m, (dir / "deg.3mf").string());
        FAIL();
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("triangle 4 uses vertex 2 twice"));
    }
    EXPECT_TRUE(test::listFiles(dir).empty());
}

// Tetrahedron (mesh_io_test_support.h) as 3MF XML with the given model unit,
// placed by a components object and a build item.
std::string tetraModelXml(const std::string& unit, const std::string& component_transform,
                          const std::string& item_transform) {
    return R"(<?xml version="1.0" encoding="UTF-8"?>
<model unit=")" + unit + R"(" xml:lang="en-US" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">
 <resources>
  <object id="1" type="model"><mesh>
   <vertices><vertex x="0" y="0" z="0"/><vertex x="4" y="0" z="0"/><vertex x="0" y="3" z="0"/><vertex x="0" y="0" z="5"/></vertices>
   <triangles><triangle v1="0" v2="2" v3="1"/><triangle v1="0" v2="1" v3="3"/><triangle v1="0" v2="3" v3="2"/><triangle v1="1" v2="2" v3="3"/></triangles>
  </mesh></object>
  <object id="2" type="model"><components><component objectid="1" transform=")" +
           component_transform + R"("/></components></object>
 </resources>
 <build><item objectid="2" transform=")" + item_transform + R"("/></build>
</model>)";
}

TEST(ThreeMfReader, UnitsComponentsAndTransformsAreApplied) {
    // Component: x scaled by 2, then z + 1. Item: x + 10. Unit: inch.
    // Vertex (4,0,0) -> (8,0,1) -> (18,0,1) inch = (457.2, 0, 25.4) mm.
    const std::string package =
        test::threeMfPackage(tetraModelXml("inch", "2 0 0 0 1 0 0 0 1 0 0 1", "1 0 0 0 1 0 0 0 1 10 0 0"));
    MeshReadReport report;
    const Mesh m = parse3mf(package, "inch.3mf", &report);
    ASSERT_EQ(m.vertexCount(), 4u);
    EXPECT_DOUBLE_EQ(m.positions[1].x, 18 * 25.4);
    EXPECT_DOUBLE_EQ(m.positions[1].y, 0.0);
    EXPECT_DOUBLE_EQ(m.positions[1].z, 25.4);
    EXPECT_DOUBLE_EQ(m.positions[3].z, 6 * 25.4);
    EXPECT_NEAR(signedVolume(m), 2 * 10 * std::pow(25.4, 3), 1e-6 * std::pow(25.4, 3));
    bool noted_unit = false;
    for (const auto& n : report.notes) noted_unit |= n.find("inch") != std::string::npos;
    EXPECT_TRUE(noted_unit);
}

TEST(ThreeMfReader, TransformMatrixIsReadInThe3mfRowVectorConvention) {
    // 3MF: [x y z 1] * M with M = (m00 m01 m02 / m10 m11 m12 / m20 m21 m22 /
    // m30 m31 m32). "0 1 0 -1 0 0 0 0 1 0 0 0" turns 90 degrees about z:
    // x' = -y, y' = x. Vertex (0,3,0) -> (-3,0,0); (4,0,0) -> (0,4,0).
    const std::string package = test::threeMfPackage(
        tetraModelXml("millimeter", "1 0 0 0 1 0 0 0 1 0 0 0", "0 1 0 -1 0 0 0 0 1 0 0 0"));
    const Mesh m = parse3mf(package, "rot.3mf");
    EXPECT_EQ(m.positions[2], (Vec3{-3, 0, 0}));
    EXPECT_EQ(m.positions[1], (Vec3{0, 4, 0}));
}

TEST(ThreeMfReader, GarbageIsAnInputErrorWithLib3mfsReason) {
    try {
        parse3mf("PK\x03\x04 this is not a zip file", "junk.3mf");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.path(), "junk.3mf");
        EXPECT_THAT(e.what(), HasSubstr("not a readable 3MF package"));
        EXPECT_THAT(e.what(), HasSubstr("lib3mf error"));
    }
    EXPECT_THROW(parse3mf("", "empty.3mf"), InputError);
}

TEST(ThreeMfReader, IndexOutOfRangeInTheXmlIsAnInputError) {
    std::string xml = tetraModelXml("millimeter", "1 0 0 0 1 0 0 0 1 0 0 0", "1 0 0 0 1 0 0 0 1 0 0 0");
    xml.replace(xml.find(R"(v3="3")"), 6, R"(v3="7")");
    EXPECT_THROW(parse3mf(test::threeMfPackage(xml), "range.3mf"), InputError);
}

/// What lib3mf itself sees of a package: its build items, and per build
/// item the object's kind, its components' objects and their triangles and
/// default base material (group, index, display colour).
struct Lib3mfView {
    size_t build_items = 0;
    bool item_is_components = false;
    DWORD item_triangles = 0;  ///< a mesh object's own
    struct Component {
        std::string name;
        DWORD triangles = 0;
        DWORD group = 0, index = 0;
        BYTE red = 0, green = 0, blue = 0, alpha = 0;
    };
    std::vector<Component> components;
};

Lib3mfView viewOf(const std::string& path) {
    Lib3mfView v;
    Lib3mfModel lib(path);
    NMR::PLib3MFModelBuildItemIterator* items = nullptr;
    EXPECT_EQ(NMR::lib3mf_model_getbuilditems(lib.model, &items), LIB3MF_OK);
    BOOL has = false;
    while (NMR::lib3mf_builditemiterator_movenext(items, &has) == LIB3MF_OK && has) {
        ++v.build_items;
        NMR::PLib3MFModelBuildItem* item = nullptr;
        NMR::lib3mf_builditemiterator_getcurrent(items, &item);
        NMR::PLib3MFModelObjectResource* object = nullptr;
        NMR::lib3mf_builditem_getobjectresource(item, &object);
        BOOL components = false;
        NMR::lib3mf_object_iscomponentsobject(object, &components);
        v.item_is_components = components;
        if (!components) NMR::lib3mf_meshobject_gettrianglecount(object, &v.item_triangles);
        DWORD count = 0;
        if (components) NMR::lib3mf_componentsobject_getcomponentcount(object, &count);
        for (DWORD k = 0; k < count; ++k) {
            NMR::PLib3MFModelComponent* component = nullptr;
            NMR::lib3mf_componentsobject_getcomponent(object, k, &component);
            NMR::PLib3MFModelObjectResource* part = nullptr;
            NMR::lib3mf_component_getobjectresource(component, &part);
            Lib3mfView::Component c;
            char name[256] = {};
            ULONG needed = 0;
            NMR::lib3mf_object_getnameutf8(part, name, sizeof name, &needed);
            c.name = name;
            NMR::lib3mf_meshobject_gettrianglecount(part, &c.triangles);
            NMR::PLib3MFDefaultPropertyHandler* property = nullptr;
            if (NMR::lib3mf_object_createdefaultpropertyhandler(part, &property) == LIB3MF_OK) {
                NMR::lib3mf_defaultpropertyhandler_getbasematerial(property, &c.group, &c.index);
                NMR::lib3mf_release(property);
                NMR::PLib3MFModelBaseMaterial* group = nullptr;
                if (NMR::lib3mf_model_getbasematerialbyid(lib.model, c.group, &group) == LIB3MF_OK) {
                    NMR::lib3mf_basematerial_getdisplaycolor(group, c.index, &c.red, &c.green, &c.blue, &c.alpha);
                    NMR::lib3mf_release(group);
                }
            }
            v.components.push_back(c);
            NMR::lib3mf_release(part);
            NMR::lib3mf_release(component);
        }
        NMR::lib3mf_release(object);
        NMR::lib3mf_release(item);
    }
    NMR::lib3mf_release(items);
    return v;
}

void expectPartsReadBack(const std::string& path, const std::vector<MeshPart>& parts) {
    MeshReadReport report;
    const std::vector<MeshPart> back = read3mfParts(path, &report);
    ASSERT_EQ(back.size(), parts.size());
    for (size_t k = 0; k < parts.size(); ++k) {
        EXPECT_EQ(back[k].name, parts[k].name);
        // The same triangles in the same order at the same corners (whole mm: exact in float32).
        const Mesh &a = back[k].mesh, &b = parts[k].mesh;
        EXPECT_EQ(a.positions.size(), b.positions.size());
        ASSERT_EQ(a.triangles.size(), b.triangles.size());
        for (size_t t = 0; t < a.triangles.size(); ++t)
            for (size_t c = 0; c < 3; ++c) EXPECT_EQ(a.positions[a.triangles[t][c]], b.positions[b.triangles[t][c]]);
    }
    EXPECT_EQ(report.input_triangles, 24u);
    // readMeshParts dispatches on the extension; readMesh still gives everything as one mesh.
    EXPECT_EQ(readMeshParts(path).size(), parts.size());
    // The block's corner (0,0,5) is also the base's corner: one vertex when merged as one mesh.
    EXPECT_EQ(readMesh(path).positions.size(), 15u);
}

// Two boxes that touch (the block stands on the base's top) as parts, the
// portable way: to lib3mf itself one build item, a components object whose
// two components are mesh objects named as the parts, each with its own
// base material, opaque and of a colour of its own; read back by tsf as two
// parts named as written, each with its own vertices (the corner both boxes
// have stays a vertex of each).
TEST(ThreeMfParts, PortableLayoutIsComponentsOfCoreObjectsInColours) {
    const auto dir = scratchDir();
    const std::string path = (dir / "parts.3mf").string();
    const std::vector<MeshPart> parts{{"pillars", test::box({0, 0, 0}, {20, 10, 5})},
                                      {"marks", test::box({0, 0, 5}, {4, 4, 6})}};
    MeshWriteOptions opts;
    opts.title = "two parts";
    write3mfParts(parts, path, opts);
    const Lib3mfView v = viewOf(path);
    EXPECT_EQ(v.build_items, 1u);
    EXPECT_TRUE(v.item_is_components);
    ASSERT_EQ(v.components.size(), 2u);
    for (size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(v.components[k].name, parts[k].name);
        EXPECT_EQ(v.components[k].triangles, 12u);
        EXPECT_EQ(v.components[k].index, k);
        EXPECT_EQ(v.components[k].alpha, 0xFF) << "opaque";
        const auto rgb = partDisplayColour(parts, k);
        EXPECT_EQ((std::array<uint8_t, 3>{v.components[k].red, v.components[k].green, v.components[k].blue}), rgb);
    }
    EXPECT_EQ(v.components[0].group, v.components[1].group);
    EXPECT_NE(partDisplayColour(parts, 0), partDisplayColour(parts, 1));
    expectPartsReadBack(path, parts);
    // Any other format is one part named "model".
    writeMesh(parts[0].mesh, (dir / "one.stl").string());
    const std::vector<MeshPart> stl = readMeshParts((dir / "one.stl").string());
    ASSERT_EQ(stl.size(), 1u);
    EXPECT_EQ(stl[0].name, "model");
}

// The PrusaSlicer layout: to lib3mf one mesh object holding both boxes'
// triangles (PrusaSlicer's config names the volumes), read back as the parts.
TEST(ThreeMfParts, PrusaSlicerLayoutIsOneObjectOfNamedVolumes) {
    const auto dir = scratchDir();
    const std::string path = (dir / "prusa.3mf").string();
    const std::vector<MeshPart> parts{{"pillars", test::box({0, 0, 0}, {20, 10, 5})},
                                      {"marks", test::box({0, 0, 5}, {4, 4, 6})}};
    MeshWriteOptions opts;
    opts.title = "two parts";
    opts.parts_layout = MeshWriteOptions::PartsLayout::PrusaSlicer;
    write3mfParts(parts, path, opts);
    const Lib3mfView v = viewOf(path);
    EXPECT_EQ(v.build_items, 1u);
    EXPECT_FALSE(v.item_is_components);
    EXPECT_EQ(v.item_triangles, 24u);
    expectPartsReadBack(path, parts);
}

// Colours: tsf's parts by name, any other from a palette, never two alike.
TEST(ThreeMfParts, EveryPartHasAColourOfItsOwn) {
    std::vector<MeshPart> parts;
    for (const char* n : {"pillars", "marks", "legend", "scale", "extra", "pillars", "more"}) parts.push_back({n, {}});
    std::vector<std::array<uint8_t, 3>> seen;
    for (size_t k = 0; k < parts.size(); ++k) {
        const auto rgb = partDisplayColour(parts, k);
        EXPECT_EQ(std::count(seen.begin(), seen.end(), rgb), 0) << k;
        seen.push_back(rgb);
    }
    EXPECT_EQ(seen[2], (std::array<uint8_t, 3>{0x1F, 0x1F, 0x1F}));  // the braille dots near black
}

TEST(ThreeMfParts, NoPartsIsRefused) {
    const auto dir = scratchDir();
    EXPECT_THROW(write3mfParts({}, (dir / "none.3mf").string()), InputError);
    EXPECT_FALSE(std::filesystem::exists(dir / "none.3mf"));
}

// A package of one mesh object (id 1) holding two boxes' 24 triangles, with
// PrusaSlicer's volume config beside it (reached through a relationship, as
// write3mfParts writes it).
std::string twoBoxPackage(const std::string& config) {
    const Mesh m = test::append(test::box({0, 0, 0}, {20, 10, 5}), test::box({0, 0, 5}, {4, 4, 6}));
    std::string xml = R"(<?xml version="1.0" encoding="UTF-8"?><model unit="millimeter" )"
                      R"(xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"><resources>)"
                      R"(<object id="1" type="model"><mesh><vertices>)";
    for (const Vec3& p : m.positions)
        xml += "<vertex x=\"" + std::to_string(p.x) + "\" y=\"" + std::to_string(p.y) + "\" z=\"" + std::to_string(p.z) + "\"/>";
    xml += "</vertices><triangles>";
    for (const auto& t : m.triangles)
        xml += "<triangle v1=\"" + std::to_string(t[0]) + "\" v2=\"" + std::to_string(t[1]) + "\" v3=\"" +
               std::to_string(t[2]) + "\"/>";
    xml += R"(</triangles></mesh></object></resources><build><item objectid="1"/></build></model>)";
    const std::string content_types =
        R"(<?xml version="1.0" encoding="UTF-8"?>)"
        R"(<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">)"
        R"(<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>)"
        R"(<Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>)";
    const std::string rels =
        R"(<?xml version="1.0" encoding="UTF-8"?>)"
        R"(<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">)"
        R"(<Relationship Target="/3D/3dmodel.model" Id="rel0" )"
        R"(Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>)";
    const std::string model_rels =
        R"(<?xml version="1.0" encoding="UTF-8"?>)"
        R"(<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">)"
        R"(<Relationship Target="/Metadata/Slic3r_PE_model.config" Id="rel1" Type="urn:tsf:3mf:slicer-model-config"/>)"
        R"(</Relationships>)";
    return test::storedZip({{"[Content_Types].xml", content_types},
                            {"_rels/.rels", rels},
                            {"3D/3dmodel.model", xml},
                            {"3D/_rels/3dmodel.model.rels", model_rels},
                            {"Metadata/Slic3r_PE_model.config", config}});
}

std::string volumesConfig(const std::string& volumes) {
    return R"(<?xml version="1.0" encoding="UTF-8"?><config><object id="1" instances_count="1">)" + volumes +
           "</object></config>";
}

TEST(ThreeMfParts, VolumesNamedInTheSlicerConfigSplitTheObjectAndBadRangesKeepItWhole) {
    const std::string two = volumesConfig(
        R"(<volume firstid="0" lastid="11"><metadata type="volume" key="name" value="base &amp; all"/></volume>)"
        R"(<volume firstid="12" lastid="23"><metadata type="volume" key="name" value="block"/></volume>)");
    const std::vector<MeshPart> parts = parse3mfParts(twoBoxPackage(two), "two.3mf");
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_EQ(parts[0].name, "base & all");
    EXPECT_EQ(parts[1].name, "block");
    EXPECT_EQ(parts[0].mesh.positions.size(), 8u);  // the shared corner is a vertex of each
    EXPECT_EQ(parts[1].mesh.positions.size(), 8u);
    EXPECT_EQ(parts[1].mesh.triangles.size(), 12u);

    // Ranges past the end, overlapping, or leaving triangles out: one part, and a note says why.
    for (const char* bad : {R"(<volume firstid="0" lastid="11"/><volume firstid="12" lastid="30"/>)",
                                   R"(<volume firstid="0" lastid="12"/><volume firstid="12" lastid="23"/>)",
                                   R"(<volume firstid="0" lastid="11"/>)"}) {
        MeshReadReport report;
        const std::vector<MeshPart> whole = parse3mfParts(twoBoxPackage(volumesConfig(bad)), "bad.3mf", &report);
        ASSERT_EQ(whole.size(), 1u) << bad;
        EXPECT_EQ(whole[0].mesh.triangles.size(), 24u);
        bool noted = false;
        for (const std::string& n : report.notes) noted = noted || n.find("read as one part") != std::string::npos;
        EXPECT_TRUE(noted) << bad;
    }
}

}  // namespace
}  // namespace tsf
