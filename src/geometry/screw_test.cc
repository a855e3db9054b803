// Tests for screw.h against the geometry of Chasles' theorem: motions are built as "rotate θ
// about the line through c with direction n, then slide d along n" (independent of screw.cc),
// and the recovered (l, m, θ, d) must describe that line: points on it move only along l, by d.
#include "hecal/geometry/screw.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/geometry_test_util.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/se3.h"
#include "testing/random_poses.h"
#include "testing/screw_motions.h"

namespace hecal {
namespace {

constexpr int kScrewSamples = 3000;

// The invariants every Screw from ScrewFromPose satisfies.
void ExpectValidScrew(const Screw& s) {
  EXPECT_NEAR(s.l.norm(), 1.0, 4e-16);
  EXPECT_LE(std::abs(s.l.dot(s.m)), 4e-15 * (1 + s.m.norm()));
  EXPECT_GE(s.theta, 0.0);
  EXPECT_LE(s.theta, std::numbers::pi);
}

// The point of the axis line nearest the origin, p = l × m, is moved only along l, by d; every
// point x moves as p + R(x − p) + d l with R the rotation θ about l.
void ExpectDescribesMotion(const Screw& s, const Pose& T, double tolerance) {
  const Eigen::Vector3d p = s.l.cross(s.m);
  EXPECT_LT((T * p - (p + s.d * s.l)).norm(), tolerance);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(s.theta, s.l).toRotationMatrix();
  EXPECT_LT((T.linear() - R).cwiseAbs().maxCoeff(), 4e-15);
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-4, 0.5, 0)}) {
    EXPECT_LT((T * x - (p + R * (x - p) + s.d * s.l)).norm(), tolerance);
  }
}

TEST(Screw, RecoversConstructedScrewMotion) {
  std::mt19937_64 rng(401);
  for (int i = 0; i < kScrewSamples; ++i) {
    const auto [n, c, theta, d] = testing::RandomScrewLine(rng, 1e-3, std::numbers::pi - 1e-3);
    const Pose T = testing::ScrewMotion(n, c, theta, d);
    const Screw s = ScrewFromPose(T);
    ExpectValidScrew(s);
    // θ ∈ (0, π): the axis sign is fixed by θ ≥ 0, so l = n, d and the line are unique.
    EXPECT_LT((s.l - n).norm(), 1e-14 / theta) << theta;
    EXPECT_NEAR(s.theta, theta, 4e-15);
    EXPECT_NEAR(s.d, d, 1e-14 * (1 + c.norm()) / theta);
    const Eigen::Vector3d expected_m = c.cross(n);  // moment of the line through c along n
    EXPECT_LT((s.m - expected_m).norm(), 1e-13 * (1 + c.norm()) / theta) << theta;
    ExpectDescribesMotion(s, T, 1e-13 * (1 + c.norm()));
  }
}

TEST(Screw, KnownExample) {
  // Quarter turn about the vertical line through (1, 2, 0), then 0.5 up: l = z, m = c × z.
  const Pose T = testing::ScrewMotion(Eigen::Vector3d::UnitZ(), Eigen::Vector3d(1, 2, 0),
                                      std::numbers::pi / 2, 0.5);
  const Screw s = ScrewFromPose(T);
  EXPECT_LT((s.l - Eigen::Vector3d::UnitZ()).norm(), 1e-16);
  EXPECT_LT((s.m - Eigen::Vector3d(2, -1, 0)).norm(), 1e-15);
  EXPECT_NEAR(s.theta, std::numbers::pi / 2, 1e-16);
  EXPECT_NEAR(s.d, 0.5, 1e-16);
}

TEST(Screw, RoundTripsRandomPoses) {
  std::mt19937_64 rng(402);
  std::vector<Pose> poses;
  for (int i = 0; i < kScrewSamples; ++i) poses.push_back(testing::RandomPose(rng, 2.0));
  for (const Eigen::Vector3d& omega : testing::EdgeCaseRotationVectors(rng)) {
    const double theta = omega.norm();
    const Eigen::Matrix3d R = theta == 0.0
                                  ? Eigen::Matrix3d::Identity()
                                  : Eigen::AngleAxisd(theta, omega / theta).toRotationMatrix();
    poses.push_back(MakePose(R, testing::RandomGaussianVector(rng)));
  }
  for (const Pose& T : poses) {
    const Screw s = ScrewFromPose(T);
    ExpectValidScrew(s);
    // PoseFromScrew recomputes t = d l + sinθ m + (1 − cosθ) l × m; with |m| ~ |t|/θ at tiny θ
    // the products stay at rounding level (sinθ |m| ~ |t|).
    EXPECT_LT(PoseError(PoseFromScrew(s), T), 1e-14 * (1 + T.translation().norm())) << T.matrix();
  }
}

