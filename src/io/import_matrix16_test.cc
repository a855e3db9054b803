#include "hecal/io/import_matrix16.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "hecal/io/atomic_file.h"
#include "import_internal.h"
#include "testing/elementary_rotations.h"
#include "testing/nearly_orthonormal.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;

const std::string kKuka = std::string(HECAL_SOURCE_DIR) + "/data/rwhe-kuka2/RobotPosesVec.txt";

TEST(ImportMatrix16, KukaRobotPosesMatchSourceMd) {
  const ImportedPoses poses = ParseMatrix16(ReadFile(kKuka), kKuka, std::nullopt, "", {});
  EXPECT_FALSE(poses.camera.has_value());
  ASSERT_EQ(poses.robot.rows.size(), 28u);
  EXPECT_EQ(poses.robot.rows[27].id, "27");
  Eigen::Vector3d low = Eigen::Vector3d::Constant(1e9);
  Eigen::Vector3d high = -low;
  double max_angle = 0.0;
  for (const PoseRow& row : poses.robot.rows) {
    low = low.cwiseMin(row.pose.translation());
    high = high.cwiseMax(row.pose.translation());
    max_angle =
        std::max(max_angle, so3::Distance(poses.robot.rows[0].pose.linear(), row.pose.linear()));
  }
  std::printf(
      "[kuka2] x %.3f..%.3f, y %.3f..%.3f, z %.3f..%.3f m; max rotation from pose 0 "
      "%.1f deg\n",
      low.x(), high.x(), low.y(), high.y(), low.z(), high.z(), max_angle * 180 / M_PI);
  // SOURCE.md: x -0.567..-0.507, y 1.130..1.368, z 0.430..0.606 m; rotations up to 50 deg.
  EXPECT_NEAR(low.x(), -0.567, 0.001);
  EXPECT_NEAR(high.x(), -0.507, 0.001);
  EXPECT_NEAR(low.y(), 1.130, 0.001);
  EXPECT_NEAR(high.y(), 1.368, 0.001);
  EXPECT_NEAR(low.z(), 0.430, 0.001);
  EXPECT_NEAR(high.z(), 0.606, 0.001);
  EXPECT_NEAR(max_angle * 180 / M_PI, 50.0, 1.0);
}

TEST(ImportMatrix16, ColumnMajorKukaLinesAreRejected) {
  // Transpose every line: the translation lands in the last row, which must be 0 0 0 1.
  const std::string text = ReadFile(kKuka);
  std::string transposed;
  for (const auto& line : import_internal::SplitLines(text)) {
    const auto tokens = import_internal::SplitTokens(line.text);
    if (tokens.size() != 16) continue;
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) transposed += std::string(tokens[4 * r + c]) + " ";
    }
    transposed += "\n";
  }
  try {
    ParseMatrix16(transposed, "t.txt", std::nullopt, "", {});
    ADD_FAILURE() << "column-major input accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("t.txt:1: pose 0"));
    EXPECT_THAT(std::string(e.what()), HasSubstr("column-major"));
  }
}

TEST(ImportMatrix16, UnitsAndCameraFile) {
  const std::string robot =
      "# robot\n1 0 0 100 0 1 0 0 0 0 1 0 0 0 0 1\n\n"
      "1,0,0,0, 0,1,0,200, 0,0,1,0\n";
  const std::string camera =
      "1 0 0 0 0 1 0 0 0 0 1 300 0 0 0 1\n"
      "1 0 0 0 0 1 0 0 0 0 1 400 0 0 0 1\n";
  Matrix16Options options;
  options.unit = LengthUnit::kMillimetre;
  const ImportedPoses poses = ParseMatrix16(robot, "r.txt", camera, "c.txt", options);
  EXPECT_EQ(poses.robot.unit, LengthUnit::kMillimetre);
  EXPECT_EQ(poses.robot.rows[1].line, 4);
  EXPECT_TRUE(poses.robot.rows[1].pose.translation().isApprox(Eigen::Vector3d(0, 0.2, 0)));
  EXPECT_TRUE(poses.camera->rows[1].pose.translation().isApprox(Eigen::Vector3d(0, 0, 0.4)));
  EXPECT_THAT(poses.camera_notes[3], HasSubstr("read as T_camera_target"));
}

void ExpectMatrix16Error(const std::string& robot, const std::optional<std::string>& camera,
                         const std::string& part) {
  try {
    if (camera) {
      ParseMatrix16(robot, "r.txt", std::string_view(*camera), "c.txt", {});
    } else {
      ParseMatrix16(robot, "r.txt", std::nullopt, "", {});
    }
    ADD_FAILURE() << "no error; expected " << part;
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr(part));
  }
}

TEST(ImportMatrix16, ControllerMatricesAreProjectedWithANote) {
  // Two poses as a controller writes them (2e-5 and 1e-5 from orthonormal, 17 digits).
  const testing::NearlyOrthonormal a =
      testing::ControllerMatrix(testing::Ry(0.7) * testing::Rz(2.9), 1e-5);
  const testing::NearlyOrthonormal b =
      testing::ControllerMatrix(testing::Rx(-2.2) * testing::Ry(0.1), 0.5e-5);
  const std::string text =
      "# controller log\n" +
      testing::Digits17(testing::Homogeneous(a.matrix, Eigen::Vector3d(0.4, 0.1, 0.6)), " ") +
      "\n" + testing::Digits17(testing::Homogeneous(b.matrix, Eigen::Vector3d(0.3, 0, 0.5)), " ") +
      "\n";
  const ImportedPoses poses = ParseMatrix16(text, "robot.txt", std::nullopt, "", {});
  ASSERT_EQ(poses.robot.rows.size(), 2u);
  EXPECT_LT((poses.robot.rows[0].pose.linear() - a.rotation).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((poses.robot.rows[1].pose.linear() - b.rotation).cwiseAbs().maxCoeff(), 1e-15);
  ASSERT_EQ(poses.robot.warnings.size(), 1u);
  EXPECT_THAT(poses.robot.warnings[0],
              HasSubstr("robot.txt: 2 of 2 rotation matrices were not orthonormal within 1e-6 "
                        "(largest error 2.0e-05 at line 2 (pose 0)); projected"));
}

TEST(ImportMatrix16, RejectsBadInput) {
  const std::string I = "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n";
  ExpectMatrix16Error("", std::nullopt, "r.txt: the file has no poses");
  ExpectMatrix16Error("1 2 3\n", std::nullopt, "r.txt:1: expected 16 numbers");
  ExpectMatrix16Error(I + "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 5\n", std::nullopt,
                      "r.txt:2: expected 16");
  ExpectMatrix16Error("1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 one\n", std::nullopt, "field 16");
  ExpectMatrix16Error("1 0 0 0 0 1 0 0 0 0 1 nan 0 0 0 1\n", std::nullopt, "non-finite");
  ExpectMatrix16Error("1 0 0 0 0 1 0 0 0 0 -1 0 0 0 0 1\n", std::nullopt, "a reflection");
  ExpectMatrix16Error("2 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n", std::nullopt, "not orthonormal");
  ExpectMatrix16Error("2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1\n", std::nullopt, "a rotation scaled by 2");
  ExpectMatrix16Error(I + I, I, "r.txt: has 2 poses but c.txt has 1");
}

}  // namespace
}  // namespace hecal::io
