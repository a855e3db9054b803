// Tests for dual_quaternion.h, the whole API. Truth from outside the class: Isometry3d products
// and inverses, Eigen's Hamilton product for the dual parts written out by hand, se3::Exp/Log
// (Jacobian-based, a different derivation from the closed-form dual exponential), screw motions
// built from their axis line, and Daniilidis' (cos(θ̌/2), sin(θ̌/2) ľ) expanded in the test.
#include "hecal/geometry/dual_quaternion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/geometry_test_util.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "testing/random_poses.h"
#include "testing/screw_motions.h"

namespace hecal {
namespace {

constexpr int kDualQuaternionSamples = 3000;
using Vector8d = Eigen::Matrix<double, 8, 1>;

// Distance between the 8-vectors up to the overall sign.
double SignFreeDistance(const DualQuaternion& a, const DualQuaternion& b) {
  return std::min(MaxAbs(a.ToVector() - b.ToVector()), MaxAbs(a.ToVector() + b.ToVector()));
}

Eigen::Quaterniond RandomQuaternion(std::mt19937_64& rng) {  // not unit
  hecal::NormalDistribution normal;
  // Drawn last to first: the order these tests' data were generated in.
  const double z = normal(rng);
  const double y = normal(rng);
  const double x = normal(rng);
  const double w = normal(rng);
  return Eigen::Quaterniond(w, x, y, z);
}

Eigen::Quaterniond Pure(const Eigen::Vector3d& v) {
  return {0.0, v.x(), v.y(), v.z()};
}

// Pure dual quaternion ½ (ω + ε v): ω in the real vector part, v in the dual vector part.
DualQuaternion HalfTwist(const Vector6d& xi) {
  return DualQuaternion(Pure(0.5 * xi.head<3>()), Pure(0.5 * xi.tail<3>()));
}

// Random poses plus the edge cases: identity, pure translation, exactly π about each axis,
// tiny angles, near π, gimbal-lock orientations.
std::vector<Pose> TestPoses(std::mt19937_64& rng) {
  std::vector<Pose> poses;
  for (int i = 0; i < kDualQuaternionSamples; ++i) poses.push_back(testing::RandomPose(rng, 2.0));
  for (const Eigen::Vector3d& omega : testing::EdgeCaseRotationVectors(rng)) {
    poses.push_back(MakePose(so3::Exp(omega), testing::RandomGaussianVector(rng)));
  }
  poses.push_back(Pose::Identity());
  poses.push_back(MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.1, -0.2, 0.3)));
  poses.push_back(MakePose(Eigen::Vector3d(1, -1, -1).asDiagonal(), Eigen::Vector3d(1, 2, 3)));
  poses.push_back(MakePose(Eigen::Vector3d(-1, 1, -1).asDiagonal(), Eigen::Vector3d(0, 0, 1)));
  poses.push_back(MakePose(Eigen::Vector3d(-1, -1, 1).asDiagonal(), Eigen::Vector3d(-1, 0, 0)));
  // Exact half turns where the canonical quaternion (first non-zero component positive) and
  // so3::Log's rule (largest-magnitude component positive) pick opposite signs.
  for (const Eigen::Vector3d& n :
       {Eigen::Vector3d(0.6, -0.8, 0.0), Eigen::Vector3d(0.0, 0.6, -0.8)}) {
    poses.push_back(MakePose(2.0 * n * n.transpose() - Eigen::Matrix3d::Identity(),
                             Eigen::Vector3d(0.3, 0.2, -0.1)));
  }
  const Eigen::Matrix3d pitch90 =
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  poses.push_back(MakePose(pitch90, Eigen::Vector3d(0.5, 0.5, 0.5)));
  return poses;
}