TEST(Screw, RoundTripsScrewParameters) {
  std::mt19937_64 rng(403);
  hecal::UniformRealDistribution angle(1e-6, std::numbers::pi - 1e-6);
  for (int i = 0; i < kScrewSamples; ++i) {
    Screw s;
    s.l = testing::RandomUnitVector(rng);
    const Eigen::Vector3d point = testing::RandomGaussianVector(rng);
    s.m = point.cross(s.l);
    s.theta = angle(rng);
    s.d = testing::RandomGaussianVector(rng).x();
    const Screw back = ScrewFromPose(PoseFromScrew(s));
    EXPECT_LT((back.l - s.l).norm(), 1e-15 / s.theta + 1e-15);
    EXPECT_LT((back.m - s.m).norm(), 1e-14 * (1 + s.m.norm()) / s.theta);
    EXPECT_NEAR(back.theta, s.theta, 4e-15);
    EXPECT_NEAR(back.d, s.d, 1e-14 * (1 + s.m.norm()) / s.theta);
  }
}

TEST(Screw, PoseFromScrewMatchesGeometry) {
  // Non-unit l is normalised; a component of m along l is ignored.
  std::mt19937_64 rng(404);
  for (int i = 0; i < kScrewSamples; ++i) {
    const auto [n, c, theta, d] = testing::RandomScrewLine(rng);
    Screw s;
    s.l = 3.0 * n;
    s.m = c.cross(n) + 0.7 * n;
    s.theta = theta;
    s.d = d;
    EXPECT_LT(PoseError(PoseFromScrew(s), testing::ScrewMotion(n, c, theta, d)),
              1e-14 * (1 + c.norm()));
  }
}

TEST(Screw, PureTranslationAndIdentity) {
  const Screw identity = ScrewFromPose(Pose::Identity());
  EXPECT_EQ(identity.l, Eigen::Vector3d::UnitX());
  EXPECT_EQ(identity.m, Eigen::Vector3d::Zero());
  EXPECT_EQ(identity.theta, 0.0);
  EXPECT_EQ(identity.d, 0.0);
  EXPECT_EQ(PoseFromScrew(identity).matrix(), Eigen::Matrix4d::Identity());
  const Eigen::Vector3d t(0.3, -1.2, 0.4);
  const Pose T = MakePose(Eigen::Matrix3d::Identity(), t);
  const Screw s = ScrewFromPose(T);
  EXPECT_LT((s.l - t.normalized()).norm(), 1e-16);
  EXPECT_NEAR(s.d, t.norm(), 1e-16);
  EXPECT_EQ(s.theta, 0.0);
  EXPECT_EQ(s.m, Eigen::Vector3d::Zero());
  EXPECT_LT(PoseError(PoseFromScrew(s), T), 1e-16);
}

TEST(Screw, HalfTurn) {
  // Exactly π about x through the point (0, 1, 0), plus 0.25 along x. The axis sign comes from
  // AxisAngleFromMatrix (largest |component| positive): l = +x.
  const Eigen::Matrix3d R = Eigen::Vector3d(1, -1, -1).asDiagonal();
  const Eigen::Vector3d c(0, 1, 0);
  const Pose T = MakePose(R, c - R * c + 0.25 * Eigen::Vector3d::UnitX());
  const Screw s = ScrewFromPose(T);
  EXPECT_EQ(s.l, Eigen::Vector3d::UnitX());
  EXPECT_EQ(s.theta, std::numbers::pi);
  EXPECT_NEAR(s.d, 0.25, 1e-16);
  EXPECT_LT((s.m - c.cross(Eigen::Vector3d::UnitX())).norm(), 1e-15);
  ExpectDescribesMotion(s, T, 1e-15);
  EXPECT_LT(PoseError(PoseFromScrew(s), T), 1e-15);
  // (−l, −m, −d) is the same motion at π.
  Screw flipped = s;
  flipped.l = -s.l;
  flipped.m = -s.m;
  flipped.d = -s.d;
  EXPECT_LT(PoseError(PoseFromScrew(flipped), T), 1e-15);
}

TEST(Screw, TinyAngleMomentGrowsAsOneOverTheta) {
  // Documented behaviour: as θ → 0 with a translation ⊥ the axis, the axis line moves off to
  // distance |t⊥| / θ (|m| ≈ |t⊥| / θ); the round trip stays exact.
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d t(1.0, 0.0, 0.5);
  for (double theta : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const Pose T = MakePose(Eigen::AngleAxisd(theta, n).toRotationMatrix(), t);
    const Screw s = ScrewFromPose(T);
    EXPECT_LT((s.l - n).norm(), 1e-16);
    EXPECT_NEAR(s.d, 0.5, 1e-16);
    EXPECT_NEAR(s.m.norm() * theta, 1.0, 1e-6);
    EXPECT_LT(PoseError(PoseFromScrew(s), T), 1e-15) << theta;
    ExpectDescribesMotion(s, T, 1e-15 * s.m.norm());
  }
}

TEST(Screw, AgreesWithTwist) {
  // se3::Log(T) = (θ l, θ m + d l): two independent derivations must agree.
  std::mt19937_64 rng(405);
  for (int i = 0; i < kScrewSamples; ++i) {
    const Pose T = testing::RandomPose(rng, 2.0);
    const Screw s = ScrewFromPose(T);
    const Vector6d xi = se3::Log(T);
    EXPECT_LT((xi.head<3>() - s.theta * s.l).norm(), 4e-15);
    EXPECT_LT((xi.tail<3>() - (s.theta * s.m + s.d * s.l)).norm(), 2e-14);
  }
}

}  // namespace
}  // namespace hecal
