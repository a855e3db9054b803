// ReadContourFile (contour_file.h): the points come back in file order as written, in either
// delimiter and with comments; fewer than 4 points and a wrong header are refused naming the file.
#include "hecal/io/contour_file.h"

#include <gtest/gtest.h>

#include "hecal/core/error.h"
#include "testing/scratch_folder.h"
#include "testing/thrown.h"

namespace hecal::io {
namespace {

class ContourFileTest : public testing::ScratchFolderTest {
 protected:
  ContourFileTest() : ScratchFolderTest("hecal_contour_file") {}
};

TEST_F(ContourFileTest, ReadsThePointsInFileOrder) {
  const std::string path =
      Write("square.csv", "# a square\nX,Y\n10,20\n30.5,20\n30.5,-40.25\n# done\n10,-40.25\n");
  const Eigen::Matrix2Xd points = ReadContourFile(path);
  Eigen::Matrix2Xd expected(2, 4);
  expected << 10, 30.5, 30.5, 10, 20, 20, -40.25, -40.25;
  EXPECT_EQ(points, expected);
}

TEST_F(ContourFileTest, ReadsWhitespaceSeparatedPointsWithIds) {
  const std::string path = Write("ids.txt", "id x y\na 1 2\nb 3 4\nc 5 6\nd 7 8\ne 9 10\n");
  const Eigen::Matrix2Xd points = ReadContourFile(path);
  ASSERT_EQ(points.cols(), 5);
  EXPECT_EQ(points.col(4), Eigen::Vector2d(9, 10));
}

TEST_F(ContourFileTest, FewerThanFourPointsAreRefused) {
  const std::string path = Write("three.csv", "x,y\n0,0\n1,0\n1,1\n");
  const InputError error = testing::Thrown<InputError>([&] { ReadContourFile(path); });
  EXPECT_EQ(error.source(), path);
  EXPECT_NE(error.problem().find("at least 4 points, the file has 3"), std::string::npos)
      << error.problem();
  EXPECT_NE(error.fix().find("x,y"), std::string::npos);
}

TEST_F(ContourFileTest, AWrongHeaderAndAMissingFileAreRefused) {
  const std::string path = Write("uv.csv", "u,v\n0,0\n1,0\n1,1\n0,1\n");
  EXPECT_EQ(testing::Thrown<InputError>([&] { ReadContourFile(path); }).source(), path);
  const std::string missing = (dir_ / "missing.csv").string();
  EXPECT_EQ(testing::Thrown<InputError>([&] { ReadContourFile(missing); }).source(), missing);
}

}  // namespace
}  // namespace hecal::io
