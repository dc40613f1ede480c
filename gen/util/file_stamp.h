// FileStamp: a file's size and a 64-bit hash of its bytes, to tell two
// versions of a file apart (the scene sidecar records its model's stamp, so
// `tsf verify --scene` refuses a sidecar from another run of tsf gen).
//
// The hash is FNV-1a 64 (offset basis 0xcbf29ce484222325, prime
// 0x100000001b3) over every byte: quick and simple, meant to catch an
// accident, not an adversary. The file is read in 1 MiB pieces, so any size
// needs constant memory.
#pragma once

#include <cstdint>
#include <string>

namespace tsf {

struct FileStamp {
    int64_t bytes = 0;
    uint64_t fnv1a64 = 0;
    bool operator==(const FileStamp&) const = default;
};

/// FNV-1a 64 of `size` bytes continuing from `hash` (start with kFnv1a64Basis).
inline constexpr uint64_t kFnv1a64Basis = 0xcbf29ce484222325ull;
uint64_t fnv1a64(const void* data, size_t size, uint64_t hash = kFnv1a64Basis);

/// The stamp of the file at path. Throws tsf::InputError naming path when it
/// cannot be opened or read.
FileStamp stampFile(const std::string& path);

/// The hash as 16 lower-case hex digits, and back (false for anything else).
std::string toHex(uint64_t hash);
bool parseHex64(const std::string& text, uint64_t& hash);

}  // namespace tsf