TEST(DualQuaternion, ConstructorsAndConstants) {
  const DualQuaternion identity;
  EXPECT_EQ(identity.ToVector(), (Vector8d() << 1, 0, 0, 0, 0, 0, 0, 0).finished());
  EXPECT_EQ(DualQuaternion::Identity().ToVector(), identity.ToVector());
  EXPECT_EQ(DualQuaternion::Zero().ToVector(), Vector8d::Zero());
  EXPECT_EQ(identity.ToMatrix(), Eigen::Matrix4d::Identity());
  // Pair constructor: stored as given, not normalised.
  const Eigen::Quaterniond a(1, 2, 3, 4), b(5, 6, 7, 8);
  const DualQuaternion pair(a, b);
  EXPECT_EQ(pair.ToVector(), (Vector8d() << 1, 2, 3, 4, 5, 6, 7, 8).finished());
  EXPECT_EQ(Wxyz(pair.real()), Wxyz(a));
  EXPECT_EQ(Wxyz(pair.dual()), Wxyz(b));
}

TEST(DualQuaternion, RotationTranslationConstructorIsHalfTQ) {
  std::mt19937_64 rng(501);
  for (int i = 0; i < kDualQuaternionSamples; ++i) {
    const Eigen::Quaterniond q = RandomQuaternion(rng);  // normalised by the constructor
    const Eigen::Vector3d t = testing::RandomGaussianVector(rng);
    const DualQuaternion dq(q, t);
    const Eigen::Quaterniond unit = q.normalized();
    EXPECT_LT((Wxyz(dq.real()) - Wxyz(unit)).norm(), 1e-15);
    // q' = ½ t q, the product written out: ½ (−t·q_v, q_w t + t × q_v).
    const Eigen::Vector4d expected_dual(-0.5 * t.dot(unit.vec()),
                                        0.5 * (unit.w() * t + t.cross(unit.vec())).x(),
                                        0.5 * (unit.w() * t + t.cross(unit.vec())).y(),
                                        0.5 * (unit.w() * t + t.cross(unit.vec())).z());
    EXPECT_LT((Wxyz(dq.dual()) - expected_dual).norm(), 1e-15 * (1 + t.norm()));
    EXPECT_LT(PoseError(dq.ToPose(), MakePose(unit.toRotationMatrix(), t)), 2e-15 * (1 + t.norm()));
  }
}

TEST(DualQuaternion, FromPoseRoundTripsAndIsCanonical) {
  std::mt19937_64 rng(502);
  for (const Pose& T : TestPoses(rng)) {
    const DualQuaternion dq = DualQuaternion::FromPose(T);
    EXPECT_GE(dq.real().w(), 0.0);
    EXPECT_EQ(dq.Canonical().ToVector(), dq.ToVector());
    const double scale = 1 + T.translation().norm();
    EXPECT_LT(PoseError(dq.ToPose(), T), 4e-15 * scale) << T.matrix();
    EXPECT_LT((dq.ToMatrix() - T.matrix()).cwiseAbs().maxCoeff(), 4e-15 * scale);
    EXPECT_EQ(dq.ToMatrix().row(3), Eigen::RowVector4d(0, 0, 0, 1));
    const DualNumber norm = dq.Norm();
    EXPECT_NEAR(norm.real, 1.0, 4e-16);
    EXPECT_NEAR(norm.dual, 0.0, 4e-16 * scale);
  }
}

TEST(DualQuaternion, ProductIsPoseComposition) {
  std::mt19937_64 rng(503);
  const std::vector<Pose> poses = TestPoses(rng);
  std::uniform_int_distribution<size_t> pick(0, poses.size() - 1);
  for (int i = 0; i < 2 * kDualQuaternionSamples; ++i) {
    const Pose& A = poses[pick(rng)];
    const Pose& B = poses[pick(rng)];
    const Pose AB = A * B;
    const DualQuaternion product = DualQuaternion::FromPose(A) * DualQuaternion::FromPose(B);
    const double scale = 1 + A.translation().norm() + B.translation().norm();
    EXPECT_LT(PoseError(product.ToPose(), AB), 1e-14 * scale);
    EXPECT_TRUE(product.IsSamePose(DualQuaternion::FromPose(AB), 1e-14 * scale))
        << A.matrix() << "\n"
        << B.matrix();
  }
}

