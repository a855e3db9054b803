// Intrinsics calibration on synthetic views of known cameras: exact recovery without noise, an
// RMS at the pixel-noise level (and errors consistent with the reported 1σ) with noise, the
// fix_k3 / fix_aspect_ratio options, the poorly-constrained warnings (each triggered by the data
// it describes, and absent for a well-spread set) and bad input.
#include "hecal/vision/intrinsics_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hecal/core/error.h"
#include "hecal/geometry/angle_units.h"
#include "testing/image_scene.h"
#include "testing/options_validity.h"
#include "testing/synthetic_views.h"

namespace hecal::vision {
namespace {

using testing::LookAt;
using testing::Project;

pose::CameraModel TrueCamera() {
  return {.fx = 1000.0,
          .fy = 1003.0,
          .cx = 652.3,
          .cy = 471.8,
          .width = 1280,
          .height = 960,
          .distortion = {-0.18, 0.07, 0.0009, -0.0006, -0.012}};
}

// An 11 × 8 board with 40 mm squares (0.4 × 0.28 m), centre (0.2, 0.14, 0).
const std::vector<Eigen::Vector3d>& Board() {
  static const std::vector<Eigen::Vector3d> board =
      ::hecal::testing::GridPoints({.cols = 11, .rows = 8, .pitch = 0.04, .centred = false});
  return board;
}

// A camera `distance` from the board centre, its axis tilted by `tilt` from the board normal
// towards azimuth `azimuth`, then panned so the board moves across the image.
Pose View(double distance, double tilt, double azimuth, const Eigen::Vector2d& pan) {
  const Eigen::Vector3d centre(0.2, 0.14, 0.0);
  const Eigen::Vector3d direction(std::sin(tilt) * std::cos(azimuth),
                                  std::sin(tilt) * std::sin(azimuth), -std::cos(tilt));
  return LookAt(centre + distance * direction, centre, pan);
}

// Twelve views: tilts of 20–40° in eight directions and panned towards the image corners.
std::vector<Pose> SpreadViews() {
  std::vector<Pose> views;
  for (int k = 0; k < 12; ++k) {
    const double tilt = (20.0 + 20.0 * (k % 3) / 2.0) * kRadiansPerDegree;
    const double azimuth = k * 45.0 * kRadiansPerDegree;
    const Eigen::Vector2d pan((k % 2 == 0 ? 0.12 : -0.12), (k % 4 < 2 ? 0.18 : -0.18));
    views.push_back(View(0.55 + 0.02 * (k % 5), tilt, azimuth, pan));
  }
  return views;
}

std::vector<CalibrationView> Observe(const std::vector<Pose>& poses,
                                     const pose::CameraModel& camera, double noise_px,
                                     std::mt19937_64& rng) {
  std::vector<CalibrationView> views;
  for (const Pose& T : poses) {
    CalibrationView view{Board(), Project(Board(), T, camera)};
    testing::AddNoise(noise_px, rng, &view.image_points);
    views.push_back(view);
  }
  return views;
}

bool HasWarning(const IntrinsicsResult& result, const std::string& text) {
  for (const std::string& warning : result.warnings) {
    if (warning.find(text) != std::string::npos) return true;
  }
  return false;
}

TEST(IntrinsicsCalibration, RecoversAKnownCameraFromExactPixels) {
  const pose::CameraModel truth = TrueCamera();
  std::mt19937_64 rng(1);
  const std::vector<Pose> poses = SpreadViews();
  const IntrinsicsResult result =
      CalibrateIntrinsics(Observe(poses, truth, 0.0, rng), truth.width, truth.height);
  // calibrateCamera works in single precision (pixels rounded to ~6e-5 px at 1000 px), so
  // "exact" is to that rounding: measured RMS 2.3e-5 px, fx off by 7e-5 px, distortion by 1.5e-6.
  EXPECT_LT(result.rms_px, 1e-4);
  EXPECT_NEAR(result.camera.fx, truth.fx, 1e-3);
  EXPECT_NEAR(result.camera.fy, truth.fy, 1e-3);
  EXPECT_NEAR(result.camera.cx, truth.cx, 1e-3);
  EXPECT_NEAR(result.camera.cy, truth.cy, 1e-3);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_NEAR(result.camera.distortion[k], truth.distortion[k], 1e-5) << "coefficient " << k;
  }
  EXPECT_EQ(result.camera.width, truth.width);
  EXPECT_EQ(result.camera.height, truth.height);
  ASSERT_EQ(result.T_camera_target.size(), poses.size());
  ASSERT_EQ(result.view_rms_px.size(), poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_LT(testing::RotationError(result.T_camera_target[i], poses[i]), 1e-6);
    EXPECT_LT(testing::TranslationError(result.T_camera_target[i], poses[i]), 1e-6);
    EXPECT_LT(result.view_rms_px[i], 1e-4);
  }
  EXPECT_TRUE(result.warnings.empty()) << result.warnings.front();
}

TEST(IntrinsicsCalibration, RmsMatchesThePixelNoiseAndErrorsMatchTheReportedSigma) {
  const pose::CameraModel truth = TrueCamera();
  const std::vector<Pose> poses = SpreadViews();
  constexpr double kNoise = 0.3;
  std::mt19937_64 rng(42);
  const IntrinsicsResult result =
      CalibrateIntrinsics(Observe(poses, truth, kNoise, rng), truth.width, truth.height);
  // The RMS is per point (sqrt(Σ‖e_k‖²/N), both coordinates), so for σ per coordinate the
  // least-squares residuals give σ·sqrt(2)·sqrt((2N − P)/(2N)), N points, P parameters (9
  // intrinsics + 6 per view); its relative sampling spread is ~1/sqrt(2·(2N − P)) ≈ 2%.
  const double n = 2.0 * static_cast<double>(poses.size() * Board().size());
  const double p = 9.0 + 6.0 * static_cast<double>(poses.size());
  const double expected = kNoise * std::sqrt(2.0) * std::sqrt((n - p) / n);
  EXPECT_NEAR(result.rms_px, expected, 0.08 * expected);
  // Every estimate within 4σ of the truth, by the σ calibrateCamera reports.
  EXPECT_NEAR(result.camera.fx, truth.fx, 4.0 * result.sigma.fx);
  EXPECT_NEAR(result.camera.fy, truth.fy, 4.0 * result.sigma.fy);
  EXPECT_NEAR(result.camera.cx, truth.cx, 4.0 * result.sigma.cx);
  EXPECT_NEAR(result.camera.cy, truth.cy, 4.0 * result.sigma.cy);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_GT(result.sigma.distortion[k], 0.0);
    EXPECT_NEAR(result.camera.distortion[k], truth.distortion[k], 4.0 * result.sigma.distortion[k])
        << "coefficient " << k;
  }
  // The σ are meaningful (not zero, not huge): 0.3 px noise on 1056 points.
  EXPECT_GT(result.sigma.fx, 0.01);
  EXPECT_LT(result.sigma.fx, 2.0);
  EXPECT_TRUE(result.warnings.empty()) << result.warnings.front();
}

