#include "gen/util/file_stamp.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
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

FileStamp stampFile(const std::string& path, StampHash algorithm) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw InputError(path, 0, 0, std::string("cannot open: ") + std::strerror(errno));
    FileStamp s;
    s.algorithm = algorithm;
    s.hash = kFnv1a64Basis;
    std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> xxh(XXH3_createState(), &XXH3_freeState);
    if (!xxh || XXH3_64bits_reset(xxh.get()) != XXH_OK) {
        std::fclose(f);
        throw InputError(path, 0, 0, "cannot start hashing the file");
    }
    std::vector<unsigned char> buf(size_t(1) << 20);
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), f)) > 0) {
        if (algorithm == StampHash::Fnv1a64) s.hash = fnv1a64(buf.data(), n, s.hash);
        else XXH3_64bits_update(xxh.get(), buf.data(), n);
        s.bytes += int64_t(n);
    }
    const bool failed = std::ferror(f) != 0;
    std::fclose(f);
    if (failed) throw InputError(path, 0, 0, "cannot read the file");
    if (algorithm == StampHash::Xxh3_64) s.hash = XXH3_64bits_digest(xxh.get());
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