TEST(DualQuaternion, NegativeRealPartStillGivesThePose) {
  // Two rotations of 0.9π about the same axis compose to 1.8π: the product's real w is
  // cos(0.9π) < 0, yet it is the same pose as FromPose(A·B) (which has w > 0).
  std::mt19937_64 rng(504);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d n = testing::RandomUnitVector(rng);
    const Pose A = MakePose(Eigen::AngleAxisd(0.9 * std::numbers::pi, n).toRotationMatrix(),
                            testing::RandomGaussianVector(rng));
    const Pose B = MakePose(Eigen::AngleAxisd(0.9 * std::numbers::pi, n).toRotationMatrix(),
                            testing::RandomGaussianVector(rng));
    const DualQuaternion product = DualQuaternion::FromPose(A) * DualQuaternion::FromPose(B);
    ASSERT_LT(product.real().w(), 0.0);
    EXPECT_LT(PoseError(product.ToPose(), A * B), 1e-14);
    EXPECT_LT((product.Rotation().toRotationMatrix() - (A * B).linear()).cwiseAbs().maxCoeff(),
              1e-14);
    EXPECT_LT((product.TransformPoint(Eigen::Vector3d(1, 2, 3)) - A * B * Eigen::Vector3d(1, 2, 3))
                  .norm(),
              1e-13);
    const DualQuaternion canonical = product.Canonical();
    EXPECT_GT(canonical.real().w(), 0.0);
    EXPECT_EQ(canonical.ToVector(), -product.ToVector());
    EXPECT_LT(MaxAbs(canonical.ToVector() - DualQuaternion::FromPose(A * B).ToVector()), 1e-14);
    EXPECT_TRUE(product.IsSamePose(DualQuaternion::FromPose(A * B), 1e-14));
  }
}

TEST(DualQuaternion, CanonicalTieBreaks) {
  // w = 0: first non-zero component of the 8-vector decides.
  const DualQuaternion a(Eigen::Quaterniond(0, -1, 0, 0), Eigen::Quaterniond(0, 0, 1, 0));
  EXPECT_EQ(a.Canonical().ToVector(), (Vector8d() << 0, 1, 0, 0, 0, 0, -1, 0).finished());
  const DualQuaternion b(Eigen::Quaterniond(0, 0, 0.6, -0.8), Eigen::Quaterniond(0, 1, 0, 0));
  EXPECT_EQ(b.Canonical().ToVector(), b.ToVector());
  EXPECT_EQ(DualQuaternion::Zero().Canonical().ToVector(), Vector8d::Zero());
}

TEST(DualQuaternion, ConjugateAndInverse) {
  std::mt19937_64 rng(505);
  const DualQuaternion one = DualQuaternion::Identity();
  for (const Pose& T : TestPoses(rng)) {
    const DualQuaternion dq = DualQuaternion::FromPose(T);
    const DualQuaternion conj = dq.Conjugate();
    EXPECT_EQ(Wxyz(conj.real()),
              Eigen::Vector4d(dq.real().w(), -dq.real().x(), -dq.real().y(), -dq.real().z()));
    EXPECT_EQ(Wxyz(conj.dual()),
              Eigen::Vector4d(dq.dual().w(), -dq.dual().x(), -dq.dual().y(), -dq.dual().z()));
    const double scale = 1 + T.translation().norm();
    // Unit: conjugate = inverse = the inverse pose.
    EXPECT_LT(MaxAbs(conj.ToVector() - dq.Inverse().ToVector()), 1e-15 * scale);
    EXPECT_LT(MaxAbs((dq * conj).ToVector() - one.ToVector()), 2e-15 * scale);
    EXPECT_LT(PoseError(conj.ToPose(), T.inverse()), 4e-15 * scale);
  }
  // Not unit: q̌ q̌⁻¹ = q̌⁻¹ q̌ = 1 for any q̌ with non-zero real part.
  for (int i = 0; i < kDualQuaternionSamples; ++i) {
    const Eigen::Quaterniond dual_part = RandomQuaternion(rng);  // drawn first
    const DualQuaternion dq(RandomQuaternion(rng), dual_part);
    const DualQuaternion inv = dq.Inverse();
    const double scale = (1 + dq.dual().norm() / dq.real().norm());
    const double conditioning = scale * scale;
    EXPECT_LT(MaxAbs((dq * inv).ToVector() - one.ToVector()), 4e-15 * conditioning);
    EXPECT_LT(MaxAbs((inv * dq).ToVector() - one.ToVector()), 4e-15 * conditioning);
  }
}

