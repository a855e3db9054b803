#include "hecal/io/import_tabb.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "testing/nearly_orthonormal.h"
#include "testing/pose_spread.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;

const std::string kTabbDir = std::string(HECAL_SOURCE_DIR) + "/data/tabb-rwhe-dataset1/";

ImportedPoses LoadTabb() {
  return ParseTabb(ReadFile(kTabbDir + "robot_cali.txt"), kTabbDir + "robot_cali.txt",
                   ReadFile(kTabbDir + "cali.txt"), kTabbDir + "cali.txt");
}

// Tabb's own result (rwhe_AA_RPI/transformations.txt, mm): X = wTb = T_target_base and
// Z = cTg = T_camera_gripper, with target2cam_i · X = Z · base2gripper_i.
struct TabbAnswer {
  Pose T_target_base;
  Pose T_camera_gripper;
};

TabbAnswer ReadAnswer() {
  std::istringstream in(ReadFile(kTabbDir + "rwhe_AA_RPI/transformations.txt"));
  std::string label;
  Eigen::Matrix4d X;
  Eigen::Matrix4d Z;
  in >> label;  // X
  for (int k = 0; k < 16; ++k) in >> X(k / 4, k % 4);
  in >> label >> label;  // Z 0
  for (int k = 0; k < 16; ++k) in >> Z(k / 4, k % 4);
  EXPECT_TRUE(in) << "cannot parse transformations.txt";
  const auto to_pose = [](const Eigen::Matrix4d& M) {
    return testing::PoseOf(M.topLeftCorner<3, 3>(), M.topRightCorner<3, 1>() * 1e-3);
  };
  return {to_pose(X), to_pose(Z)};
}

// Eye-in-hand: T_base_target_i = T_base_gripper_i · X · T_camera_target_i, X = T_gripper_camera.
std::vector<Pose> BaseTarget(const ImportedPoses& poses, const Pose& X, bool invert_robot) {
  std::vector<Pose> targets;
  for (size_t i = 0; i < poses.robot.rows.size(); ++i) {
    const Pose& robot = poses.robot.rows[i].pose;
    targets.push_back((invert_robot ? robot.inverse() : robot) * X * poses.camera->rows[i].pose);
  }
  return targets;
}

TEST(ImportTabb, RealDataMatchesTabbsAnswerPosePerPose) {
  const ImportedPoses poses = LoadTabb();
  ASSERT_EQ(poses.robot.rows.size(), 88u);
  ASSERT_EQ(poses.camera->rows.size(), 88u);
  EXPECT_EQ(poses.robot.unit, LengthUnit::kMillimetre);
  EXPECT_EQ(poses.camera->unit, LengthUnit::kMillimetre);
  EXPECT_EQ(poses.robot.rows[0].id, "image0");
  EXPECT_EQ(poses.camera->rows[87].id, "image87");
  EXPECT_EQ(poses.robot.rows[87].id, "image87");
  // cali.txt line 1: t = (-267.636, 270.545, 2122.28) mm, stored in metres.
  EXPECT_NEAR(poses.camera->rows[0].pose.translation().z(), 2.12228, 1e-9);

  // SOURCE.md: per-pose consistency with Tabb's X and Z: mean 0.39 deg / 6.4 mm, max 1.8 deg /
  // 15.7 mm (pose 76).
  const TabbAnswer answer = ReadAnswer();
  const Pose T_gripper_camera = answer.T_camera_gripper.inverse();
  const Pose T_base_target = answer.T_target_base.inverse();
  const std::vector<Pose> targets = BaseTarget(poses, T_gripper_camera, false);
  const testing::Spread spread = testing::SpreadAround(targets, T_base_target);
  std::printf(
      "[tabb] per-pose consistency: mean %.3f deg / %.2f mm, max %.3f deg / %.2f mm "
      "(pose %zu)\n",
      spread.mean_rotation_deg, spread.mean_translation * 1e3, spread.max_rotation_deg,
      spread.max_translation * 1e3, spread.worst_translation);
  EXPECT_NEAR(spread.mean_rotation_deg, 0.39, 0.02);
  EXPECT_NEAR(spread.mean_translation, 0.0064, 0.0003);
  EXPECT_NEAR(spread.max_rotation_deg, 1.82, 0.05);
  EXPECT_NEAR(spread.max_translation, 0.0157, 0.0005);
  EXPECT_EQ(spread.worst_translation, 76u);

  // Without the inverse (robot_cali.txt read as T_base_gripper) nothing is consistent.
  const testing::Spread wrong =
      testing::SpreadAround(BaseTarget(poses, T_gripper_camera, true), T_base_target);
  EXPECT_GT(wrong.mean_rotation_deg, 30.0);
  EXPECT_GT(wrong.mean_translation, 0.5);
}

