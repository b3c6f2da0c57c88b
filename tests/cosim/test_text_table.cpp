// The text-table kit of the CSV readers: trimming, splitting a line into fields, whole-field
// numbers and the data lines of a table with comments.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "cosim/io/TextTable.hpp"

using namespace flexehd::cosim;
using Fields = std::vector<std::string_view>;

TEST(TextTable, TrimsBlanksAndCarriageReturnsAtBothEnds) {
    EXPECT_EQ(trim("  a b\t\r\n"), "a b");
    EXPECT_EQ(trim("\r\t x"), "x");
    EXPECT_EQ(trim(" \t\r\n"), "");
    EXPECT_EQ(trim(""), "");
}

TEST(TextTable, SplitsOnCommasKeepingEmptyFields) {
    EXPECT_EQ(split(" a , b,c \r"), (Fields{"a", "b", "c"}));
    EXPECT_EQ(split("a,"), (Fields{"a", ""}));
    EXPECT_EQ(split(",,"), (Fields{"", "", ""}));
    EXPECT_EQ(split(""), (Fields{""}));
    EXPECT_EQ(split("1;2", ';'), (Fields{"1", "2"}));
}

TEST(TextTable, ChoosesCommaThenSemicolonThenWhiteSpace) {
    EXPECT_EQ(splitFields("1; 2, 3"), (Fields{"1; 2", "3"}));
    EXPECT_EQ(splitFields("1 ;2"), (Fields{"1", "2"}));
    EXPECT_EQ(splitFields("  1 \t 2e5  "), (Fields{"1", "2e5"}));
    EXPECT_EQ(splitFields(""), Fields{});
}

TEST(TextTable, ReadsAWholeFieldAsAFiniteNumber) {
    double v = 0.0;
    EXPECT_TRUE(parseNumber("+1e-3", v));
    EXPECT_DOUBLE_EQ(v, 1e-3);
    EXPECT_TRUE(parseNumber(" -2.5\r", v));
    EXPECT_DOUBLE_EQ(v, -2.5);
    for (const char* bad : {"1e", "", " ", "+", "++1", "1 2", "1,5", "abc", "inf", "nan", "1e999", "0x10"})
        EXPECT_FALSE(parseNumber(bad, v)) << "'" << bad << "'";
}

TEST(TextTable, ReadsAWholeFieldAsAWholeNumberThatFits) {
    int i = 0;
    EXPECT_TRUE(parseWhole("+42", i));
    EXPECT_EQ(i, 42);
    EXPECT_TRUE(parseWhole(" -7 ", i));
    EXPECT_EQ(i, -7);
    for (const char* bad : {"1.5", "", "1e3", "99999999999", "7 1"}) EXPECT_FALSE(parseWhole(bad, i)) << "'" << bad << "'";
    long long big = 0;
    EXPECT_TRUE(parseWhole("99999999999", big));
    EXPECT_EQ(big, 99999999999LL);
}

TEST(TextTable, SkipsBlankAndCommentLinesAndNumbersTheRest) {
    std::istringstream in("\xEF\xBB\xBFx,y\r\n\n  # note\r\n 1, 2 \r\n   \n3,4");
    DataLines lines(in, /*skipByteOrderMark=*/true);
    ASSERT_TRUE(lines.next());
    EXPECT_EQ(lines.text(), "x,y");
    EXPECT_EQ(lines.number(), 1);
    ASSERT_TRUE(lines.next());
    EXPECT_EQ(lines.text(), "1, 2");
    EXPECT_EQ(lines.number(), 4);
    EXPECT_TRUE(lines.terminated());
    ASSERT_TRUE(lines.next());
    EXPECT_EQ(lines.text(), "3,4");
    EXPECT_EQ(lines.number(), 6);
    EXPECT_FALSE(lines.terminated());
    EXPECT_FALSE(lines.next());
}

TEST(TextTable, KeepsAByteOrderMarkUnlessAskedToSkipIt) {
    std::istringstream in("\xEF\xBB\xBFx");
    DataLines lines(in);
    ASSERT_TRUE(lines.next());
    EXPECT_EQ(lines.text(), "\xEF\xBB\xBFx");
}
