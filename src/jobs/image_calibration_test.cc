// CalibrateFromImages (image_calibration.h) on simulated image stations (testing/image_scene.h):
// the document's stations, rejections and reasons against the images that were skipped, blurred or
// paired with a wrong robot pose, and X against the known truth.
#include "hecal/jobs/image_calibration.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "testing/image_scene.h"

namespace hecal::jobs {
namespace {

// 13 images im0 … im12: im1 was skipped by the front end; the other twelve are stations, with
// the true camera poses (σ 0.1 mrad / 0.1 mm) and pixels of 0.2 px noise, except im4 (the fourth
// station: 2 px more, a blurred view) and im9 (the ninth: its robot pose is off by 5°).
ImageCalibrationInput Input(const testing::ImageScene& s) {
  ImageCalibrationInput input;
  input.unit = io::LengthUnit::kMillimetre;
  input.intrinsics_source = "camera.yaml";
  input.notes = {"a note of the caller"};
  size_t station = 0;
  for (int i = 0; i < 13; ++i) {
    input.image_ids.push_back("im" + std::to_string(i));
    input.skipped.push_back(i == 1 ? "no target found" : "");
    if (i == 1) continue;
    Matrix6d covariance = Matrix6d::Identity() * 1e-8;
    input.stations.push_back(
        {s.poses.T_base_gripper[station], s.poses.T_camera_target_true[station], covariance,
         estimation::ImagePoints{s.images[station].target, s.images[station].pixels}});
    ++station;
  }
  return input;
}

TEST(ImageCalibration, DocumentListsEveryImageAndWhyEachRejectedOneIsOut) {
  const testing::PoseNoise robot{0.01 * kRadiansPerDegree, 0.05e-3};
  testing::ImageScene s = testing::MakeImageScene(
      testing::ImageSceneOptions::For(handeye::Setup::kEyeInHand, 12, 31, robot, 0.2));
  std::mt19937_64 rng(9);
  hecal::NormalDistribution gaussian;
  for (Eigen::Vector2d& pixel : s.images[3].pixels) {
    const double dy = gaussian(rng);  // y first: the order the test's data were generated in
    const double dx = gaussian(rng);
    pixel += 2.0 * Eigen::Vector2d(dx, dy);
  }
  ImageCalibrationInput input = Input(s);
  Vector6d slip;
  slip << 0.0, 0.0, 5.0 * kRadiansPerDegree, 0.0, 0.0, 0.0;
  input.stations[8].T_base_gripper = input.stations[8].T_base_gripper * se3::Exp(slip);
  estimation::ImageCalibrationOptions options;
  options.setup = handeye::Setup::kEyeInHand;
  options.camera = testing::DefaultCamera();

  const report::ResultDocument document = CalibrateFromImages(input, options);
  EXPECT_EQ(document.setup, handeye::Setup::kEyeInHand);
  EXPECT_EQ(document.unit, io::LengthUnit::kMillimetre);
  EXPECT_EQ(document.station_ids, input.image_ids);
  EXPECT_EQ(document.rejected, (std::vector<int>{1, 4, 9}));  // image indices, in order
  ASSERT_TRUE(document.images);
  const report::ImageReport& report = *document.images;
  ASSERT_EQ(report.skipped_reasons.size(), 3u);
  EXPECT_EQ(report.skipped_reasons[0], "no target found");
  EXPECT_EQ(report.skipped_reasons[1].rfind("outlier: reprojection RMS ", 0), 0u);
  EXPECT_EQ(report.skipped_reasons[2].rfind("outlier: pose residual ", 0), 0u);
  EXPECT_EQ(report.intrinsics_source, "camera.yaml");
  EXPECT_FALSE(report.intrinsics_rms_px);
  EXPECT_EQ(report.image_rms_px.size(), 10u);  // the stations used
  ASSERT_EQ(document.results.size(), 1u);
  const estimation::CalibrationResult& result = document.results.front();
  EXPECT_EQ(result.rejected_ids, (std::vector<std::string>{"im4", "im9"}));
  ASSERT_FALSE(result.warnings.empty());
  EXPECT_EQ(result.warnings.front(), "a note of the caller");
  EXPECT_LT(se3::Log(s.poses.X.inverse() * result.X).head<3>().norm(), 0.05 * kRadiansPerDegree);
}

TEST(ImageCalibration, StationsMustMatchTheUsedImages) {
  const testing::PoseNoise none{0.0, 0.0};
  const testing::ImageScene s = testing::MakeImageScene(
      testing::ImageSceneOptions::For(handeye::Setup::kEyeInHand, 12, 5, none, 0.0));
  ImageCalibrationInput input = Input(s);
  estimation::ImageCalibrationOptions options;
  options.camera = testing::DefaultCamera();
  input.stations.pop_back();
  EXPECT_THROW(CalibrateFromImages(input, options), InputError);
  input = Input(s);
  input.skipped.pop_back();
  EXPECT_THROW(CalibrateFromImages(input, options), InputError);
}

}  // namespace
}  // namespace hecal::jobs
