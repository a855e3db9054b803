#include "hecal/estimation/reprojection_refinement.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "testing/image_scene.h"
#include "testing/options_validity.h"

namespace hecal::estimation {
namespace {
const testing::PoseNoise kNoNoise{0.0, 0.0};

ReprojectionOptions Options(handeye::Setup setup, PoseSigma robot) {
  ReprojectionOptions options;
  options.setup = setup;
  options.camera = testing::DefaultCamera();
  options.robot_sigma = robot;
  return options;
}

// Noise-free images: the refinement recovers X and Z to 1e-9 from a start 1° / 5 mm off, with the
// robot poses free (σ > 0) and fixed (σ = 0).
TEST(ReprojectionRefinement, NoiseFreeDataConvergeToTheTruth) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::ImageScene s =
        testing::MakeImageScene(testing::ImageSceneOptions::For(setup, 8, 21, kNoNoise, 0.0));
    const Vector6d kick = (Vector6d() << 0.01, -0.012, 0.008, 0.005, -0.004, 0.003).finished();
    for (PoseSigma robot : {PoseSigma{0.05 * kRadiansPerDegree, 1e-4}, PoseSigma{0.0, 0.0}}) {
      ReprojectionOptions options = Options(setup, robot);
      options.pixel_sigma = 0.5;
      const ReprojectionResult result =
          RefineReprojection(s.poses.T_base_gripper, s.ImagesAs<ImagePoints>(),
                             s.poses.X * se3::Exp(kick), s.poses.Z * se3::Exp(-kick), options);
      EXPECT_LT(se3::Log(s.poses.X.inverse() * result.X).norm(), 1e-9);
      EXPECT_LT(se3::Log(s.poses.Z.inverse() * result.Z).norm(), 1e-9);
      EXPECT_LT(result.rms_px, 1e-6);
      ASSERT_EQ(result.image_rms_px.size(), 8u);
    }
  }
}

// Noise-free images, the intrinsics refined from a start 2% / 3 px / 20% off: X, Z and the
// intrinsics converge to the truth.
TEST(ReprojectionRefinement, RefinesTheIntrinsicsToTheTruth) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::ImageScene s =
        testing::MakeImageScene(testing::ImageSceneOptions::For(setup, 10, 41, kNoNoise, 0.0));
    ReprojectionOptions options = Options(setup, PoseSigma{0.05 * kRadiansPerDegree, 1e-4});
    options.pixel_sigma = 0.5;
    options.refine_intrinsics = true;
    const pose::CameraModel truth = testing::DefaultCamera();
    options.camera.fx *= 1.02;
    options.camera.fy *= 0.98;
    options.camera.cx += 3.0;
    options.camera.cy -= 3.0;
    options.camera.distortion[0] *= 0.8;
    options.camera.distortion[1] *= 1.2;
    const ReprojectionResult result = RefineReprojection(
        s.poses.T_base_gripper, s.ImagesAs<ImagePoints>(), s.poses.X, s.poses.Z, options);
    EXPECT_LT(se3::Log(s.poses.X.inverse() * result.X).norm(), 1e-8) << handeye::SetupName(setup);
    EXPECT_LT(se3::Log(s.poses.Z.inverse() * result.Z).norm(), 1e-8);
    EXPECT_LT((pose::IntrinsicsOf(result.camera) - pose::IntrinsicsOf(truth)).norm(), 1e-6);
    ASSERT_TRUE(result.intrinsics_covariance.has_value());
    EXPECT_GT((*result.intrinsics_covariance)(0, 0), 0.0);
  }
}

// With pixel and robot noise, the predicted covariance of X is honest: over 100 trials the mean
// squared Mahalanobis distance of the X error (6 dof) is 6 within sampling error (±1.0 is about
// 3 standard errors of the mean of 100 χ²₆ draws, sd √12/√100 ≈ 0.35), and the estimated pixel
// sigma is the true one within 5%.
TEST(ReprojectionRefinement, CovarianceMatchesTheErrors) {
  const double pixel_sigma = 0.4;
  const PoseSigma robot{0.03 * kRadiansPerDegree, 0.2e-3};
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    double mahalanobis = 0.0, sigma_ratio = 0.0;
    constexpr int kTrials = 100;
    for (int trial = 0; trial < kTrials; ++trial) {
      const testing::PoseNoise noise{robot.rotation, robot.translation};
      const testing::ImageScene s = testing::MakeImageScene(
          testing::ImageSceneOptions::For(setup, 10, 1000 + trial, noise, pixel_sigma));
      const ReprojectionResult result =
          RefineReprojection(s.poses.T_base_gripper, s.ImagesAs<ImagePoints>(), s.poses.X,
                             s.poses.Z, Options(setup, robot));
      const Vector6d e = se3::Log(s.poses.X.inverse() * result.X);
      mahalanobis += e.dot(result.covariance.topLeftCorner<6, 6>().ldlt().solve(e));
      sigma_ratio += result.pixel_sigma / pixel_sigma;
      EXPECT_TRUE(result.pixel_sigma_estimated);
    }
    EXPECT_NEAR(mahalanobis / kTrials, 6.0, 1.0) << handeye::SetupName(setup);
    EXPECT_NEAR(sigma_ratio / kTrials, 1.0, 0.05) << handeye::SetupName(setup);
  }
}

