// FileStamp: a file's size and a 64-bit hash of its bytes, to tell two
// versions of a file apart (the scene sidecar records its model's stamp, so
// `tsf verify --scene` refuses a sidecar from another run of tsf gen).
//
// The hash is XXH3-64 (xxHash, seed 0) over every byte: it runs at memory
// speed, so stamping a model of hundreds of megabytes costs about what
// reading it back from the page cache does. Sidecars written before it
// record FNV-1a 64 (offset basis 0xcbf29ce484222325, prime 0x100000001b3),
// a byte at a time and about 15 times slower; a stamp says which it holds,
// and a file is stamped again the same way to compare. Either is meant to
// catch an accident, not an adversary. The file is read in 1 MiB pieces, so
// any size needs constant memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace tsf {

enum class StampHash : uint8_t {
    Xxh3_64,  ///< XXH3 64-bit, seed 0 (what tsf writes)
    Fnv1a64,  ///< FNV-1a 64 (sidecars written before XXH3)
};

struct FileStamp {
    int64_t bytes = 0;
    uint64_t hash = 0;
    StampHash algorithm = StampHash::Xxh3_64;
    bool operator==(const FileStamp&) const = default;
};

/// The name a sidecar records the hash under: "xxh3_64" or "fnv1a64".
const char* stampHashName(StampHash algorithm);

/// FNV-1a 64 of `size` bytes continuing from `hash` (start with kFnv1a64Basis).
inline constexpr uint64_t kFnv1a64Basis = 0xcbf29ce484222325ull;
uint64_t fnv1a64(const void* data, size_t size, uint64_t hash = kFnv1a64Basis);

/// XXH3 64 of `size` bytes with `seed` (0: the hash stamps record).
uint64_t xxh3_64(const void* data, size_t size, uint64_t seed = 0);

/// The XXH3 stamp of bytes given piece by piece: the stamp stampFile gives
/// a file holding them, taken while the file is written instead of reading
/// it back.
class StampHasher {
public:
    StampHasher();
    ~StampHasher();
    StampHasher(const StampHasher&) = delete;
    StampHasher& operator=(const StampHasher&) = delete;
    void update(const void* data, size_t size);
    FileStamp stamp() const;

private:
    struct State;
    std::unique_ptr<State> state_;
    int64_t bytes_ = 0;
};

/// The stamp of the file at path, hashed with `algorithm`. Throws
/// tsf::InputError naming path when it cannot be opened or read.
FileStamp stampFile(const std::string& path, StampHash algorithm = StampHash::Xxh3_64);

/// The hash as 16 lower-case hex digits, and back (false for anything else).
std::string toHex(uint64_t hash);
bool parseHex64(const std::string& text, uint64_t& hash);

}  // namespace tsf
