#include "hecal/estimation/loop_residual.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "hecal/geometry/se3.h"
#include "testing/random_poses.h"

namespace hecal::estimation {
namespace {

// Central differences of r = Log(Z⁻¹ A X B) under X·Exp(h e_k), Z·Exp(h e_k) — independent of the
// analytic formula.
Matrix6x12d NumericJacobian(const Pose& A, const Pose& B, const Pose& X, const Pose& Z) {
  constexpr double h = 1e-6;
  Matrix6x12d J;
  for (int k = 0; k < 12; ++k) {
    Vector6d e = Vector6d::Zero();
    e(k % 6) = h;
    const bool on_x = k < 6;
    const Vector6d plus =
        LoopResidual(A, B, on_x ? X * se3::Exp(e) : X, on_x ? Z : Z * se3::Exp(e));
    const Vector6d minus =
        LoopResidual(A, B, on_x ? X * se3::Exp(-e) : X, on_x ? Z : Z * se3::Exp(-e));
    J.col(k) = (plus - minus) / (2.0 * h);
  }
  return J;
}

TEST(LoopResidual, ZeroOnAConsistentLoop) {
  std::mt19937_64 rng(3);
  const Pose X = testing::RandomPose(rng, 0.05);
  const Pose Z = testing::RandomPose(rng, 1.0);
  const Pose B = testing::RandomPose(rng, 1.0);
  const Pose A = Z * B.inverse() * X.inverse();
  EXPECT_LT(LoopResidual(A, B, X, Z).norm(), 1e-14);
}

TEST(LoopResidual, AnalyticJacobianMatchesFiniteDifferences) {
  std::mt19937_64 rng(4);
  // Residual angles from 0 (a consistent loop) to near π.
  for (double residual_angle : {0.0, 1e-3, 0.3, 1.5, 2.8, 3.1}) {
    for (int trial = 0; trial < 5; ++trial) {
      const Pose X = testing::RandomPose(rng, 0.5);
      const Pose Z = testing::RandomPose(rng, 1.0);
      const Pose B = testing::RandomPose(rng, 1.0);
      Vector6d error;
      error << testing::RandomRotationVector(rng, residual_angle), 0.2, -0.1, 0.3;
      if (residual_angle == 0.0) error.setZero();
      // A chosen so that Z⁻¹ A X B = Exp(error).
      const Pose A = Z * se3::Exp(error) * B.inverse() * X.inverse();
      Matrix6x12d J;
      const Vector6d r = LoopResidual(A, B, X, Z, &J);
      EXPECT_LT((r - error).norm(), 1e-9);
      const Matrix6x12d numeric = NumericJacobian(A, B, X, Z);
      EXPECT_LT((J - numeric).norm(), 1e-6 * (1.0 + numeric.norm()))
          << "angle " << residual_angle << "\nanalytic\n"
          << J << "\nnumeric\n"
          << numeric;
    }
  }
}

// The Ceres cost through the manifold: (ambient Jacobian) · PlusJacobian must be the derivative
// of the whitened residual along Plus(x, δ), checked by differences through Plus itself.
TEST(LoopCost, TangentJacobianThroughManifoldMatchesFiniteDifferences) {
  std::mt19937_64 rng(5);
  const Se3RightManifold manifold;
  const Pose X = testing::RandomPose(rng, 0.05);
  const Pose Z = testing::RandomPose(rng, 1.0);
  const Pose B = testing::RandomPose(rng, 1.0);
  Vector6d error;
  error << 0.1, -0.2, 0.05, 0.01, 0.02, -0.03;
  const Pose A = Z * se3::Exp(error) * B.inverse() * X.inverse();
  Matrix6d M = Matrix6d::Random();
  const Matrix6d whitening = M * M.transpose() + Matrix6d::Identity();
  std::unique_ptr<ceres::CostFunction> cost(LoopCost::Create(A, B, whitening));

  double x[kPoseAmbientSize], z[kPoseAmbientSize];
  PoseToParameters(X, x);
  PoseToParameters(Z, z);
  const double* parameters[2] = {x, z};
  Vector6d residual;
  Eigen::Matrix<double, 6, kPoseAmbientSize, Eigen::RowMajor> ambient[2];
  double* jacobians[2] = {ambient[0].data(), ambient[1].data()};
  ASSERT_TRUE(cost->Evaluate(parameters, residual.data(), jacobians));
  EXPECT_LT((residual - whitening * error).norm(), 1e-9);

  Eigen::Matrix<double, kPoseAmbientSize, kPoseTangentSize, Eigen::RowMajor> plus_jacobian;
  for (int block = 0; block < 2; ++block) {
    double* p = block == 0 ? x : z;
    ASSERT_TRUE(manifold.PlusJacobian(p, plus_jacobian.data()));
    const Matrix6d tangent = ambient[block] * plus_jacobian;
    constexpr double h = 1e-6;
    for (int k = 0; k < 6; ++k) {
      Vector6d delta = Vector6d::Zero();
      double moved_plus[kPoseAmbientSize], moved_minus[kPoseAmbientSize];
      delta(k) = h;
      manifold.Plus(p, delta.data(), moved_plus);
      delta(k) = -h;
      manifold.Plus(p, delta.data(), moved_minus);
      Vector6d r_plus, r_minus;
      const double* pp[2] = {block == 0 ? moved_plus : x, block == 0 ? z : moved_plus};
      const double* pm[2] = {block == 0 ? moved_minus : x, block == 0 ? z : moved_minus};
      cost->Evaluate(pp, r_plus.data(), nullptr);
      cost->Evaluate(pm, r_minus.data(), nullptr);
      const Vector6d numeric = (r_plus - r_minus) / (2.0 * h);
      EXPECT_LT((tangent.col(k) - numeric).norm(), 1e-6 * (1.0 + numeric.norm()))
          << "block " << block << " column " << k;
    }
  }
}

}  // namespace
}  // namespace hecal::estimation
