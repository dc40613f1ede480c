#include "gen/readers/netcdf_classic_size.h"

#include <limits>
#include <vector>

#include "gen/util/error.h"

namespace tsf {
namespace {

constexpr uint32_t kTagDimension = 0x0A, kTagVariable = 0x0B, kTagAttribute = 0x0C;
// A record count that says "streaming: count the records yourself".
constexpr uint64_t kStreamingRecords = 0xFFFFFFFFull;

// Bytes of one value of a netCDF type (NC_BYTE = 1 ... NC_UINT64 = 11); 0 for an unknown type.
int64_t typeBytes(uint32_t type) {
    static constexpr int64_t kBytes[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
    return type < sizeof kBytes / sizeof kBytes[0] ? kBytes[type] : 0;
}

// Big-endian fields of the header; `ok` turns false at the first read past
// the end of `bytes` (and every read after returns 0).
struct HeaderCursor {
    std::string_view bytes;
    size_t at = 0;
    bool ok = true;
    bool ran_out = false;       ///< `ok` turned false at the end of `bytes`
    bool wide_counts = false;   ///< CDF-5: counts and sizes are 8 bytes
    bool wide_offsets = false;  ///< CDF-2 and CDF-5: data offsets are 8 bytes

    uint64_t read(size_t n) {
        if (!ok || bytes.size() - at < n) {
            ran_out = ran_out || ok;
            ok = false;
            return 0;
        }
        uint64_t v = 0;
        for (size_t k = 0; k < n; ++k) v = v << 8 | static_cast<unsigned char>(bytes[at + k]);
        at += n;
        return v;
    }
    uint32_t u32() { return uint32_t(read(4)); }
    uint64_t count() { return read(wide_counts ? 8 : 4); }
    uint64_t offset() { return read(wide_offsets ? 8 : 4); }
    void skip(uint64_t n) {
        if (!ok || bytes.size() - at < n) {
            ran_out = ran_out || ok;
            ok = false;
        } else {
            at += size_t(n);
        }
    }
    // A name or a value array, padded to 4 bytes.
    void skipPadded(uint64_t n) {
        if (n > std::numeric_limits<uint64_t>::max() - 3) ok = false;
        else skip((n + 3) / 4 * 4);
    }
    std::string name() {
        const uint64_t n = count();
        const size_t start = at;
        skipPadded(n);
        return ok ? std::string(bytes.substr(start, size_t(n))) : std::string();
    }
    // A list's tag and length; false (and `ok` false) for a wrong tag.
    uint64_t list(uint32_t tag) {
        const uint32_t t = u32();
        const uint64_t n = count();
        if (t != tag && !(t == 0 && n == 0)) ok = false;
        return n;
    }
    void skipAttributes() {
        const uint64_t n = list(kTagAttribute);
        for (uint64_t k = 0; k < n && ok; ++k) {
            name();
            const int64_t size = typeBytes(u32());
            const uint64_t values = count();
            if (size == 0 || values > std::numeric_limits<uint64_t>::max() / 8) ok = false;
            else skipPadded(values * uint64_t(size));
        }
    }
};

// a * b, false on overflow past int64.
bool multiply(int64_t a, int64_t b, int64_t& out) {
    if (a != 0 && b > std::numeric_limits<int64_t>::max() / a) return false;
    out = a * b;
    return true;
}

struct Variable {
    std::string name;
    int64_t begin = 0;
    int64_t bytes = 0;  ///< the whole variable, or one record of a record variable
    bool record = false;
};

}  // namespace

bool isNetcdfClassic(std::string_view head) {
    return head.size() >= 4 && head.substr(0, 3) == "CDF" && (head[3] == '\x01' || head[3] == '\x02' || head[3] == '\x05');
}

std::optional<NetcdfClassicExtent> netcdfClassicExtent(std::string_view head) {
    if (!isNetcdfClassic(head)) return std::nullopt;
    HeaderCursor c{head, 4};
    c.wide_counts = head[3] == '\x05';
    c.wide_offsets = head[3] != '\x01';
    const auto cut = [&]() -> std::optional<NetcdfClassicExtent> {
        if (!c.ran_out) return std::nullopt;
        NetcdfClassicExtent e;
        e.header_cut = true;
        e.end_bytes = int64_t(head.size()) + 1;
        return e;
    };
    const uint64_t records = c.count();
    if (!c.ok) return cut();
    if ( records == kStreamingRecords || records > uint64_t(std::numeric_limits<int64_t>::max()))
        return std::nullopt;

    std::vector<int64_t> dims;  // lengths; 0 is the record dimension
    const uint64_t n_dims = c.list(kTagDimension);
    for (uint64_t k = 0; k < n_dims && c.ok; ++k) {
        c.name();
        const uint64_t length = c.count();
        if (length > uint64_t(std::numeric_limits<int64_t>::max())) return std::nullopt;
        dims.push_back(int64_t(length));
    }
    c.skipAttributes();

    std::vector<Variable> vars;
    const uint64_t n_vars = c.list(kTagVariable);
    for (uint64_t k = 0; k < n_vars && c.ok; ++k) {
        Variable v;
        v.name = c.name();
        const uint64_t rank = c.count();
        std::vector<int64_t> lengths;
        for (uint64_t d = 0; d < rank && c.ok; ++d) {
            const uint64_t id = c.count();
            if (!c.ok) return cut();
            if (id >= dims.size()) return std::nullopt;
            lengths.push_back(dims[size_t(id)]);
        }
        c.skipAttributes();
        const int64_t size = typeBytes(c.u32());
        c.count();  // vsize: capped at 2^32 - 1 for large variables, so computed below instead
        const uint64_t begin = c.offset();
        if (!c.ok) return cut();
        if (size == 0 || begin > uint64_t(std::numeric_limits<int64_t>::max())) return std::nullopt;
        v.begin = int64_t(begin);
        v.record = !lengths.empty() && lengths[0] == 0;
        v.bytes = size;
        for (size_t d = v.record ? 1 : 0; d < lengths.size(); ++d)
            if (!multiply(v.bytes, lengths[d], v.bytes)) return std::nullopt;
        vars.push_back(std::move(v));
    }
    if (!c.ok) return cut();

    // One record holds a record of each record variable, each padded to 4
    // bytes unless there is only one (netCDF's NC_calcsize).
    int64_t record_bytes = 0, record_vars = 0;
    for (const Variable& v : vars)
        if (v.record) ++record_vars;
    for (const Variable& v : vars)
        if (v.record) record_bytes += record_vars == 1 ? v.bytes : (v.bytes + 3) / 4 * 4;

    NetcdfClassicExtent out;
    out.end_bytes = int64_t(c.at);  // the header itself
    for (const Variable& v : vars) {
        int64_t end = v.begin;
        if (v.record) {
            if (records == 0) continue;
            int64_t before = 0;
            if (!multiply(int64_t(records) - 1, record_bytes, before)) return std::nullopt;
            end += before;
        }
        if (end > std::numeric_limits<int64_t>::max() - v.bytes) return std::nullopt;
        end += v.bytes;
        if (end > out.end_bytes) {
            out.end_bytes = end;
            out.last_variable = v.name;
        }
    }
    return out;
}

void checkNetcdfClassicComplete(std::string_view head, int64_t file_bytes, const std::string& path) {
    const std::optional<NetcdfClassicExtent> extent = netcdfClassicExtent(head);
    if (!extent || file_bytes >= extent->end_bytes) return;
    if (extent->header_cut) {
        if (int64_t(head.size()) < file_bytes) return;  // only the head was read: the netCDF library judges the rest
        throw InputError(path, 0, 0,
                         "is a truncated netCDF file: it ends inside its header, after " + std::to_string(file_bytes) +
                             " bytes (was the download or copy cut short?)");
    }
    throw InputError(path, 0, 0,
                     "is a truncated netCDF file: its header says the data" +
                         (extent->last_variable.empty() ? std::string()
                                                        : " (of variable '" + extent->last_variable + "')") +
                         " runs to byte " + std::to_string(extent->end_bytes) + ", but the file has " +
                         std::to_string(file_bytes) +
                         " bytes; the missing values would be read as zeros (was the download or copy cut short?)");
}

}  // namespace tsf
