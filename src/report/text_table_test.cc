// Table cells against hand-written strings.
#include "hecal/report/text_table.h"

#include <gtest/gtest.h>

#include <limits>

namespace hecal::report {
namespace {

TEST(TextTable, PadAlignsAndKeepsLongText) {
  EXPECT_EQ(Pad("ab", 5), "   ab");
  EXPECT_EQ(Pad("ab", 5, true), "ab   ");
  EXPECT_EQ(Pad("abcdef", 3), "abcdef");
}

TEST(TextTable, NumberFormats) {
  EXPECT_EQ(Printf("%.1fx", 2.26), "2.3x");
  EXPECT_EQ(Fixed(1.0 / 3.0, 3), "0.333");
  EXPECT_EQ(Fixed(std::numeric_limits<double>::infinity(), 3), "inf");
  EXPECT_EQ(Fixed(std::numeric_limits<double>::quiet_NaN(), 3), "nan");
  EXPECT_EQ(Readable(0.5), "0.5000");
  EXPECT_EQ(Readable(0.0), "0.0000");
  EXPECT_EQ(Readable(1.234e-7), "1.23e-07");
  EXPECT_EQ(Readable(-2e-4), "-2.00e-04");
}

}  // namespace
}  // namespace hecal::report
