// UT vs Monte Carlo on the contour pose (docs/contour.md#uncertainty-of-the-motion), and the bias
// flag near zero tilt.
#include "hecal/contour/pose_uncertainty.h"

#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "contour/contour_test_util.h"
#include "hecal/contour/contour_study.h"
#include "hecal/contour/perspective_view.h"
#include "hecal/contour/shape_space.h"
#include "hecal/core/error.h"
#include "hecal/geometry/angle_units.h"
#include "testing/options_validity.h"

namespace hecal::contour {
namespace {

struct Input {
  Vector6d shape;
  Matrix6d covariance;
};

Input WeakPerspectiveInput(const Eigen::Matrix3d& R, const Eigen::Vector3d& T) {
  const ShapeSpace space(TemplateImage(DefaultTarget(), kCamera));
  return {ShapeFromPose(R, T, kCamera), space.FitCovariance(0.5)};
}

TEST(PoseUncertainty, ThirteenSigmaPointsAndMonteCarloAgreeAwayFromZeroTilt) {
  const Eigen::Matrix3d R = RotationZyx(25 * kRadiansPerDegree, 0.0, 40 * kRadiansPerDegree);
  const Input in = WeakPerspectiveInput(R, Eigen::Vector3d(80, -40, -1000));
  const ContourPoseUncertainty ut =
      UnscentedPose(in.shape, in.covariance, kCamera, RotationForm::kZyx);
  EXPECT_EQ(ut.sigma_shapes.size(), 13u);  // the centre first, then ±c S_i
  EXPECT_EQ(ut.sigma_poses.size(), 13u);
  EXPECT_FALSE(ut.any_biased);
  uncertainty::MonteCarloOptions mc;
  mc.samples = 5000;
  const auto moments = MonteCarloPose(in.shape, in.covariance, kCamera, RotationForm::kZyx, mc);
  EXPECT_EQ(moments.failures, 0);
  for (int j = 0; j < 6; ++j) {
    const double ratio = std::sqrt(ut.covariance(j, j) / moments.covariance(j, j));
    EXPECT_NEAR(ratio, 1.0, 0.10) << j;
    EXPECT_NEAR(ut.mean(j), moments.mean(j), 3 * moments.mean_std_error(j) + 1e-9) << j;
  }
}

TEST(PoseUncertainty, BiasFlagNearZeroTiltOnly) {
  // No tilt: the mirrored sigma points of Rx/Ry fold onto one sign
  // (docs/contour.md#the-bias-check).
  const Input zero = WeakPerspectiveInput(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
  const ContourPoseUncertainty folded =
      UnscentedPose(zero.shape, zero.covariance, kCamera, RotationForm::kZyx);
  EXPECT_TRUE(folded.any_biased);
  EXPECT_TRUE(folded.biased[3] || folded.biased[4]);
  EXPECT_GT(folded.mean(3) + folded.mean(4), folded.parameters(3) + folded.parameters(4));
  // 30° about x: far from the fold, no flag.
  const Input tilted =
      WeakPerspectiveInput(RotationZyx(30 * kRadiansPerDegree, 0, 0), Eigen::Vector3d::Zero());
  EXPECT_FALSE(
      UnscentedPose(tilted.shape, tilted.covariance, kCamera, RotationForm::kZyx).any_biased);
}

TEST(PoseUncertainty, InPlaneAngleIsUnwrappedAcrossZero) {
  // Rz = 0 with noise: samples on both sides of 0 / 2π must average near 0, not π.
  const Input in =
      WeakPerspectiveInput(RotationZyx(20 * kRadiansPerDegree, 0, 0), Eigen::Vector3d::Zero());
  const ContourPoseUncertainty ut =
      UnscentedPose(in.shape, in.covariance, kCamera, RotationForm::kZyx);
  EXPECT_LT(std::abs(PoseDifference(ut.mean, ut.parameters, RotationForm::kZyx)(5)), 1e-3);
  EXPECT_LT(std::sqrt(ut.covariance(5, 5)), 0.01);
  uncertainty::MonteCarloOptions mc;
  mc.samples = 2000;
  const auto moments = MonteCarloPose(in.shape, in.covariance, kCamera, RotationForm::kZyx, mc);
  EXPECT_LT(std::sqrt(moments.covariance(5, 5)), 0.01);
  Vector6d a = Vector6d::Zero(), b = Vector6d::Zero();
  a(5) = 0.01;
  b(5) = 2 * std::numbers::pi - 0.01;
  a(3) = 0.01;  // Rx is not circular: no wrap
  b(3) = 2 * std::numbers::pi - 0.01;
  const Vector6d d = PoseDifference(a, b, RotationForm::kZyx);
  EXPECT_NEAR(d(5), 0.02, 1e-12);
  EXPECT_NEAR(d(3), 0.02 - 2 * std::numbers::pi, 1e-12);
}

TEST(PoseUncertainty, LinearInTranslationForPureLateralMotion) {
  // tx, ty enter Tx, Ty linearly for a fixed scale: with noise only on tx the UT is exact.
  const Input in = WeakPerspectiveInput(Eigen::Matrix3d::Identity(), Eigen::Vector3d(100, 0, 0));
  Matrix6d only_tx = Matrix6d::Zero();
  only_tx(0, 0) = 0.04;
  const ContourPoseUncertainty ut = UnscentedPose(in.shape, only_tx, kCamera, RotationForm::kZyx);
  const double sd = std::sqrt(ut.covariance(0, 0));
  EXPECT_NEAR(sd, 0.2 * kCamera.z0 / kCamera.focal, 1e-9);
  EXPECT_NEAR(ut.mean(0), 100.0, 1e-9);
}

// A covariance whose sigma points leave the region where the shape has a pose (det M ≤ 0) is
// named as too wide for the shape — the shape itself has a pose.
TEST(PoseUncertainty, ACovarianceTooWideForTheShapeIsNamed) {
  Vector6d shape;
  shape << 0, 0, 0.1, 0.1, 0, 0;
  EXPECT_NO_THROW(PoseFromShape(shape, kCamera, RotationForm::kZyx));
  try {
    UnscentedPose(shape, Matrix6d::Identity() * 1e6, kCamera, RotationForm::kZyx);
    FAIL() << "expected DegenerateError";
  } catch (const DegenerateError& error) {
    EXPECT_NE(std::string(error.what()).find("Σ_S is too large for the shape vector"),
              std::string::npos)
        << error.what();
  }
}

TEST(UnscentedPoseOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const UnscentedPoseOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "UnscentedPoseOptions.unscented", [](auto& o) {
    o.unscented = uncertainty::UnscentedParameters::Symmetric(1.5);
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "UnscentedPoseOptions.bias_threshold",
                            [](auto& o) { o.bias_threshold = 0.0; }));
}

}  // namespace
}  // namespace hecal::contour