TEST(IntrinsicsCalibration, FixedK3AndAspectRatioStayFixed) {
  pose::CameraModel truth = TrueCamera();
  truth.fy = truth.fx;
  truth.distortion[4] = 0.0;
  std::mt19937_64 rng(2);
  IntrinsicsOptions options;
  options.fix_k3 = true;
  options.fix_aspect_ratio = true;
  const IntrinsicsResult result = CalibrateIntrinsics(Observe(SpreadViews(), truth, 0.0, rng),
                                                      truth.width, truth.height, options);
  EXPECT_EQ(result.camera.fx, result.camera.fy);
  EXPECT_EQ(result.camera.distortion[4], 0.0);
  EXPECT_EQ(result.sigma.distortion[4], 0.0);
  EXPECT_EQ(result.sigma.fx, result.sigma.fy);
  EXPECT_NEAR(result.camera.fx, truth.fx, 1e-3);
  EXPECT_LT(result.rms_px, 1e-4);
}

TEST(IntrinsicsCalibration, WarnsAboutFewViews) {
  const pose::CameraModel truth = TrueCamera();
  std::mt19937_64 rng(3);
  const std::vector<Pose> all = SpreadViews();
  const std::vector<Pose> four(all.begin(), all.begin() + 4);
  const IntrinsicsResult result =
      CalibrateIntrinsics(Observe(four, truth, 0.1, rng), truth.width, truth.height);
  EXPECT_TRUE(HasWarning(result, "only 4 views")) << ::testing::PrintToString(result.warnings);
}