TEST(DualQuaternion, NormAndNormalize) {
  std::mt19937_64 rng(506);
  for (int i = 0; i < kDualQuaternionSamples; ++i) {
    // General q̌: |q̌| = |q| + ε (q·q')/|q|, from the 4-vectors.
    const Eigen::Quaterniond dual_part = RandomQuaternion(rng);
    const DualQuaternion dq(RandomQuaternion(rng), dual_part);
    const Eigen::Vector4d q = Wxyz(dq.real()), qd = Wxyz(dq.dual());
    const DualNumber norm = dq.Norm();
    EXPECT_NEAR(norm.real, q.norm(), 1e-15 * q.norm());
    EXPECT_NEAR(norm.dual, q.dot(qd) / q.norm(), 1e-14 * qd.norm());
    // Normalized: |real| = 1, real ⟂ dual, Norm() = (1, 0); Normalize() does it in place.
    const DualQuaternion unit = dq.Normalized();
    EXPECT_NEAR(unit.real().norm(), 1.0, 4e-16);
    EXPECT_NEAR(Wxyz(unit.real()).dot(Wxyz(unit.dual())), 0.0, 1e-15 * (1 + qd.norm() / q.norm()));
    DualQuaternion in_place = dq;
    in_place.Normalize();
    EXPECT_EQ(in_place.ToVector(), unit.ToVector());
    EXPECT_EQ(dq.Normalized().ToVector(), unit.ToVector());  // Normalized() is const
  }
  // Scaling a unit q̌ by a dual number s + εs' (s > 0) is undone exactly by Normalize, and the
  // pose is unchanged throughout (ToPose / Translation are invariant to that scaling).
  hecal::NormalDistribution normal;
  for (const Pose& T : TestPoses(rng)) {
    const DualQuaternion dq = DualQuaternion::FromPose(T);
    const double s = std::exp(normal(rng));
    const double s_dual = normal(rng);
    const DualQuaternion factor(Eigen::Quaterniond(s, 0, 0, 0),
                                Eigen::Quaterniond(s_dual, 0, 0, 0));
    const DualQuaternion product = factor * dq;
    const DualNumber norm = product.Norm();
    EXPECT_NEAR(norm.real, s, 1e-15 * s);
    EXPECT_NEAR(norm.dual, s_dual, 1e-14 * (s + std::abs(s_dual)) * (1 + T.translation().norm()));
    const double scale = 1 + T.translation().norm();
    EXPECT_LT(MaxAbs(product.Normalized().ToVector() - dq.ToVector()), 4e-15 * scale);
    EXPECT_LT(PoseError(product.ToPose(), T), 1e-14 * scale);
    EXPECT_LT((product.Translation() - T.translation()).norm(), 1e-14 * scale);
    // Negative scale: the same pose, opposite sign.
    EXPECT_TRUE((product * -1.0).Normalized().IsSamePose(dq, 4e-15 * scale));
  }
}

