#include "hecal/io/delimited_text.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace hecal::io {
namespace {

std::vector<std::string> Lines(std::string_view text) {
  LineCursor cursor(text);
  std::vector<std::string> lines;
  std::string_view line;
  while (cursor.Next(&line)) {
    lines.emplace_back(line);
    EXPECT_EQ(cursor.line_number(), static_cast<int>(lines.size()));
  }
  return lines;
}

std::vector<std::string> Split(std::string_view line, Separator separator) {
  std::vector<Field> fields;
  std::string error;
  EXPECT_TRUE(SplitFields(line, separator, &fields, &error)) << error;
  std::vector<std::string> values;
  for (const Field& field : fields) values.push_back(FieldValue(field));
  return values;
}

using Strings = std::vector<std::string>;

TEST(LineCursorTest, SplitsLinesAndStripsCarriageReturns) {
  EXPECT_EQ(Lines("a\nb\r\n\nc"), (Strings{"a", "b", "", "c"}));
  EXPECT_EQ(Lines("a\n"), (Strings{"a"}));
  EXPECT_EQ(Lines(""), Strings{});
  EXPECT_EQ(Lines("\n"), (Strings{""}));
}

TEST(LineCursorTest, SkipsByteOrderMark) {
  EXPECT_EQ(Lines("\xEF\xBB\xBFx,y\n1,2\n"), (Strings{"x,y", "1,2"}));
}

TEST(LineClassificationTest, BlankAndComment) {
  EXPECT_TRUE(IsBlank(""));
  EXPECT_TRUE(IsBlank(" \t "));
  EXPECT_FALSE(IsBlank(" x"));
  EXPECT_TRUE(IsComment("# hello"));
  EXPECT_TRUE(IsComment("   #"));
  EXPECT_FALSE(IsComment("x # y"));
  EXPECT_EQ(CommentText("  #  euler: ZYX  "), "euler: ZYX");
}

// Every byte against the C library's tolower in the "C" locale (ASCII letters only); bytes
// outside ASCII (UTF-8 of "É") are left as they are.
TEST(LowercaseTest, LowersAsciiLettersOnly) {
  std::string every;
  for (int c = 1; c < 256; ++c) every += static_cast<char>(c);
  const std::string lower = Lowercase(every);
  ASSERT_EQ(lower.size(), every.size());
  for (size_t i = 0; i < every.size(); ++i) {
    const auto c = static_cast<unsigned char>(every[i]);
    const int expected = c < 128 ? std::tolower(c) : c;
    EXPECT_EQ(static_cast<unsigned char>(lower[i]), expected) << i;
  }
  EXPECT_EQ(Lowercase("X_MM.PNG \xc3\x89"), "x_mm.png \xc3\x89");
  EXPECT_EQ(Lowercase(""), "");
}

TEST(SplitFieldsTest, CommaSeparatedFieldsAreTrimmed) {
  EXPECT_EQ(Split("1, 2 ,\t3", Separator::kComma), (Strings{"1", "2", "3"}));
  EXPECT_EQ(Split("a,,b,", Separator::kComma), (Strings{"a", "", "b", ""}));
  EXPECT_EQ(Split("a b,c", Separator::kComma), (Strings{"a b", "c"}));
}

TEST(SplitFieldsTest, WhitespaceSeparatedFields) {
  EXPECT_EQ(Split("  1\t2   3  ", Separator::kWhitespace), (Strings{"1", "2", "3"}));
  EXPECT_EQ(Split("   ", Separator::kWhitespace), Strings{});
  EXPECT_EQ(Split("\"a b\" c", Separator::kWhitespace), (Strings{"a b", "c"}));
}

TEST(SplitFieldsTest, AnySeparatorForNumberLines) {
  EXPECT_EQ(Split(" 1, 2\t3  4 ,5,6 ", Separator::kAny), (Strings{"1", "2", "3", "4", "5", "6"}));
  EXPECT_EQ(Split("1,,2", Separator::kAny), (Strings{"1", "", "2"}));
  EXPECT_EQ(Split("1 2,", Separator::kAny), (Strings{"1", "2", ""}));
  EXPECT_EQ(Split("  ", Separator::kAny), Strings{});
}

TEST(SplitFieldsTest, QuotedFields) {
  EXPECT_EQ(Split("\"a,b\",\"say \"\"hi\"\"\", c", Separator::kComma),
            (Strings{"a,b", "say \"hi\"", "c"}));
  EXPECT_EQ(Split(" \"x\" ,y", Separator::kComma), (Strings{"x", "y"}));
  EXPECT_EQ(Split("\"\",1", Separator::kComma), (Strings{"", "1"}));
}

TEST(SplitFieldsTest, RejectsBrokenQuotes) {
  std::vector<Field> fields;
  std::string error;
  EXPECT_FALSE(SplitFields("a,\"b", Separator::kComma, &fields, &error));
  EXPECT_NE(error.find("not closed"), std::string::npos) << error;
  EXPECT_FALSE(SplitFields("\"a\"b,c", Separator::kComma, &fields, &error));
  EXPECT_NE(error.find("after the closing quote"), std::string::npos) << error;
  EXPECT_FALSE(SplitFields("\"a\"b c", Separator::kWhitespace, &fields, &error));
}

TEST(DetectSeparatorTest, CommaWhenPresent) {
  EXPECT_EQ(DetectSeparator("x,y,z"), Separator::kComma);
  EXPECT_EQ(DetectSeparator("1 0 0 0"), Separator::kWhitespace);
  EXPECT_EQ(DetectSeparator("1\t0"), Separator::kWhitespace);
}

TEST(ParseDoubleTest, AcceptsPlainNumbers) {
  double value = 0.0;
  ASSERT_TRUE(ParseDouble("1.5", &value));
  EXPECT_EQ(value, 1.5);
  ASSERT_TRUE(ParseDouble("+2", &value));
  EXPECT_EQ(value, 2.0);
  ASSERT_TRUE(ParseDouble("-1e-3", &value));
  EXPECT_EQ(value, -1e-3);
  ASSERT_TRUE(ParseDouble(".5", &value));
  EXPECT_EQ(value, 0.5);
  ASSERT_TRUE(ParseDouble("0.1", &value));
  EXPECT_EQ(value, 0.1);
}

TEST(ParseDoubleTest, RejectsEverythingElse) {
  double value = 0.0;
  for (const char* text :
       {"", "+", "-", "abc", "1.5x", "1,5", "+-1", "++1", "0x10", " 1", "1 ", "1e999"}) {
    EXPECT_FALSE(ParseDouble(text, &value)) << text;
  }
}

TEST(ParseDoubleTest, NonFiniteParsesForTheCallerToReject) {
  double value = 0.0;
  ASSERT_TRUE(ParseDouble("nan", &value));
  EXPECT_TRUE(std::isnan(value));
  ASSERT_TRUE(ParseDouble("-inf", &value));
  EXPECT_TRUE(std::isinf(value));
}

// Fixed decimals, rounded to nearest (the binary value decides ties: 2.675 is 2.67499…), and a
// dash for what is not a number.
TEST(FormatFixedTest, DecimalsAndNonFinite) {
  EXPECT_EQ(FormatFixed(1.23456, 2), "1.23");
  EXPECT_EQ(FormatFixed(-0.5, 3), "-0.500");
  EXPECT_EQ(FormatFixed(99.96, 1), "100.0");
  EXPECT_EQ(FormatFixed(2.675, 2), "2.67");
  EXPECT_EQ(FormatFixed(12.7, 0), "13");
  EXPECT_EQ(FormatFixed(std::numeric_limits<double>::quiet_NaN(), 2), "-");
  EXPECT_EQ(FormatFixed(-std::numeric_limits<double>::infinity(), 4), "-");
}

TEST(FormatDoubleTest, ShortestRoundTrip) {
  EXPECT_EQ(FormatDouble(0.1), "0.1");
  EXPECT_EQ(FormatDouble(-0.0), "0");
  EXPECT_EQ(FormatDouble(1000.0), "1000");
  EXPECT_EQ(FormatDouble(1e-20), "1e-20");
  std::mt19937_64 rng(7);
  for (int i = 0; i < 100000; ++i) {
    uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof(x));
    if (!std::isfinite(x)) continue;
    double back = 0.0;
    ASSERT_TRUE(ParseDouble(FormatDouble(x), &back)) << FormatDouble(x);
    if (x == 0.0) {
      EXPECT_EQ(back, 0.0);
    } else {
      EXPECT_EQ(back, x) << FormatDouble(x);
    }
  }
  const double extremes[] = {std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::denorm_min(),
                             -std::numeric_limits<double>::min()};
  for (double x : extremes) {
    double back = 0.0;
    ASSERT_TRUE(ParseDouble(FormatDouble(x), &back));
    EXPECT_EQ(back, x);
  }
}

TEST(QuoteFieldTest, QuotesOnlyWhenNeeded) {
  EXPECT_EQ(QuoteField("img_01"), "img_01");
  EXPECT_EQ(QuoteField("a,b"), "\"a,b\"");
  EXPECT_EQ(QuoteField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(QuoteField("#1"), "\"#1\"");
  EXPECT_EQ(QuoteField(" a"), "\" a\"");
  EXPECT_EQ(QuoteField(""), "\"\"");
}

TEST(QuoteFieldTest, QuotedFieldsSplitBackToTheValue) {
  for (const std::string value :
       {"a,b", "say \"hi\"", "#1", " a ", "\"", ",,", "x y", "a\rb", "a\r", "\v"}) {
    const std::string line = QuoteField(value) + ",1";
    std::vector<Field> fields;
    std::string error;
    ASSERT_TRUE(SplitFields(line, Separator::kComma, &fields, &error)) << line << ": " << error;
    ASSERT_EQ(fields.size(), 2u) << line;
    EXPECT_EQ(FieldValue(fields[0]), value) << line;
  }
}

}  // namespace
}  // namespace hecal::io
