// Property tests for rotation.h. Ground truth is built independently of the code under test:
// quaternions written from a known axis and angle (cos(θ/2), sin(θ/2) n), the explicit Rodrigues
// and quaternion-to-matrix formulas, Tsai & Lenz's own P → R formula, and Eigen's AngleAxisd /
// Quaterniond as peers. Samples: thousands of seeded random rotations, the edge-case rotation
// vectors of testing/random_poses.h (0, 1e-12 …, π about each axis, π − 1e-9 …) and gimbal-lock
// rotations (pitch ±π/2).
#include "hecal/geometry/rotation.h"

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

constexpr int kRotationSamples = 4000;

// q = (cos(θ/2), sin(θ/2) n): the definition, not the code under test.
Eigen::Quaterniond QuaternionOf(const Eigen::Vector3d& n, double theta) {
  const double s = std::sin(0.5 * theta);
  return Eigen::Quaterniond(std::cos(0.5 * theta), s * n.x(), s * n.y(), s * n.z());
}

// Unit quaternion → matrix, written out entry by entry.
Eigen::Matrix3d ExplicitQuaternionMatrix(const Eigen::Quaterniond& q) {
  const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
  Eigen::Matrix3d R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

// Rodrigues: R = I + sinθ [n]× + (1 − cosθ) [n]×², |n| = 1.
Eigen::Matrix3d ExplicitRodrigues(const Eigen::Vector3d& n, double theta) {
  const Eigen::Matrix3d K = Skew(n);
  return Eigen::Matrix3d::Identity() + std::sin(theta) * K + (1.0 - std::cos(theta)) * K * K;
}

struct KnownRotation {
  Eigen::Vector3d axis;  // unit
  double angle;          // [0, π]
};

// Rotations with a known axis and angle: random (angle uniform in [0, π]) and the edge cases.
std::vector<KnownRotation> KnownRotations(std::mt19937_64& rng) {
  std::vector<KnownRotation> result;
  hecal::UniformRealDistribution angle(0.0, std::numbers::pi);
  for (int i = 0; i < kRotationSamples; ++i)
    result.push_back({testing::RandomUnitVector(rng), angle(rng)});
  for (const Eigen::Vector3d& omega : testing::EdgeCaseRotationVectors(rng)) {
    const double theta = omega.norm();
    result.push_back({theta == 0.0 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d(omega / theta),
                      std::min(theta, std::numbers::pi)});
  }
  return result;
}

// Rotation matrices: random, edge cases, gimbal lock (yaw · pitch ±π/2 · roll).
std::vector<Eigen::Matrix3d> TestMatrices(std::mt19937_64& rng) {
  std::vector<Eigen::Matrix3d> result;
  for (const KnownRotation& k : KnownRotations(rng)) {
    result.push_back(ExplicitQuaternionMatrix(QuaternionOf(k.axis, k.angle)));
  }
  for (double pitch : {std::numbers::pi / 2, -std::numbers::pi / 2}) {
    for (double roll : {0.0, 0.3, -2.0, std::numbers::pi}) {
      for (double yaw : {0.0, 1.1, -std::numbers::pi / 2, std::numbers::pi}) {
        result.push_back(Elementary(2, yaw) * Elementary(1, pitch) * Elementary(0, roll));
      }
    }
  }
  result.push_back(Eigen::Vector3d(1, -1, -1).asDiagonal());  // exact half turns
  result.push_back(Eigen::Vector3d(-1, 1, -1).asDiagonal());
  result.push_back(Eigen::Vector3d(-1, -1, 1).asDiagonal());
  return result;
}

bool IsCanonical(const Eigen::Quaterniond& q) {
  for (double c : {q.w(), q.x(), q.y(), q.z()}) {
    if (c != 0.0) return c > 0.0;
  }
  return true;
}

TEST(CanonicalQuaternion, SignRules) {
  const auto canon = [](double w, double x, double y, double z) {
    return Wxyz(CanonicalQuaternion(Eigen::Quaterniond(w, x, y, z)));
  };
  EXPECT_EQ(canon(0.5, -0.5, 0.5, -0.5), Eigen::Vector4d(0.5, -0.5, 0.5, -0.5));  // w > 0 kept
  EXPECT_EQ(canon(-0.5, -0.5, 0.5, -0.5), Eigen::Vector4d(0.5, 0.5, -0.5, 0.5));  // w < 0 flips
  EXPECT_EQ(canon(0.0, -0.6, 0.8, 0.0), Eigen::Vector4d(0.0, 0.6, -0.8, 0.0));    // x decides
  EXPECT_EQ(canon(0.0, 0.0, -0.6, 0.8), Eigen::Vector4d(0.0, 0.0, 0.6, -0.8));    // then y
  EXPECT_EQ(canon(0.0, 0.0, 0.0, -1.0), Eigen::Vector4d(0.0, 0.0, 0.0, 1.0));     // then z
  EXPECT_EQ(canon(0.0, 0.6, -0.8, 0.0), Eigen::Vector4d(0.0, 0.6, -0.8, 0.0));
  EXPECT_EQ(canon(1e-300, -1.0, 0.0, 0.0), Eigen::Vector4d(1e-300, -1.0, 0.0, 0.0));  // w > 0
  std::mt19937_64 rng(201);
  for (int i = 0; i < kRotationSamples; ++i) {
    const Eigen::Quaterniond q(testing::RandomRotation(rng));
    const Eigen::Quaterniond c = CanonicalQuaternion(q);
    EXPECT_TRUE(IsCanonical(c));
    EXPECT_TRUE(Wxyz(c) == Wxyz(q) || Wxyz(c) == -Wxyz(q));
    EXPECT_EQ(Wxyz(CanonicalQuaternion(c)), Wxyz(c));  // idempotent
  }
}

TEST(QuaternionFromMatrix, MatchesKnownQuaternionEverywhere) {
  // Shepperd's method must be accurate to rounding for every angle, including near π where the
  // trace method loses all digits. The true quaternion is built from the known axis/angle.
  std::mt19937_64 rng(202);
  for (const KnownRotation& k : KnownRotations(rng)) {
    const Eigen::Quaterniond truth = QuaternionOf(k.axis, k.angle);  // w = cos(θ/2) ≥ 0
    const Eigen::Matrix3d R = ExplicitQuaternionMatrix(truth);
    const Eigen::Quaterniond q = QuaternionFromMatrix(R);
    EXPECT_TRUE(IsCanonical(q));
    EXPECT_NEAR(q.norm(), 1.0, 2.3e-16);
    // At exactly π the computed w is ±rounding, so only ±q is determined.
    const double error = std::min((Wxyz(q) - Wxyz(truth)).norm(), (Wxyz(q) + Wxyz(truth)).norm());
    EXPECT_LT(error, 1e-15) << k.angle << " " << k.axis.transpose();
    if (k.angle < std::numbers::pi - 1e-12) {
      EXPECT_LT((Wxyz(q) - Wxyz(truth)).norm(), 1e-15) << k.angle;
    }
  }
}

TEST(QuaternionFromMatrix, NearPiAgreesToRoundingAndBeatsTraceFormula) {
  std::mt19937_64 rng(203);
  for (double eps : {1e-3, 1e-6, 1e-9, 1e-12}) {
    for (int i = 0; i < 200; ++i) {
      const Eigen::Vector3d n = testing::RandomUnitVector(rng);
      const Eigen::Quaterniond truth = QuaternionOf(n, std::numbers::pi - eps);
      const Eigen::Quaterniond q = QuaternionFromMatrix(ExplicitQuaternionMatrix(truth));
      // The vector part is the rotation axis to full precision; w = cos(θ/2) ≈ ε/2 to ~1e-16
      // absolute (it is a difference of O(1) matrix entries).
      EXPECT_LT((q.vec() - truth.vec()).norm(), 1e-15) << eps;
      EXPECT_NEAR(q.w(), truth.w(), 2e-16) << eps;
    }
  }
}

TEST(QuaternionFromMatrix, AgreesWithEigenPeer) {
  std::mt19937_64 rng(204);
  for (const Eigen::Matrix3d& R : TestMatrices(rng)) {
    const Eigen::Quaterniond ours = QuaternionFromMatrix(R);
    const Eigen::Quaterniond eigen(R);
    const double error =
        std::min((Wxyz(ours) - Wxyz(eigen)).norm(), (Wxyz(ours) + Wxyz(eigen)).norm());
    EXPECT_LT(error, 1e-15) << R;
  }
}

TEST(MatrixFromQuaternion, MatchesExplicitFormulaAndNormalises) {
  std::mt19937_64 rng(205);
  hecal::NormalDistribution normal;
  for (int i = 0; i < kRotationSamples; ++i) {
    // Drawn last to first: the order these tests' data were generated in.
    const double z = normal(rng), y = normal(rng), x = normal(rng), w = normal(rng);
    const Eigen::Quaterniond q = Eigen::Quaterniond(w, x, y, z).normalized();
    const Eigen::Matrix3d expected = ExplicitQuaternionMatrix(q);
    EXPECT_LT(MaxAbs(MatrixFromQuaternion(q) - expected), 2e-15);
    // Not unit: normalised first; −q is the same rotation.
    const Eigen::Quaterniond scaled(3.7 * q.w(), 3.7 * q.x(), 3.7 * q.y(), 3.7 * q.z());
    EXPECT_LT(MaxAbs(MatrixFromQuaternion(scaled) - expected), 2e-15);
    const Eigen::Quaterniond negated(-q.w(), -q.x(), -q.y(), -q.z());
    EXPECT_LT(MaxAbs(MatrixFromQuaternion(negated) - expected), 2e-15);
  }
  // Hamilton convention: (cos 45°, 0, 0, sin 45°) turns x into y.
  const Eigen::Quaterniond z90(std::sqrt(0.5), 0, 0, std::sqrt(0.5));
  EXPECT_LT(
      (MatrixFromQuaternion(z90) * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(),
      1e-15);
}

TEST(QuaternionRotationVector, MatchesDefinitionAndRoundTrips) {
  std::mt19937_64 rng(206);
  for (const KnownRotation& k : KnownRotations(rng)) {
    const Eigen::Vector3d omega = k.angle * k.axis;
    const Eigen::Quaterniond truth = QuaternionOf(k.axis, k.angle);
    const Eigen::Quaterniond q = QuaternionFromRotationVector(omega);
    // Relative accuracy of the vector part at tiny angles (1e-12 rad keeps all digits).
    EXPECT_LT((q.vec() - truth.vec()).norm(), 1e-15 * std::min(1.0, k.angle) + 1e-300);
    // |ω| rounds to θ(1 ± 3ε), and w = cos(|ω|/2) inherits ½ sin(θ/2) of that: ≤ 1e-15.
    EXPECT_NEAR(q.w(), truth.w(), 1e-15);
    const Eigen::Vector3d back = RotationVectorFromQuaternion(q);
    if (k.angle < std::numbers::pi) {
      EXPECT_LT((back - omega).norm(), 2e-15 * std::min(1.0, k.angle) + 1e-300) << k.angle;
    } else {
      EXPECT_LT(std::min((back - omega).norm(), (back + omega).norm()), 2e-15);
    }
  }
}

TEST(QuaternionRotationVector, AgreesWithEigenAngleAxis) {
  std::mt19937_64 rng(207);
  hecal::UniformRealDistribution angle(0.0, 2.0 * std::numbers::pi);
  for (int i = 0; i < kRotationSamples; ++i) {
    const Eigen::Vector3d n = testing::RandomUnitVector(rng);
    const double theta = angle(rng);
    const Eigen::Quaterniond eigen(Eigen::AngleAxisd(theta, n));
    EXPECT_LT((Wxyz(QuaternionFromRotationVector(theta * n)) - Wxyz(eigen)).norm(), 1e-15);
  }
}

TEST(QuaternionRotationVector, NegativeAndNonUnitQuaternionsGiveShortRotation) {
  std::mt19937_64 rng(208);
  hecal::UniformRealDistribution angle(0.0, std::numbers::pi - 1e-6);
  for (int i = 0; i < kRotationSamples; ++i) {
    const Eigen::Vector3d n = testing::RandomUnitVector(rng);
    const double theta = angle(rng);
    const Eigen::Quaterniond q = QuaternionOf(n, theta);
    // −q (w < 0, i.e. "rotation by 2π − θ about −n") is the same rotation: still ω = θ n.
    const Eigen::Quaterniond negated(-2.0 * q.w(), -2.0 * q.x(), -2.0 * q.y(), -2.0 * q.z());
    const Eigen::Vector3d omega = RotationVectorFromQuaternion(negated);
    EXPECT_LE(omega.norm(), std::numbers::pi);
    EXPECT_LT((omega - theta * n).norm(), 4e-15) << theta;
  }
  // Exactly π (w = 0): the largest-magnitude component comes out positive.
  EXPECT_EQ(RotationVectorFromQuaternion(Eigen::Quaterniond(0, -1, 0, 0)),
            Eigen::Vector3d(std::numbers::pi, 0, 0));
  const Eigen::Vector3d omega = RotationVectorFromQuaternion(Eigen::Quaterniond(0, 0.6, -0.8, 0));
  EXPECT_LT((omega - std::numbers::pi * Eigen::Vector3d(-0.6, 0.8, 0)).norm(), 2e-15);
}

TEST(QuaternionRotationVector, ContinuousAcrossSmallAngleBranch) {
  // rotation.cc uses a series below |vec| = 1e-8 (θ ≈ 2e-8): check both sides against θ n.
  std::mt19937_64 rng(209);
  for (double theta : {1.9e-8, 1.99999999e-8, 2e-8, 2.00000001e-8, 2.1e-8}) {
    for (int i = 0; i < 20; ++i) {
      const Eigen::Vector3d n = testing::RandomUnitVector(rng);
      const Eigen::Vector3d back = RotationVectorFromQuaternion(QuaternionOf(n, theta));
      EXPECT_LT((back - theta * n).norm(), 1e-15 * theta);
    }
  }
}

TEST(AxisAngle, RoundTripsAndMatchesRodrigues) {
  std::mt19937_64 rng(210);
  for (const KnownRotation& k : KnownRotations(rng)) {
    const Eigen::Matrix3d expected = ExplicitRodrigues(k.axis, k.angle);
    const Eigen::Matrix3d R = MatrixFromAxisAngle({k.axis, k.angle});
    EXPECT_LT(MaxAbs(R - expected), 2e-15);
    // Non-unit axis: normalised first.
    EXPECT_LT(MaxAbs(MatrixFromAxisAngle({4.0 * k.axis, k.angle}) - expected), 2e-15);
    const AxisAngle back = AxisAngleFromMatrix(R);
    EXPECT_NEAR(back.axis.norm(), 1.0, 2.3e-16);
    EXPECT_GE(back.angle, 0.0);
    EXPECT_LE(back.angle, std::numbers::pi);
    EXPECT_NEAR(back.angle, k.angle, 2e-15 * std::min(1.0, k.angle) + 1e-300) << k.angle;
    if (k.angle > 1e-12 && k.angle < std::numbers::pi - 1e-9) {
      // Axis accuracy degrades as 1/θ only through the rounding of R itself.
      EXPECT_LT((back.axis - k.axis).norm(), 1e-15 / std::min(1.0, k.angle) + 1e-15) << k.angle;
    }
    EXPECT_LT(MaxAbs(MatrixFromAxisAngle(back) - R), 2e-15);
  }
}

TEST(AxisAngle, IdentityAndHalfTurnConventions) {
  const AxisAngle identity = AxisAngleFromMatrix(Eigen::Matrix3d::Identity());
  EXPECT_EQ(identity.angle, 0.0);
  EXPECT_EQ(identity.axis, Eigen::Vector3d::UnitX());
  const AxisAngle half_z = AxisAngleFromMatrix(Eigen::Vector3d(-1, -1, 1).asDiagonal());
  EXPECT_EQ(half_z.angle, std::numbers::pi);
  EXPECT_EQ(half_z.axis, Eigen::Vector3d::UnitZ());
  // Axis (0.6, −0.8, 0) at π: the largest-magnitude component (y) is made positive.
  const Eigen::Vector3d n(0.6, -0.8, 0.0);
  const AxisAngle half = AxisAngleFromMatrix(2.0 * n * n.transpose() - Eigen::Matrix3d::Identity());
  EXPECT_NEAR(half.angle, std::numbers::pi, 1e-15);
  EXPECT_LT((half.axis + n).norm(), 1e-15);
}

TEST(AxisAngle, AgreesWithEigenAngleAxis) {
  std::mt19937_64 rng(211);
  for (const Eigen::Matrix3d& R : TestMatrices(rng)) {
    const Eigen::AngleAxisd eigen(R);
    const AxisAngle ours = AxisAngleFromMatrix(R);
    EXPECT_NEAR(ours.angle, eigen.angle(), 2e-15);
    if (eigen.angle() > 1e-6 && eigen.angle() < std::numbers::pi - 1e-6) {
      EXPECT_LT((ours.axis - eigen.axis()).norm(), 1e-9);  // Eigen's axis is less exact
    }
  }
}

TEST(TsaiRodrigues, NormIsTwiceSinHalfAngleAlongAxis) {
  std::mt19937_64 rng(212);
  for (const KnownRotation& k : KnownRotations(rng)) {
    const Eigen::Matrix3d R = ExplicitRodrigues(k.axis, k.angle);
    const Eigen::Vector3d P = TsaiRodriguesFromMatrix(R);
    const Eigen::Vector3d expected = 2.0 * std::sin(0.5 * k.angle) * k.axis;
    if (k.angle < std::numbers::pi - 1e-12) {
      EXPECT_LT((P - expected).norm(), 2e-15 * std::min(1.0, k.angle) + 1e-300) << k.angle;
    } else {
      EXPECT_LT(std::min((P - expected).norm(), (P + expected).norm()), 2e-15);
    }
    EXPECT_NEAR(P.norm(), 2.0 * std::sin(0.5 * k.angle), 4e-15);
  }
}

TEST(TsaiRodrigues, MatrixMatchesTsaiLenzFormula) {
  // Tsai & Lenz (1989) eq. 10: R = (1 − |P|²/2) I + ½ (P Pᵀ + √(4 − |P|²) [P]×).
  std::mt19937_64 rng(213);
  hecal::UniformRealDistribution radius(0.0, 2.0);
  for (int i = 0; i < kRotationSamples; ++i) {
    const Eigen::Vector3d axis = testing::RandomUnitVector(rng);  // drawn before the radius
    const Eigen::Vector3d P = radius(rng) * axis;
    const double p2 = P.squaredNorm();
    const Eigen::Matrix3d expected = (1.0 - 0.5 * p2) * Eigen::Matrix3d::Identity() +
                                     0.5 * (P * P.transpose() + std::sqrt(4.0 - p2) * Skew(P));
    const Eigen::Matrix3d R = MatrixFromTsaiRodrigues(P);
    EXPECT_LT(MaxAbs(R - expected), 4e-15);
    // P → R → P is exact for |P| < 2 (θ ≤ π picks the same sign).
    EXPECT_LT((TsaiRodriguesFromMatrix(R) - P).norm(), 4e-15) << P.norm();
  }
  // |P| = 2 is a half turn; values a hair above 2 are clamped to it.
  const Eigen::Vector3d P = (2.0 + 5e-10) * Eigen::Vector3d(1, 2, 2).normalized();
  const Eigen::Matrix3d R = MatrixFromTsaiRodrigues(P);
  const Eigen::Vector3d n = Eigen::Vector3d(1, 2, 2).normalized();
  EXPECT_LT(MaxAbs(R - (2.0 * n * n.transpose() - Eigen::Matrix3d::Identity())), 1e-9);
}

// Tsai's P = 2 sin(θ/2) n is flat in θ at π: |P| changes by only (π − θ)²/4, so P carries the
// angle there only to ~ε/cos(θ/2) (at worst √ε ≈ 1.5e-8 at exactly π). That is the
// representation, not the code; P → R is held to this bound, everything else to rounding.
double TsaiTolerance(const Eigen::Matrix3d& R) {
  const double cos_half = 0.5 * std::sqrt(std::max(0.0, 1.0 + R.trace()));
  return 4e-15 + 1e-15 / std::max(cos_half, 1e-8);
}

TEST(RotationConversions, EveryChainRoundTrips) {
  // matrix → quaternion → rotvec → axis–angle → matrix, and every pairwise round trip.
  std::mt19937_64 rng(214);
  double worst = 0.0;
  for (const Eigen::Matrix3d& R : TestMatrices(rng)) {
    const Eigen::Quaterniond q = QuaternionFromMatrix(R);
    const Eigen::Vector3d omega = RotationVectorFromQuaternion(q);
    const double theta = omega.norm();
    const AxisAngle axis_angle{
        theta == 0.0 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d(omega / theta), theta};
    const Eigen::Matrix3d back = MatrixFromAxisAngle(axis_angle);
    const double error = MaxAbs(back - R);
    worst = std::max(worst, error);
    EXPECT_LT(error, 4e-15) << R;
    EXPECT_LT(MaxAbs(MatrixFromQuaternion(q) - R), 2e-15);
    EXPECT_LT(MaxAbs(MatrixFromQuaternion(QuaternionFromRotationVector(omega)) - R), 2e-15);
    EXPECT_LT(MaxAbs(MatrixFromAxisAngle(AxisAngleFromMatrix(R)) - R), 2e-15);
    EXPECT_LT(MaxAbs(MatrixFromTsaiRodrigues(TsaiRodriguesFromMatrix(R)) - R), TsaiTolerance(R));
    EXPECT_LT(MaxAbs(MatrixFromTsaiRodrigues(TsaiRodriguesFromMatrix(back)) - R), TsaiTolerance(R));
    // The quaternion chain is sign-consistent: rotvec → quaternion gives back the canonical q
    // (up to sign only at exactly π).
    const Eigen::Quaterniond q2 = QuaternionFromRotationVector(omega);
    EXPECT_LT(std::min((Wxyz(q2) - Wxyz(q)).norm(), (Wxyz(q2) + Wxyz(q)).norm()), 2e-15);
  }
  RecordProperty("worst_error", ::testing::PrintToString(worst));
}

TEST(TsaiRodrigues, ConditioningNearPiIsBoundedBySqrtEpsilon) {
  std::mt19937_64 rng(215);
  for (double eps : {0.0, 1e-12, 1e-9, 1e-6, 1e-3}) {
    for (int i = 0; i < 50; ++i) {
      const Eigen::Vector3d n = testing::RandomUnitVector(rng);
      const Eigen::Matrix3d R = ExplicitRodrigues(n, std::numbers::pi - eps);
      const double error = MaxAbs(MatrixFromTsaiRodrigues(TsaiRodriguesFromMatrix(R)) - R);
      EXPECT_LT(error, TsaiTolerance(R)) << eps;
      EXPECT_LT(error, 1e-7) << eps;
    }
  }
}

}  // namespace
}  // namespace hecal