TEST(DualQuaternion, LogIsHalfTheSe3Twist) {
  // Log(DQ(T)) = ½ (ω + ε v), (ω, v) = se3::Log(T), including pure translation, tiny angles,
  // near π and exactly π (same sign rule as so3::Log).
  std::mt19937_64 rng(507);
  for (const Pose& T : TestPoses(rng)) {
    const DualQuaternion log = DualQuaternion::FromPose(T).Log();
    const Vector6d xi = se3::Log(T);
    const DualQuaternion expected = HalfTwist(xi);
    const double scale = 1 + T.translation().norm();
    EXPECT_LT(std::abs(log.real().w()), 4e-16);  // ln|q|, |q| = 1 to rounding
    EXPECT_LT(std::abs(log.dual().w()), 1e-15 * scale);
    EXPECT_LT((log.real().vec() - expected.real().vec()).norm(),
              2e-15 * std::min(1.0, xi.head<3>().norm()) + 1e-300)
        << T.matrix();
    EXPECT_LT((log.dual().vec() - expected.dual().vec()).norm(), 1e-14 * scale) << T.matrix();
  }
}

TEST(DualQuaternion, ExpMatchesSe3Exp) {
  // Exp(½ (ω + ε v)) = DQ(se3::Exp(ω, v)) up to sign, for any angle (Exp is total).
  std::mt19937_64 rng(508);
  std::vector<Vector6d> twists =
      testing::RandomTwists(rng, kDualQuaternionSamples, 3.0 * std::numbers::pi);
  twists.push_back(testing::Twist(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 3)));
  twists.push_back(Vector6d::Zero());
  for (const Vector6d& xi : twists) {
    const DualQuaternion exp = HalfTwist(xi).Exp();
    const double scale = 1 + xi.tail<3>().norm();
    EXPECT_LT(PoseError(exp.ToPose(), se3::Exp(xi)), 1e-14 * scale) << xi.transpose();
    EXPECT_LT(SignFreeDistance(exp, DualQuaternion::FromPose(se3::Exp(xi))), 1e-14 * scale);
    const DualNumber norm = exp.Norm();
    EXPECT_NEAR(norm.real, 1.0, 4e-16);
    EXPECT_NEAR(norm.dual, 0.0, 1e-15 * scale);
  }
  EXPECT_EQ(DualQuaternion::Zero().Exp().ToVector(), DualQuaternion::Identity().ToVector());
}

TEST(DualQuaternion, ExpLogRoundTrips) {
  std::mt19937_64 rng(509);
  for (const Pose& T : TestPoses(rng)) {
    const DualQuaternion dq = DualQuaternion::FromPose(T);
    const double scale = 1 + T.translation().norm();
    EXPECT_LT(SignFreeDistance(dq.Log().Exp(), dq), 4e-15 * scale) << T.matrix();
    // Square root: Exp(½ Log q̌)² = q̌.
    const DualQuaternion root = (dq.Log() * 0.5).Exp();
    EXPECT_LT(SignFreeDistance(root * root, dq), 1e-14 * scale);
  }
  hecal::UniformRealDistribution angle(0.0, std::numbers::pi);
  for (int i = 0; i < kDualQuaternionSamples; ++i) {
    const Eigen::Vector3d v = testing::RandomGaussianVector(rng);  // drawn first
    const Vector6d xi = testing::Twist(testing::RandomRotationVector(rng, angle(rng)), v);
    const DualQuaternion p = HalfTwist(xi);
    const double scale = 1 + xi.tail<3>().norm();
    EXPECT_LT(MaxAbs(p.Exp().Log().ToVector() - p.ToVector()), 1e-14 * scale) << xi.transpose();
  }
  // Tiny and near-π angles, around the series switches (σ at 1e-4, κ at 1e-2 half-angles).
  for (double theta : {1e-12, 1e-9, 1.99e-4, 2.01e-4, 1.99e-2, 2.01e-2, std::numbers::pi - 1e-6,
                       std::numbers::pi - 1e-9}) {
    for (int i = 0; i < 20; ++i) {
      const Eigen::Vector3d v = testing::RandomGaussianVector(rng);
      const Vector6d xi = testing::Twist(testing::RandomRotationVector(rng, theta), v);
      const DualQuaternion p = HalfTwist(xi);
      EXPECT_LT(MaxAbs(p.Exp().Log().ToVector() - p.ToVector()), 1e-14) << theta;
      EXPECT_LT(PoseError(p.Exp().ToPose(), se3::Exp(xi)), 1e-14) << theta;
    }
  }
}

