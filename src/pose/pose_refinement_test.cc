// The reprojection refinement: convergence to the truth on noise-free data from poor starts, the
// predicted covariance against the empirical one over many noisy trials (given and estimated σ),
// the residuals it reports, and its refusals.
#include "hecal/pose/pose_refinement.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <random>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/geometry/se3.h"
#include "pose/pose_test_util.h"
#include "testing/options_validity.h"
#include "testing/pose_scenes.h"

namespace hecal::pose {
namespace {

using testing::PointShape;
using testing::RandomScene;

// The truth moved by a rotation of `angle` about a random axis and a translation of `offset`
// in a random direction (built with Eigen, not se3::Exp).
Pose Perturbed(std::mt19937_64& rng, const Pose& T, double angle, double offset) {
  const Eigen::Matrix3d dR =
      Eigen::AngleAxisd(angle, testing::RandomUnitVector(rng)).toRotationMatrix();
  return MakePose(T.linear() * dR, T.translation() + offset * testing::RandomUnitVector(rng));
}

TEST(PoseRefinement, ConvergesToTheTruthOnNoiseFreeDataFromPoorStarts) {
  std::mt19937_64 rng(1);
  for (PointShape shape : {PointShape::kVolume, PointShape::kPlane}) {
    for (int trial = 0; trial < 40; ++trial) {
      const testing::PointView scene = RandomScene(rng, 12, shape);
      // Up to 0.5 rad and 0.1 m off, but every point still in front of the camera.
      const Pose start = Perturbed(rng, scene.T_camera_target, 0.5 * (trial % 5 + 1) / 5.0, 0.1);
      const RefinementResult result =
          RefinePose(start, scene.object_points, scene.pixels, scene.camera);
      EXPECT_TRUE(result.converged);
      EXPECT_LT(RotationError(result.T_camera_target, scene.T_camera_target), 1e-9);
      EXPECT_LT((result.T_camera_target.translation() - scene.T_camera_target.translation()).norm(),
                1e-9);
      EXPECT_LT(result.rms_px, 1e-6);
    }
  }
}

TEST(PoseRefinement, ResidualsAreTheReprojectionErrorsAtTheResult) {
  std::mt19937_64 rng(2);
  const testing::PointView scene = RandomScene(rng, 20, PointShape::kVolume);
  const std::vector<Eigen::Vector2d> noisy = testing::AddPixelNoise(rng, scene.pixels, 0.7);
  const RefinementResult result =
      RefinePose(scene.T_camera_target, scene.object_points, noisy, scene.camera);
  ASSERT_EQ(result.residuals_px.size(), noisy.size());
  double sum = 0.0;
  for (std::size_t k = 0; k < noisy.size(); ++k) {
    const Eigen::Vector2d e =
        Project(scene.camera, result.T_camera_target * scene.object_points[k]) - noisy[k];
    EXPECT_LT((e - result.residuals_px[k]).norm(), 1e-12);
    sum += e.squaredNorm();
  }
  EXPECT_NEAR(result.rms_px, std::sqrt(sum / 20.0), 1e-12);
  EXPECT_NEAR(result.sigma_px, std::sqrt(sum / (40.0 - 6.0)), 1e-12);
  EXPECT_EQ(result.sigma_source, SigmaSource::kEstimated);
  // The ML estimate fits the noisy pixels better than the truth does.
  double truth_sum = 0.0;
  for (std::size_t k = 0; k < noisy.size(); ++k) {
    truth_sum += (scene.pixels[k] - noisy[k]).squaredNorm();
  }
  EXPECT_LT(sum, truth_sum);
}

// Monte Carlo: one scene, many noise draws. The error ε = Log(T̂⁻¹ T_true) (right perturbation at
// the estimate) should follow N(0, Σ̂). With σ given, ε ᵀ Σ̂⁻¹ ε is χ²(6): mean 6, variance 12,
// so over M = 400 trials its mean has standard deviation √(12/400) = 0.17; we allow ±0.7 (4 SD),
// which leaves room for the small bias of the first-order (linearised) covariance at 0.5 px. The
// empirical variance of each component, relative to the mean predicted one, has standard
// deviation √(2/400) = 0.07; we allow 0.75…1.3.
TEST(PoseRefinement, PredictedCovarianceMatchesTheEmpiricalOne) {
  constexpr int kTrials = 400;
  constexpr double kSigma = 0.5;
  for (PointShape shape : {PointShape::kVolume, PointShape::kPlane}) {
    std::mt19937_64 rng(shape == PointShape::kVolume ? 3 : 4);
    const testing::PointView scene = RandomScene(rng, 15, shape);
    RefinementOptions options;
    options.pixel_sigma = kSigma;
    double mahalanobis = 0.0;
    Matrix6d empirical = Matrix6d::Zero(), predicted = Matrix6d::Zero();
    for (int trial = 0; trial < kTrials; ++trial) {
      const RefinementResult result =
          RefinePose(scene.T_camera_target, scene.object_points,
                     testing::AddPixelNoise(rng, scene.pixels, kSigma), scene.camera, options);
      ASSERT_EQ(result.sigma_source, SigmaSource::kGiven);
      ASSERT_EQ(result.sigma_px, kSigma);
      const Vector6d e = se3::Log(result.T_camera_target.inverse() * scene.T_camera_target);
      mahalanobis += e.dot(result.covariance.inverse() * e);
      empirical += e * e.transpose();
      predicted += result.covariance;
    }
    mahalanobis /= kTrials;
    empirical /= kTrials;
    predicted /= kTrials;
    EXPECT_NEAR(mahalanobis, 6.0, 0.7) << "shape " << static_cast<int>(shape);
    for (int i = 0; i < 6; ++i) {
      const double ratio = empirical(i, i) / predicted(i, i);
      EXPECT_GT(ratio, 0.75) << "component " << i;
      EXPECT_LT(ratio, 1.3) << "component " << i;
    }
  }
}

// With σ estimated from the residuals, σ̂²/σ² ~ χ²(ν)/ν, ν = 2N − 6: unbiased, so its mean over
// M trials is 1 with standard deviation √(2/(νM)); and ε ᵀ Σ̂⁻¹ ε = 6 F(6, ν) has mean
// 6ν/(ν − 2). N = 30: ν = 54, mean 6.23, standard deviation of the mean over 400 trials 0.19;
// we allow ±0.8 (4 SD); σ̂² within 1 ± 0.04 (4 SD of 0.0096).
TEST(PoseRefinement, EstimatedSigmaIsUnbiasedAndScalesTheCovariance) {
  constexpr int kTrials = 400, kPoints = 30;
  constexpr double kSigma = 0.8;
  std::mt19937_64 rng(5);
  const testing::PointView scene = RandomScene(rng, kPoints, PointShape::kVolume);
  double mahalanobis = 0.0, variance_ratio = 0.0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const RefinementResult result =
        RefinePose(scene.T_camera_target, scene.object_points,
                   testing::AddPixelNoise(rng, scene.pixels, kSigma), scene.camera);
    ASSERT_EQ(result.sigma_source, SigmaSource::kEstimated);
    const Vector6d e = se3::Log(result.T_camera_target.inverse() * scene.T_camera_target);
    mahalanobis += e.dot(result.covariance.inverse() * e);
    variance_ratio += result.sigma_px * result.sigma_px / (kSigma * kSigma);
  }
  const double nu = 2.0 * kPoints - 6.0;
  EXPECT_NEAR(mahalanobis / kTrials, 6.0 * nu / (nu - 2.0), 0.8);
  EXPECT_NEAR(variance_ratio / kTrials, 1.0, 0.04);
}

TEST(PoseRefinement, RefusesAStartWithPointsBehindTheCamera) {
  std::mt19937_64 rng(6);
  const testing::PointView scene = RandomScene(rng, 10, PointShape::kVolume);
  const Pose behind = MakePose(scene.T_camera_target.linear(),
                               scene.T_camera_target.translation() - Eigen::Vector3d(0, 0, 2));
  EXPECT_THROW(RefinePose(behind, scene.object_points, scene.pixels, scene.camera),
               DegenerateError);
}

TEST(PoseRefinement, RefusesPointsOnALine) {
  const CameraModel camera = CameraModel::Pinhole(1000.0);
  const Pose T = MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, 1.0));
  std::vector<Eigen::Vector3d> line;
  std::vector<Eigen::Vector2d> pixels;
  for (int k = 0; k < 8; ++k) {
    line.emplace_back(0.02 * k, 0.01 * k, 0.03 * k);
    pixels.push_back(Project(camera, T * line.back()));
  }
  EXPECT_THROW(RefinePose(T, line, pixels, camera), DegenerateError);
}

