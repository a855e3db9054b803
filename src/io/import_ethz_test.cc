#include "hecal/io/import_ethz.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "testing/pose_spread.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;

const std::string kEthzDir = std::string(HECAL_SOURCE_DIR) + "/data/ethz-robot-arm/";
const std::string kRobot =
    kEthzDir + "robot_arm_complete_bag_color_and_ir_base_link_sr300_hinge.csv";
const std::string kCamera = kEthzDir + "robot_arm_complete_bag_color_and_ir_target_ir.csv";

// SOURCE.md reference (OpenCV PARK): X = T_hinge_camera.
Pose ReferenceX() {
  Eigen::Matrix3d R;
  R << 0.45313, -0.01182, 0.89136, -0.89144, -0.00894, 0.45305, 0.00261, -0.99989, -0.01459;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return testing::PoseOf(svd.matrixU() * svd.matrixV().transpose(),
                         Eigen::Vector3d(0.00019, -0.01594, 0.00522));
}

// As SOURCE.md pairs them: one camera pose every >= 1 s, with the nearest robot pose within 10 ms.
std::vector<std::pair<size_t, size_t>> PairByStamp(const PoseTable& robot,
                                                   const PoseTable& camera) {
  std::vector<std::pair<size_t, size_t>> pairs;
  double last = -1e300;
  for (size_t c = 0; c < camera.rows.size(); ++c) {
    const double t = *camera.rows[c].stamp;
    if (t < last + 1.0) continue;
    const auto it =
        std::lower_bound(robot.rows.begin(), robot.rows.end(), t,
                         [](const PoseRow& row, double stamp) { return *row.stamp < stamp; });
    size_t best = robot.rows.size();
    double best_dt = 0.010;
    for (auto candidate : {it, it == robot.rows.begin() ? it : it - 1}) {
      if (candidate == robot.rows.end()) continue;
      const double dt = std::abs(*candidate->stamp - t);
      if (dt <= best_dt) {
        best_dt = dt;
        best = static_cast<size_t>(candidate - robot.rows.begin());
      }
    }
    if (best == robot.rows.size()) continue;
    pairs.emplace_back(best, c);
    last = t;
  }
  return pairs;
}

TEST(ImportEthz, RealStreamsKeepStampsAndMatchTheReferenceTarget) {
  const ImportedPoses poses =
      ParseEthzStreams(ReadFile(kRobot), kRobot, ReadFile(kCamera), kCamera);
  EXPECT_FALSE(poses.synchronised);
  ASSERT_EQ(poses.robot.rows.size(), 2817u);
  ASSERT_EQ(poses.camera->rows.size(), 1703u);
  EXPECT_DOUBLE_EQ(*poses.robot.rows.front().stamp, 1487321563.68);
  EXPECT_DOUBLE_EQ(*poses.robot.rows.back().stamp, 1487321620.00);
  EXPECT_DOUBLE_EQ(*poses.camera->rows.front().stamp, 1487321563.1803279);
  EXPECT_EQ(poses.robot.rows[5].id, "r5");
  EXPECT_EQ(poses.camera->rows[5].id, "c5");
  // Robot row 0 as in the file: t = (0.6177, 0.0326, 0.8919), q (x,y,z,w) read in that order.
  const Pose& robot0 = poses.robot.rows[0].pose;
  EXPECT_NEAR(robot0.translation().x(), 0.617706133479, 1e-12);
  const Eigen::Quaterniond q(robot0.linear());
  EXPECT_NEAR(std::abs(q.w()), 0.450630511528, 1e-9);
  EXPECT_NEAR(std::abs(q.x()), 0.534764115264, 1e-9);

  const auto pairs = PairByStamp(poses.robot, *poses.camera);
  const Pose X = ReferenceX();
  std::vector<Pose> targets;
  std::vector<Pose> wrong;
  for (const auto& [r, c] : pairs) {
    const Pose& T_base_gripper = poses.robot.rows[r].pose;
    const Pose& T_camera_target = poses.camera->rows[c].pose;
    targets.push_back(T_base_gripper * X * T_camera_target);
    wrong.push_back(T_base_gripper * X * T_camera_target.inverse());  // T_W_E not inverted
  }
  const Pose mean = testing::ChordalMean(targets);
  const testing::Spread spread = testing::SpreadAround(targets, mean);
  const double std_max_axis = testing::MaxAxisStd(targets);
  std::printf(
      "[ethz] %zu pairs; T_base_target t = (%.4f, %.4f, %.4f) m, max-axis std %.2f mm, "
      "rotation spread mean %.2f / max %.2f deg\n",
      pairs.size(), mean.translation().x(), mean.translation().y(), mean.translation().z(),
      std_max_axis * 1e3, spread.mean_rotation_deg, spread.max_rotation_deg);
  // SOURCE.md: 57 pairs, target in base t = (0.6589, -0.2100, 0.0084) m, std 2-3 mm.
  EXPECT_NEAR(static_cast<double>(pairs.size()), 57.0, 2.0);
  EXPECT_NEAR(mean.translation().x(), 0.6589, 0.005);
  EXPECT_NEAR(mean.translation().y(), -0.2100, 0.005);
  EXPECT_NEAR(mean.translation().z(), 0.0084, 0.005);
  EXPECT_LT(std_max_axis, 0.005);
  EXPECT_LT(spread.max_rotation_deg, 3.0);
  EXPECT_GT(testing::MaxAxisStd(wrong), 0.05);
}

