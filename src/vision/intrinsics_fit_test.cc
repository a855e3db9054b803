// CheckIntrinsicsFit on views projected with OpenCV's own model (cv::projectPoints) through a
// known camera, with 0.05 px of pixel noise, and checked against intrinsics changed the way users
// get them wrong: the verdict, and the correction that recovers the true camera.
#include "hecal/vision/intrinsics_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "hecal/core/error.h"
#include "hecal/geometry/angle_units.h"
#include "testing/image_scene.h"
#include "testing/options_validity.h"
#include "testing/synthetic_views.h"

namespace hecal::vision {
namespace {

using Kind = IntrinsicsCorrection::Kind;
constexpr double kNoisePx = 0.05;

// A 1920 × 1200 machine-vision camera (the kind of data/rwhe-kuka2).
pose::CameraModel WideCamera() {
  return {.fx = 1056.0,
          .fy = 1057.0,
          .cx = 958.8,
          .cy = 586.9,
          .width = 1920,
          .height = 1200,
          .distortion = {-0.13, 0.10, 0.0001, 0.0003, -0.05}};
}

// 8 views of `points` (a planar target around `centre`) from 0.45–0.6 m, tilted 15–35° towards
// directions 45° apart, panned across the image; pixels through `camera` with noise.
std::vector<CalibrationView> Views(const std::vector<Eigen::Vector3d>& points,
                                   const Eigen::Vector3d& centre, const pose::CameraModel& camera,
                                   double distance = 0.45) {
  std::mt19937_64 rng(7);
  std::vector<CalibrationView> views;
  for (int k = 0; k < 8; ++k) {
    const double tilt = (15.0 + 10.0 * (k % 3)) * kRadiansPerDegree;
    const double azimuth = 45.0 * k * kRadiansPerDegree;
    const Eigen::Vector3d eye =
        centre + (distance + 0.05 * (k % 4)) * Eigen::Vector3d(std::sin(tilt) * std::cos(azimuth),
                                                               std::sin(tilt) * std::sin(azimuth),
                                                               -std::cos(tilt));
    const Pose T = testing::LookAt(
        eye, centre, Eigen::Vector2d(k % 2 == 0 ? 0.1 : -0.1, k % 4 < 2 ? 0.1 : -0.1));
    std::vector<Eigen::Vector2d> pixels = testing::Project(points, T, camera);
    testing::AddNoise(kNoisePx, rng, &pixels);
    views.push_back({points, pixels});
  }
  return views;
}

// A 9 × 6 chessboard of 30 mm squares.
std::vector<CalibrationView> BoardViews(const pose::CameraModel& camera) {
  return Views(
      ::hecal::testing::GridPoints({.cols = 9, .rows = 6, .pitch = 0.03, .centred = false}),
      Eigen::Vector3d(0.12, 0.075, 0.0), camera);
}

TEST(IntrinsicsFit, TrueIntrinsicsFit) {
  const std::vector<CalibrationView> views = BoardViews(WideCamera());
  const IntrinsicsFit fit = CheckIntrinsicsFit(views, WideCamera());
  EXPECT_EQ(fit.verdict, IntrinsicsVerdict::kFits);
  // Both fits leave the pixel noise: RMS of 2-D noise of 0.05 px per axis is ~0.07 px.
  EXPECT_LT(fit.median_rms_px, 0.1);
  ASSERT_TRUE(fit.median_free_rms_px.has_value());
  EXPECT_NEAR(*fit.median_free_rms_px, fit.median_rms_px, 0.01);
  EXPECT_FALSE(fit.correction.has_value());
  EXPECT_FALSE(fit.points_do_not_fit);
}

// Each mistake, and the correction that undoes it (recovering the true camera).
TEST(IntrinsicsFit, NamesTheMistakeThatMakesTheImagesFit) {
  const pose::CameraModel truth = WideCamera();
  const std::vector<CalibrationView> views = BoardViews(truth);

  pose::CameraModel focal = truth;  // a focal length 10× too large
  focal.fx *= 10.0;
  focal.fy *= 10.0;
  IntrinsicsFit fit = CheckIntrinsicsFit(views, focal);
  EXPECT_EQ(fit.verdict, IntrinsicsVerdict::kDoesNotFit);
  ASSERT_TRUE(fit.correction.has_value());
  EXPECT_EQ(fit.correction->kind, Kind::kScaleFocal);
  EXPECT_NEAR(fit.correction->scale, 0.1, 0.001);
  EXPECT_NEAR(fit.correction->camera.fx, truth.fx, 1.0);
  EXPECT_LT(fit.correction->median_rms_px, 0.1);

  pose::CameraModel swapped = truth;  // cx and cy swapped
  std::swap(swapped.cx, swapped.cy);
  fit = CheckIntrinsicsFit(views, swapped);
  EXPECT_EQ(fit.verdict, IntrinsicsVerdict::kDoesNotFit);
  ASSERT_TRUE(fit.correction.has_value());
  EXPECT_EQ(fit.correction->kind, Kind::kSwapPrincipalPoint);
  EXPECT_EQ(fit.correction->camera.cx, truth.cx);

  // The intrinsics of the same camera at twice the resolution: c' = (c + ½)·2 − ½.
  pose::CameraModel doubled = truth;
  doubled.fx *= 2.0;
  doubled.fy *= 2.0;
  doubled.cx = 2.0 * truth.cx + 0.5;
  doubled.cy = 2.0 * truth.cy + 0.5;
  fit = CheckIntrinsicsFit(views, doubled);
  EXPECT_EQ(fit.verdict, IntrinsicsVerdict::kDoesNotFit);
  ASSERT_TRUE(fit.correction.has_value());
  EXPECT_EQ(fit.correction->kind, Kind::kScaleResolution);
  EXPECT_NEAR(fit.correction->scale, 0.5, 0.005);
  EXPECT_NEAR(fit.correction->camera.cx, truth.cx, 1.0);
  EXPECT_NEAR(fit.correction->camera.cy, truth.cy, 1.0);

  // A focal length 10% off: not beyond 2 px, but far worse than the free fit.
  pose::CameraModel off = truth;
  off.fx *= 1.1;
  off.fy *= 1.1;
  fit = CheckIntrinsicsFit(views, off);
  EXPECT_EQ(fit.verdict, IntrinsicsVerdict::kSuspect);
  EXPECT_LT(fit.median_rms_px, 2.0);
  ASSERT_TRUE(fit.correction.has_value());
  EXPECT_EQ(fit.correction->kind, Kind::kScaleFocal);
  EXPECT_NEAR(fit.correction->scale, 1.0 / 1.1, 0.005);
}

// Images that are already undistorted, with the lens's distortion still in the camera file.
TEST(IntrinsicsFit, SeesDistortionOnUndistortedImages) {
  pose::CameraModel rectified = WideCamera();
  rectified.distortion = {0.0, 0.0, 0.0, 0.0, 0.0};
  const std::vector<CalibrationView> views = BoardViews(rectified);
  pose::CameraModel given = rectified;
  given.distortion = {-0.3, 0.1, 0.0, 0.0, 0.0};
  const IntrinsicsFit fit = CheckIntrinsicsFit(views, given);
  EXPECT_NE(fit.verdict, IntrinsicsVerdict::kFits);
  ASSERT_TRUE(fit.correction.has_value());
  EXPECT_EQ(fit.correction->kind, Kind::kNoDistortion);
  EXPECT_LT(fit.correction->median_rms_px, 0.1);
}

// Points labelled with the wrong layout (two rows of the board swapped): no K fits, and neither
// does a free homography, so the points are blamed and no correction is offered.
TEST(IntrinsicsFit, BlamesThePointsWhenNoHomographyFitsEither) {
  const pose::CameraModel truth = WideCamera();
  std::vector<CalibrationView> views = BoardViews(truth);
  for (CalibrationView& view : views) {
    for (int c = 0; c < 9; ++c) {
      std::swap(view.object_points[static_cast<size_t>(c)],
                view.object_points[static_cast<size_t>(27 + c)]);
    }
  }
  const IntrinsicsFit fit = CheckIntrinsicsFit(views, truth);
  EXPECT_EQ(fit.verdict, IntrinsicsVerdict::kDoesNotFit);
  EXPECT_TRUE(fit.points_do_not_fit);
  EXPECT_FALSE(fit.correction.has_value());
  ASSERT_TRUE(fit.median_free_rms_px.has_value());
  EXPECT_GT(*fit.median_free_rms_px, 1.0);
}

// A single tag (4 points: no free homography to compare with): 1 px is a warning. A 10 cm tag at
// 0.3 m in a 640 × 480 camera with fx 10× too large.
TEST(IntrinsicsFit, SingleTagsUseTheAbsoluteThreshold) {
  pose::CameraModel camera;
  camera.fx = 620.0;
  camera.fy = 622.0;
  camera.cx = 321.5;
  camera.cy = 238.0;
  camera.width = 640;
  camera.height = 480;
  const std::vector<Eigen::Vector3d> tag = {
      {-0.05, -0.05, 0.0}, {0.05, -0.05, 0.0}, {0.05, 0.05, 0.0}, {-0.05, 0.05, 0.0}};
  const std::vector<CalibrationView> views = Views(tag, Eigen::Vector3d::Zero(), camera, 0.3);
  EXPECT_EQ(CheckIntrinsicsFit(views, camera).verdict, IntrinsicsVerdict::kFits);
  pose::CameraModel focal = camera;
  focal.fx *= 10.0;
  focal.fy *= 10.0;
  const IntrinsicsFit fit = CheckIntrinsicsFit(views, focal);
  EXPECT_FALSE(fit.median_free_rms_px.has_value());
  EXPECT_GE(fit.median_rms_px, 1.0);
  EXPECT_NE(fit.verdict, IntrinsicsVerdict::kFits);
  ASSERT_TRUE(fit.correction.has_value());
  EXPECT_EQ(fit.correction->kind, Kind::kScaleFocal);
  EXPECT_NEAR(fit.correction->scale, 0.1, 0.005);
}

TEST(IntrinsicsFit, RejectsUnusableInput) {
  const pose::CameraModel camera = WideCamera();
  EXPECT_THROW(CheckIntrinsicsFit({}, camera), InputError);
  CalibrationView three;
  three.object_points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  three.image_points = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_THROW(CheckIntrinsicsFit({three}, camera), InputError);
  IntrinsicsFitOptions options;
  options.refuse_rms_px = 0.0;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_THROW(CheckIntrinsicsFit(BoardViews(camera), camera, options), InputError);
}

TEST(IntrinsicsFitOptions, IsValidNamesTheField) {
  using hecal::testing::RefusesNaming;
  const IntrinsicsFitOptions defaults;
  EXPECT_TRUE(hecal::testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsFitOptions.refuse_rms_px",
                            [](auto& o) { o.refuse_rms_px = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsFitOptions.warn_ratio",
                            [](auto& o) { o.warn_ratio = -1.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsFitOptions.min_warn_rms_px",
                            [](auto& o) { o.min_warn_rms_px = std::nan(""); }));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsFitOptions.warn_rms_px_without_free",
                            [](auto& o) { o.warn_rms_px_without_free = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsFitOptions.free_floor_px", [](auto& o) {
    o.free_floor_px = std::numeric_limits<double>::infinity();
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsFitOptions.max_diagnosis_views",
                            [](auto& o) { o.max_diagnosis_views = 0; }));
}

}  // namespace
}  // namespace hecal::vision