TEST(DualQuaternion, ExpLogWithScalarParts) {
  // log(a + εb) = ln a + ε b/a for the dual norm; Exp(s + εs' + p̌) = eˢ (1 + εs') Exp(p̌).
  std::mt19937_64 rng(510);
  hecal::NormalDistribution normal;
  for (int i = 0; i < 500; ++i) {
    const Pose T = testing::RandomPose(rng);
    const DualQuaternion unit = DualQuaternion::FromPose(T);
    const double s = normal(rng), s_dual = normal(rng);
    const DualQuaternion factor(Eigen::Quaterniond(std::exp(s), 0, 0, 0),
                                Eigen::Quaterniond(s_dual * std::exp(s), 0, 0, 0));
    const DualQuaternion scaled = factor * unit;
    const DualQuaternion log = scaled.Log();
    EXPECT_NEAR(log.real().w(), s, 1e-14);
    EXPECT_NEAR(log.dual().w(), s_dual, 1e-13);
    EXPECT_LT((log.real().vec() - unit.Log().real().vec()).norm(), 1e-14);
    EXPECT_LT((log.dual().vec() - unit.Log().dual().vec()).norm(), 1e-13);
    EXPECT_LT(SignFreeDistance(log.Exp(), scaled), 1e-13 * std::exp(std::abs(s)));
  }
}

TEST(DualQuaternion, ScrewLinearInterpolationFollowsSe3Geodesic) {
  // q̌0 · Exp(s · Log(q̌0* q̌1)) (ScLERP) is the same curve as se3::Interpolate.
  std::mt19937_64 rng(511);
  for (int i = 0; i < 500; ++i) {
    const Pose T0 = testing::RandomPose(rng);
    const Pose T1 = testing::RandomPose(rng);
    const DualQuaternion q0 = DualQuaternion::FromPose(T0);
    const DualQuaternion q1 = DualQuaternion::FromPose(T1);
    for (double s : {0.0, 0.3, 0.5, 1.0}) {
      const DualQuaternion qs = q0 * ((q0.Conjugate() * q1).Log() * s).Exp();
      EXPECT_LT(PoseError(qs.ToPose(), se3::Interpolate(T0, T1, s)), 1e-13) << s;
    }
  }
}

TEST(DualQuaternion, TransformPointAndVector) {
  std::mt19937_64 rng(512);
  for (const Pose& T : TestPoses(rng)) {
    const DualQuaternion dq = DualQuaternion::FromPose(T);
    const Eigen::Vector3d p = testing::RandomGaussianVector(rng, 2.0);
    const double scale = 1 + T.translation().norm() + p.norm();
    EXPECT_LT((dq.TransformPoint(p) - T * p).norm(), 4e-15 * scale);
    EXPECT_LT((dq.TransformVector(p) - T.linear() * p).norm(), 4e-15 * scale);
    // The sandwich q̌ (1 + ε p) q̌̄ with the full conjugate q̌̄ = q* − ε q'* gives 1 + ε (R p + t).
    const DualQuaternion point(Eigen::Quaterniond::Identity(), Pure(p));
    const Eigen::Quaterniond dual_conj = dq.dual().conjugate();
    const DualQuaternion full_conjugate(
        dq.real().conjugate(),
        Eigen::Quaterniond(-dual_conj.w(), -dual_conj.x(), -dual_conj.y(), -dual_conj.z()));
    const DualQuaternion sandwich = dq * point * full_conjugate;
    EXPECT_LT((Wxyz(sandwich.real()) - Eigen::Vector4d(1, 0, 0, 0)).norm(), 2e-15);
    EXPECT_LT(std::abs(sandwich.dual().w()), 4e-15 * scale);
    EXPECT_LT((dq.TransformPoint(p) - sandwich.dual().vec()).norm(), 4e-15 * scale);
    const Eigen::Vector3d rotated = (dq.real() * Pure(p) * dq.real().conjugate()).vec();
    EXPECT_LT((dq.TransformVector(p) - rotated).norm(), 4e-15 * scale);
  }
}