TEST(ImportTabb, IntrinsicsComeFromCaliTxt) {
  const ImportedPoses poses = LoadTabb();
  ASSERT_TRUE(poses.intrinsics.has_value());
  EXPECT_DOUBLE_EQ(poses.intrinsics->fx, 1081.59);
  EXPECT_DOUBLE_EQ(poses.intrinsics->fy, 1083.49);
  EXPECT_DOUBLE_EQ(poses.intrinsics->cx, 317.249);
  EXPECT_DOUBLE_EQ(poses.intrinsics->cy, 245.791);
  ASSERT_EQ(poses.intrinsics->distortion.size(), 5u);
  EXPECT_DOUBLE_EQ(poses.intrinsics->distortion[0], -0.223875);
  EXPECT_DOUBLE_EQ(poses.intrinsics->distortion[4], -0.0108216);
}

const std::string kRobotOne =
    "1\n"
    "1 0 0 10\n"
    "0 1 0 20\n"
    "0 0 1 30\n"
    "0 0 0 1\n";
const std::string kCameraLine =
    "a.png 1000 0 320 0 1000 240 0 0 1 1 0 0 0 1 0 0 0 1 1 2 3 0.1 0.2 0 0 0.3 0 0 0 \n";

TEST(ImportTabb, InvertsTheRobotPoseAndKeepsMillimetres) {
  const ImportedPoses poses = ParseTabb(kRobotOne, "r.txt", "1\n" + kCameraLine, "c.txt");
  // B = T_gripper_base with t = (10, 20, 30) mm → T_base_gripper has t = −(10, 20, 30) mm.
  EXPECT_TRUE(
      poses.robot.rows[0].pose.translation().isApprox(Eigen::Vector3d(-0.01, -0.02, -0.03), 1e-12));
  EXPECT_TRUE(poses.camera->rows[0].pose.translation().isApprox(
      Eigen::Vector3d(0.001, 0.002, 0.003), 1e-12));
  EXPECT_EQ(poses.robot.rows[0].id, "a");
}

void ExpectTabbError(const std::string& robot, const std::string& camera, const std::string& part) {
  try {
    ParseTabb(robot, "r.txt", camera, "c.txt");
    ADD_FAILURE() << "no error; expected " << part;
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr(part));
  }
}

TEST(ImportTabb, RejectsBadInput) {
  const std::string camera = "1\n" + kCameraLine;
  ExpectTabbError("", camera, "r.txt: the file is empty");
  ExpectTabbError("x\n", camera, "r.txt:1: the first line should be the number of poses");
  ExpectTabbError("2\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n", camera,
                  "r.txt:1: N is 2 but the file has 1 poses");
  ExpectTabbError("1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n", camera, "has only 3 of its 4 matrix rows");
  ExpectTabbError("1\n1 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n", camera, "r.txt:2: expected 4 numbers");
  ExpectTabbError("1\n1 0 0 0\n0 1 0 nan\n0 0 1 0\n0 0 0 1\n", camera, "non-finite");
  ExpectTabbError("1\n1 0 0 0\n0 1 0 x\n0 0 1 0\n0 0 0 1\n", camera, "r.txt:3: field 4");
  ExpectTabbError("1\n1 0 0 0\n0 0.9 0 0\n0 0 1 0\n0 0 0 1\n", camera, "not orthonormal");
  ExpectTabbError(kRobotOne, "2\n" + kCameraLine, "c.txt:1: N is 2 but the file has 1 image lines");
  ExpectTabbError(kRobotOne, "1\na.png 1 2 3\n", "c.txt:2: expected 30 fields");
  ExpectTabbError(kRobotOne, "1\n" + std::string(kCameraLine).replace(0, 5, "12345"),
                  "should be the image name");
  ExpectTabbError(kRobotOne + "\n" + "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n", camera, "N is 1");
  ExpectTabbError("2\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n",
                  camera, "has 2 robot poses but c.txt has 1 camera poses");
  ExpectTabbError(kRobotOne, "2\n" + kCameraLine + kCameraLine, "appears twice");
  // Files given the wrong way round say so.
  ExpectTabbError(camera, kRobotOne, "looks like cali.txt");
  // The rotation tolerance is 1e-3, widened to 6u for 3 decimals (u = 5e-4): 1.002 is 4.0e-3 off.
  ExpectTabbError("1\n1 0 0 0\n0 1.002 0 0\n0 0 1 0\n0 0 0 1\n", camera,
                  "r.txt:2: pose 0 (B_0): the rotation matrix is not orthonormal: max(|R^T R - I|, "
                  "|det R - 1|) = 4.0e-03, more than the 3.0e-03 allowed for entries printed to "
                  "+-5.0e-04");
  ExpectTabbError("1\n-1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n", camera, "a reflection (det R = -1)");
}

