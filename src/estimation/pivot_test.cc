#include "hecal/estimation/pivot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "hecal/sim/pivot_simulation.h"
#include "hecal/uncertainty/consistency.h"

namespace hecal::estimation {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Vector6d Stacked(const Eigen::Vector3d& tip, const Eigen::Vector3d& pivot) {
  Vector6d x;
  x << tip, pivot;
  return x;
}

// Poses holding `tip` at `pivot` while the flange turns about `axis` (flange frame) only.
std::vector<Pose> OneAxisPoses(const Eigen::Vector3d& axis, double max_angle,
                               const Eigen::Vector3d& tip, const Eigen::Vector3d& pivot) {
  std::vector<Pose> poses;
  const Eigen::Matrix3d start = so3::Exp(Eigen::Vector3d(0.3, -0.2, 0.1));
  for (int i = 0; i < 12; ++i) {
    const double angle = max_angle * (-1.0 + 2.0 * i / 11.0);
    const Eigen::Matrix3d R = start * so3::Exp(angle * axis.normalized());
    poses.push_back(MakePose(R, pivot - R * tip));
  }
  return poses;
}

TEST(PivotTest, RecoversTheTruthExactlyWithoutNoise) {
  std::mt19937_64 rng(3);
  const sim::PivotScene scene = SimulatePivot(sim::PivotSceneOptions{}, rng);
  for (const std::optional<PoseSigma>& sigma :
       {std::optional<PoseSigma>(), std::optional<PoseSigma>(PoseSigma{1e-3, 1e-4})}) {
    PivotOptions options;
    options.sigma = sigma;
    const PivotResult result = CalibratePivot(scene.T_base_flange, options);
    EXPECT_LT((result.tip - scene.tip).norm(), 1e-9);
    EXPECT_LT((result.pivot - scene.pivot).norm(), 1e-9);
    EXPECT_LT((result.algebraic_tip - scene.tip).norm(), 1e-9);
    EXPECT_LT(result.rms, 1e-9);
    EXPECT_EQ(result.sigma_estimated, !sigma.has_value());
    for (const PivotStation& station : result.stations) {
      EXPECT_TRUE(station.used);
      EXPECT_FALSE(station.outlier);
    }
  }
}

// 0.1 mm / 0.1 deg, told to the estimator: the mean NEES of (t_tip, p) over 200 trials lies in
// the χ²(1200)/200 band, and the 2σ ellipsoid covers about 95%.
TEST(PivotTest, CovarianceIsConsistentOver200Trials) {
  const PoseSigma sigma{0.1 * kDegree, 0.1e-3};
  sim::PivotSceneOptions scene_options;
  scene_options.rotation_sigma = sigma.rotation;
  scene_options.translation_sigma = sigma.translation;
  PivotOptions options;
  options.sigma = sigma;
  constexpr int kTrials = 200;
  double sum = 0.0;
  int covered = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    std::mt19937_64 rng(1000 + trial);
    const sim::PivotScene scene = SimulatePivot(scene_options, rng);
    const PivotResult result = CalibratePivot(scene.T_base_flange, options);
    const double nees = uncertainty::Nees(
        Stacked(result.tip, result.pivot) - Stacked(scene.tip, scene.pivot), result.covariance);
    sum += nees;
    if (nees <= uncertainty::ChiSquareQuantile(uncertainty::SigmaProbability(2.0), 6)) ++covered;
  }
  const double mean = sum / kTrials;
  EXPECT_GT(mean, uncertainty::ChiSquareQuantile(0.025, 6 * kTrials) / kTrials);
  EXPECT_LT(mean, uncertainty::ChiSquareQuantile(0.975, 6 * kTrials) / kTrials);
  EXPECT_NEAR(covered / static_cast<double>(kTrials), 0.9545, 0.04);
}

