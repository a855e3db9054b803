// Pose from affinity (docs/contour.md#motion-from-an-affinity): exact inversion of the
// weak-perspective model on every axis and combined, both rotation forms, their ranges and the
// Necker rule, singular input.
#include "hecal/contour/affine_pose.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "contour/contour_test_util.h"
#include "hecal/contour/perspective_view.h"
#include "hecal/contour/shape_space.h"
#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/euler.h"
#include "testing/options_validity.h"

namespace hecal::contour {
namespace {

Eigen::Matrix3d Zxz(double phi, double theta, double psi) {
  return MatrixFromEuler(Eigen::Vector3d(phi, theta, psi), *EulerSequence::Parse("ZXZ"));
}

// The pose recovered from the model's own shape vector equals the truth (or, in the form's
// ranges, exactly the truth) to 1e-9 relative.
void ExpectRecovered(const Eigen::Matrix3d& R, const Eigen::Vector3d& T, RotationForm form,
                     bool in_range) {
  const Vector6d S = ShapeFromPose(R, T, kCamera);
  const ContourPose pose = PoseFromShape(S, kCamera, form);
  EXPECT_LT((pose.translation - T).norm(), 1e-9 * (kCamera.z0 + T.norm())) << T.transpose();
  const Eigen::Matrix3d expected = in_range ? R : CanonicalPose(R, T, form).rotation;
  EXPECT_LT((pose.rotation - expected).norm(), 1e-9) << "R\n" << R << "\ngot\n" << pose.rotation;
  // The Euler angles reproduce the rotation and lie in the form's ranges.
  EXPECT_LT(
      (MatrixFromEuler(pose.euler, *EulerSequence::Parse(RotationSequence(form))) - pose.rotation)
          .norm(),
      1e-12);
  EXPECT_GE(pose.euler(0), 0.0);
  EXPECT_LT(pose.euler(0), 2.0 * std::numbers::pi);
  if (form == RotationForm::kZxz) {
    EXPECT_LT(pose.euler(0), std::numbers::pi);
    EXPECT_GE(pose.euler(1), 0.0);
    EXPECT_LT(pose.euler(1), std::numbers::pi / 2);
    EXPECT_GE(pose.euler(2), 0.0);
    EXPECT_LT(pose.euler(2), 2.0 * std::numbers::pi);
  } else {
    EXPECT_GE(pose.euler(1) + pose.euler(2), 0.0);
    EXPECT_LT(std::abs(pose.euler(1)), std::numbers::pi / 2);
    EXPECT_LT(std::abs(pose.euler(2)), std::numbers::pi / 2);
  }
  // The returned pose gives back the shape vector: the mirror is indistinguishable.
  EXPECT_LT((ShapeFromPose(pose.rotation, pose.translation, kCamera) - S).norm(), 1e-12);
}

TEST(AffinePose, EveryAxisAloneZyx) {
  const RotationForm f = RotationForm::kZyx;
  for (double v : {0.0, 1.0, 50.0, 250.0, -250.0}) {
    ExpectRecovered(Eigen::Matrix3d::Identity(), Eigen::Vector3d(v, 0, 0), f, true);
    ExpectRecovered(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, v, 0), f, true);
  }
  for (double v : {-3500.0, -1000.0, 0.0, 2000.0}) {
    ExpectRecovered(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, v), f, true);
  }
  // Out-of-plane angles over [0, 90°), including tiny ones (no cancellation near 0).
  for (double a : {1e-8, 1e-4, 0.5, 5.0, 20.0, 45.0, 80.0, 89.0}) {
    ExpectRecovered(RotationZyx(a * kRadiansPerDegree, 0, 0), Eigen::Vector3d::Zero(), f, true);
    ExpectRecovered(RotationZyx(0, a * kRadiansPerDegree, 0), Eigen::Vector3d::Zero(), f, true);
  }
  for (double a : {0.0, 1e-6, 10.0, 90.0, 179.0, 180.0, 270.0, 359.9}) {
    ExpectRecovered(RotationZyx(0, 0, a * kRadiansPerDegree), Eigen::Vector3d::Zero(), f, true);
  }
}

