#include "hecal/estimation/reprojection_cost.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "hecal/geometry/se3.h"
#include "testing/image_scene.h"
#include "testing/random_poses.h"

namespace hecal::estimation {
namespace {

// The residual is the whitened pixel error of the model, and the analytic Jacobians (lifted into
// the ambient layout) match central differences of the residual along right perturbations of X,
// Z and G and along each intrinsic parameter, for both setups.
TEST(ReprojectionCost, JacobiansMatchFiniteDifferences) {
  std::mt19937_64 rng(3);
  const pose::CameraModel camera = testing::DefaultCamera();
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::ImageScene stations = testing::MakeImageScene(
        testing::ImageSceneOptions::For(setup, 4, 11, testing::PoseNoise{}, 0.0));
    for (size_t i = 0; i < stations.images.size(); ++i) {
      const Eigen::Vector3d P = stations.images[i].target[7];
      const Eigen::Vector2d u(300.0, 200.0);
      const ReprojectionCost cost(setup, camera, P, u, 0.5);
      std::array<Pose, 3> poses = {stations.poses.X, stations.poses.Z,
                                   stations.poses.T_base_gripper_true[i]};
      std::array<std::array<double, kPoseAmbientSize>, 3> parameters;
      for (int b = 0; b < 3; ++b) PoseToParameters(poses[b], parameters[b].data());
      const pose::IntrinsicParameters intrinsics = pose::IntrinsicsOf(camera);
      const double* blocks[4] = {parameters[0].data(), parameters[1].data(), parameters[2].data(),
                                 intrinsics.data()};
      Eigen::Vector2d r;
      std::array<Eigen::Matrix<double, 2, kPoseAmbientSize, Eigen::RowMajor>, 3> J;
      Eigen::Matrix<double, 2, pose::kNumIntrinsics, Eigen::RowMajor> J_intrinsics;
      double* jacobians[4] = {J[0].data(), J[1].data(), J[2].data(), J_intrinsics.data()};
      ASSERT_TRUE(cost.Evaluate(blocks, r.data(), jacobians));
      EXPECT_LT(
          (r - (pose::Project(camera, CameraFromUnknowns(setup, poses[0], poses[1], poses[2]) * P) -
                u) /
                   0.5)
              .norm(),
          1e-9);
      for (int b = 0; b < 3; ++b) {
        EXPECT_EQ(J[b].col(6).norm(), 0.0);
        for (int k = 0; k < 6; ++k) {
          constexpr double h = 1e-6;
          Vector6d e = Vector6d::Zero();
          e(k) = h;
          Eigen::Vector2d r_plus, r_minus;
          for (double sign : {1.0, -1.0}) {
            std::array<double, kPoseAmbientSize> moved;
            PoseToParameters(poses[b] * se3::Exp(sign * e), moved.data());
            const double* perturbed[4] = {blocks[0], blocks[1], blocks[2], blocks[3]};
            perturbed[b] = moved.data();
            ASSERT_TRUE(cost.Evaluate(perturbed, (sign > 0 ? r_plus : r_minus).data(), nullptr));
          }
          const Eigen::Vector2d numeric = (r_plus - r_minus) / (2.0 * h);
          EXPECT_LT((numeric - J[b].col(k)).norm(), 1e-5 * (1.0 + numeric.norm()))
              << "block " << b << " column " << k;
        }
      }
      for (int k = 0; k < pose::kNumIntrinsics; ++k) {
        const double h = 1e-5 * std::max(1.0, std::abs(intrinsics(k)));
        pose::IntrinsicParameters plus = intrinsics, minus = intrinsics;
        plus(k) += h;
        minus(k) -= h;
        Eigen::Vector2d r_plus, r_minus;
        const double* blocks_plus[4] = {blocks[0], blocks[1], blocks[2], plus.data()};
        const double* blocks_minus[4] = {blocks[0], blocks[1], blocks[2], minus.data()};
        ASSERT_TRUE(cost.Evaluate(blocks_plus, r_plus.data(), nullptr));
        ASSERT_TRUE(cost.Evaluate(blocks_minus, r_minus.data(), nullptr));
        const Eigen::Vector2d numeric = (r_plus - r_minus) / (2.0 * h);
        EXPECT_LT((numeric - J_intrinsics.col(k)).norm(), 1e-6 * (1.0 + numeric.norm()))
            << "intrinsic " << k;
      }
    }
  }
}

TEST(ReprojectionCost, CameraFromUnknownsFollowsTheModel) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::ImageScene stations = testing::MakeImageScene(
        testing::ImageSceneOptions::For(setup, 5, 12, testing::PoseNoise{}, 0.0));
    for (size_t i = 0; i < 5; ++i) {
      const Pose B = CameraFromUnknowns(setup, stations.poses.X, stations.poses.Z,
                                        stations.poses.T_base_gripper_true[i]);
      EXPECT_TRUE(B.isApprox(stations.poses.T_camera_target_true[i], 1e-12));
    }
  }
}

TEST(RobotPosePriorCost, IsTheWhitenedLogAndItsJacobian) {
  std::mt19937_64 rng(5);
  const Pose measured = testing::RandomPose(rng, 1.0);
  const Pose G =
      measured * se3::Exp((Vector6d() << 0.01, -0.02, 0.005, 0.003, 0.001, -0.002).finished());
  const RobotPosePriorCost cost(measured, 0.002, 0.0005);
  std::array<double, kPoseAmbientSize> p;
  PoseToParameters(G, p.data());
  const double* blocks[1] = {p.data()};
  Vector6d r;
  Eigen::Matrix<double, 6, kPoseAmbientSize, Eigen::RowMajor> J;
  double* jacobians[1] = {J.data()};
  ASSERT_TRUE(cost.Evaluate(blocks, r.data(), jacobians));
  Vector6d expected = se3::Log(measured.inverse() * G);
  expected.head<3>() /= 0.002;
  expected.tail<3>() /= 0.0005;
  EXPECT_LT((r - expected).norm(), 1e-9);
  for (int k = 0; k < 6; ++k) {
    constexpr double h = 1e-7;
    Vector6d e = Vector6d::Zero();
    e(k) = h;
    std::array<double, kPoseAmbientSize> plus, minus;
    PoseToParameters(G * se3::Exp(e), plus.data());
    PoseToParameters(G * se3::Exp(-e), minus.data());
    Vector6d rp, rm;
    const double* bp[1] = {plus.data()};
    const double* bm[1] = {minus.data()};
    ASSERT_TRUE(cost.Evaluate(bp, rp.data(), nullptr));
    ASSERT_TRUE(cost.Evaluate(bm, rm.data(), nullptr));
    EXPECT_LT(((rp - rm) / (2 * h) - J.col(k).head<6>()).norm(), 1e-4 * (1.0 + J.col(k).norm()));
  }
}

}  // namespace
}  // namespace hecal::estimation
