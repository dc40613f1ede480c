// The property the Falcon frame parser must keep on ANY byte stream, shared
// by the randomised test (falcon_packet_test.cpp) and the libFuzzer entry
// point (fuzz/falcon_packet_fuzzer.cpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "haptics/falcon/falcon_packet.h"

namespace tsf::haptics::testing {

/// Pushes data into a parser in pieces (sizes from `seed`), takes every
/// frame out, and aborts if a decoded frame does not re-encode to 16 bytes
/// that occur in the input (its spare byte 14 aside), or if a frame occurring intact in the input is
/// not found when the input is fed whole, or if feeding in pieces finds
/// other frames than feeding at once. Returns the frames found.
inline size_t checkFalconStream(const uint8_t* data, size_t size, unsigned seed) {
    const std::span<const uint8_t> in(data, size);
    FalconFrameParser pieces;
    size_t at = 0, found = 0;
    FalconReport r;
    while (at < size) {
        const size_t n = std::min(size - at, size_t(1 + (seed = seed * 1103515245u + 12345u) % 40));
        pieces.push(in.subspan(at, n));
        at += n;
        while (pieces.next(r)) {
            // Byte 14 is not checked by the decoder, so it is not compared.
            const FalconPacket p = encodeFalconReport(r);
            bool seen = false;
            for (size_t i = 0; i + kFalconPacketBytes <= size && !seen; ++i) {
                seen = true;
                for (size_t k = 0; k < kFalconPacketBytes && seen; ++k) seen = k == 14 || data[i + k] == p[k];
            }
            if (!seen) std::abort();
            ++found;
        }
    }
    // Every valid frame in the input is found by a parser fed the input at once
    // unless a valid frame overlaps it (the parser takes the first one).
    FalconFrameParser whole;
    whole.push(in.first(std::min(size, FalconFrameParser::kCapacity)));
    size_t whole_found = 0;
    while (whole.next(r)) ++whole_found;
    size_t present = 0;
    for (size_t i = 0; i + kFalconPacketBytes <= std::min(size, FalconFrameParser::kCapacity); ++i) {
        FalconReport x;
        if (decodeFalconReport(std::span<const uint8_t, kFalconPacketBytes>(data + i, kFalconPacketBytes), x)) {
            ++present;
            i += kFalconPacketBytes - 1;  // frames found are consumed whole
        }
    }
    if (whole_found != present) std::abort();
    // Feeding in pieces finds exactly what feeding at once finds.
    if (size <= FalconFrameParser::kCapacity && found != whole_found) std::abort();
    return found;
}

}  // namespace tsf::haptics::testing
