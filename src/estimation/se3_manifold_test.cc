#include "hecal/estimation/se3_manifold.h"

#include <gtest/gtest.h>

#include <random>

#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "testing/random_poses.h"

namespace hecal::estimation {
namespace {

using AmbientVector = Eigen::Matrix<double, kPoseAmbientSize, 1>;

TEST(Se3Manifold, ParametersRoundTrip) {
  std::mt19937_64 rng(1);
  for (int trial = 0; trial < 20; ++trial) {
    const Pose T = testing::RandomPose(rng, 2.0);
    double p[kPoseAmbientSize];
    PoseToParameters(T, p);
    EXPECT_NEAR(Eigen::Map<Eigen::Vector4d>(p).norm(), 1.0, 1e-15);
    EXPECT_LT((PoseFromParameters(p).matrix() - T.matrix()).norm(), 1e-14);
  }
}

TEST(Se3Manifold, PlusIsRightMultiplicationByExp) {
  std::mt19937_64 rng(2);
  const Se3RightManifold manifold;
  for (const Eigen::Vector3d& omega : testing::EdgeCaseRotationVectors(rng)) {
    const Pose T = testing::RandomPose(rng, 1.0);
    Vector6d delta;
    delta << omega, 0.3, -0.2, 0.1;
    double x[kPoseAmbientSize], y[kPoseAmbientSize];
    PoseToParameters(T, x);
    ASSERT_TRUE(manifold.Plus(x, delta.data(), y));
    const Pose expected = T * se3::Exp(delta);
    EXPECT_LT((PoseFromParameters(y).matrix() - expected.matrix()).norm(), 1e-12);
    // Minus inverts Plus (|ω| < π; at exactly π the sign of ω is ambiguous).
    if (omega.norm() < 3.14) {
      Vector6d back;
      ASSERT_TRUE(manifold.Minus(y, x, back.data()));
      EXPECT_LT((back - delta).norm(), 1e-9) << omega.transpose();
    }
  }
}

TEST(Se3Manifold, LiftedJacobiansAreLeftInverses) {
  const Se3RightManifold manifold;
  double x[kPoseAmbientSize];
  PoseToParameters(Pose::Identity(), x);
  Eigen::Matrix<double, kPoseAmbientSize, kPoseTangentSize, Eigen::RowMajor> plus;
  Eigen::Matrix<double, kPoseTangentSize, kPoseAmbientSize, Eigen::RowMajor> minus;
  ASSERT_TRUE(manifold.PlusJacobian(x, plus.data()));
  ASSERT_TRUE(manifold.MinusJacobian(x, minus.data()));
  EXPECT_TRUE((minus * plus).isIdentity(0.0));
  EXPECT_EQ(plus.row(6).norm(), 0.0);
}

}  // namespace
}  // namespace hecal::estimation