TEST(PivotTest, RotationAboutOneAxisNamesTheUnobservableComponent) {
  const Eigen::Vector3d tip(0.01, -0.02, 0.15), pivot(0.6, 0.1, 0.2);
  for (const Eigen::Vector3d& axis : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 1, 0)}) {
    const std::vector<Pose> poses = OneAxisPoses(axis, 40 * kDegree, tip, pivot);
    try {
      CalibratePivot(poses, PivotOptions{});
      ADD_FAILURE() << "no DegenerateError";
    } catch (const DegenerateError& e) {
      const std::string text = e.unobservable();
      EXPECT_NE(text.find("the tip offset along the flange axis"), std::string::npos) << text;
      EXPECT_NE(text.find("the pivot point along the base axis"), std::string::npos) << text;
      EXPECT_NE(std::string(e.what()).find("tilt the tool about a second axis"), std::string::npos);
      // The named flange axis is the rotation axis (either sign, printed to 3 decimals).
      const Eigen::Vector3d n = axis.normalized();
      char x[16];
      std::snprintf(x, sizeof x, "%.3f", std::abs(n.x()));
      EXPECT_NE(text.find(x), std::string::npos) << text;
    }
  }
}

TEST(PivotTest, TinyRotationObservesNothing) {
  sim::PivotSceneOptions scene_options;
  scene_options.max_tilt = 1.0 * kDegree;
  std::mt19937_64 rng(5);
  const sim::PivotScene scene = SimulatePivot(scene_options, rng);
  try {
    CalibratePivot(scene.T_base_flange, PivotOptions{});
    ADD_FAILURE() << "no DegenerateError";
  } catch (const DegenerateError& e) {
    EXPECT_NE(e.unobservable().find("the tip offset or the pivot point"), std::string::npos)
        << e.what();
    EXPECT_NE(e.unobservable().find("barely rotated"), std::string::npos) << e.what();
  }
}

TEST(PivotTest, TooFewStationsAreRefused) {
  std::mt19937_64 rng(6);
  sim::PivotSceneOptions scene_options;
  scene_options.stations = 2;
  const sim::PivotScene scene = SimulatePivot(scene_options, rng);
  EXPECT_THROW(CalibratePivot(scene.T_base_flange, PivotOptions{}), DegenerateError);
}

// A station moved by 20 mm (200 σ) is flagged and left out; the fit of the others is as good as
// without it, for the noise given and estimated.
TEST(PivotTest, FlagsAndLeavesOutAGrossOutlier) {
  sim::PivotSceneOptions scene_options;
  scene_options.rotation_sigma = 0.1 * kDegree;
  scene_options.translation_sigma = 0.1e-3;
  std::mt19937_64 rng(7);
  sim::PivotScene scene = SimulatePivot(scene_options, rng);
  constexpr int kBad = 4;
  scene.T_base_flange[kBad].translation() += Eigen::Vector3d(0.012, -0.016, 0.0);
  for (const std::optional<PoseSigma>& sigma :
       {std::optional<PoseSigma>(), std::optional<PoseSigma>(PoseSigma{0.1 * kDegree, 1e-4})}) {
    PivotOptions options;
    options.sigma = sigma;
    const PivotResult result = CalibratePivot(scene.T_base_flange, options);
    for (int i = 0; i < static_cast<int>(result.stations.size()); ++i) {
      EXPECT_EQ(result.stations[i].outlier, i == kBad) << i;
      EXPECT_EQ(result.stations[i].used, i != kBad) << i;
    }
    EXPECT_GT(result.stations[kBad].standardized, 20.0);
    // Within 4σ of the truth: the outlier no longer pulls the fit.
    for (int k = 0; k < 3; ++k) {
      EXPECT_LT(std::abs(result.tip(k) - scene.tip(k)), 4 * std::sqrt(result.covariance(k, k)));
      EXPECT_LT(std::abs(result.pivot(k) - scene.pivot(k)),
                4 * std::sqrt(result.covariance(3 + k, 3 + k)));
    }
    PivotOptions keep = options;
    keep.reject_outliers = false;
    const PivotResult kept = CalibratePivot(scene.T_base_flange, keep);
    EXPECT_TRUE(kept.stations[kBad].outlier);
    EXPECT_TRUE(kept.stations[kBad].used);
  }
}

TEST(PivotTest, RefusesNoTranslationNoise) {
  PivotOptions options;
  options.sigma = PoseSigma{0.001, 0.0};
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_EQ(why.rfind("PivotOptions.sigma: ", 0), 0u) << why;
}

}  // namespace
}  // namespace hecal::estimation
