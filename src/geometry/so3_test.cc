// Property tests for so3.h. Truth comes from outside the code under test: the explicit Rodrigues
// formula, Eigen::AngleAxisd, rotations built with a known angle, acos of the trace where that is
// well conditioned, the explicit Jacobian formulas and their series. Exp∘Log below π, the adjoint
// and the Jacobians against finite differences are the typed Lie-group suite's
// (lie_group_test.cc). Every sample set includes testing::EdgeCaseRotationVectors (0, 1e-12 … 1e-2,
// exactly π about each axis, π − 1e-9 …) and gimbal-lock rotations (pitch ±π/2 with roll and yaw).
#include "hecal/geometry/so3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/geometry_test_util.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/skew.h"
#include "testing/random_poses.h"

namespace hecal {
namespace {

constexpr int kSo3Samples = 4000;

// R = I + sinθ/θ K + (1 − cosθ)/θ² K², written here independently of so3.cc (θ ≥ 1e-3 so the
// closed form is exact to rounding).
Eigen::Matrix3d RodriguesFormula(const Eigen::Vector3d& omega) {
  const double theta = omega.norm();
  const Eigen::Matrix3d K = Skew(omega);
  return Eigen::Matrix3d::Identity() + std::sin(theta) / theta * K +
         (1.0 - std::cos(theta)) / (theta * theta) * K * K;
}

// Gimbal-lock rotations of the xyz / ZYX Euler sequences: pitch exactly ±π/2.
std::vector<Eigen::Matrix3d> GimbalLockRotations() {
  std::vector<Eigen::Matrix3d> result;
  for (double pitch : {std::numbers::pi / 2, -std::numbers::pi / 2}) {
    for (double roll : {0.0, 0.3, -2.0, std::numbers::pi}) {
      for (double yaw : {0.0, 1.1, -std::numbers::pi / 2}) {
        result.push_back(Elementary(2, yaw) * Elementary(1, pitch) * Elementary(0, roll));
      }
    }
  }
  return result;
}

// Random rotations, the edge-case rotation vectors' rotations and the gimbal-lock rotations.
std::vector<Eigen::Matrix3d> TestRotations(std::mt19937_64& rng) {
  std::vector<Eigen::Matrix3d> result;
  for (int i = 0; i < kSo3Samples; ++i) result.push_back(testing::RandomRotation(rng));
  for (const Eigen::Vector3d& omega : testing::EdgeCaseRotationVectors(rng)) {
    const double theta = omega.norm();
    result.push_back(theta == 0.0 ? Eigen::Matrix3d::Identity()
                                  : Eigen::AngleAxisd(theta, omega / theta).toRotationMatrix());
  }
  for (const Eigen::Matrix3d& R : GimbalLockRotations()) result.push_back(R);
  return result;
}

// ω uniform in direction with |ω| uniform in [0, max_angle), plus the edge cases below π.
std::vector<Eigen::Vector3d> TestRotationVectors(std::mt19937_64& rng, double max_angle) {
  std::vector<Eigen::Vector3d> result;
  hecal::UniformRealDistribution angle(0.0, max_angle);
  for (int i = 0; i < kSo3Samples; ++i)
    result.push_back(testing::RandomRotationVector(rng, angle(rng)));
  for (const Eigen::Vector3d& omega : testing::EdgeCaseRotationVectors(rng)) {
    if (omega.norm() < std::numbers::pi) result.push_back(omega);
  }
  return result;
}

// Angles at which the Jacobians are checked: tiny, both sides of the series threshold (1e-2),
// generic, and near π.
const std::vector<double>& So3JacobianTestAngles() {
  static const std::vector<double> angles = {0.0,
                                             1e-9,
                                             1e-6,
                                             1e-4,
                                             0.99e-2,
                                             1.01e-2,
                                             0.1,
                                             0.5,
                                             1.0,
                                             2.0,
                                             3.0,
                                             std::numbers::pi - 1e-2,
                                             std::numbers::pi - 1e-3};
  return angles;
}

TEST(So3Exp, MatchesRodriguesFormulaAndEigenAngleAxis) {
  std::mt19937_64 rng(101);
  hecal::UniformRealDistribution angle(1e-3, 3.0 * std::numbers::pi);  // Exp is total: beyond π too
  for (int i = 0; i < kSo3Samples; ++i) {
    const Eigen::Vector3d omega = testing::RandomRotationVector(rng, angle(rng));
    const Eigen::Matrix3d R = so3::Exp(omega);
    EXPECT_LT(MaxAbs(R - RodriguesFormula(omega)), 2e-15) << omega.transpose();
    const Eigen::Matrix3d R_eigen =
        Eigen::AngleAxisd(omega.norm(), omega.normalized()).toRotationMatrix();
    EXPECT_LT(MaxAbs(R - R_eigen), 2e-15) << omega.transpose();
  }
}

TEST(So3Exp, TinyAnglesMatchTaylorSeries) {
  // For θ ≤ 1e-6, I + (1 − θ²/6) K + (½ − θ²/24) K² is exact to O(θ⁵) < 1e-30: a truth with no
  // cancellation, checked relative to θ in the off-diagonal (antisymmetric) part.
  std::mt19937_64 rng(102);
  for (double theta : {0.0, 1e-15, 1e-12, 1e-9, 1e-7, 1e-6}) {
    for (int i = 0; i < 20; ++i) {
      const Eigen::Vector3d omega = testing::RandomRotationVector(rng, theta);
      const Eigen::Matrix3d K = Skew(omega);
      const double t2 = omega.squaredNorm();
      const Eigen::Matrix3d expected =
          Eigen::Matrix3d::Identity() + (1.0 - t2 / 6.0) * K + (0.5 - t2 / 24.0) * K * K;
      const Eigen::Matrix3d R = so3::Exp(omega);
      EXPECT_LE(MaxAbs(R - expected), 2.3e-16) << theta;
      EXPECT_LE(Vee(R - expected).norm(), 1e-15 * theta) << theta;
      EXPECT_LE((Vee(R) - omega).norm(), 1e-15 * theta + t2) << theta;
    }
  }
}

TEST(So3Exp, IsOrthonormalForAllAngles) {
  std::mt19937_64 rng(103);
  hecal::UniformRealDistribution angle(0.0, 20.0);
  for (int i = 0; i < kSo3Samples; ++i) {
    const Eigen::Matrix3d R = so3::Exp(testing::RandomRotationVector(rng, angle(rng)));
    // A few ulps: the products in RᵀR and det R round (Eigen's AngleAxisd peaks at 1.6e-15 too).
    EXPECT_LT(so3::OrthonormalityError(R), 3e-15);
  }
  for (const Eigen::Vector3d& omega : testing::EdgeCaseRotationVectors(rng)) {
    EXPECT_LT(so3::OrthonormalityError(so3::Exp(omega)), 3e-15) << omega.transpose();
  }
}

TEST(So3ExpLog, ExpOfLogIsIdentity) {
  std::mt19937_64 rng(104);
  double worst = 0.0;
  for (const Eigen::Matrix3d& R : TestRotations(rng)) {
    const double error = MaxAbs(so3::Exp(so3::Log(R)) - R);
    worst = std::max(worst, error);
    EXPECT_LT(error, 2e-15) << R;
  }
  RecordProperty("worst_error", ::testing::PrintToString(worst));
}

TEST(So3ExpLog, LogOfExpAtPiIsPlusOrMinus) {
  std::mt19937_64 rng(106);
  std::vector<Eigen::Vector3d> cases;
  for (int i = 0; i < 500; ++i)
    cases.push_back(testing::RandomRotationVector(rng, std::numbers::pi));
  for (int axis = 0; axis < 3; ++axis) {
    cases.push_back(std::numbers::pi * Eigen::Vector3d::Unit(axis));
    cases.push_back(-std::numbers::pi * Eigen::Vector3d::Unit(axis));
  }
  for (const Eigen::Vector3d& omega : cases) {
    const Eigen::Vector3d log = so3::Log(so3::Exp(omega));
    EXPECT_LT(std::min((log - omega).norm(), (log + omega).norm()), 2e-15) << omega.transpose();
  }
}

TEST(So3Log, NormIsAtMostPiAndWrapsLargerAngles) {
  std::mt19937_64 rng(107);
  hecal::UniformRealDistribution angle(std::numbers::pi + 1e-6, 2.0 * std::numbers::pi - 1e-6);
  for (int i = 0; i < kSo3Samples; ++i) {
    // A rotation by α ∈ (π, 2π) about n is a rotation by 2π − α about −n.
    const double alpha = angle(rng);
    const Eigen::Vector3d n = testing::RandomUnitVector(rng);
    const Eigen::Vector3d log = so3::Log(so3::Exp(alpha * n));
    EXPECT_LE(log.norm(), std::numbers::pi * (1.0 + 1e-15));
    EXPECT_LT((log - (alpha - 2.0 * std::numbers::pi) * n).norm(), 1e-14) << alpha;
  }
  for (const Eigen::Matrix3d& R : TestRotations(rng)) {
    EXPECT_LE(so3::Log(R).norm(), std::numbers::pi * (1.0 + 1e-15));
  }
}

TEST(So3Log, ExactlyPiHasDeterministicSign) {
  // Exact half-turn matrices R = 2 n nᵀ − I: ±ω are both valid; so3.h promises the one whose
  // largest-magnitude component is positive.
  EXPECT_EQ(so3::Log(Eigen::Vector3d(1, -1, -1).asDiagonal()),
            Eigen::Vector3d(std::numbers::pi, 0, 0));
  EXPECT_EQ(so3::Log(Eigen::Vector3d(-1, 1, -1).asDiagonal()),
            Eigen::Vector3d(0, std::numbers::pi, 0));
  EXPECT_EQ(so3::Log(Eigen::Vector3d(-1, -1, 1).asDiagonal()),
            Eigen::Vector3d(0, 0, std::numbers::pi));
  for (const Eigen::Vector3d& n :
       {Eigen::Vector3d(0.6, -0.8, 0.0), Eigen::Vector3d(-0.6, 0.8, 0.0),
        Eigen::Vector3d(1, 1, 0).normalized(), Eigen::Vector3d(-2, 1, 2).normalized(),
        Eigen::Vector3d(1, 1, 1).normalized()}) {
    const Eigen::Matrix3d R = 2.0 * n * n.transpose() - Eigen::Matrix3d::Identity();
    Eigen::Index largest;
    n.cwiseAbs().maxCoeff(&largest);
    const Eigen::Vector3d expected = (n(largest) > 0 ? std::numbers::pi : -std::numbers::pi) * n;
    const Eigen::Vector3d log = so3::Log(R);
    EXPECT_LT((log - expected).norm(), 2e-15) << n.transpose() << " got " << log.transpose();
    EXPECT_GT(log(largest), 0.0);
  }
}

TEST(So3Angle, MatchesConstructedAngleNearZeroAndPi) {
  std::mt19937_64 rng(108);
  for (double theta : {0.0, 1e-15, 1e-12, 1e-9, 1e-6, 1e-4, 1e-2, 0.5, 2.0, std::numbers::pi - 1e-2,
                       std::numbers::pi - 1e-6, std::numbers::pi - 1e-9, std::numbers::pi - 1e-12,
                       std::numbers::pi}) {
    for (int i = 0; i < 50; ++i) {
      const Eigen::Vector3d n = testing::RandomUnitVector(rng);
      const Eigen::Matrix3d R = Eigen::AngleAxisd(theta, n).toRotationMatrix();
      // Relative accuracy near 0 (where acos of the trace would give ~1e-8 at best), absolute
      // accuracy of a few ulps near π.
      EXPECT_LE(std::abs(so3::Angle(R) - theta), 1e-15 * std::min(theta, 1.0) + 1e-300) << theta;
    }
  }
}

TEST(So3Angle, AgreesWithAcosOfTraceWhereWellConditioned) {
  std::mt19937_64 rng(109);
  for (int i = 0; i < kSo3Samples; ++i) {
    const Eigen::Matrix3d R = testing::RandomRotation(rng);
    const double cos_theta = 0.5 * (R.trace() - 1.0);
    if (std::abs(cos_theta) > 0.9) continue;  // acos loses digits there; covered above
    EXPECT_NEAR(so3::Angle(R), std::acos(cos_theta), 5e-15);
  }
}

TEST(So3Distance, IsConstructedAngleSymmetricAndInvariant) {
  std::mt19937_64 rng(110);
  hecal::UniformRealDistribution angle(0.0, std::numbers::pi);
  for (int i = 0; i < kSo3Samples; ++i) {
    const Eigen::Matrix3d R_a = testing::RandomRotation(rng);
    const double theta = angle(rng);
    const Eigen::Matrix3d delta =
        Eigen::AngleAxisd(theta, testing::RandomUnitVector(rng)).toRotationMatrix();
    const Eigen::Matrix3d R_b = R_a * delta;
    EXPECT_NEAR(so3::Distance(R_a, R_b), theta, 4e-15);
    EXPECT_NEAR(so3::Distance(R_b, R_a), theta, 4e-15);
    // Bi-invariance: the same relative rotation seen from any frame.
    const Eigen::Matrix3d Q = testing::RandomRotation(rng);
    EXPECT_NEAR(so3::Distance(Q * R_a, Q * R_b), theta, 4e-15);
    EXPECT_NEAR(so3::Distance(R_a * Q, R_b * Q), theta, 4e-15);
  }
  EXPECT_EQ(so3::Distance(Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity()), 0.0);
}

TEST(So3Jacobians, MatchExplicitFormulas) {
  // Solà et al. (2018) eqs. (143)–(146), written out here; θ ≥ 0.1 and ≤ 3 keeps them exact.
  std::mt19937_64 rng(111);
  hecal::UniformRealDistribution angle(0.1, 3.0);
  for (int i = 0; i < kSo3Samples; ++i) {
    const Eigen::Vector3d omega = testing::RandomRotationVector(rng, angle(rng));
    const double t = omega.norm();
    const Eigen::Matrix3d K = Skew(omega);
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d Jr =
        I - (1 - std::cos(t)) / (t * t) * K + (t - std::sin(t)) / (t * t * t) * K * K;
    const Eigen::Matrix3d Jr_inv =
        I + 0.5 * K + (1 / (t * t) - (1 + std::cos(t)) / (2 * t * std::sin(t))) * K * K;
    EXPECT_LT(MaxAbs(so3::RightJacobian(omega) - Jr), 2e-15);
    EXPECT_LT(MaxAbs(so3::RightJacobianInverse(omega) - Jr_inv), 1e-14);
    EXPECT_LT(MaxAbs(so3::LeftJacobian(omega) - Jr.transpose()), 2e-15);
    EXPECT_LT(MaxAbs(so3::LeftJacobianInverse(omega) - Jr_inv.transpose()), 1e-14);
  }
}

// Jl(ω) = Σₙ [ω]×ⁿ / (n + 1)!, summed in long double: a reference independent of the closed
// forms and of their series switch, ~2000 times more precise than double.
Eigen::Matrix3d LeftJacobianBySeries(const Eigen::Vector3d& omega) {
  using Matrix3l = Eigen::Matrix<long double, 3, 3>;
  const Matrix3l K = Skew(omega).cast<long double>();
  Matrix3l term = Matrix3l::Identity();
  Matrix3l sum = Matrix3l::Identity();
  for (int n = 1; n < 60; ++n) {
    term = term * K / static_cast<long double>(n + 1);
    sum += term;
  }
  return sum.cast<double>();
}

TEST(So3Jacobians, MatchLongDoubleSeriesToRounding) {
  std::mt19937_64 rng(120);
  std::vector<Eigen::Vector3d> cases = TestRotationVectors(rng, std::numbers::pi);
  for (double theta : So3JacobianTestAngles()) {
    for (int i = 0; i < 20; ++i) cases.push_back(testing::RandomRotationVector(rng, theta));
  }
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (const Eigen::Vector3d& omega : cases) {
    const Eigen::Matrix3d reference = LeftJacobianBySeries(omega);
    EXPECT_LT(MaxAbs(so3::LeftJacobian(omega) - reference), 5e-16) << omega.transpose();
    EXPECT_LT(MaxAbs(so3::RightJacobian(omega) - reference.transpose()), 5e-16);
    EXPECT_LT(MaxAbs(so3::LeftJacobianInverse(omega) * reference - I), 1e-15) << omega.transpose();
    EXPECT_LT(MaxAbs(so3::RightJacobianInverse(omega) * reference.transpose() - I), 1e-15);
  }
}

TEST(So3Jacobians, InversesAndLeftRightRelations) {
  std::mt19937_64 rng(115);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (const Eigen::Vector3d& omega : TestRotationVectors(rng, std::numbers::pi)) {
    const Eigen::Matrix3d R = so3::Exp(omega);
    EXPECT_LT(MaxAbs(so3::RightJacobian(omega) * so3::RightJacobianInverse(omega) - I), 1e-14);
    EXPECT_LT(MaxAbs(so3::LeftJacobian(omega) * so3::LeftJacobianInverse(omega) - I), 1e-14);
    // Jl(ω) = R Jr(ω) and Jl(ω) = Jr(−ω).
    EXPECT_LT(MaxAbs(so3::LeftJacobian(omega) - R * so3::RightJacobian(omega)), 1e-15);
    EXPECT_LT(MaxAbs(so3::LeftJacobian(omega) - so3::RightJacobian(-omega)), 1e-15);
    // Jacobians leave the rotation axis alone: J ω = ω.
    EXPECT_LT((so3::RightJacobian(omega) * omega - omega).norm(), 1e-15 * (1 + omega.norm()));
  }
}

TEST(So3Jacobians, ContinuousAcrossSeriesThreshold) {
  // so3.cc switches to Taylor series below θ = 1e-2: the branches must agree to rounding there.
  std::mt19937_64 rng(116);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d n = testing::RandomUnitVector(rng);
    const Eigen::Vector3d below = testing::RotationVectorAtThreshold(n, 1e-2, true);
    const Eigen::Vector3d above = testing::RotationVectorAtThreshold(n, 1e-2, false);
    const double step = (above - below).norm();  // J changes by at most ~step/2 between them
    EXPECT_LT(MaxAbs(so3::LeftJacobian(below) - so3::LeftJacobian(above)), 2.3e-16 + step);
    EXPECT_LT(MaxAbs(so3::LeftJacobianInverse(below) - so3::LeftJacobianInverse(above)),
              2.3e-16 + step);
  }
}

TEST(So3Interpolate, EndpointsMidpointAndConstantSpeed) {
  std::mt19937_64 rng(118);
  hecal::UniformRealDistribution angle(0.0, std::numbers::pi - 1e-6);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Matrix3d R0 = testing::RandomRotation(rng);
    const double theta = angle(rng);
    const Eigen::Vector3d n = testing::RandomUnitVector(rng);
    const Eigen::Matrix3d R1 = R0 * Eigen::AngleAxisd(theta, n).toRotationMatrix();
    EXPECT_LT(MaxAbs(so3::Interpolate(R0, R1, 0.0) - R0), 1e-15);
    EXPECT_LT(MaxAbs(so3::Interpolate(R0, R1, 1.0) - R1), 2e-15);
    const Eigen::Matrix3d mid = so3::Interpolate(R0, R1, 0.5);
    EXPECT_NEAR(so3::Distance(R0, mid), 0.5 * theta, 4e-15);
    EXPECT_NEAR(so3::Distance(mid, R1), 0.5 * theta, 4e-15);
    for (double s : {0.1, 0.25, 0.7, 0.9}) {
      // The geodesic is R0 · (rotation by sθ about the same axis n).
      const Eigen::Matrix3d expected = R0 * Eigen::AngleAxisd(s * theta, n).toRotationMatrix();
      EXPECT_LT(MaxAbs(so3::Interpolate(R0, R1, s) - expected), 4e-15) << theta;
      EXPECT_NEAR(so3::Distance(R0, so3::Interpolate(R0, R1, s)), s * theta, 4e-15);
    }
  }
}