// A station whose pixels are shifted by 5 px is flagged; the others are not.
TEST(ReprojectionRefinement, FlagsAnImageThatDoesNotFit) {
  testing::ImageScene s = testing::MakeImageScene(
      testing::ImageSceneOptions::For(handeye::Setup::kEyeInHand, 8, 31, kNoNoise, 0.3));
  for (Eigen::Vector2d& u : s.images[5].pixels) u += Eigen::Vector2d(5.0, -3.0);
  const ReprojectionResult result =
      RefineReprojection(s.poses.T_base_gripper, s.ImagesAs<ImagePoints>(), s.poses.X, s.poses.Z,
                         Options(handeye::Setup::kEyeInHand, {0.0, 0.0}));
  for (size_t i = 0; i < result.image_outlier.size(); ++i)
    EXPECT_EQ(result.image_outlier[i], i == 5) << i << " " << result.image_rms_px[i];
}

TEST(ReprojectionRefinement, RefusesTooFewImagesAndBadSigmas) {
  const testing::ImageScene s = testing::MakeImageScene(
      testing::ImageSceneOptions::For(handeye::Setup::kEyeInHand, 2, 41, kNoNoise, 0.0));
  EXPECT_THROW(RefineReprojection(s.poses.T_base_gripper, s.ImagesAs<ImagePoints>(), s.poses.X,
                                  s.poses.Z, Options(handeye::Setup::kEyeInHand, {0.0, 0.0})),
               DegenerateError);
  ReprojectionOptions bad = Options(handeye::Setup::kEyeInHand, {-1.0, 0.0});
  EXPECT_THROW(RefineReprojection(s.poses.T_base_gripper, s.ImagesAs<ImagePoints>(), s.poses.X,
                                  s.poses.Z, bad),
               InputError);
}

// A start the solver cannot use is refused with its reason before Ceres runs: robot lengths in
// millimetres read as metres (the translations × 1000), a start that puts the target behind the
// camera (X turned half a turn), a non-finite start or robot pose.
TEST(ReprojectionRefinement, RefusesAStartItCannotUse) {
  const testing::ImageScene s = testing::MakeImageScene(
      testing::ImageSceneOptions::For(handeye::Setup::kEyeInHand, 6, 43, kNoNoise, 0.0));
  const ReprojectionOptions options =
      Options(handeye::Setup::kEyeInHand, {0.05 * kRadiansPerDegree, 1e-4});
  const auto message = [&](const std::vector<Pose>& robot, const Pose& X, const Pose& Z) {
    try {
      RefineReprojection(robot, s.ImagesAs<ImagePoints>(), X, Z, options);
    } catch (const DegenerateError& error) {
      return std::string(error.what());
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  std::vector<Pose> millimetres = s.poses.T_base_gripper;
  for (Pose& G : millimetres) G.translation() *= 1000.0;
  EXPECT_NE(message(millimetres, s.poses.X, s.poses.Z).find("beyond any robot's reach"),
            std::string::npos);
  const Pose turned =
      s.poses.X * Pose(Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()));
  EXPECT_NE(message(s.poses.T_base_gripper, turned, s.poses.Z).find("behind the camera of image 1"),
            std::string::npos);
  Pose nan = s.poses.X;
  nan.translation().x() = std::nan("");
  EXPECT_NE(message(s.poses.T_base_gripper, nan, s.poses.Z).find("start X, Z is not finite"),
            std::string::npos);
  std::vector<Pose> robot_nan = s.poses.T_base_gripper;
  robot_nan[2].translation().y() = std::numeric_limits<double>::infinity();
  EXPECT_NE(message(robot_nan, s.poses.X, s.poses.Z).find("the robot pose is not finite"),
            std::string::npos);
  // The truth itself is accepted.
  EXPECT_EQ(message(s.poses.T_base_gripper, s.poses.X, s.poses.Z), "no error");
}

TEST(ReprojectionOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const ReprojectionOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  ReprojectionOptions edge;
  edge.pixel_sigma = kMaxPixelSigma;
  EXPECT_TRUE(testing::IsValidOptions(edge));
  EXPECT_TRUE(RefusesNaming(defaults, "ReprojectionOptions.robot_sigma", [](auto& o) {
    o.robot_sigma = PoseSigma{-0.1, 0.0};
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "ReprojectionOptions.pixel_sigma",
                            [](auto& o) { o.pixel_sigma = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ReprojectionOptions.pixel_sigma",
                            [](auto& o) { o.pixel_sigma = 100.5; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ReprojectionOptions.max_sigma_iterations",
                            [](auto& o) { o.max_sigma_iterations = 0; }));
}

}  // namespace
}  // namespace hecal::estimation