// How many of the printed rotations are more than 1e-6 from orthonormal, by the definition
// max(|MᵀM − I|, |det M − 1|) written out here.
int BeyondRounding(const std::vector<Eigen::Matrix3d>& matrices) {
  int count = 0;
  for (const Eigen::Matrix3d& M : matrices) {
    const double gram = (M.transpose() * M - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (std::max(gram, std::abs(M.determinant() - 1.0)) > 1e-6) ++count;
  }
  return count;
}

TEST(ImportTabb, SixDecimalRotationsAreProjectedWithANote) {
  const ImportedPoses poses = LoadTabb();
  // The printed matrices, read with a plain stream parser: B_i (robot) and R of each image line.
  std::vector<Eigen::Matrix3d> robot;
  std::istringstream robot_in(ReadFile(kTabbDir + "robot_cali.txt"));
  int count = 0;
  robot_in >> count;
  for (int i = 0; i < count; ++i) {
    Eigen::Matrix4d B;
    for (int k = 0; k < 16; ++k) robot_in >> B(k / 4, k % 4);
    robot.push_back(B.topLeftCorner<3, 3>());
  }
  std::vector<Eigen::Matrix3d> camera;
  std::istringstream camera_in(ReadFile(kTabbDir + "cali.txt"));
  camera_in >> count;
  for (int i = 0; i < count; ++i) {
    std::string name;
    double K[9];
    Eigen::Matrix3d R;
    double rest[11];
    camera_in >> name;
    for (double& value : K) camera_in >> value;
    for (int k = 0; k < 9; ++k) camera_in >> R(k / 3, k % 3);
    for (double& value : rest) camera_in >> value;
    camera.push_back(R);
  }
  ASSERT_TRUE(robot_in && camera_in);
  ASSERT_EQ(robot.size(), 88u);
  ASSERT_EQ(camera.size(), 88u);

  // Each pose is the nearest rotation to what the file prints.
  for (size_t i = 0; i < 88; ++i) {
    EXPECT_TRUE(
        testing::IsNearestRotation(poses.robot.rows[i].pose.inverse().linear(), robot[i], 1e-12))
        << "B_" << i;
    EXPECT_TRUE(testing::IsNearestRotation(poses.camera->rows[i].pose.linear(), camera[i], 1e-12))
        << "image " << i;
  }
  // One note per file, counting the matrices beyond 1e-6, all within what 6 decimals explain.
  const int robot_count = BeyondRounding(robot);
  ASSERT_GT(robot_count, 0);
  ASSERT_EQ(poses.robot.warnings.size(), 1u);
  EXPECT_THAT(poses.robot.warnings[0],
              HasSubstr("robot_cali.txt: " + std::to_string(robot_count) +
                        " of 88 rotation matrices were not orthonormal within 1e-6"));
  EXPECT_THAT(poses.robot.warnings[0], HasSubstr("within what entries printed to +-5.0e-07 allow"));
  const int camera_count = BeyondRounding(camera);
  ASSERT_EQ(poses.camera->warnings.size(), camera_count > 0 ? 1u : 0u);
  if (camera_count > 0) {
    EXPECT_THAT(poses.camera->warnings[0],
                HasSubstr("cali.txt: " + std::to_string(camera_count) + " of 88 rotation"));
  }
}

TEST(ImportTabb, AllowsForTheSixDecimalsOfTheRealFiles) {
  // Rotation about z by 0.3 rad printed with 6 decimals: off by ~1e-6, accepted.
  const std::string robot = "1\n0.955336 -0.295520 0 0\n0.295520 0.955336 0 0\n0 0 1 0\n0 0 0 1\n";
  EXPECT_NO_THROW(ParseTabb(robot, "r.txt", "1\n" + kCameraLine, "c.txt"));
}

}  // namespace
}  // namespace hecal::io