TEST(DualQuaternion, RotationTranslationAccessors) {
  std::mt19937_64 rng(513);
  for (const Pose& T : TestPoses(rng)) {
    const DualQuaternion dq = DualQuaternion::FromPose(T);
    const double scale = 1 + T.translation().norm();
    EXPECT_LT((dq.Translation() - T.translation()).norm(), 4e-15 * scale);
    const Eigen::Quaterniond tq = dq.TranslationQuaternion();
    EXPECT_EQ(tq.w(), 0.0);
    EXPECT_LT((tq.vec() - T.translation()).norm(), 4e-15 * scale);
    // t = 2 q' q*, written out with Eigen's product.
    EXPECT_LT(((dq.dual() * dq.real().conjugate()).vec() * 2.0 - T.translation()).norm(),
              4e-15 * scale);
    EXPECT_LT((dq.Rotation().toRotationMatrix() - T.linear()).cwiseAbs().maxCoeff(), 2e-15);
    EXPECT_NEAR(dq.Rotation().norm(), 1.0, 4e-16);
    // Rotation() normalises a scaled real part.
    const DualQuaternion scaled = dq * 2.5;
    EXPECT_LT((Wxyz(scaled.Rotation()) - Wxyz(dq.real())).norm(), 1e-15);
  }
}

TEST(DualQuaternion, ScrewConversions) {
  std::mt19937_64 rng(514);
  hecal::UniformRealDistribution angle(0.0, std::numbers::pi);
  for (int i = 0; i < kDualQuaternionSamples; ++i) {
    // Daniilidis: q̌ = (cos(θ̌/2), sin(θ̌/2) ľ), θ̌ = θ + εd, ľ = l + εm, expanded here.
    Screw screw;
    screw.l = testing::RandomUnitVector(rng);
    const Eigen::Vector3d c = testing::RandomGaussianVector(rng);
    screw.m = c.cross(screw.l);
    screw.theta = angle(rng);
    screw.d = testing::RandomGaussianVector(rng).x();
    const double ch = std::cos(0.5 * screw.theta), sh = std::sin(0.5 * screw.theta);
    Vector8d expected;
    expected << ch, sh * screw.l, -0.5 * screw.d * sh, sh * screw.m + 0.5 * screw.d * ch * screw.l;
    const DualQuaternion dq = DualQuaternion::FromScrew(screw);
    EXPECT_LT(MaxAbs(dq.ToVector() - expected), 1e-15 * (1 + c.norm()));
    // It is the constructed screw motion, and agrees with screw.h's PoseFromScrew.
    const Pose T = testing::ScrewMotion(screw.l, c, screw.theta, screw.d);
    EXPECT_LT(PoseError(dq.ToPose(), T), 1e-14 * (1 + c.norm()));
    EXPECT_LT(PoseError(dq.ToPose(), PoseFromScrew(screw)), 1e-14 * (1 + c.norm()));
    // Log = ½ θ̌ ľ = ½ (θ l + ε (θ m + d l)).
    const DualQuaternion log = dq.Log();
    EXPECT_LT((log.real().vec() - 0.5 * screw.theta * screw.l).norm(), 4e-15);
    EXPECT_LT((log.dual().vec() - 0.5 * (screw.theta * screw.m + screw.d * screw.l)).norm(),
              1e-14 * (1 + c.norm()));
  }
  for (const Pose& T : TestPoses(rng)) {
    const DualQuaternion dq = DualQuaternion::FromPose(T);
    const Screw from_dq = dq.ToScrew();
    const Screw from_pose = ScrewFromPose(T);
    const double tolerance = 1e-14 * (1 + T.translation().norm()) / std::max(from_pose.theta, 1e-6);
    EXPECT_NEAR(from_dq.theta, from_pose.theta, 4e-15);
    EXPECT_NEAR(from_dq.d, from_pose.d, tolerance);
    EXPECT_LT((from_dq.l - from_pose.l).norm(), tolerance);
    EXPECT_LT((from_dq.m - from_pose.m).norm(), tolerance * (1 + from_pose.m.norm()));
    EXPECT_TRUE(
        DualQuaternion::FromScrew(from_pose).IsSamePose(dq, 1e-14 * (1 + T.translation().norm())))
        << T.matrix();
  }
  // Pure translation: l = t/|t|, d = |t|, θ = 0 → (1, 0) + ε (0, ½ t).
  Screw translation;
  translation.l = Eigen::Vector3d(0, 0.6, 0.8);
  translation.d = 2.0;
  EXPECT_LT(MaxAbs(DualQuaternion::FromScrew(translation).ToVector() -
                   (Vector8d() << 1, 0, 0, 0, 0, 0, 0.6, 0.8).finished()),
            1e-16);
}

