#include "hecal/io/stamp_file.h"

#include <gtest/gtest.h>

#include <string>

#include "hecal/core/error.h"
#include "testing/thrown.h"

namespace hecal::io {
namespace {

TEST(StampFile, MatchesImagesByStem) {
  const auto stamps = ParseStampFile(
      "# camera trigger log\nimage,stamp\nimages/im_01.png,0.5\nim_02,1.5\n\n", "stamps.csv");
  ASSERT_EQ(stamps.size(), 2u);
  EXPECT_DOUBLE_EQ(stamps.at("im_01"), 0.5);
  EXPECT_DOUBLE_EQ(stamps.at("im_02"), 1.5);
  EXPECT_DOUBLE_EQ(ParseStampFile("stamp file\n3.25 a.png\n", "s.txt").at("a"), 3.25);
}

TEST(StampFile, MistakesNameTheLine) {
  const auto error = [](const std::string& text) {
    return std::string(testing::Thrown<InputError>([&] { ParseStampFile(text, "s.csv"); }).what());
  };
  EXPECT_NE(error("name,time\n").find("s.csv:1"), std::string::npos);
  EXPECT_NE(error("image,stamp\na.png,x\n").find("s.csv:2"), std::string::npos);
  EXPECT_NE(error("image,stamp\na.png,1\na.jpg,2\n").find("stamped twice"), std::string::npos);
  EXPECT_NE(error("").find("is empty"), std::string::npos);
}

TEST(StampFile, FileNamesThatAreStamps) {
  EXPECT_DOUBLE_EQ(StampFromFileName("1634567890.125"), 1634567890.125);
  EXPECT_THROW(StampFromFileName("im_01"), InputError);
}

}  // namespace
}  // namespace hecal::io