void ExpectEthzError(const std::string& robot, const std::string& camera, const std::string& part) {
  try {
    ParseEthzStreams(robot, "robot.csv", camera, "camera.csv");
    ADD_FAILURE() << "no error; expected " << part;
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr(part));
  }
}

TEST(ImportEthz, InvertsTheCameraStream) {
  // Camera at (0, 0, -1) in the target frame, looking along +z: the target is at +1 m in z.
  const ImportedPoses poses =
      ParseEthzStreams("1.0, 0.1, 0.2, 0.3, 0, 0, 0, 1\n", "robot.csv",
                       "1.5, 0, 0, -1, 0, 0, 0, 1\n2.5, 0, 0, -2, 0, 0, 0, 1\n", "camera.csv");
  EXPECT_TRUE(poses.robot.rows[0].pose.translation().isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
  EXPECT_TRUE(poses.camera->rows[1].pose.translation().isApprox(Eigen::Vector3d(0, 0, 2)));
  EXPECT_DOUBLE_EQ(*poses.camera->rows[1].stamp, 2.5);
}

TEST(ImportEthz, AcceptsTheReadmeHeaderLine) {
  const ImportedPoses poses = ParseEthzStreams(
      "t, x, y, z, q_x, q_y, q_z, q_w\n1.0, 0.1, 0.2, 0.3, 0, 0, 0, 1\n", "robot.csv",
      "T,X,Y,Z,QX,QY,QZ,QW\n1.5, 0, 0, -1, 0, 0, 0, 1\n", "camera.csv");
  EXPECT_EQ(poses.robot.rows.size(), 1u);
  EXPECT_EQ(poses.robot.rows[0].line, 2);
  EXPECT_EQ(poses.camera->rows.size(), 1u);
}

TEST(ImportEthz, RejectsBadInput) {
  const std::string good = "1.0, 0, 0, 0, 0, 0, 0, 1\n";
  ExpectEthzError("", good, "robot.csv: the file has no poses");
  ExpectEthzError(good, "\n\n", "camera.csv: the file has no poses");
  ExpectEthzError("t, x, y, z, qw, qx, qy, qz\n" + good, good, "robot.csv:1: field 1");
  ExpectEthzError(good + "t, x, y, z, q_x, q_y, q_z, q_w\n", good, "robot.csv:2: field 1");
  ExpectEthzError(good + "2.0, 0, 0, 0, 0, 0, 1\n", good, "robot.csv:2: expected 8 numbers");
  ExpectEthzError(good, "1.0, 0, 0, 0, 0, 0, 0, 0\n", "zero quaternion");
  ExpectEthzError(good, "1.0, 0, 0, 0, 0, 0, 0, 2\n", "norm 2");
  ExpectEthzError("nan, 0, 0, 0, 0, 0, 0, 1\n", good, "stamp is not finite");
  ExpectEthzError("1.0, inf, 0, 0, 0, 0, 0, 1\n", good, "non-finite");
}

}  // namespace
}  // namespace hecal::io
