// The one line/column convention of every text reader (gen/util/text_scanner.h):
// 1-based lines and columns, CRLF, LF and a lone CR each end a line, columns
// count characters, comments run to the end of the line.
#include "gen/util/text_scanner.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gen/util/error.h"

namespace tsf {
namespace {

struct Token {
    std::string text;
    int line, column;
    friend bool operator==(const Token&, const Token&) = default;
};

std::ostream& operator<<(std::ostream& os, const Token& t) {
    return os << "'" << t.text << "'@" << t.line << ":" << t.column;
}

std::vector<Token> tokens(std::string_view text, char comment = '\0') {
    TextScanner s(text, "t", comment);
    std::vector<Token> out;
    std::string_view token;
    while (s.next(token)) out.push_back({std::string(token), s.line(), s.column()});
    return out;
}

TEST(TextScanner, EveryLineEndCountsOnce) {
    const std::vector<Token> want = {{"a", 1, 1}, {"bb", 2, 2}, {"c", 3, 1}, {"d", 5, 3}};
    EXPECT_EQ(tokens("a\n bb\nc\n\n  d"), want);
    EXPECT_EQ(tokens("a\r\n bb\r\nc\r\n\r\n  d"), want);
    EXPECT_EQ(tokens("a\r bb\rc\r\r  d"), want);
    EXPECT_EQ(tokens("a\r\n bb\rc\n\r\n  d"), want);
}

TEST(TextScanner, ColumnsCountCharactersNotBytes) {
    // "é" is two bytes, "€" three: the token after them is still in column 4.
    EXPECT_EQ(tokens("é € x"), (std::vector<Token>{{"é", 1, 1}, {"€", 1, 3}, {"x", 1, 5}}));
    EXPECT_EQ(tokens("\tv\f\vw"), (std::vector<Token>{{"v", 1, 2}, {"w", 1, 5}}));
}

TEST(TextScanner, CommentsRunToTheEndOfTheLineAndEndATokenTheyTouch) {
    EXPECT_EQ(tokens("1 # 2 3\r4#5\n# 6\n7", '#'), (std::vector<Token>{{"1", 1, 1}, {"4", 2, 1}, {"7", 4, 1}}));
    EXPECT_EQ(tokens("1 # 2", '\0'), (std::vector<Token>{{"1", 1, 1}, {"#", 1, 3}, {"2", 1, 5}}));
}

TEST(TextScanner, LineByLine) {
    TextScanner s("v 1 2\r\n\r\nf 3 # x\n", "t", '#');
    std::string_view token;
    ASSERT_TRUE(s.nextOnLine(token));
    EXPECT_EQ(token, "v");
    ASSERT_TRUE(s.nextOnLine(token));
    ASSERT_TRUE(s.nextOnLine(token));
    EXPECT_EQ(token, "2");
    EXPECT_FALSE(s.nextOnLine(token)) << "the line has no more tokens";
    ASSERT_TRUE(s.skipLine());
    EXPECT_EQ(s.line(), 2);
    EXPECT_EQ(s.column(), 0);
    EXPECT_FALSE(s.nextOnLine(token)) << "a blank line";
    ASSERT_TRUE(s.skipLine());
    ASSERT_TRUE(s.nextOnLine(token));
    EXPECT_EQ(token, "f");
    EXPECT_EQ(s.line(), 3);
    ASSERT_TRUE(s.nextOnLine(token));
    EXPECT_FALSE(s.nextOnLine(token)) << "a comment";
    ASSERT_TRUE(s.skipLine());
    EXPECT_FALSE(s.skipLine()) << "no line after the last line end";
}

TEST(TextScanner, ErrorsNameThePathAndPosition) {
    TextScanner s("ok\n  bad\n", "f.txt");
    std::string_view token;
    ASSERT_TRUE(s.next(token));
    ASSERT_TRUE(s.next(token));
    try {
        s.fail("no good");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.path(), "f.txt");
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.column(), 3);
        EXPECT_EQ(e.detail(), "no good");
    }
    EXPECT_FALSE(s.next(token));
    try {
        s.failHere("unexpected end of file");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 2) << "the last line a person sees, not the empty one after the final line end";
        EXPECT_EQ(e.column(), 0);
    }
}

TEST(TextScanner, StartsAnywhere) {
    // As the PGM reader does after the magic number "P2".
    TextScanner s("P2 12\n 7", "p.pgm", '#', 2, 1, 3);
    std::string_view token;
    ASSERT_TRUE(s.next(token));
    EXPECT_EQ(token, "12");
    EXPECT_EQ(s.column(), 4);
    EXPECT_EQ(s.offset(), 5u);
    ASSERT_TRUE(s.next(token));
    EXPECT_EQ(s.line(), 2);
    EXPECT_EQ(s.column(), 2);
}

}  // namespace
}  // namespace tsf
