// Property tests for se3.h. Independent truth: the 4×4 matrix exponential of the twist (Eigen's
// unsupported MatrixFunctions, Padé with scaling and squaring), screw motions constructed from an
// axis line, the adjoint identities, and the Jacobians' inverse and left/right relations on both
// sides of se3.cc's series threshold (θ = 0.1), so3.cc's (θ = 1e-2), and near π. Exp∘Log,
// Log∘Exp and the Jacobians against finite differences are the typed Lie-group suite's
// (lie_group_test.cc).
// Tangent order is (ω, v), rotation first (docs/conventions.md).
#include "hecal/geometry/se3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "geometry/geometry_test_util.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/skew.h"
#include "hecal/geometry/so3.h"
#include "testing/random_poses.h"
#include "testing/screw_motions.h"

namespace hecal {
namespace {

constexpr int kSe3Samples = 3000;

// exp of the 4×4 twist matrix [[ω]× v; 0 0]: a peer that knows nothing about Jacobians.
Eigen::Matrix4d MatrixExponential(const Vector6d& xi) {
  Eigen::Matrix4d X = Eigen::Matrix4d::Zero();
  X.topLeftCorner<3, 3>() = Skew(xi.head<3>());
  X.topRightCorner<3, 1>() = xi.tail<3>();
  return X.exp();
}

// Rotation angles for Jacobian checks: tiny, both sides of 1e-2 (so3 series) and of 0.1 (the
// coupling block's series), generic, near π.
const std::vector<double>& Se3JacobianTestAngles() {
  static const std::vector<double> angles = {0.0,
                                             1e-9,
                                             1e-6,
                                             1e-4,
                                             0.99e-2,
                                             1.01e-2,
                                             0.0999,
                                             0.1001,
                                             0.5,
                                             1.0,
                                             2.0,
                                             3.0,
                                             std::numbers::pi - 1e-2,
                                             std::numbers::pi - 1e-3};
  return angles;
}

TEST(Se3, TangentOrderIsRotationFirst) {
  // (0,0,0, 1,0,0) is a pure translation along x; (θ,0,0, 0,0,0) a pure rotation about x.
  const Pose T = se3::Exp(testing::Twist(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()));
  EXPECT_EQ(T.linear(), Eigen::Matrix3d::Identity());
  EXPECT_EQ(T.translation(), Eigen::Vector3d::UnitX());
  const Pose R = se3::Exp(testing::Twist(0.5 * Eigen::Vector3d::UnitX(), Eigen::Vector3d::Zero()));
  EXPECT_LT(
      MaxAbs(R.linear() - Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()).toRotationMatrix()),
      1e-16);
  EXPECT_EQ(R.translation(), Eigen::Vector3d::Zero());
  // Log of a pure translation puts it in the last three slots.
  const Vector6d xi = se3::Log(MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 2, 3)));
  EXPECT_EQ(xi, testing::Twist(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 3)));
  // ω ∥ v: a screw along z, rotation θ and translation d along the same axis.
  const Pose S = se3::Exp(testing::Twist(Eigen::Vector3d(0, 0, 1.2), Eigen::Vector3d(0, 0, 0.7)));
  EXPECT_LT((S.translation() - Eigen::Vector3d(0, 0, 0.7)).norm(), 1e-16);
}

TEST(Se3Exp, MatchesMatrixExponential) {
  std::mt19937_64 rng(301);
  std::vector<Vector6d> twists = testing::RandomTwists(rng, kSe3Samples, 3.0 * std::numbers::pi);
  for (const Vector6d& xi : twists) {
    const double scale = 1.0 + xi.tail<3>().norm();
    EXPECT_LT(MaxAbs(se3::Exp(xi).matrix() - MatrixExponential(xi)), 1e-14 * scale)
        << xi.transpose();
  }
}

TEST(Se3Exp, GivesTheConstructedScrewMotion) {
  // Chasles: Exp(θ n, θ c × n + d n) is rotation θ about the line through c along n, then d.
  std::mt19937_64 rng(302);
  for (int i = 0; i < kSe3Samples; ++i) {
    const auto [n, c, theta, d] = testing::RandomScrewLine(rng);
    const Pose expected = testing::ScrewMotion(n, c, theta, d);
    const Vector6d xi = testing::Twist(theta * n, theta * c.cross(n) + d * n);
    EXPECT_LT(PoseError(se3::Exp(xi), expected), 1e-14 * (1 + c.norm())) << theta;
  }
}

