// Fixtures of the mesh_io tests: a minimal stored-ZIP builder for writing 3MF
// packages by hand. Meshes, scratch folders and file helpers come from the
// shared test support (tests/support/).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/files.h"
#include "tests/support/meshes.h"

namespace tsf::test {

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
