#include "import_internal.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "hecal/io/import_types.h"

namespace hecal::io::import_internal {
namespace {

using ::testing::HasSubstr;

TEST(ImportInternal, ParseNumberIsStrict) {
  EXPECT_DOUBLE_EQ(ParseNumber("1.5")->value, 1.5);
  EXPECT_DOUBLE_EQ(ParseNumber("+2")->value, 2.0);
  EXPECT_DOUBLE_EQ(ParseNumber("-0.25e1")->value, -2.5);
  EXPECT_DOUBLE_EQ(ParseNumber("1.")->value, 1.0);
  EXPECT_DOUBLE_EQ(ParseNumber(".5")->value, 0.5);
  EXPECT_TRUE(std::isnan(ParseNumber("nan")->value));
  EXPECT_TRUE(std::isinf(ParseNumber("-inf")->value));
  EXPECT_TRUE(std::isinf(ParseNumber("1e999")->value));
  EXPECT_EQ(ParseNumber("1e-999")->value, 0.0);
  for (const char* bad :
       {"", "-", ".", "e5", "1e", "1,5", "0x10", "1.5.2", " 1", "1 ", "one", "--1", "1e+", "++1"}) {
    EXPECT_FALSE(ParseNumber(bad).has_value()) << bad;
  }
}

TEST(ImportInternal, PrintedRoundingFollowsTheDigits) {
  EXPECT_DOUBLE_EQ(PrintedRounding("0.985976"), 5e-7);
  EXPECT_DOUBLE_EQ(PrintedRounding("-0.5"), 0.05);
  EXPECT_DOUBLE_EQ(PrintedRounding("1.17359e-06"), 5e-12);
  EXPECT_DOUBLE_EQ(PrintedRounding("1.5E+2"), 5.0);
  // No fraction digits: exact (0, 1, OpenCV's "1.").
  EXPECT_EQ(PrintedRounding("1"), 0.0);
  EXPECT_EQ(PrintedRounding("1."), 0.0);
  EXPECT_EQ(PrintedRounding("1e-5"), 0.0);
}

const Origin kOrigin{"f.txt", 7, "pose 3"};

std::string ErrorOf(const double* values, int count, double rounding = 0.0) {
  try {
    PoseFromRowMajor(values, count, rounding, 1.0, kOrigin);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ImportInternal, PoseChecks) {
  const double ok[16] = {0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1};
  const Pose pose = PoseFromRowMajor(ok, 16, 0.0, 1e-3, kOrigin);
  EXPECT_TRUE(pose.translation().isApprox(Eigen::Vector3d(0.001, 0.002, 0.003)));
  EXPECT_DOUBLE_EQ(pose.linear()(0, 1), -1.0);
  EXPECT_TRUE(PoseFromRowMajor(ok, 12, 0.0, 1.0, kOrigin)
                  .isApprox(PoseFromRowMajor(ok, 16, 0.0, 1.0, kOrigin)));

  double nan[16] = {1, 0, 0, 0, 0, 1, 0, NAN, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_THAT(ErrorOf(nan, 16), HasSubstr("f.txt:7: pose 3 contains a non-finite number (nan at "
                                          "row 2, column 4)"));
  const double last[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1};
  EXPECT_THAT(ErrorOf(last, 16), HasSubstr("last row of the 4x4 matrix is (0 0 1 1)"));
  const double transposed[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 4, 5, 6, 1};
  EXPECT_THAT(ErrorOf(transposed, 16), HasSubstr("looks column-major"));
  const double skew[16] = {1, 0.001, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_THAT(ErrorOf(skew, 16), HasSubstr("not orthonormal: max(|R^T R - I|, |det R - 1|) = "
                                           "1.0e-03, more than the 1.0e-06 allowed"));
  const double mirror[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1};
  EXPECT_THAT(ErrorOf(mirror, 16), HasSubstr("a reflection"));
  EXPECT_THAT(ErrorOf(ok, 9), HasSubstr("9 numbers"));
  // 2e-6 off: rejected at full precision, accepted for numbers printed with 6 decimals.
  const double near[16] = {1.000001, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_THAT(ErrorOf(near, 16), HasSubstr("not orthonormal"));
  EXPECT_EQ(ErrorOf(near, 16, 5e-7), "");
  // Accepted rotations are projected onto SO(3).
  const Pose projected = PoseFromRowMajor(near, 16, 5e-7, 1.0, kOrigin);
  EXPECT_LT(so3::OrthonormalityError(projected.linear()), 1e-14);
}

TEST(ImportInternal, QuaternionChecks) {
  const Pose pose = PoseFromQuaternion(Eigen::Vector3d(1, 2, 3), Eigen::Vector4d(0, 0, 0, 1), 0.0,
                                       1.0, kOrigin);  // 180 deg about z
  EXPECT_TRUE(pose.linear().isApprox(Eigen::Vector3d(-1, -1, 1).asDiagonal().toDenseMatrix()));
  const auto error = [](const Eigen::Vector4d& q, double rounding) -> std::string {
    try {
      PoseFromQuaternion(Eigen::Vector3d::Zero(), q, rounding, 1.0, kOrigin);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_THAT(error(Eigen::Vector4d::Zero(), 0.0), HasSubstr("zero quaternion"));
  EXPECT_THAT(error(Eigen::Vector4d(1.001, 0, 0, 0), 0.0), HasSubstr("norm 1.001"));
  EXPECT_EQ(error(Eigen::Vector4d(0.7071, 0, 0, 0.7071), 5e-5), "");  // printed to 4 decimals
  EXPECT_THAT(error(Eigen::Vector4d(NAN, 0, 0, 1), 0.0), HasSubstr("non-finite"));
}

TEST(ImportInternal, LinesAndTokens) {
  const std::vector<TextLine> lines = SplitLines(
      "\xEF\xBB\xBF"
      "a\r\n\nb c\n");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].text, "a");
  EXPECT_EQ(lines[2].number, 3);
  EXPECT_EQ(lines[2].text, "b c");
  EXPECT_EQ(SplitLines("x\ny").back().text, "y");
  const std::vector<std::string_view> tokens = SplitTokens(" 1, 2\t3 ,,4 ");
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens[3], "4");
  EXPECT_TRUE(IsCommentLine("  # note"));
  EXPECT_TRUE(IsBlankLine(" \t"));
  EXPECT_EQ(FileStem("dir/sub/image7.png"), "image7");
  EXPECT_EQ(FileStem("image7"), "image7");
  EXPECT_EQ(Quoted(std::string("a\nb")), "\"a?b\"");
}

TEST(ImportInternal, IntrinsicsYaml) {
  ImportedIntrinsics intrinsics;
  intrinsics.fx = 1081.59;
  intrinsics.fy = 1083.49;
  intrinsics.cx = 317.249;
  intrinsics.cy = 245.791;
  intrinsics.distortion = {-0.223875, 0.164635, 0.000135341, 0.000967829, -0.0108216};
  EXPECT_EQ(FormatIntrinsicsYaml(intrinsics, {"from cali.txt"}),
            "# from cali.txt\nfx: 1081.59\nfy: 1083.49\ncx: 317.249\ncy: 245.791\n"
            "distortion:\n  model: plumb_bob\n  coefficients: [-0.223875, 0.164635, "
            "0.000135341, 0.000967829, -0.0108216]\n");
  EXPECT_THAT(FormatIntrinsicsYaml(intrinsics, {}, 640, 480),
              HasSubstr("width: 640\nheight: 480\n"));
}

}  // namespace
}  // namespace hecal::io::import_internal
