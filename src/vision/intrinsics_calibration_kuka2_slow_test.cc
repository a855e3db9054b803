// Real data: data/rwhe-kuka2 (28 images 1920×1200, chessboard 24×17 inner corners, 15 mm; see
// its SOURCE.md). hecal's image chain — DetectTarget, then CalibrateIntrinsics — against the
// reference that SOURCE.md computed with OpenCV 4.6 (findChessboardCornersSB EXHAUSTIVE |
// ACCURACY, then calibrateCamera on all 28 views): RMS 0.074 px,
// K = [1056.2855 0 958.7994; 0 1056.4172 586.9487; 0 0 1],
// (k1, k2, p1, p2, k3) = (−0.131337, 0.099230, 0.000133, 0.000312, −0.049132).
// Tolerance: DetectTarget, told to use the SB detector only (DetectOptions::chessboard_fast_first
// = false; by default it tries findChessboardCorners + edge refinement first, whose corners
// differ slightly: cli_kuka2_images_test), uses the same detector and CalibrateIntrinsics the same
// calibrateCamera,
// so the result equals the reference up to its printed rounding (measured: every printed digit
// agrees; RMS 0.07405 px). Bounds: 2e-3 px on K (printed to 1e-4), 2e-6 on the distortion
// (printed to 1e-6), 1e-3 px on the RMS (printed to 1e-3) — a few times the rounding and below
// the estimate's own 1σ for every parameter (σ(fx) ≈ 0.065 px, 30× the bound; σ(p1) ≈ 8e-6, the
// closest, 4×), so any change of the corner positions that matters statistically fails the test.
// Slow: the SB detector takes ~2.4 s per image per core (label `slow`).
#include <gtest/gtest.h>

#include <array>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "hecal/vision/detection.h"
#include "hecal/vision/intrinsics_calibration.h"
#include "testing/target_specs.h"

namespace hecal::vision {
namespace {

TEST(IntrinsicsCalibrationKuka2, ReproducesTheOpenCvReference) {
  const pose::TargetSpec target = hecal::testing::Chessboard(24, 17, 0.015);
  const std::vector<pose::ObjectPoint> board = pose::ObjectPoints(target);

  DetectOptions sb_only;
  sb_only.chessboard_fast_first = false;
  constexpr int kImages = 28;
  std::vector<CalibrationView> views(kImages);
  std::vector<std::string> failures(kImages);
  cv::parallel_for_(cv::Range(0, kImages), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      const std::string path = std::string(HECAL_SOURCE_DIR) + "/data/rwhe-kuka2/images/im_" +
                               (i < 9 ? "0" : "") + std::to_string(i + 1) + ".png";
      const Detection detection =
          DetectTarget(cv::imread(path, cv::IMREAD_GRAYSCALE), target, sb_only);
      if (detection.status != DetectionStatus::kFound) {
        failures[static_cast<std::size_t>(i)] = path + ": " + detection.message;
        continue;
      }
      for (const ImagePoint& point : detection.points) {
        views[static_cast<std::size_t>(i)].object_points.push_back(
            board[static_cast<std::size_t>(point.id)].position);
        views[static_cast<std::size_t>(i)].image_points.push_back(point.pixel);
      }
    }
  });
  for (const std::string& failure : failures) ASSERT_TRUE(failure.empty()) << failure;

  const IntrinsicsResult result = CalibrateIntrinsics(views, 1920, 1200);
  EXPECT_NEAR(result.rms_px, 0.074, 1e-3);
  EXPECT_NEAR(result.camera.fx, 1056.2855, 2e-3);
  EXPECT_NEAR(result.camera.fy, 1056.4172, 2e-3);
  EXPECT_NEAR(result.camera.cx, 958.7994, 2e-3);
  EXPECT_NEAR(result.camera.cy, 586.9487, 2e-3);
  const std::array<double, 5> reference = {-0.131337, 0.099230, 0.000133, 0.000312, -0.049132};
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_NEAR(result.camera.distortion[k], reference[k], 2e-6) << "coefficient " << k;
  }
  // The bounds above are below the statistical 1σ, as the comment says.
  EXPECT_GT(result.sigma.fx, 10 * 2e-3);
  EXPECT_GT(result.sigma.cy, 10 * 2e-3);
  for (std::size_t k = 0; k < 5; ++k) EXPECT_GT(result.sigma.distortion[k], 2 * 2e-6);
  // 28 well-spread views of a large board: nothing to warn about.
  EXPECT_TRUE(result.warnings.empty()) << ::testing::PrintToString(result.warnings);
}

}  // namespace
}  // namespace hecal::vision
