#include <gtest/gtest.h>

#include "gen/scad/scad_variables.h"

namespace tsf {
namespace {

TEST(ScadVariables, FindsTopLevelAssignmentsOnly) {
    const std::string text =
        "/* [Size] */\n"
        "// cell = 3; in a comment\n"
        "cell = 5;  // [1:0.1:50]\n"
        "name = \"a; b = 2\";\n"
        "use <lib/tsf.scad>\n"
        "model = f(x = 1, y = [for (i = [0:2]) let(k = i) k]);\n"
        "module m(a = 1) { inner = 2; cube(a); }\n"
        "function g(q = 3) = let(w = q) w;\n"
        "if (cell == 5) { hidden = 1; }\n"
        "cell = 6;\n"
        "$fn=12;\n";
    EXPECT_EQ(scadTopLevelVariables(text), (std::vector<std::string>{"cell", "name", "model", "$fn"}));
    EXPECT_FALSE(scadHasInclude(text));
    EXPECT_TRUE(scadHasInclude("include <x.scad>\n"));
    EXPECT_FALSE(scadHasInclude("// include <x.scad>\n"));
    EXPECT_TRUE(scadTopLevelVariables("").empty());
    EXPECT_EQ(scadTopLevelVariables("a = [1, 2"), (std::vector<std::string>{"a"}));  // unfinished text does not throw
}

}  // namespace
}  // namespace tsf
