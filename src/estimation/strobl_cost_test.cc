#include "hecal/estimation/strobl_cost.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "testing/random_poses.h"

namespace hecal::estimation {
namespace {

struct Loop {
  Pose A, B, X, Z;
};

// A loop whose discrepancy Z⁻¹ A X B is Exp(error).
Loop MakeLoop(std::mt19937_64& rng, const Vector6d& error) {
  Loop loop;
  loop.X = testing::RandomPose(rng, 0.5);
  loop.Z = testing::RandomPose(rng, 1.0);
  loop.B = testing::RandomPose(rng, 1.0);
  loop.A = loop.Z * se3::Exp(error) * loop.B.inverse() * loop.X.inverse();
  return loop;
}

TEST(StroblResidual, RotationAngleAndBothTranslationEnds) {
  std::mt19937_64 rng(41);
  Vector6d error;
  error << 0.3, -0.2, 0.1, 0.05, 0.02, -0.04;
  const Loop loop = MakeLoop(rng, error);
  const Vector9d e = StroblResidual(loop.A, loop.B, loop.X, loop.Z);
  const Pose M = loop.A * loop.X * loop.B;
  // Rotation angle from the trace formula (independent of Log).
  const double angle = std::acos((loop.Z.linear().transpose() * M.linear()).trace() * 0.5 - 0.5);
  EXPECT_NEAR(e.head<3>().norm(), angle, 1e-12);
  // Target end: distance between the target origins |t_M − t_Z|; base end: where M Z⁻¹ moves
  // the base origin.
  const double target_end = (M.translation() - loop.Z.translation()).norm();
  const double base_end = (M * loop.Z.inverse()).translation().norm();
  EXPECT_NEAR(e.segment<3>(3).squaredNorm() + e.segment<3>(6).squaredNorm(),
              0.5 * (target_end * target_end + base_end * base_end), 1e-12);
  EXPECT_GT(std::abs(target_end - base_end), 1e-3);  // the two ends really differ
}

TEST(StroblResidual, AnalyticJacobianMatchesFiniteDifferences) {
  std::mt19937_64 rng(42);
  for (double angle : {0.0, 1e-3, 0.5, 2.0, 3.0}) {
    Vector6d error;
    error << testing::RandomRotationVector(rng, angle), 0.1, -0.3, 0.2;
    const Loop loop = MakeLoop(rng, error);
    Matrix9x12d J;
    StroblResidual(loop.A, loop.B, loop.X, loop.Z, &J);
    Matrix9x12d numeric;
    constexpr double h = 1e-6;
    for (int k = 0; k < 12; ++k) {
      Vector6d d = Vector6d::Zero();
      d(k % 6) = h;
      auto at = [&](double sign) {
        const Pose X = k < 6 ? loop.X * se3::Exp(sign * d) : loop.X;
        const Pose Z = k < 6 ? loop.Z : loop.Z * se3::Exp(sign * d);
        return StroblResidual(loop.A, loop.B, X, Z);
      };
      numeric.col(k) = (at(1.0) - at(-1.0)) / (2.0 * h);
    }
    EXPECT_LT((J - numeric).norm(), 1e-6 * (1.0 + numeric.norm())) << "angle " << angle;
  }
}

TEST(StroblCost, WeightsTheResidualAndItsJacobian) {
  std::mt19937_64 rng(43);
  Vector6d error;
  error << 0.1, 0.2, -0.1, 0.01, 0.0, 0.02;
  const Loop loop = MakeLoop(rng, error);
  const double sigma_r = 0.01, sigma_t = 0.002;
  std::unique_ptr<ceres::CostFunction> cost(StroblCost::Create(loop.A, loop.B, sigma_r, sigma_t));
  double x[kPoseAmbientSize], z[kPoseAmbientSize];
  PoseToParameters(loop.X, x);
  PoseToParameters(loop.Z, z);
  const double* parameters[2] = {x, z};
  Vector9d residual;
  Eigen::Matrix<double, 9, kPoseAmbientSize, Eigen::RowMajor> ambient[2];
  double* jacobians[2] = {ambient[0].data(), ambient[1].data()};
  ASSERT_TRUE(cost->Evaluate(parameters, residual.data(), jacobians));
  Matrix9x12d J;
  const Vector9d e = StroblResidual(loop.A, loop.B, loop.X, loop.Z, &J);
  EXPECT_LT((residual.head<3>() - e.head<3>() / sigma_r).norm(), 1e-9);
  EXPECT_LT((residual.tail<6>() - e.tail<6>() / sigma_t).norm(), 1e-9);
  EXPECT_LT((ambient[1].leftCols<6>().bottomRows<6>() - J.block<6, 6>(3, 6) / sigma_t).norm(),
            1e-6);
  EXPECT_EQ(ambient[0].col(6).norm(), 0.0);
}

}  // namespace
}  // namespace hecal::estimation
