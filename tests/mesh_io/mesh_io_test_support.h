// Shared fixtures for the mesh_io tests: hand-drawn meshes, a per-test
// scratch folder, file helpers and a minimal stored-ZIP builder for writing
// 3MF packages by hand.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "gen/mesh.h"

namespace tsf::test {

// Cube of side s at origin o, CCW seen from outside.
//
//        7-------6
//       /|      /|          z
//      4-------5 |          |  y
//      | 3-----|-2          | /
//      |/      |/           |/
//      0-------1            +---- x
//
// 0=(0,0,0) 1=(s,0,0) 2=(s,s,0) 3=(0,s,0), 4..7 the same at z = s.
inline Mesh cube(double s = 1.0, Vec3 o = {}) {
    Mesh m;
    for (int i = 0; i < 8; ++i) {
        const double x = (i == 1 || i == 2 || i == 5 || i == 6) ? s : 0.0;
        const double y = (i == 2 || i == 3 || i == 6 || i == 7) ? s : 0.0;
        const double z = i >= 4 ? s : 0.0;
        m.positions.push_back({o.x + x, o.y + y, o.z + z});
    }
    m.triangles = {{0, 3, 2}, {0, 2, 1},   // bottom, -z
                   {4, 5, 6}, {4, 6, 7},   // top, +z
                   {0, 1, 5}, {0, 5, 4},   // front, -y
                   {3, 7, 6}, {3, 6, 2},   // back, +y
                   {0, 4, 7}, {0, 7, 3},   // left, -x
                   {1, 2, 6}, {1, 6, 5}};  // right, +x
    return m;
}

// Right-angled tetrahedron, CCW seen from outside, volume 4*3*5/6 = 10.
//
//            3 (0,0,5)
//           /|\
//          / | \
//         /  0  \          0 = (0,0,0)
//        / /   \ \         1 = (4,0,0)
//        1 ------ 2        2 = (0,3,0)
//
// Faces: {0,2,1} base (normal -z), {0,1,3} (normal -y), {0,3,2} (normal -x),
// {1,2,3} slanted (normal (15,20,12)/sqrt(769)).
inline Mesh tetrahedron() {
    Mesh m;
    m.positions = {{0, 0, 0}, {4, 0, 0}, {0, 3, 0}, {0, 0, 5}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

// A scratch folder of its own for the running test, emptied first.
inline std::filesystem::path scratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir =
        std::filesystem::path(TSF_TEST_SCRATCH) / (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Names of the files in dir (to check no temporary file is left behind).
inline std::vector<std::string> listFiles(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    return names;
}

// CRC-32 (IEEE 802.3, as ZIP uses), bit by bit: slow and obviously right.
inline uint32_t crc32(const std::string& data) {
    uint32_t crc = 0xFFFFFFFFu;
    for (unsigned char byte : data) {
        crc ^= byte;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

// A ZIP archive with the entries stored uncompressed (method 0).
inline std::string storedZip(const std::vector<std::pair<std::string, std::string>>& entries) {
    auto u16 = [](std::string& s, uint32_t v) {
        s += static_cast<char>(v & 0xFF);
        s += static_cast<char>((v >> 8) & 0xFF);
    };
    auto u32 = [&](std::string& s, uint32_t v) {
        u16(s, v & 0xFFFF);
        u16(s, v >> 16);
    };
    std::string zip, central;
    for (const auto& [name, data] : entries) {
        const auto offset = static_cast<uint32_t>(zip.size());
        const uint32_t crc = crc32(data);
        const auto size = static_cast<uint32_t>(data.size());
        u32(zip, 0x04034b50);  // local file header
        u16(zip, 20); u16(zip, 0); u16(zip, 0); u16(zip, 0); u16(zip, 0x21);  // version, flags, method, time, date
        u32(zip, crc); u32(zip, size); u32(zip, size);
        u16(zip, static_cast<uint32_t>(name.size())); u16(zip, 0);
        zip += name;
        zip += data;
        u32(central, 0x02014b50);  // central directory header
        u16(central, 20); u16(central, 20); u16(central, 0); u16(central, 0); u16(central, 0); u16(central, 0x21);
        u32(central, crc); u32(central, size); u32(central, size);
        u16(central, static_cast<uint32_t>(name.size())); u16(central, 0); u16(central, 0);
        u16(central, 0); u16(central, 0); u32(central, 0); u32(central, offset);
        central += name;
    }
    const auto central_offset = static_cast<uint32_t>(zip.size());
    zip += central;
    u32(zip, 0x06054b50);  // end of central directory
    u16(zip, 0); u16(zip, 0);
    u16(zip, static_cast<uint32_t>(entries.size())); u16(zip, static_cast<uint32_t>(entries.size()));
    u32(zip, static_cast<uint32_t>(central.size())); u32(zip, central_offset);
    u16(zip, 0);
    return zip;
}

// A 3MF package around the given 3D/3dmodel.model XML.
inline std::string threeMfPackage(const std::string& model_xml) {
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
    return storedZip({{"[Content_Types].xml", content_types}, {"_rels/.rels", rels}, {"3D/3dmodel.model", model_xml}});
}

}  // namespace tsf::test
