// Checks that a command's outputs never destroy a file the user did not name
// as an output: an output that is one of the inputs, or two outputs of one
// command that are the same file ("-o s.stl --preview s.stl").
//
// Paths are compared as files, not as strings: "./a.stl", "a.stl" and
// "dir/../a.stl" are the same file, and so are two names of one file through
// a symbolic or hard link when it exists.
#pragma once

#include <string>
#include <vector>

namespace tsf {

struct NamedPath {
    std::string path;  ///< as the user wrote it
    std::string role;  ///< how the user named it: "the input", "-o", "--preview", ...
};

/// True when `a` and `b` name the same file (existing or not).
bool sameFile(const std::string& a, const std::string& b);

/// Throws tsf::InputError naming both roles when an output is the same file
/// as an input or as an earlier output. Empty paths are ignored.
void checkOutputPaths(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

}  // namespace tsf
