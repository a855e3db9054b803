// The scene generator (testing/scene.h) against its own definition: the truth satisfies
// Z = A_i X B_i (handeye/problem.h) in both setups, the cameras stay in the cube and within the
// tilt of the protocol, noise has the stated standard deviation, and gross outliers replace
// exactly the robot poses they report.
#include "testing/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"

namespace hecal::testing {
namespace {

class SceneSetupTest : public ::testing::TestWithParam<handeye::Setup> {};

TEST_P(SceneSetupTest, TruthSatisfiesTheModelAndTheProtocolBounds) {
  std::mt19937_64 rng(7);
  SceneOptions options;
  options.setup = GetParam();
  options.stations = 40;
  const Scene scene = MakeScene(options, rng);
  ASSERT_EQ(scene.T_base_gripper_true.size(), 40u);
  const bool in_hand = GetParam() == handeye::Setup::kEyeInHand;
  const Pose& flange_offset = in_hand ? scene.X : scene.Z;
  EXPECT_LE(flange_offset.translation().cwiseAbs().maxCoeff(), options.hand_eye_offset);
  for (size_t i = 0; i < 40; ++i) {
    const Pose& G = scene.T_base_gripper_true[i];
    const Pose A = in_hand ? G : G.inverse();
    const Pose ZXB = A * scene.X * scene.T_camera_target_true[i];
    EXPECT_LT((ZXB.matrix() - scene.Z.matrix()).norm(), 1e-12);
    // Noise-free: measured = true.
    EXPECT_TRUE(scene.T_base_gripper[i].isApprox(G, 0.0));
    EXPECT_TRUE(scene.T_camera_target[i].isApprox(scene.T_camera_target_true[i], 0.0));
    const Pose T_target_camera = scene.T_camera_target_true[i].inverse();
    const Eigen::Vector3d offset =
        T_target_camera.translation() - Eigen::Vector3d(0.0, 0.0, -options.start_distance);
    EXPECT_LE(offset.cwiseAbs().maxCoeff(), 0.5 * options.cube_side);
    // The optical axis leans from the target normal by at most the combined tilt:
    // cos(angle) = cos α cos β.
    const double lean = std::acos(T_target_camera.linear()(2, 2));
    EXPECT_LE(lean, std::acos(std::cos(options.max_tilt) * std::cos(options.max_tilt)) + 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(BothSetups, SceneSetupTest,
                         ::testing::Values(handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand));

TEST(SceneTest, NoiseIsARightPerturbationWithTheStatedSigma) {
  std::mt19937_64 rng(8);
  const PoseNoise noise{0.01, 0.002};
  const Pose T = MakePose(so3::Exp(Eigen::Vector3d(0.3, -0.2, 1.0)), Eigen::Vector3d(1, 2, 3));
  constexpr int kDraws = 20000;
  Vector6d sum = Vector6d::Zero(), sum_sq = Vector6d::Zero();
  for (int k = 0; k < kDraws; ++k) {
    const Vector6d delta = se3::Log(T.inverse() * AddPoseNoise(T, noise, rng));
    sum += delta;
    sum_sq += delta.cwiseProduct(delta);
  }
  for (int k = 0; k < 6; ++k) {
    const double sigma = k < 3 ? noise.rotation_sigma : noise.translation_sigma;
    EXPECT_NEAR(sum(k) / kDraws, 0.0, 5.0 * sigma / std::sqrt(kDraws)) << k;
    EXPECT_NEAR(std::sqrt(sum_sq(k) / kDraws), sigma, 0.03 * sigma) << k;
  }
  EXPECT_TRUE(AddPoseNoise(T, PoseNoise{}, rng).isApprox(T, 0.0));
}

TEST(SceneTest, ReplaceRobotPosesReplacesExactlyTheReportedStations) {
  std::mt19937_64 rng(9);
  SceneOptions options;
  options.stations = 12;
  Scene scene = MakeScene(options, rng);
  const Scene clean = scene;
  const std::vector<int> replaced = ReplaceRobotPoses(&scene, 5, rng);
  ASSERT_EQ(replaced.size(), 5u);
  EXPECT_TRUE(std::is_sorted(replaced.begin(), replaced.end()));
  const std::set<int> distinct(replaced.begin(), replaced.end());
  EXPECT_EQ(distinct.size(), 5u);
  for (int i = 0; i < 12; ++i) {
    const auto k = static_cast<size_t>(i);
    const bool moved = !scene.T_base_gripper[k].isApprox(clean.T_base_gripper[k], 1e-9);
    EXPECT_EQ(moved, distinct.count(i) == 1) << i;
    EXPECT_TRUE(scene.T_camera_target[k].isApprox(clean.T_camera_target[k], 0.0));
    if (moved) {
      EXPECT_LE(scene.T_base_gripper[k].translation().cwiseAbs().maxCoeff(), 1.0);
    }
  }
  EXPECT_THROW(ReplaceRobotPoses(&scene, 13, rng), std::invalid_argument);
  EXPECT_TRUE(ReplaceRobotPoses(&scene, 0, rng).empty());
}

}  // namespace
}  // namespace hecal::testing
