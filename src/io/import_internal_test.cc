#include "import_internal.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "hecal/core/error.h"
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

const Origin kOrigin{"f.txt", 7, "pose 3"};

std::string PoseErrorOf(const double* values, int count, double rounding = 0.0) {
  RotationInput rotations("f.txt");
  try {
    PoseFromRowMajor(values, count, rounding, 1.0, kOrigin, &rotations);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ImportInternal, PoseChecks) {
  RotationInput rotations("f.txt");
  const double ok[16] = {0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1};
  const Pose pose = PoseFromRowMajor(ok, 16, 0.0, 1e-3, kOrigin, &rotations);
  EXPECT_TRUE(pose.translation().isApprox(Eigen::Vector3d(0.001, 0.002, 0.003)));
  EXPECT_DOUBLE_EQ(pose.linear()(0, 1), -1.0);
  EXPECT_TRUE(PoseFromRowMajor(ok, 12, 0.0, 1.0, kOrigin, &rotations)
                  .isApprox(PoseFromRowMajor(ok, 16, 0.0, 1.0, kOrigin, &rotations)));

  double nan[16] = {1, 0, 0, 0, 0, 1, 0, NAN, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_THAT(PoseErrorOf(nan, 16),
              HasSubstr("f.txt:7: pose 3 contains a non-finite number (nan at "
                        "row 2, column 4)"));
  const double last[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1};
  EXPECT_THAT(PoseErrorOf(last, 16), HasSubstr("last row of the 4x4 matrix is (0 0 1 1)"));
  const double transposed[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 4, 5, 6, 1};
  EXPECT_THAT(PoseErrorOf(transposed, 16), HasSubstr("looks column-major"));
  // The rotation rule (rotation_input.h) with the origin's line and name in its messages.
  const double skew[16] = {1, 0.01, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_THAT(PoseErrorOf(skew, 16),
              HasSubstr("f.txt:7: pose 3: the rotation matrix is not orthonormal: max(|R^T R - "
                        "I|, |det R - 1|) = 1.0e-02, more than the 1.0e-03 allowed"));
  const double mirror[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1};
  EXPECT_THAT(PoseErrorOf(mirror, 16),
              HasSubstr("f.txt:7: pose 3: the rotation matrix is a reflection"));
  EXPECT_THAT(PoseErrorOf(ok, 9), HasSubstr("9 numbers"));
  EXPECT_TRUE(rotations.Notes().empty());
  // 2e-5 off: projected onto SO(3), with a note.
  const double near[16] = {1.00001, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const Pose projected = PoseFromRowMajor(near, 16, 0.0, 1.0, kOrigin, &rotations);
  EXPECT_LT((projected.linear() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-15);
  ASSERT_EQ(rotations.Notes().size(), 1u);
  EXPECT_THAT(rotations.Notes()[0], HasSubstr("at line 7 (pose 3)"));
}

TEST(ImportInternal, QuaternionChecks) {
  RotationInput rotations("f.txt");
  const Pose pose = PoseFromQuaternion(Eigen::Vector3d(1, 2, 3), Eigen::Vector4d(0, 0, 0, 1), 0.0,
                                       1.0, kOrigin, "w, x, y, z", &rotations);  // 180° about z
  EXPECT_TRUE(pose.linear().isApprox(Eigen::Vector3d(-1, -1, 1).asDiagonal().toDenseMatrix()));
  const auto error = [](const Eigen::Vector4d& q, double rounding) -> std::string {
    RotationInput checked("f.txt");
    try {
      PoseFromQuaternion(Eigen::Vector3d::Zero(), q, rounding, 1.0, kOrigin, "w, x, y, z",
                         &checked);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_THAT(error(Eigen::Vector4d::Zero(), 0.0), HasSubstr("pose 3: zero quaternion"));
  EXPECT_THAT(error(Eigen::Vector4d(1.5, 0, 0, 0), 0.0), HasSubstr("norm 1.5"));
  EXPECT_THAT(error(Eigen::Vector4d(1.5, 0, 0, 0), 0.0), HasSubstr("are w, x, y, z a quaternion"));
  EXPECT_EQ(error(Eigen::Vector4d(1.001, 0, 0, 0), 0.0), "");
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