TEST(AffinePose, CombinedMotionsInRangeAreExactZyx) {
  std::mt19937_64 rng(7);
  hecal::UniformRealDistribution tilt(0.0, 85.0), spin(0.0, 360.0), lateral(-400, 400),
      depth(-3500, 3000);
  for (int trial = 0; trial < 500; ++trial) {
    // Drawn last to first: the order these tests' data were generated in.
    const double rz = spin(rng) * kRadiansPerDegree;
    const double ry = tilt(rng) * kRadiansPerDegree;
    const double rx = tilt(rng) * kRadiansPerDegree;
    const Eigen::Matrix3d R = RotationZyx(rx, ry, rz);
    if (!(R(2, 2) > 0.05)) continue;
    const double tz = depth(rng);
    const double ty = lateral(rng);
    const double tx = lateral(rng);
    ExpectRecovered(R, Eigen::Vector3d(tx, ty, tz), RotationForm::kZyx, true);
  }
}

TEST(AffinePose, CombinedMotionsInRangeAreExactZxz) {
  std::mt19937_64 rng(8);
  hecal::UniformRealDistribution phi(0.0, 179.9), theta(0.0, 87.0), psi(0.0, 359.9),
      lateral(-400, 400), depth(-3500, 3000);
  for (int trial = 0; trial < 500; ++trial) {
    const double tz = depth(rng);
    const double ty = lateral(rng);
    const double tx = lateral(rng);
    const double c = psi(rng) * kRadiansPerDegree;
    const double b = theta(rng) * kRadiansPerDegree;
    const double a = phi(rng) * kRadiansPerDegree;
    ExpectRecovered(Zxz(a, b, c), Eigen::Vector3d(tx, ty, tz), RotationForm::kZxz, true);
  }
}

TEST(AffinePose, OutOfRangeGivesTheNeckerMirror) {
  // Opposite-sign tilts (no rotation has both ≥ 0), negative tilts, φ ∈ [π, 2π) in zxz: the
  // form's member of the mirror pair, which has the same shape vector.
  std::mt19937_64 rng(9);
  hecal::UniformRealDistribution tilt(-85.0, 85.0), spin(0.0, 360.0);
  for (int trial = 0; trial < 300; ++trial) {
    const double rz = spin(rng) * kRadiansPerDegree;
    const double ry = tilt(rng) * kRadiansPerDegree;
    const double rx = tilt(rng) * kRadiansPerDegree;
    const Eigen::Matrix3d R = RotationZyx(rx, ry, rz);
    if (!(R(2, 2) > 0.05)) continue;
    const Eigen::Vector3d T(10, -20, 300);
    ExpectRecovered(R, T, RotationForm::kZyx, false);
    ExpectRecovered(R, T, RotationForm::kZxz, false);
    const Eigen::Matrix3d got =
        PoseFromShape(ShapeFromPose(R, T, kCamera), kCamera, RotationForm::kZyx).rotation;
    EXPECT_TRUE((got - R).norm() < 1e-9 || (got - NeckerMirror(R)).norm() < 1e-9);
  }
  // The rule: Rx = −30°, Ry = 10° comes back as its mirror (30°, −10°).
  const ContourPose mirrored =
      PoseFromShape(ShapeFromPose(RotationZyx(-30 * kRadiansPerDegree, 10 * kRadiansPerDegree, 0.5),
                                  Eigen::Vector3d::Zero(), kCamera),
                    kCamera, RotationForm::kZyx);
  EXPECT_NEAR(mirrored.euler(2), 30 * kRadiansPerDegree, 1e-12);
  EXPECT_NEAR(mirrored.euler(1), -10 * kRadiansPerDegree, 1e-12);
  EXPECT_NEAR(mirrored.euler(0), 0.5, 1e-12);
}

TEST(AffinePose, GimbalLockOfZxzIsDeterministic) {
  // θ = 0 (λ1 = λ2): φ = 0 and ψ carries the in-plane rotation.
  const ContourPose pose =
      PoseFromShape(ShapeFromPose(RotationZyx(0, 0, 2.0), Eigen::Vector3d(5, 6, -100), kCamera),
                    kCamera, RotationForm::kZxz);
  EXPECT_EQ(pose.euler(0), 0.0);
  EXPECT_EQ(pose.euler(1), 0.0);
  EXPECT_NEAR(pose.euler(2), 2.0, 1e-14);
  // Identity affinity: the identity pose in both forms.
  for (RotationForm form : {RotationForm::kZyx, RotationForm::kZxz}) {
    const ContourPose identity = PoseFromShape(Vector6d::Zero(), kCamera, form);
    EXPECT_EQ(identity.rotation, Eigen::Matrix3d::Identity());
    EXPECT_EQ(identity.translation, Eigen::Vector3d::Zero());
    EXPECT_EQ(identity.euler, Eigen::Vector3d::Zero());
  }
}