TEST(Se3Adjoint, MatchesExplicitBlocksAndConjugation) {
  std::mt19937_64 rng(305);
  for (int i = 0; i < kSe3Samples; ++i) {
    const Pose T = testing::RandomPose(rng, 2.0);
    const Matrix6d Ad = se3::Adjoint(T);
    // (ω, v) order: [R 0; [t]× R  R].
    const Eigen::Matrix3d R = T.linear();
    EXPECT_EQ(Matrix6d(Ad).topLeftCorner(3, 3), R);
    EXPECT_EQ(Matrix6d(Ad).topRightCorner(3, 3), Eigen::Matrix3d::Zero());
    EXPECT_EQ(Matrix6d(Ad).bottomRightCorner(3, 3), R);
    for (int j = 0; j < 3; ++j) {  // ([t]× R) column j = t × (R column j)
      EXPECT_LT((Ad.col(j).tail<3>() - T.translation().cross(R.col(j))).norm(), 1e-15 * 8);
    }
    // T Exp(δ) T⁻¹ = Exp(Ad(T) δ), checked with the matrix exponential peer.
    // v drawn before ω: the order these tests' data were generated in.
    const Eigen::Vector3d v = testing::RandomGaussianVector(rng);
    const Vector6d delta = testing::Twist(testing::RandomRotationVector(rng, 2.0), v);
    const Eigen::Matrix4d lhs = T.matrix() * MatrixExponential(delta) * T.inverse().matrix();
    EXPECT_LT(MaxAbs(lhs - se3::Exp(Ad * delta).matrix()), 4e-14);
  }
}

TEST(Se3Adjoint, IsAHomomorphism) {
  std::mt19937_64 rng(306);
  for (int i = 0; i < kSe3Samples; ++i) {
    const Pose T1 = testing::RandomPose(rng, 2.0);
    const Pose T2 = testing::RandomPose(rng, 2.0);
    EXPECT_LT(MaxAbs(se3::Adjoint(T1 * T2) - se3::Adjoint(T1) * se3::Adjoint(T2)), 1e-14);
    EXPECT_LT(MaxAbs(se3::Adjoint(T1.inverse()) * se3::Adjoint(T1) - Matrix6d::Identity()), 1e-14);
  }
  EXPECT_EQ(se3::Adjoint(Pose::Identity()), Matrix6d::Identity());
}

// For each test angle: 10 twists with that rotation angle and v of norm ~1.
std::vector<Vector6d> JacobianTwists(std::mt19937_64& rng) {
  std::vector<Vector6d> result;
  for (double theta : Se3JacobianTestAngles()) {
    for (int i = 0; i < 10; ++i) {
      const Eigen::Vector3d v = testing::RandomGaussianVector(rng);  // drawn before ω
      result.push_back(testing::Twist(testing::RandomRotationVector(rng, theta), v));
    }
  }
  return result;
}

TEST(Se3Jacobians, InversesAndLeftRightRelations) {
  std::mt19937_64 rng(310);
  hecal::UniformRealDistribution angle(0.0, std::numbers::pi);
  std::vector<Vector6d> twists = JacobianTwists(rng);
  for (int i = 0; i < kSe3Samples; ++i) {
    const Eigen::Vector3d v = testing::RandomGaussianVector(rng);
    twists.push_back(testing::Twist(testing::RandomRotationVector(rng, angle(rng)), v));
  }
  for (const Vector6d& xi : twists) {
    const double scale = 1 + xi.tail<3>().norm();
    EXPECT_LT(MaxAbs(se3::RightJacobian(xi) * se3::RightJacobianInverse(xi) - Matrix6d::Identity()),
              1e-14 * scale);
    EXPECT_LT(MaxAbs(se3::LeftJacobian(xi) * se3::LeftJacobianInverse(xi) - Matrix6d::Identity()),
              1e-14 * scale);
    // Jl(ξ) = Ad(Exp(ξ)) Jr(ξ): an identity the implementation does not use.
    EXPECT_LT(MaxAbs(se3::LeftJacobian(xi) - se3::Adjoint(se3::Exp(xi)) * se3::RightJacobian(xi)),
              1e-14 * scale);
    EXPECT_LT(MaxAbs(se3::LeftJacobian(xi) - se3::RightJacobian(-xi)), 1e-15 * scale);
    // Jacobians fix the generator: Jl(ξ) ξ = ξ.
    EXPECT_LT((se3::LeftJacobian(xi) * xi - xi).norm(), 1e-14 * scale);
  }
}

// Jl(ξ) = Σₙ adξⁿ / (n + 1)!, adξ = [[ω]× 0; [v]× [ω]×] in (ω, v) order, summed in long double
// (64-bit mantissa): a reference 2000 times more precise than double, independent of Barfoot's
// closed form and of its series switch.
Matrix6d LeftJacobianBySeries(const Vector6d& xi) {
  using Matrix6l = Eigen::Matrix<long double, 6, 6>;
  Matrix6l ad = Matrix6l::Zero();
  const Eigen::Matrix3d W = Skew(xi.head<3>());
  ad.topLeftCorner<3, 3>() = W.cast<long double>();
  ad.bottomRightCorner<3, 3>() = W.cast<long double>();
  ad.bottomLeftCorner<3, 3>() = Skew(xi.tail<3>()).cast<long double>();
  Matrix6l term = Matrix6l::Identity();
  Matrix6l sum = Matrix6l::Identity();
  for (int n = 1; n < 80 && term.cwiseAbs().maxCoeff() > 1e-30L; ++n) {
    term = term * ad / static_cast<long double>(n + 1);
    sum += term;
  }
  return sum.cast<double>();
}