TEST(PoseRefinement, SigmaNeedsRedundancyUnlessGiven) {
  std::mt19937_64 rng(7);
  const testing::PointView scene = RandomScene(rng, 3, PointShape::kVolume);
  EXPECT_THROW(RefinePose(scene.T_camera_target, scene.object_points, scene.pixels, scene.camera),
               DegenerateError);
  RefinementOptions options;
  options.pixel_sigma = 1.0;
  const RefinementResult result =
      RefinePose(scene.T_camera_target, scene.object_points, scene.pixels, scene.camera, options);
  EXPECT_EQ(result.sigma_source, SigmaSource::kGiven);
  EXPECT_GT(result.covariance.determinant(), 0.0);
}

TEST(PoseRefinement, RejectsInvalidOptions) {
  std::mt19937_64 rng(8);
  const testing::PointView scene = RandomScene(rng, 10, PointShape::kVolume);
  RefinementOptions options;
  std::string why;
  EXPECT_TRUE(options.IsValid(&why));
  options.pixel_sigma = -1.0;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_THROW(
      RefinePose(scene.T_camera_target, scene.object_points, scene.pixels, scene.camera, options),
      InputError);
  options.pixel_sigma.reset();
  options.max_iterations = 0;
  EXPECT_FALSE(options.IsValid(&why));
}

TEST(RefinementOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const RefinementOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "RefinementOptions.max_iterations",
                            [](auto& o) { o.max_iterations = 0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "RefinementOptions.relative_cost_tolerance",
                            [](auto& o) { o.relative_cost_tolerance = -1.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "RefinementOptions.pixel_sigma",
                            [](auto& o) { o.pixel_sigma = std::nan(""); }));
}

}  // namespace
}  // namespace hecal::pose
