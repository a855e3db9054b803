// Pose methods by name: the names, what each method returns (linear-raw = the linear pose paper
// alone, no covariance; linear and dlt = refined, with covariance), agreement of the refined
// methods at the same maximum-likelihood pose, and the advice when a method refuses the data.
#include "hecal/pose/pose_method.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "hecal/core/error.h"
#include "pose/pose_test_util.h"
#include "testing/options_validity.h"
#include "testing/pose_scenes.h"

namespace hecal::pose {
namespace {

using testing::PointShape;
using testing::RandomScene;

TEST(PoseMethod, NamesRoundTrip) {
  ASSERT_EQ(PoseMethods().size(), 3u);
  for (const PoseMethodInfo& info : PoseMethods()) {
    ASSERT_TRUE(ParsePoseMethod(info.name).has_value());
    EXPECT_EQ(*ParsePoseMethod(info.name), info.method);
    EXPECT_EQ(Info(info.method).name, info.name);
  }
  EXPECT_EQ(*ParsePoseMethod("linear-raw"), PoseMethod::kLinearRaw);
  EXPECT_FALSE(ParsePoseMethod("ippe").has_value());
  EXPECT_FALSE(ParsePoseMethod("Linear").has_value());
}

TEST(PoseMethod, LinearRawIsTheSeedMethodAlone) {
  std::mt19937_64 rng(1);
  const testing::PointView scene = RandomScene(rng, 10, PointShape::kVolume);
  const std::vector<Eigen::Vector2d> noisy = testing::AddPixelNoise(rng, scene.pixels, 1.0);
  const PoseEstimate raw =
      EstimatePose(PoseMethod::kLinearRaw, scene.object_points, noisy, scene.camera);
  const Pose seed = LinearPose(scene.object_points, noisy, scene.camera).T_camera_target;
  EXPECT_EQ(raw.method, "linear-raw");
  EXPECT_TRUE(raw.T_camera_target.isApprox(seed, 0.0));
  EXPECT_FALSE(raw.covariance.has_value());
  EXPECT_NEAR(raw.rms_px,
              RmsPx(ReprojectionResiduals(seed, scene.object_points, noisy, scene.camera)), 0.0);
}

TEST(PoseMethod, RefinedMethodsReachTheSameMaximumLikelihoodPose) {
  std::mt19937_64 rng(2);
  for (int trial = 0; trial < 30; ++trial) {
    const testing::PointView scene = RandomScene(rng, 12, PointShape::kVolume);
    const std::vector<Eigen::Vector2d> noisy = testing::AddPixelNoise(rng, scene.pixels, 1.0);
    PoseOptions options;
    options.refinement.pixel_sigma = 1.0;
    const PoseEstimate linear =
        EstimatePose(PoseMethod::kLinear, scene.object_points, noisy, scene.camera, options);
    const PoseEstimate dlt =
        EstimatePose(PoseMethod::kDlt, scene.object_points, noisy, scene.camera, options);
    const PoseEstimate raw =
        EstimatePose(PoseMethod::kLinearRaw, scene.object_points, noisy, scene.camera, options);
    EXPECT_EQ(linear.method, "linear");
    EXPECT_EQ(dlt.method, "dlt");
    ASSERT_TRUE(linear.covariance.has_value());
    ASSERT_TRUE(dlt.covariance.has_value());
    EXPECT_EQ(linear.sigma_source, SigmaSource::kGiven);
    // The same minimum from two starts, to the precision a stop on the cost allows: √ε of the
    // pose's uncertainty (≈ 1e-3 rad here), 1e-11 typically, 1e-9 along a weak direction.
    EXPECT_LT(RotationError(linear.T_camera_target, dlt.T_camera_target), 1e-8);
    EXPECT_LT((linear.T_camera_target.translation() - dlt.T_camera_target.translation()).norm(),
              1e-8);
    // Refinement only lowers the reprojection error of the paper's estimate.
    EXPECT_LE(linear.rms_px, raw.rms_px + 1e-12);
  }
}

TEST(PoseMethod, DltHandlesPlanarTargetsThatLinearRefuses) {
  std::mt19937_64 rng(3);
  const testing::PointView scene = RandomScene(rng, 20, PointShape::kPlane);
  const std::vector<Eigen::Vector2d> noisy = testing::AddPixelNoise(rng, scene.pixels, 0.3);
  const PoseEstimate dlt = EstimatePose(PoseMethod::kDlt, scene.object_points, noisy, scene.camera);
  EXPECT_LT(RotationError(dlt.T_camera_target, scene.T_camera_target), 5e-3);
  EXPECT_TRUE(dlt.covariance.has_value());
  for (PoseMethod method : {PoseMethod::kLinear, PoseMethod::kLinearRaw}) {
    try {
      EstimatePose(method, scene.object_points, noisy, scene.camera);
      ADD_FAILURE() << "expected DegenerateError";
    } catch (const DegenerateError& e) {
      EXPECT_NE(std::string(e.what()).find("--method ippe or dlt"), std::string::npos) << e.what();
    }
  }
}

TEST(PoseMethod, WarnsWhenTheSeedEstimateIsUnreliable) {
  std::mt19937_64 rng(5);
  const testing::PointView scene = RandomScene(rng, 8, PointShape::kVolume);
  for (PoseMethod method : {PoseMethod::kLinear, PoseMethod::kLinearRaw, PoseMethod::kDlt}) {
    EXPECT_TRUE(
        EstimatePose(method, scene.object_points, scene.pixels, scene.camera).warnings.empty());
  }
  // Two image points swapped: the linear pose paper's step 3 is far from a rotation (residual ≈
  // 0.8).
  std::vector<Eigen::Vector2d> swapped = scene.pixels;
  std::swap(swapped[0], swapped[5]);
  EXPECT_GT(LinearPose(scene.object_points, swapped, scene.camera).rotation_residual,
            kUnreliableRotationResidual);
  for (PoseMethod method : {PoseMethod::kLinear, PoseMethod::kLinearRaw}) {
    const PoseEstimate estimate = EstimatePose(method, scene.object_points, swapped, scene.camera);
    ASSERT_EQ(estimate.warnings.size(), 1u) << Info(method).name;
    EXPECT_NE(estimate.warnings[0].find("compare with --method dlt"), std::string::npos)
        << estimate.warnings[0];
  }
}

TEST(PoseMethod, FinishPoseWithoutRefinementKeepsTheStart) {
  std::mt19937_64 rng(4);
  const testing::PointView scene = RandomScene(rng, 8, PointShape::kVolume);
  const PoseEstimate kept = FinishPose("ippe", scene.T_camera_target, false, scene.object_points,
                                       scene.pixels, scene.camera);
  EXPECT_EQ(kept.method, "ippe");
  EXPECT_TRUE(kept.T_camera_target.isApprox(scene.T_camera_target, 0.0));
  EXPECT_FALSE(kept.covariance.has_value());
  EXPECT_LT(kept.rms_px, 1e-9);
}

TEST(PoseOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const PoseOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "LinearPoseOptions.planarity_tolerance",
                            [](auto& o) { o.linear.planarity_tolerance = 2.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "DltPoseOptions.planarity_tolerance",
                            [](auto& o) { o.dlt.planarity_tolerance = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "RefinementOptions.pixel_sigma",
                            [](auto& o) { o.refinement.pixel_sigma = 0.0; }));
}

}  // namespace
}  // namespace hecal::pose
