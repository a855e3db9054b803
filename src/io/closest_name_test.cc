#include "closest_name.h"

#include <gtest/gtest.h>

namespace hecal::io::internal {
namespace {

TEST(ClosestName, EditDistance) {
  EXPECT_EQ(EditDistance("", ""), 0u);
  EXPECT_EQ(EditDistance("abc", ""), 3u);
  EXPECT_EQ(EditDistance("kitten", "sitting"), 3u);  // the textbook example
  EXPECT_EQ(EditDistance("sqaure", "square"), 2u);   // a swap is two substitutions
  EXPECT_EQ(EditDistance("square", "sqaure"), EditDistance("sqaure", "square"));
}

TEST(ClosestName, Suggestions) {
  constexpr std::string_view kKeys[] = {"cols", "rows", "square", "marker", "spacing"};
  EXPECT_EQ(ClosestName("sqaure", kKeys), "square");
  EXPECT_EQ(ClosestName("Rows", kKeys), "rows");  // case is ignored
  EXPECT_EQ(ClosestName("col", kKeys), "cols");
  EXPECT_EQ(ClosestName("banana", kKeys), "");   // nothing close
  EXPECT_EQ(ClosestName("columns", kKeys), "");  // 3 edits from cols: a different word
  constexpr std::string_view kDictionaries[] = {"DICT_5X5_250", "DICT_5X5_1000", "DICT_4X4_250"};
  EXPECT_EQ(ClosestName("dict_5x5_250", kDictionaries), "DICT_5X5_250");
  EXPECT_EQ(ClosestName("DICT_5X5_25", kDictionaries), "DICT_5X5_250");  // tie → earlier
  EXPECT_EQ(DidYouMean("markr", kKeys), " (did you mean 'marker'?)");
  EXPECT_EQ(DidYouMean("zzz", kKeys), "");
  EXPECT_EQ(ClosestName(std::string(100, 'a'), kKeys), "");
}

}  // namespace
}  // namespace hecal::io::internal