TEST(Se3Jacobians, MatchLongDoubleSeriesToRounding) {
  std::mt19937_64 rng(313);
  std::vector<Vector6d> twists = JacobianTwists(rng);
  for (double threshold : {0.1, 1e-2}) {
    for (int i = 0; i < 50; ++i) {
      const Eigen::Vector3d n = testing::RandomUnitVector(rng);
      twists.push_back(testing::Twist(testing::RotationVectorAtThreshold(n, threshold, true),
                                      testing::RandomGaussianVector(rng)));
      twists.push_back(testing::Twist(testing::RotationVectorAtThreshold(n, threshold, false),
                                      testing::RandomGaussianVector(rng)));
    }
  }
  hecal::UniformRealDistribution angle(0.05, 0.6);  // where the closed forms cancel most
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d v = testing::RandomGaussianVector(rng);
    twists.push_back(testing::Twist(testing::RandomRotationVector(rng, angle(rng)), v));
  }
  for (const Vector6d& xi : twists) {
    const Matrix6d reference = LeftJacobianBySeries(xi);
    const double scale = 1 + xi.tail<3>().norm();
    EXPECT_LT(MaxAbs(se3::LeftJacobian(xi) - reference), 1e-15 * scale) << xi.transpose();
    EXPECT_LT(MaxAbs(se3::RightJacobian(-xi) - reference), 1e-15 * scale) << xi.transpose();
    // Jl⁻¹ against the inverse of the reference (Jl is well conditioned for θ < π).
    EXPECT_LT(MaxAbs(se3::LeftJacobianInverse(xi) * reference - Matrix6d::Identity()),
              2e-15 * scale * scale)
        << xi.transpose();
  }
}

TEST(Se3Jacobians, ContinuousAcrossSeriesThresholds) {
  // The coupling block switches to series below θ = 0.1, so3's blocks below 1e-2: on each side
  // of a threshold the two branches must agree to rounding (J moves by ≲ |v| · step there). The
  // allowance is the rounding of J⁻¹ = products of three matrices, ~2ε(1 + |v|); before the c2
  // fix in se3.cc the jump at 0.1 was 2.2e-14.
  std::mt19937_64 rng(311);
  for (double threshold : {0.1, 1e-2}) {
    for (int i = 0; i < 100; ++i) {
      const Eigen::Vector3d n = testing::RandomUnitVector(rng);
      const Eigen::Vector3d v = testing::RandomGaussianVector(rng);
      const Vector6d below =
          testing::Twist(testing::RotationVectorAtThreshold(n, threshold, true), v);
      const Vector6d above =
          testing::Twist(testing::RotationVectorAtThreshold(n, threshold, false), v);
      const double tolerance = 2e-15 * (1 + v.norm()) + (above - below).norm() * (1 + v.norm());
      EXPECT_LT(MaxAbs(se3::LeftJacobian(below) - se3::LeftJacobian(above)), tolerance);
      EXPECT_LT(MaxAbs(se3::LeftJacobianInverse(below) - se3::LeftJacobianInverse(above)),
                tolerance);
    }
  }
}

TEST(Se3Interpolate, EndpointsAndScrewGeodesic) {
  std::mt19937_64 rng(312);
  for (int i = 0; i < 1000; ++i) {
    const Pose T0 = testing::RandomPose(rng, 2.0);
    const auto [n, c, theta, d] = testing::RandomScrewLine(rng, 0.0, std::numbers::pi - 1e-6);
    const Pose T1 = T0 * testing::ScrewMotion(n, c, theta, d);
    EXPECT_LT(PoseError(se3::Interpolate(T0, T1, 0.0), T0), 1e-15);
    EXPECT_LT(PoseError(se3::Interpolate(T0, T1, 1.0), T1), 1e-14);
    for (double s : {0.1, 0.5, 0.8}) {
      // The geodesic follows the same screw: rotation sθ about the same line, translation s d.
      const Pose expected = T0 * testing::ScrewMotion(n, c, s * theta, s * d);
      EXPECT_LT(PoseError(se3::Interpolate(T0, T1, s), expected), 1e-14 * (1 + c.norm()));
    }
  }
  // Pure translation: straight-line interpolation.
  const Pose A = MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 0, 0));
  const Pose B = MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(3, 4, 0));
  EXPECT_LT((se3::Interpolate(A, B, 0.25).translation() - Eigen::Vector3d(1.5, 1, 0)).norm(),
            1e-15);
}

}  // namespace
}  // namespace hecal