TEST(DualQuaternion, VectorLayoutAndArithmetic) {
  std::mt19937_64 rng(515);
  for (int i = 0; i < 100; ++i) {
    Vector8d v;
    for (int k = 0; k < 8; ++k) v(k) = testing::RandomGaussianVector(rng).x();
    const DualQuaternion dq = DualQuaternion::FromVector(v);
    EXPECT_EQ(dq.ToVector(), v);
    EXPECT_EQ(dq.real().w(), v(0));
    EXPECT_EQ(dq.real().z(), v(3));
    EXPECT_EQ(dq.dual().w(), v(4));
    EXPECT_EQ(dq.dual().x(), v(5));
    Vector8d u;
    for (int k = 0; k < 8; ++k) u(k) = testing::RandomGaussianVector(rng).x();
    const DualQuaternion other = DualQuaternion::FromVector(u);
    EXPECT_EQ((dq + other).ToVector(), v + u);
    EXPECT_EQ((dq - other).ToVector(), v - u);
    EXPECT_EQ((dq * 2.5).ToVector(), 2.5 * v);
    // Product: real = q r, dual = q r' + q' r (Eigen's Hamilton product for each part).
    const DualQuaternion product = dq * other;
    const Eigen::Quaterniond q = dq.real(), qd = dq.dual(), r = other.real(), rd = other.dual();
    Vector8d expected;
    expected << Wxyz(q * r), Wxyz(q * rd) + Wxyz(qd * r);
    EXPECT_LT(MaxAbs(product.ToVector() - expected), 1e-14);
  }
}

TEST(DualQuaternion, IsSamePoseUpToSign) {
  std::mt19937_64 rng(516);
  const DualQuaternion dq = DualQuaternion::FromPose(testing::RandomPose(rng));
  EXPECT_TRUE(dq.IsSamePose(dq, 0.0));
  EXPECT_TRUE(dq.IsSamePose(dq * -1.0, 0.0));
  const DualQuaternion nudged =
      dq + DualQuaternion(Eigen::Quaterniond(0, 0, 0, 0), Eigen::Quaterniond(0, 1e-9, 0, 0));
  EXPECT_TRUE(dq.IsSamePose(nudged, 2e-9));
  EXPECT_FALSE(dq.IsSamePose(nudged, 1e-10));
  EXPECT_TRUE((dq * -1.0).IsSamePose(nudged, 2e-9));
  const DualQuaternion other = DualQuaternion::FromPose(testing::RandomPose(rng));
  EXPECT_FALSE(dq.IsSamePose(other, 1e-3));
}

}  // namespace
}  // namespace hecal