TEST(IntrinsicsCalibration, WarnsWhenAllBoardsAreParallel) {
  // Nearly fronto-parallel views at different distances and positions in the image: Zhang's
  // method cannot separate focal length from distance (every normal is near the optical axis).
  const pose::CameraModel truth = TrueCamera();
  const Eigen::Vector3d centre(0.2, 0.14, 0.0);
  std::vector<Pose> poses;
  for (int k = 0; k < 8; ++k) {
    // Tilted by at most 4° (normals within 8° of each other), turned about the optical axis,
    // at 0.5–0.7 m, moved around the image.
    const Eigen::Matrix3d R =
        (Eigen::AngleAxisd(15.0 * kRadiansPerDegree * k, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(4.0 * kRadiansPerDegree, Eigen::Vector3d(std::cos(k), std::sin(k), 0.0)))
            .toRotationMatrix();
    const Eigen::Vector3d centre_camera((k % 2 == 0 ? 0.06 : -0.06), (k % 4 < 2 ? 0.05 : -0.05),
                                        0.5 + 0.03 * k);
    poses.push_back(MakePose(R, centre_camera - R * centre));
  }
  std::mt19937_64 rng(4);
  const IntrinsicsResult result =
      CalibrateIntrinsics(Observe(poses, truth, 0.2, rng), truth.width, truth.height);
  EXPECT_LT(result.normal_spread_deg, 10.0);
  EXPECT_TRUE(HasWarning(result, "board normals")) << ::testing::PrintToString(result.warnings);
  // ... and the focal length is indeed poorly determined.
  EXPECT_TRUE(HasWarning(result, "focal length is poorly determined"))
      << ::testing::PrintToString(result.warnings) << " sigma fx " << result.sigma.fx;
}

TEST(IntrinsicsCalibration, WarnsWhenThePointsCoverLittleOfTheImage) {
  // The spread views, but from twice the distance and without panning: the board stays in
  // the middle of the image.
  const pose::CameraModel truth = TrueCamera();
  std::vector<Pose> poses;
  for (int k = 0; k < 12; ++k) {
    poses.push_back(
        View(1.3, 30.0 * kRadiansPerDegree, k * 30.0 * kRadiansPerDegree, Eigen::Vector2d::Zero()));
  }
  std::mt19937_64 rng(5);
  const IntrinsicsResult result =
      CalibrateIntrinsics(Observe(poses, truth, 0.1, rng), truth.width, truth.height);
  EXPECT_LT(result.coverage, 0.5);
  EXPECT_TRUE(HasWarning(result, "cover only")) << ::testing::PrintToString(result.warnings);
}

TEST(IntrinsicsCalibration, BadInputIsReported) {
  const pose::CameraModel truth = TrueCamera();
  std::mt19937_64 rng(6);
  std::vector<CalibrationView> views = Observe(SpreadViews(), truth, 0.0, rng);

  const std::vector<CalibrationView> two(views.begin(), views.begin() + 2);
  EXPECT_THROW(CalibrateIntrinsics(two, truth.width, truth.height), DegenerateError);
  EXPECT_THROW(CalibrateIntrinsics(views, 0, truth.height), InputError);

  std::vector<CalibrationView> mismatched = views;
  mismatched[1].image_points.pop_back();
  EXPECT_THROW(CalibrateIntrinsics(mismatched, truth.width, truth.height), InputError);

  std::vector<CalibrationView> off_plane = views;
  off_plane[2].object_points[5].z() = 0.01;
  EXPECT_THROW(CalibrateIntrinsics(off_plane, truth.width, truth.height), InputError);

  std::vector<CalibrationView> tiny = views;
  tiny[0].object_points.resize(3);
  tiny[0].image_points.resize(3);
  EXPECT_THROW(CalibrateIntrinsics(tiny, truth.width, truth.height), InputError);

  IntrinsicsOptions options;
  options.min_coverage = 2.0;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("min_coverage"), std::string::npos);
  EXPECT_THROW(CalibrateIntrinsics(views, truth.width, truth.height, options), InputError);
}

TEST(IntrinsicsOptions, IsValidNamesTheField) {
  using hecal::testing::RefusesNaming;
  const IntrinsicsOptions defaults;
  EXPECT_TRUE(hecal::testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsOptions.recommended_views",
                            [](auto& o) { o.recommended_views = -1; }));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsOptions.min_normal_spread_deg",
                            [](auto& o) { o.min_normal_spread_deg = 181.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsOptions.min_coverage",
                            [](auto& o) { o.min_coverage = 2.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsOptions.max_focal_sigma_relative",
                            [](auto& o) { o.max_focal_sigma_relative = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsOptions.max_principal_sigma_px",
                            [](auto& o) { o.max_principal_sigma_px = -1.0; }));
}

}  // namespace
}  // namespace hecal::vision
