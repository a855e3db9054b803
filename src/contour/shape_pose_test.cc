#include "hecal/contour/shape_pose.h"

#include <gtest/gtest.h>

#include <limits>

#include "hecal/core/error.h"
#include "testing/options_validity.h"

namespace hecal::contour {
namespace {

ShapePoseOptions Options() {
  ShapePoseOptions options;
  options.camera.focal = 1000.0;
  options.camera.z0 = 2000.0;
  return options;
}

// A pure image translation with M = I: Tx = Z0 tx / f, Ty = Z0 ty / f (affine_pose.h, eqs. 14–15),
// no rotation, no depth change.
TEST(ShapePose, TranslationOnlyShapeGivesTheLateralMotion) {
  const ShapePose result =
      EstimateShapePose((Vector6d() << 10.0, -5.0, 0, 0, 0, 0).finished(), Options());
  EXPECT_NEAR(result.pose.translation.x(), 20.0, 1e-9);
  EXPECT_NEAR(result.pose.translation.y(), -10.0, 1e-9);
  EXPECT_NEAR(result.pose.translation.z(), 0.0, 1e-9);
  EXPECT_TRUE(result.pose.rotation.isIdentity(1e-12));
  EXPECT_FALSE(result.uncertainty);
}

// M = 0.8 I: the target shrinks, 1 + Tz/Z0 = 1/0.8, so Tz = 500.
TEST(ShapePose, UniformScaleGivesTheDepthChange) {
  const ShapePose result =
      EstimateShapePose((Vector6d() << 0, 0, -0.2, -0.2, 0, 0).finished(), Options());
  EXPECT_NEAR(result.pose.translation.z(), 500.0, 1e-9);
}

// Tx is linear in tx at M = I, so the UT is exact: var(Tx) = (Z0/f)² var(tx).
TEST(ShapePose, CovarianceOfTxPropagatesExactlyThroughTheLinearPart) {
  ShapePoseOptions options = Options();
  Matrix6d covariance = Matrix6d::Zero();
  covariance(0, 0) = 0.01;
  options.shape_covariance = covariance;
  const ShapePose result =
      EstimateShapePose((Vector6d() << 10.0, 0, 0.1, 0.1, 0, 0).finished(), options);
  ASSERT_TRUE(result.uncertainty);
  const double scale = options.camera.z0 / (options.camera.focal * 1.1);  // √λ1 = 1.1
  EXPECT_NEAR(result.uncertainty->covariance(0, 0), scale * scale * 0.01, 1e-12);
  EXPECT_NEAR(result.uncertainty->covariance(1, 1), 0.0, 1e-12);
}

TEST(ShapePose, InvalidCentreWeightIsAnInputError) {
  ShapePoseOptions options = Options();
  options.shape_covariance = Matrix6d::Identity() * 1e-6;
  options.unscented.unscented = uncertainty::UnscentedParameters::Symmetric(1.0);
  EXPECT_THROW(EstimateShapePose(Vector6d::Zero(), options), InputError);
}

TEST(ShapePose, SingularShapeIsDegenerate) {
  EXPECT_THROW(EstimateShapePose((Vector6d() << 0, 0, -1.0, 0, 0, 0).finished(), Options()),
               DegenerateError);
}

TEST(ShapePoseOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const ShapePoseOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "ContourCamera.focal", [](auto& o) { o.camera.focal = 0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapePoseOptions.form",
                            [](auto& o) { o.form = static_cast<RotationForm>(5); }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapePoseOptions.shape_covariance", [](auto& o) {
    o.shape_covariance = Matrix6d::Identity();
    (*o.shape_covariance)(0, 1) = 0.5;  // not symmetric
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapePoseOptions.shape_covariance", [](auto& o) {
    o.shape_covariance = Matrix6d::Identity();
    (*o.shape_covariance)(2, 2) = -1.0;  // a negative variance
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapePoseOptions.shape_covariance", [](auto& o) {
    o.shape_covariance = Matrix6d::Identity() * std::numeric_limits<double>::quiet_NaN();
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "UnscentedPoseOptions.unscented", [](auto& o) {
    o.shape_covariance = Matrix6d::Identity();
    o.unscented.unscented = uncertainty::UnscentedParameters::Symmetric(1.0);
  }));
}

}  // namespace
}  // namespace hecal::contour
