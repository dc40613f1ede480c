#include "gen/readers/file_magic.h"

#include "gen/util/error.h"

namespace tsf {
namespace {

bool startsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

// NUL in every other byte of the first `n` (and text in the others): UTF-16 without a byte-order mark.
bool looksLikeUtf16WithoutMark(std::string_view head) {
    constexpr size_t kPairs = 16;
    if (head.size() < 2 * kPairs) return false;
    for (const size_t nul_at : {size_t(0), size_t(1)}) {
        bool all = true;
        for (size_t k = 0; k < kPairs && all; ++k) {
            const unsigned char text = static_cast<unsigned char>(head[2 * k + 1 - nul_at]);
            all = head[2 * k + nul_at] == '\0' && text >= 0x09 && text < 0x7F;
        }
        if (all) return true;
    }
    return false;
}

}  // namespace

void refuseUtf16Text(std::string_view head, const std::string& path) {
    using namespace std::string_view_literals;
    if (!startsWith(head, "\xFF\xFE"sv) && !startsWith(head, "\xFE\xFF"sv) && !looksLikeUtf16WithoutMark(head)) return;
    throw InputError(path, 0, 0,
                     "is UTF-16 text (\"Unicode text\"); tsf reads UTF-8 or ASCII: save it as UTF-8 (a spreadsheet's "
                     "\"CSV UTF-8\"), or convert it: iconv -f UTF-16 -t UTF-8");
}

std::string binaryFileKind(std::string_view head) {
    using namespace std::string_view_literals;
    if (startsWith(head, "II*\0"sv) || startsWith(head, "MM\0*"sv) || startsWith(head, "II+\0"sv) ||
        startsWith(head, "MM\0+"sv))
        return "a TIFF image";
    if (startsWith(head, "\xFF\xD8\xFF"sv)) return "a JPEG image";
    if (startsWith(head, "\0\0\0\x0CjP  "sv) || startsWith(head, "\xFF\x4F\xFF\x51"sv)) return "a JPEG 2000 image";
    if (startsWith(head, "GIF87a"sv) || startsWith(head, "GIF89a"sv)) return "a GIF image";
    if (startsWith(head, "BM"sv) && head.find('\0') != std::string_view::npos) return "a BMP image";
    if (startsWith(head, "PK\x03\x04"sv)) return "a ZIP archive (an .xlsx or .ods spreadsheet?)";
    if (startsWith(head, "\x89HDF\r\n\x1a\n"sv)) return "an HDF5 file";
    if (startsWith(head, "CDF\x01"sv) || startsWith(head, "CDF\x02"sv) ||
        startsWith(head, "CDF\x05"sv))
        return "a netCDF file";
    if (startsWith(head, "%PDF"sv)) return "a PDF document";
    if (head.find('\0') != std::string_view::npos) return "a binary file";
    return "";
}

}  // namespace tsf
