#include "gen/util/file_stamp.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

// Header-only: the functions are compiled here, nothing to link.
#define XXH_INLINE_ALL
#include <xxhash.h>

#include "gen/util/error.h"

namespace tsf {

uint64_t fnv1a64(const void* data, size_t size, uint64_t hash) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t k = 0; k < size; ++k) {
        hash ^= p[k];
        hash *= 0x100000001b3ull;
    }
    return hash;
}

uint64_t xxh3_64(const void* data, size_t size, uint64_t seed) { return XXH3_64bits_withSeed(data, size, seed); }

const char* stampHashName(StampHash algorithm) { return algorithm == StampHash::Fnv1a64 ? "fnv1a64" : "xxh3_64"; }

struct StampHasher::State {
    XXH3_state_t xxh;
};

StampHasher::StampHasher() : state_(std::make_unique<State>()) { XXH3_64bits_reset(&state_->xxh); }
StampHasher::~StampHasher() = default;

void StampHasher::update(const void* data, size_t size) {
    XXH3_64bits_update(&state_->xxh, data, size);
    bytes_ += int64_t(size);
}

FileStamp StampHasher::stamp() const {
    FileStamp s;
    s.algorithm = StampHash::Xxh3_64;
    s.bytes = bytes_;
    s.hash = XXH3_64bits_digest(&state_->xxh);
    return s;
}

FileStamp stampFile(const std::string& path, StampHash algorithm) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw InputError(path, 0, 0, std::string("cannot open: ") + std::strerror(errno));
    StampHasher xxh;
    uint64_t fnv = kFnv1a64Basis;
    int64_t bytes = 0;
    std::vector<unsigned char> buf(size_t(1) << 20);
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), f)) > 0) {
        if (algorithm == StampHash::Fnv1a64) fnv = fnv1a64(buf.data(), n, fnv);
        else xxh.update(buf.data(), n);
        bytes += int64_t(n);
    }
    const bool failed = std::ferror(f) != 0;
    std::fclose(f);
    if (failed) throw InputError(path, 0, 0, "cannot read the file");
    if (algorithm == StampHash::Xxh3_64) return xxh.stamp();
    FileStamp s;
    s.algorithm = algorithm;
    s.bytes = bytes;
    s.hash = fnv;
    return s;
}

std::string toHex(uint64_t hash) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
    return buf;
}

bool parseHex64(const std::string& text, uint64_t& hash) {
    if (text.size() != 16) return false;
    uint64_t v = 0;
    for (char c : text) {
        int d;
        if (c >= '0' && c <= '9') d = c - '0';
        else if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
        else return false;
        v = v << 4 | uint64_t(d);
    }
    hash = v;
    return true;
}

}  // namespace tsf
