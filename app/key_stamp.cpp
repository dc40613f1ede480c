// The model's stamp at the end of its keys. See key_stamp.h.
#include "app/key_stamp.h"

#include <cctype>
#include <filesystem>
#include <optional>
#include <sstream>

#include "gen/util/error.h"
#include "gen/util/file_bytes.h"

namespace tsf::cli {
namespace {

constexpr const char* kPrefix = "MODEL STAMP: ";
// Keys are a few KB; a larger file of that name is not tsf's.
constexpr int64_t kMaxKeyBytes = 1 << 20;

std::string upper(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

std::string keyStampLine(const std::string& model_name, const FileStamp& stamp) {
    return "Model stamp: " + model_name + ", " + std::to_string(stamp.bytes) + " bytes, XXH3 " + upper(toHex(stamp.hash));
}

std::pair<std::string, std::string> keyPathsBeside(const std::string& model_path) {
    std::filesystem::path base(model_path);
    base.replace_extension();
    return {base.string() + ".key.txt", base.string() + ".key.brf"};
}

void checkKeysMatchModel(const std::string& model_path) {
    const std::string name = std::filesystem::path(model_path).filename().string();
    std::optional<FileStamp> now;
    const auto [text_path, brf_path] = keyPathsBeside(model_path);
    for (const std::string& key : {text_path, brf_path}) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(key, ec) || std::filesystem::file_size(key, ec) > uintmax_t(kMaxKeyBytes)) continue;
        // The last stamp line of the key, compared in capitals (the BRF has no small letters).
        const std::string text = upper(readFileBytes(key, kMaxKeyBytes));
        const size_t at = text.rfind(kPrefix);
        if (at == std::string::npos) continue;
        std::istringstream line(text.substr(at + std::char_traits<char>::length(kPrefix), text.find_first_of("\r\n", at) - at -
                                                                                          std::char_traits<char>::length(kPrefix)));
        std::string file, bytes_word, hash_name, hex;
        int64_t bytes = 0;
        std::getline(line, file, ',');
        if (file != upper(name) || !(line >> bytes >> bytes_word >> hash_name >> hex) || hash_name != "XXH3") continue;
        uint64_t hash = 0;
        for (char& c : hex) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (!parseHex64(hex, hash)) continue;
        if (!now) now = stampFile(model_path, StampHash::Xxh3_64);
        if (now->bytes == bytes && now->hash == hash) continue;
        throw InputError(key, 0, 0,
                         "is the key of another version of " + name + " (" + std::to_string(bytes) + " bytes, hash " +
                             toHex(hash) + "; " + model_path + " has " + std::to_string(now->bytes) + " bytes, hash " +
                             toHex(now->hash) +
                             "): the model and its key come from different runs of tsf gen (one may have been "
                             "interrupted); run tsf gen again");
    }
}

}  // namespace tsf::cli
