#include "hecal/handeye/shiu_ahmad.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <vector>

#include "handeye/handeye_test_util.h"
#include "hecal/core/error.h"
#include "hecal/geometry/skew.h"
#include "hecal/geometry/so3.h"
#include "testing/handeye_solver_suite.h"

namespace hecal::handeye {
namespace {

// X maps the camera-side axis of the first motion to its negative (k_A = −k_B): the rotation
// R_0 taking k_B to k_A is not the minimal one, which is where an implementation built on
// k_B × k_A would divide by zero.
TEST(ShiuAhmad, AntiparallelAxesAreNoSpecialCase) {
  std::mt19937_64 rng(61);
  const Eigen::Vector3d k_B = testing::RandomUnitVector(rng);
  const Eigen::Vector3d normal = k_B.cross(testing::RandomUnitVector(rng)).normalized();
  Pose X = testing::RandomPose(rng, 0.1);
  X.linear() = so3::Exp(std::numbers::pi * normal);  // half-turn about an axis normal to k_B
  std::vector<Motion> motions = {MotionFor(X, 1.1 * k_B, rng),
                                 MotionFor(X, 0.8 * testing::RandomUnitVector(rng), rng)};
  ASSERT_LT((so3::Log(motions[0].A.linear()).normalized() + k_B).norm(), 1e-12);
  testing::ExpectPoseNear(SolveShiuAhmad(motions), X, 1e-9, "X");
}

// One motion leaves the one-parameter family Rot(k_A, β) R_0: the normal matrix is singular.
TEST(ShiuAhmad, OneMotionLeavesTheFamilyUndetermined) {
  std::mt19937_64 rng(62);
  const Pose X = testing::RandomPose(rng, 0.1);
  EXPECT_THROW(SolveShiuAhmad({MotionFor(X, Eigen::Vector3d(0.3, -1.0, 0.4), rng)}),
               DegenerateError);
}

// The basis-free projector of shiu_ahmad.h (S2): for unit k_A, k_B and any bases
// (e₁, e₂, k_B), (f₁, f₂, k_A), v vᵀ + w wᵀ = (I − k_B k_Bᵀ) ⊗ (I − k_A k_Aᵀ) + [k_B]× ⊗ [k_A]×
// with v = vec(f₁e₁ᵀ + f₂e₂ᵀ), w = vec(f₂e₁ᵀ − f₁e₂ᵀ) (column-major vec).
TEST(ShiuAhmad, FamilyProjectorIdentity) {
  std::mt19937_64 rng(63);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Vector3d k_A = testing::RandomUnitVector(rng);
    const Eigen::Vector3d k_B = testing::RandomUnitVector(rng);
    const Eigen::Vector3d e1 = k_B.cross(testing::RandomUnitVector(rng)).normalized();
    const Eigen::Vector3d f1 = k_A.cross(testing::RandomUnitVector(rng)).normalized();
    const Eigen::Vector3d e2 = k_B.cross(e1), f2 = k_A.cross(f1);
    const Eigen::Matrix3d V = f1 * e1.transpose() + f2 * e2.transpose();
    const Eigen::Matrix3d W = f2 * e1.transpose() - f1 * e2.transpose();
    const Eigen::Map<const Eigen::Matrix<double, 9, 1>> v(V.data()), w(W.data());
    const Eigen::Matrix<double, 9, 9> lhs = v * v.transpose() + w * w.transpose();
    const Eigen::Matrix3d P_B = Eigen::Matrix3d::Identity() - k_B * k_B.transpose();
    const Eigen::Matrix3d P_A = Eigen::Matrix3d::Identity() - k_A * k_A.transpose();
    Eigen::Matrix<double, 9, 9> rhs;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        rhs.block<3, 3>(3 * r, 3 * c) = P_B(r, c) * P_A + Skew(k_B)(r, c) * Skew(k_A);
      }
    }
    EXPECT_LT((lhs - rhs).cwiseAbs().maxCoeff(), 1e-14);
    // …and every member U + cos β V + sin β W of the family maps k_B to k_A and is a rotation.
    const Eigen::Matrix3d R = k_A * k_B.transpose() + std::cos(0.7) * V + std::sin(0.7) * W;
    EXPECT_LT((R * k_B - k_A).norm(), 1e-14);
    EXPECT_LT(so3::OrthonormalityError(R), 1e-14);
  }
}

}  // namespace
}  // namespace hecal::handeye
