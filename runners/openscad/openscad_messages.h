// OpenSCAD's console output as structured messages.
//
// OpenSCAD prints one message per line, e.g.
//   ERROR: Assertion '(x > 0)' failed: "tsf_model: cell_mm must be ..." in file model.scad, line 12
//   WARNING: Ignoring unknown variable 'foo' in file model.scad, line 3
//   TRACE: called by 'tsf_model' in file model.scad, line 40
//   ECHO: "hello"
//   Can't open input file 'x.scad'!
// parseOpenScadOutput keeps the lines that are messages (ERROR, WARNING,
// TRACE, ECHO, DEPRECATED, and "Can't ..." failures), with the file and line
// they name, and the text of a failed assert() apart; progress and statistics
// lines are dropped.
#pragma once

#include <string>
#include <vector>

namespace tsf {

struct ScadMessage {
    enum class Kind { Error, Warning, Trace, Echo, Deprecated };
    Kind kind = Kind::Error;
    std::string text;            ///< the line without its "ERROR: " etc. prefix
    std::string file;            ///< file the message names ("" = none)
    int line = 0;                ///< 1-based line in `file` (0 = none)
    std::string assert_message;  ///< a failed assert(): the message argument ("" = not an assert)
};

std::vector<ScadMessage> parseOpenScadOutput(const std::string& output);

/// The message as OpenSCAD printed it ("ERROR: ..."), one line.
std::string formatScadMessage(const ScadMessage& message);

const char* toString(ScadMessage::Kind kind);  ///< "ERROR", "WARNING", "TRACE", "ECHO", "DEPRECATED"

}  // namespace tsf
