// The model's stamp at the end of its keys (MODEL.key.txt, MODEL.key.brf),
// so that keys and a model from different runs of tsf gen (a run killed
// while it renamed its files) are told apart: tsf verify refuses the pair.
//
// The stamp is the model file's size and XXH3 hash (gen/util/file_stamp.h):
// it depends on the model's bytes only, never on a time, a process or a
// folder, so the same run writes the same keys. It is the key's last line,
// after everything a reader reads: "Model stamp: m.stl, 2534 bytes, XXH3
// 0123456789ABCDEF" (capitals and digits: valid Braille ASCII, so the BRF
// carries it on a last page of its own).
#pragma once

#include <string>

#include "gen/util/file_stamp.h"

namespace tsf::cli {

/// The stamp line (no line end) for the model file named `model_name`.
std::string keyStampLine(const std::string& model_name, const FileStamp& stamp);

/// Throws tsf::InputError naming the key when MODEL.key.txt or
/// MODEL.key.brf beside `model_path` carries the stamp of another version
/// of that model file. Keys without a stamp, or stamping another file
/// name, are not judged.
void checkKeysMatchModel(const std::string& model_path);

/// The keys beside a model: MODEL.key.txt and MODEL.key.brf for MODEL.stl.
std::pair<std::string, std::string> keyPathsBeside(const std::string& model_path);

}  // namespace tsf::cli