TEST(So3OrthonormalityError, ZeroForRotationsLargeOtherwise) {
  std::mt19937_64 rng(119);
  for (const Eigen::Matrix3d& R : TestRotations(rng)) {
    EXPECT_LT(so3::OrthonormalityError(R), 3e-15);
    // A reflection is orthogonal but has det −1: error |−1 − 1| = 2.
    const Eigen::Matrix3d reflection = R * Eigen::Vector3d(1, 1, -1).asDiagonal();
    EXPECT_NEAR(so3::OrthonormalityError(reflection), 2.0, 1e-14);
    // 1.01 R: MᵀM − I = 0.0201 I, det − 1 = 1.01³ − 1 = 0.030301 (the larger).
    EXPECT_NEAR(so3::OrthonormalityError(1.01 * R), 0.030301, 1e-14);
  }
  EXPECT_EQ(so3::OrthonormalityError(Eigen::Matrix3d::Identity()), 0.0);
  EXPECT_EQ(so3::OrthonormalityError(Eigen::Matrix3d::Zero()), 1.0);
  // A single perturbed entry ε shows up as ≈ ε.
  Eigen::Matrix3d M = Eigen::Matrix3d::Identity();
  M(0, 1) = 1e-7;
  EXPECT_NEAR(so3::OrthonormalityError(M), 1e-7, 1e-13);
}

}  // namespace
}  // namespace hecal
