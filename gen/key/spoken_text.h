// Text tsf writes for people (the summary, the key's last section) made
// fit for a screen reader: "61 x 87 px -> 34 x 57 hexagons" is read aloud
// as "61 x 87 px dash greater 34 x 57 hexagons".
#pragma once

#include <string>

namespace tsf {

/// "A x B" between two numbers becomes "A by B" (so does "x" between a
/// number and "mm", "px", ...: only an x with a digit before it and a digit
/// after it is a dimension), " -> " becomes " to ", and "mm^3" and "mm^2"
/// become "cubic mm" and "square mm" words. Everything else is kept.
std::string spokenText(const std::string& text);

/// Breaks a line longer than `width` characters after its clauses ("; "),
/// and a clause longer than a line after its items (", "), continuation
/// lines indented by `indent` spaces: a screen reader moves a line at a
/// time. Never inside an item, so a phrase (a path, a message a script
/// looks for) stays on one line, which may then be longer than `width`.
/// Lines already short are kept. Keeps the final newline.
std::string shortLines(const std::string& text, size_t width, size_t indent);

}  // namespace tsf
