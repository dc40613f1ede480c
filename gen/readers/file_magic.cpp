#include "gen/readers/file_magic.h"

namespace tsf {
namespace {

bool startsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

}  // namespace

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
