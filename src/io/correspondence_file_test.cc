// The correspondence file (docs/global.md): both coordinate forms, motions grouped by station
// pair, and one InputError naming the line for each malformed input.
#include "hecal/io/correspondence_file.h"

#include <gtest/gtest.h>

#include "hecal/core/error.h"

namespace hecal::io {
namespace {

TEST(CorrespondenceFile, ReadsPixelsGroupedIntoMotionsInOrderOfAppearance) {
  const CorrespondenceFile file = ParseCorrespondenceFile(
      "# matches\nfirst,second,id,u1,v1,u2,v2\n1,2,7,10.5,20,11,21\n2,3,0,1,2,3,4\n"
      "1,2,8,30,40,31,41\n",
      "m.csv");
  ASSERT_TRUE(file.pixels);
  ASSERT_EQ(file.motions.size(), 2u);
  EXPECT_EQ(file.motions[0].first, "1");
  EXPECT_EQ(file.motions[0].second, "2");
  EXPECT_EQ(file.motions[0].ids, (std::vector<int>{7, 8}));
  EXPECT_EQ(file.motions[0].first_points[0], Eigen::Vector3d(10.5, 20, 1));
  EXPECT_EQ(file.motions[0].second_points[1], Eigen::Vector3d(31, 41, 1));
  EXPECT_EQ(file.motions[0].lines, (std::vector<int>{3, 5}));
  EXPECT_EQ(file.motions[1].first, "2");
}

TEST(CorrespondenceFile, NormalisesBearingsAndNumbersMatchesWithoutAnIdColumn) {
  const CorrespondenceFile file = ParseCorrespondenceFile(
      "X2,Y2,Z2,first,second,x1,y1,z1\n0,0,2,a,b,3,0,4\n0,1,0,a,b,0,0,1\n", "b.csv");
  ASSERT_FALSE(file.pixels);
  ASSERT_EQ(file.motions.size(), 1u);
  EXPECT_TRUE(file.motions[0].first_points[0].isApprox(Eigen::Vector3d(0.6, 0, 0.8)));
  EXPECT_TRUE(file.motions[0].second_points[0].isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_EQ(file.motions[0].ids, (std::vector<int>{0, 1}));
}

void ExpectCorrespondenceError(const std::string& text, int line, const std::string& words) {
  try {
    ParseCorrespondenceFile(text, "c.csv");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), line) << error.what();
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
    EXPECT_FALSE(error.fix().empty());
  }
}

TEST(CorrespondenceFile, RefusesMalformedInputNamingTheLine) {
  ExpectCorrespondenceError("", 0, "no header");
  ExpectCorrespondenceError("first,second,u1,v1,u2,v2\n", 1, "no matches");
  ExpectCorrespondenceError("first,second,u1,v1,u2,v2,w\n", 1, "unknown column 'w'");
  ExpectCorrespondenceError("first,first,u1,v1,u2,v2\n", 1, "twice");
  ExpectCorrespondenceError("first,u1,v1,u2,v2\n1,1,2,3,4\n", 1, "missing column 'second'");
  ExpectCorrespondenceError("first,second,u1,v1,u2\n", 1, "incomplete");
  ExpectCorrespondenceError("first,second\n", 1, "no coordinate");
  ExpectCorrespondenceError("first,second,u1,v1,u2,v2,x1,y1,z1,x2,y2,z2\n", 1, "both");
  ExpectCorrespondenceError("first,second,u1,v1,u2,v2\n1,2,3,4,5\n", 2, "5 fields for 6 columns");
  ExpectCorrespondenceError("first,second,u1,v1,u2,v2\n1,2,3,4,5,nan\n", 2, "not a finite number");
  ExpectCorrespondenceError("first,second,u1,v1,u2,v2\n1,2,3,4,5,6,\n", 2, "7 fields");
  ExpectCorrespondenceError("first,second,u1,v1,u2,v2\n1,1,3,4,5,6\n", 2, "do not name a motion");
  ExpectCorrespondenceError("first,second,id,u1,v1,u2,v2\n1,2,0,3,4,5,6\n1,2,0,3,4,5,6\n", 3,
                            "appears twice");
  ExpectCorrespondenceError("first,second,id,u1,v1,u2,v2\n1,2,0.5,3,4,5,6\n", 2, "not an integer");
  ExpectCorrespondenceError("first,second,x1,y1,z1,x2,y2,z2\n1,2,0,0,0,0,0,1\n", 2, "length 0");
}

}  // namespace
}  // namespace hecal::io