TEST(AffinePose, SeedEquationsByHand) {
  // A pure approach Tz = −2500 doubles the image: M = 2 I, so λ1 = 4, Tz/Z0 = 1/2 − 1.
  Vector6d S;
  S << 120.0, -60.0, 1.0, 1.0, 0.0, 0.0;
  const ContourPose pose = PoseFromShape(S, kCamera, RotationForm::kZyx);
  EXPECT_NEAR(pose.translation.z(), -2500.0, 1e-9);
  EXPECT_NEAR(pose.translation.x(), 5000.0 * 120.0 / (6024.0 * 2.0), 1e-9);  // eq. 14
  EXPECT_NEAR(pose.translation.y(), 5000.0 * -60.0 / (6024.0 * 2.0), 1e-9);  // eq. 15
  // A tilt about x by θ: M = diag(1, cos θ), eq. 10 gives cos θ = sqrt(λ2/λ1).
  S << 0.0, 0.0, 0.0, std::cos(0.3) - 1.0, 0.0, 0.0;
  EXPECT_NEAR(PoseFromShape(S, kCamera, RotationForm::kZyx).euler(2), 0.3, 1e-14);
}

TEST(AffinePose, SingularAndReflectedAffinitiesAreRejected) {
  Vector6d edge_on;  // M = diag(1, 0): the plane seen edge-on, θ = 90°
  edge_on << 0, 0, 0, -1, 0, 0;
  Vector6d reflected;  // M = diag(1, −1)
  reflected << 0, 0, 0, -2, 0, 0;
  Vector6d nan = Vector6d::Zero();
  nan(4) = std::numeric_limits<double>::quiet_NaN();
  for (const Vector6d& S : {edge_on, reflected, nan}) {
    EXPECT_THROW(PoseFromShape(S, kCamera, RotationForm::kZyx), DegenerateError);
  }
  Eigen::Matrix3d edge;  // exactly 90° about x
  edge << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  EXPECT_THROW(ShapeFromPose(edge, Eigen::Vector3d::Zero(), kCamera), DegenerateError);
  EXPECT_THROW(ShapeFromPose(RotationZyx(0, 1.6, 0), Eigen::Vector3d::Zero(), kCamera),
               DegenerateError);
  EXPECT_THROW(ShapeFromPose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, -5000), kCamera),
               DegenerateError);
  EXPECT_THROW(ValidateContourCamera({0.0, 1.0}), InputError);
  EXPECT_THROW(ValidateContourCamera({1.0, -1.0}), InputError);
}

TEST(AffinePose, ParametersAndNames) {
  const ContourPose pose =
      CanonicalPose(RotationZyx(0.1, 0.2, 0.3), Eigen::Vector3d(1, 2, 3), RotationForm::kZyx);
  const Vector6d p = PoseParameters(pose);
  EXPECT_NEAR(p(3), 0.1, 1e-14);
  EXPECT_NEAR(p(4), 0.2, 1e-14);
  EXPECT_NEAR(p(5), 0.3, 1e-14);
  EXPECT_EQ(PoseParameterNames(RotationForm::kZyx)[3], "Rx");
  EXPECT_EQ(ParseRotationForm("zxz"), RotationForm::kZxz);
  EXPECT_FALSE(ParseRotationForm("xyz"));
}

TEST(AffinePose, OverflowingShapeVectorsAreRejectedNotNaN) {
  // det M = 1e320 overflows to inf: before the guard this returned a NaN pose.
  Vector6d S;
  S << 1e160, 0, 1e160, 1e160, 0, 0;
  EXPECT_THROW(PoseFromShape(S, kCamera, RotationForm::kZyx), DegenerateError);
  S << 0, 0, 1e155, 0, 0, 0;
  EXPECT_THROW(PoseFromShape(S, kCamera, RotationForm::kZxz), DegenerateError);
  // Large but representable: a finite pose.
  S << 1e3, 0, 1e3, 1e3, 0, 0;
  EXPECT_TRUE(PoseFromShape(S, kCamera, RotationForm::kZyx).translation.allFinite());
}

TEST(ContourCamera, IsValidNamesTheField) {
  const ContourCamera defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(
      testing::RefusesNaming(defaults, "ContourCamera.focal", [](auto& c) { c.focal = -1; }));
  EXPECT_TRUE(testing::RefusesNaming(defaults, "ContourCamera.z0", [](auto& c) { c.z0 = 0; }));
}

}  // namespace
}  // namespace hecal::contour
