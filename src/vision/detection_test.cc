// DetectTarget against ground truth: images rendered by RenderTarget (render.h; its pattern and
// its area-exactness are checked in render_test) through a camera with lens distortion at known
// poses. Every detected point is compared with the projection of its object point
// (pose::Project), and cv::solvePnP on the detection with the true pose; with and without the
// camera, whose lens model removes the marker corners' outward bias.
#include "hecal/vision/detection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <string>

#include "hecal/core/error.h"
#include "hecal/vision/render.h"
#include "testing/detection_errors.h"
#include "testing/options_validity.h"
#include "testing/rendered_scene.h"

namespace hecal::vision {
namespace {

using hecal::testing::AprilTagGrid;
using hecal::testing::CompareWithTruth;
using hecal::testing::DetectionCamera;
using hecal::testing::FrontalView;
using hecal::testing::ProjectedTruth;

pose::TargetSpec Chessboard() {
  return {.type = pose::TargetType::kChessboard, .cols = 9, .rows = 6, .square = 0.03};
}

pose::TargetSpec Charuco() {
  return {.type = pose::TargetType::kCharuco,
          .cols = 7,
          .rows = 5,
          .square = 0.04,
          .marker = 0.03,
          .dictionary = "DICT_5X5_250"};
}

pose::TargetSpec ArucoGrid() {
  return {.type = pose::TargetType::kArucoGrid,
          .cols = 5,
          .rows = 4,
          .marker = 0.04,
          .spacing = 0.01,
          .dictionary = "DICT_4X4_250",
          .first_id = 7};
}

pose::TargetSpec Circles() {
  return {.type = pose::TargetType::kCircles, .cols = 7, .rows = 5, .square = 0.04};
}

pose::TargetSpec AsymmetricCircles() {
  return {.type = pose::TargetType::kAsymmetricCircles, .cols = 4, .rows = 11, .square = 0.02};
}

bool IsCircleGrid(const pose::TargetSpec& target) {
  return target.type == pose::TargetType::kCircles ||
         target.type == pose::TargetType::kAsymmetricCircles;
}

// What the detector should find for every point: the projected point, or for circle grids the
// centroid of the imaged disc (RenderOptions::circle_radius × the smallest centre distance).
std::vector<Eigen::Vector2d> DetectorTruth(const pose::TargetSpec& target,
                                           const pose::CameraModel& camera, const Pose& T,
                                           const RenderOptions& render) {
  if (!IsCircleGrid(target)) return ProjectedTruth(target, camera, T).pixels;
  const std::vector<pose::ObjectPoint> points = pose::ObjectPoints(target);
  double spacing = std::numeric_limits<double>::infinity();
  for (const pose::ObjectPoint& a : points) {
    for (const pose::ObjectPoint& b : points) {
      if (a.id != b.id) spacing = std::min(spacing, (a.position - b.position).norm());
    }
  }
  std::vector<Eigen::Vector2d> centroids;
  for (const pose::ObjectPoint& point : points) {
    centroids.push_back(hecal::testing::ImagedDiscCentroid(camera, T, point.position,
                                                           render.circle_radius * spacing));
  }
  return centroids;
}

struct ChainCase {
  const char* name;
  pose::TargetSpec target;
  double distance;
  double tilt_x_deg, tilt_y_deg, roll_deg;
};

class RenderDetect : public ::testing::TestWithParam<ChainCase> {};

// Noise-free renders (blur σ = 0.7 px), detected with the camera (used by the marker grids):
// RMS error below 0.05 px and every point within 0.1 px of the truth, and the PnP pose on the
// detected points within 0.02° and 0.2 mm of the true pose. Measured RMS / max (px): chessboard
// 0.021 / 0.050, charuco 0.011 / 0.019, aruco_grid 0.028 / 0.070 (0.033 / 0.076 without the
// camera), apriltag_grid 0.034 / 0.075 (0.039 / 0.092), circles 0.004 / 0.010, acircles
// 0.004 / 0.009.
TEST_P(RenderDetect, PointsAndPoseMatchTheTruth) {
  const ChainCase& c = GetParam();
  const pose::CameraModel camera = DetectionCamera();
  const Pose T_camera_target =
      FrontalView(c.target, c.distance, c.tilt_x_deg, c.tilt_y_deg, c.roll_deg);
  RenderOptions render;
  render.blur_sigma = 0.7;
  const cv::Mat image = RenderTarget(c.target, camera, T_camera_target, render);
  const Detection detection = DetectTarget(image, c.target, {}, camera);
  // A symmetric circle grid is found completely but its half turn is fixed only by the image
  // rule (order_consistency_test covers that); its x axis points right here, as in the truth.
  const DetectionStatus expected = c.target.type == pose::TargetType::kCircles
                                       ? DetectionStatus::kAmbiguous
                                       : DetectionStatus::kFound;
  ASSERT_EQ(detection.status, expected) << detection.message;
  EXPECT_EQ(detection.num_points(), pose::PointCount(c.target));
  EXPECT_EQ(detection.total_points, pose::PointCount(c.target));
  const hecal::testing::PixelErrors errors =
      CompareWithTruth(detection, DetectorTruth(c.target, camera, T_camera_target, render));
  const Pose pnp = hecal::testing::OpenCvPose(detection, c.target, camera);
  const double rotation = hecal::testing::RotationErrorDeg(pnp, T_camera_target);
  const double translation = (pnp.translation() - T_camera_target.translation()).norm();
  std::cout << c.name << ": max " << errors.max << " px, rms " << errors.rms << " px; pose "
            << rotation << " deg, " << translation * 1e3 << " mm; sharpness " << detection.sharpness
            << " px\n";
  EXPECT_LT(errors.rms, 0.05);
  EXPECT_LT(errors.max, 0.1);
  EXPECT_LT(rotation, 0.02);
  EXPECT_LT(translation, 2e-4);
}

INSTANTIATE_TEST_SUITE_P(
    Targets, RenderDetect,
    ::testing::Values(ChainCase{"chessboard", Chessboard(), 0.45, 20.0, -15.0, 10.0},
                      ChainCase{"charuco", Charuco(), 0.45, -15.0, 20.0, -25.0},
                      ChainCase{"aruco_grid", ArucoGrid(), 0.5, 25.0, 10.0, 35.0},
                      ChainCase{"apriltag_grid", AprilTagGrid(), 0.5, -20.0, -20.0, 160.0},
                      ChainCase{"circles", Circles(), 0.5, 15.0, 10.0, 5.0},
                      ChainCase{"acircles", AsymmetricCircles(), 0.45, -10.0, 15.0, -8.0}),
    [](const ::testing::TestParamInfo<ChainCase>& param_info) {
      return std::string(param_info.param.name);
    });

// Under perspective a centroid is not the projected centre: the circle grid's points sit
// O(f r² tilt / Z²) px from the projections (detection.h) — about 0.07 px here — and the
// detector follows the imaged centroid instead.
TEST(DetectTarget, CircleCentresAreImagedCentroidsNotProjectedCentres) {
  const pose::TargetSpec target = AsymmetricCircles();
  const pose::CameraModel camera = DetectionCamera();
  const Pose T = FrontalView(target, 0.45, 25.0, 0.0, 0.0);
  RenderOptions render;
  render.blur_sigma = 0.7;
  const Detection detection = DetectTarget(RenderTarget(target, camera, T, render), target);
  ASSERT_EQ(detection.status, DetectionStatus::kFound) << detection.message;
  const double to_centroids =
      CompareWithTruth(detection, DetectorTruth(target, camera, T, render)).rms;
  const double to_projections =
      CompareWithTruth(detection, ProjectedTruth(target, camera, T).pixels).rms;
  EXPECT_LT(to_centroids, 0.02);
  EXPECT_GT(to_projections, 0.04);
}

// Sensor noise (σ = 2 grey levels) and more blur (σ = 1.2 px): the points stay within 0.1 px RMS.
TEST(DetectTarget, NoisyImagesStaySubPixel) {
  const pose::CameraModel camera = DetectionCamera();
  for (const pose::TargetSpec& target : {Chessboard(), Charuco(), ArucoGrid()}) {
    const Pose T = FrontalView(target, 0.5, 15.0, 20.0, 5.0);
    RenderOptions render;
    render.blur_sigma = 1.2;
    render.noise_sigma = 2.0;
    render.seed = 7;
    const Detection detection = DetectTarget(RenderTarget(target, camera, T, render), target);
    ASSERT_EQ(detection.status, DetectionStatus::kFound) << detection.message;
    EXPECT_LT(CompareWithTruth(detection, ProjectedTruth(target, camera, T).pixels).rms, 0.1)
        << pose::TargetTypeName(target.type);
  }
}

cv::Mat RenderAt(const pose::TargetSpec& target, const Pose& T) {
  RenderOptions render;
  render.blur_sigma = 0.7;
  return RenderTarget(target, DetectionCamera(), T, render);
}

// Lens distortion bends straight edges (detection.h, "The camera"). Strong barrel distortion
// (k1 = −0.3, k2 = 0.1), targets 0.35 m away: the mean outward offset of the points
// (hecal::testing::MeanOutwardOffset). Marker grids without the camera: corners on lines fitted in
// the distorted image, outward by 0.125–0.128 px (measured; asserted > 0.06); with it
// −0.0013–−0.0004 px (asserted within ±0.01). Chessboard and ChArUco saddle corners, fitted with
// quadratic edge curves, −0.002 and +0.0007 px (within ±0.01) without using the camera: their
// points are the same with and without it.
TEST(DetectTarget, TheCameraRemovesTheOutwardBiasOfMarkerCorners) {
  pose::CameraModel camera = DetectionCamera();
  camera.distortion = {-0.3, 0.1, 0.0, 0.0, 0.0};
  RenderOptions render;
  render.blur_sigma = 0.7;
  for (const pose::TargetSpec& target : {ArucoGrid(), AprilTagGrid(), Chessboard(), Charuco()}) {
    const std::string name(pose::TargetTypeName(target.type));
    const Pose T = FrontalView(target, 0.35, -15.0, 20.0, -25.0);
    const cv::Mat image = RenderTarget(target, camera, T, render);
    const std::vector<Eigen::Vector2d> truth = ProjectedTruth(target, camera, T).pixels;
    const Detection with = DetectTarget(image, target, {}, camera);
    const Detection without = DetectTarget(image, target);
    ASSERT_TRUE(with.usable()) << with.message;
    ASSERT_TRUE(without.usable()) << without.message;
    const double outward_with = hecal::testing::MeanOutwardOffset(with, truth);
    const double outward_without = hecal::testing::MeanOutwardOffset(without, truth);
    std::cout << name << ": outward " << outward_with << " px with the camera, " << outward_without
              << " px without\n";
    EXPECT_LT(std::abs(outward_with), 0.01) << name;
    if (target.type == pose::TargetType::kArucoGrid ||
        target.type == pose::TargetType::kAprilTagGrid) {
      EXPECT_GT(outward_without, 0.06) << name;
    } else {
      ASSERT_EQ(with.num_points(), without.num_points()) << name;
      for (int k = 0; k < with.num_points(); ++k) {
        EXPECT_EQ(with.points[static_cast<size_t>(k)].pixel,
                  without.points[static_cast<size_t>(k)].pixel)
            << name;
      }
    }
  }
}

// A camera model with no preimage at the markers (a strong barrel model beyond its fold, here
// with the principal point far outside the image; pose::Undistort fails): the markers are refined
// in pixels, exactly as without the camera, rather than left unrefined.
TEST(DetectTarget, MarkersTheCameraCannotUndistortAreRefinedInPixels) {
  const pose::TargetSpec target = ArucoGrid();
  const Pose T = FrontalView(target, 0.5, 10.0, -10.0, 5.0);
  const cv::Mat image = RenderAt(target, T);
  pose::CameraModel folded = DetectionCamera();
  folded.cx = -1000.0;
  folded.distortion = {-2.0, 0.0, 0.0, 0.0, 0.0};
  ASSERT_FALSE(pose::Undistort(folded, Eigen::Vector2d(0.0, 0.0)).has_value());
  const Detection with = DetectTarget(image, target, {}, folded);
  const Detection without = DetectTarget(image, target);
  ASSERT_EQ(with.status, DetectionStatus::kFound) << with.message;
  ASSERT_EQ(with.num_points(), without.num_points());
  for (int k = 0; k < with.num_points(); ++k) {
    EXPECT_EQ(with.points[static_cast<size_t>(k)].pixel,
              without.points[static_cast<size_t>(k)].pixel);
  }
  EXPECT_LT(CompareWithTruth(with, ProjectedTruth(target, DetectionCamera(), T).pixels).max, 0.1);
}

// Half of a ChArUco board hidden: a partial detection whose ids are exactly the visible
// corners, each at its true position.
TEST(DetectTarget, PartialCharucoReportsTheVisibleCornersWithTheirIds) {
  const pose::TargetSpec target = Charuco();
  const Pose T = FrontalView(target, 0.45, 0.0, 0.0, 0.0);
  cv::Mat image = RenderAt(target, T);
  const std::vector<Eigen::Vector2d> truth = ProjectedTruth(target, DetectionCamera(), T).pixels;
  const double cut = 0.5 * (truth[2].x() + truth[3].x());  // between corner columns 2 and 3
  image.colRange(static_cast<int>(cut), image.cols).setTo(cv::Scalar(235));
  const Detection detection = DetectTarget(image, target);
  ASSERT_EQ(detection.status, DetectionStatus::kPartial) << detection.message;
  EXPECT_LT(detection.num_points(), detection.total_points);
  EXPECT_GE(detection.num_points(), 4);
  for (const ImagePoint& p : detection.points) {
    EXPECT_LT(truth[static_cast<size_t>(p.id)].x(), cut) << "id " << p.id;
  }
  EXPECT_LT(CompareWithTruth(detection, truth).max, 0.08);
  EXPECT_EQ(detection.order, PointOrder::kMarkers);
}

TEST(DetectTarget, PartialDetectionsFollowTheOptions) {
  const pose::TargetSpec target = ArucoGrid();
  const Pose T = FrontalView(target, 0.5, 0.0, 0.0, 0.0);
  cv::Mat image = RenderAt(target, T);
  // Keep only the top-left marker (4 points).
  const std::vector<Eigen::Vector2d> truth = ProjectedTruth(target, DetectionCamera(), T).pixels;
  const int right = static_cast<int>(0.5 * (truth[1].x() + truth[4].x()));
  const int bottom = static_cast<int>(0.5 * (truth[3].y() + truth[4 * target.cols].y()));
  image.colRange(right, image.cols).setTo(cv::Scalar(235));
  image.rowRange(bottom, image.rows).setTo(cv::Scalar(235));

  const Detection four = DetectTarget(image, target);
  ASSERT_EQ(four.status, DetectionStatus::kPartial) << four.message;
  EXPECT_EQ(four.num_points(), 4);
  EXPECT_NE(four.message.find("weak pose"), std::string::npos) << four.message;

  DetectOptions more;
  more.min_points = 5;
  EXPECT_EQ(DetectTarget(image, target, more).status, DetectionStatus::kNotFound);
  DetectOptions whole;
  whole.allow_partial = false;
  EXPECT_EQ(DetectTarget(image, target, whole).status, DetectionStatus::kNotFound);
}

// Only the top row of a ChArUco board's corners can be interpolated: 6 points on one line give
// no pose, so the detection is not_found.
TEST(DetectTarget, CollinearPartialDetectionIsRejected) {
  pose::TargetSpec target = Charuco();
  target.rows = 3;
  const Pose T = FrontalView(target, 0.45, 0.0, 0.0, 0.0);
  cv::Mat image = RenderAt(target, T);
  const std::vector<Eigen::Vector2d> truth = ProjectedTruth(target, DetectionCamera(), T).pixels;
  const int cut = static_cast<int>(truth[static_cast<size_t>(target.cols - 1)].y() + 8.0);
  image.rowRange(cut, image.rows).setTo(cv::Scalar(235));
  const Detection detection = DetectTarget(image, target);
  EXPECT_EQ(detection.status, DetectionStatus::kNotFound) << detection.message;
  EXPECT_NE(detection.message.find("one line"), std::string::npos) << detection.message;
}

// A second copy of one marker: which one belongs to the board cannot be told, so that id is
// dropped and named; the other markers are used.
TEST(DetectTarget, RepeatedMarkerIdsAreDroppedAndNamed) {
  const pose::TargetSpec target = ArucoGrid();
  const Pose T = FrontalView(target, 0.6, 0.0, 0.0, 0.0);
  cv::Mat image = RenderAt(target, T);
  const std::vector<Eigen::Vector2d> truth = ProjectedTruth(target, DetectionCamera(), T).pixels;
  const int quiet = 12;  // px of white paper copied around the marker
  const cv::Rect marker(static_cast<int>(truth[0].x()) - quiet,
                        static_cast<int>(truth[0].y()) - quiet,
                        static_cast<int>(truth[1].x() - truth[0].x()) + 2 * quiet + 1,
                        static_cast<int>(truth[3].y() - truth[0].y()) + 2 * quiet + 1);
  image(marker).copyTo(image(marker + cv::Point(0, 300)));  // below the board, on the background
  const Detection detection = DetectTarget(image, target);
  ASSERT_EQ(detection.status, DetectionStatus::kPartial) << detection.message;
  EXPECT_EQ(detection.num_points(), detection.total_points - 4);
  for (const ImagePoint& p : detection.points) EXPECT_GE(p.id, 4);
  EXPECT_NE(detection.message.find("dropped: " + std::to_string(target.first_id)),
            std::string::npos)
      << detection.message;
}

TEST(DetectTarget, EmptyBoardIsNotFoundWithAReason) {
  const cv::Mat blank(480, 640, CV_8U, cv::Scalar(200));
  for (const pose::TargetSpec& target :
       {Chessboard(), Charuco(), ArucoGrid(), AprilTagGrid(), Circles(), AsymmetricCircles()}) {
    const Detection detection = DetectTarget(blank, target);
    EXPECT_EQ(detection.status, DetectionStatus::kNotFound) << pose::TargetTypeName(target.type);
    EXPECT_TRUE(detection.points.empty());
    EXPECT_FALSE(detection.message.empty());
    EXPECT_FALSE(detection.usable());
  }
}

TEST(DetectTarget, ColourImagesAreConvertedToGrey) {
  const pose::TargetSpec target = Charuco();
  const Pose T = FrontalView(target, 0.45, 10.0, 0.0, 0.0);
  cv::Mat colour;
  cv::cvtColor(RenderAt(target, T), colour, cv::COLOR_GRAY2BGR);
  const Detection detection = DetectTarget(colour, target);
  ASSERT_EQ(detection.status, DetectionStatus::kFound) << detection.message;
  EXPECT_LT(CompareWithTruth(detection, ProjectedTruth(target, DetectionCamera(), T).pixels).max,
            0.08);
}

// Sharpness is an edge width: about 2.5σ for a Gaussian blur of σ px, for OpenCV's chessboard
// measure and for hecal's gradient measure alike, and it grows with the blur.
TEST(DetectTarget, SharpnessIsTheEdgeWidthInPixels) {
  for (const pose::TargetSpec& target :
       {Chessboard(), Charuco(), ArucoGrid(), AsymmetricCircles()}) {
    const Pose T = FrontalView(target, 0.45, 10.0, -10.0, 5.0);
    double previous = 0.0;
    for (const double sigma : {1.0, 2.0}) {
      RenderOptions render;
      render.blur_sigma = sigma;
      const Detection detection =
          DetectTarget(RenderTarget(target, DetectionCamera(), T, render), target);
      ASSERT_TRUE(detection.usable()) << detection.message;
      std::cout << pose::TargetTypeName(target.type) << " σ " << sigma << ": sharpness "
                << detection.sharpness << " px\n";
      EXPECT_GT(detection.sharpness, 1.8 * sigma) << pose::TargetTypeName(target.type);
      EXPECT_LT(detection.sharpness, 3.4 * sigma) << pose::TargetTypeName(target.type);
      EXPECT_GT(detection.sharpness, previous);
      previous = detection.sharpness;
    }
  }
}

TEST(DetectTarget, RejectsUnusableInput) {
  const cv::Mat image(480, 640, CV_8U, cv::Scalar(200));
  EXPECT_THROW(DetectTarget(cv::Mat(), Chessboard()), InputError);
  EXPECT_THROW(DetectTarget(cv::Mat(480, 640, CV_16U, cv::Scalar(0)), Chessboard()), InputError);
  pose::TargetSpec square = Chessboard();
  square.rows = square.cols;
  EXPECT_THROW(DetectTarget(image, square), InputError);
  pose::TargetSpec no_dictionary = Charuco();
  no_dictionary.dictionary = "DICT_9X9_1";
  EXPECT_THROW(DetectTarget(image, no_dictionary), InputError);
  DetectOptions options;
  options.min_points = 3;
  EXPECT_THROW(DetectTarget(image, Chessboard(), options), InputError);
  // The camera: positive focal lengths, finite values, and the image's size when it has one.
  const auto camera_error = [&image](const pose::CameraModel& camera) {
    try {
      DetectTarget(image, ArucoGrid(), {}, camera);
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "camera");
      return e.problem();
    }
    ADD_FAILURE() << "no error";
    return std::string();
  };
  pose::CameraModel camera = DetectionCamera();  // 800 x 600, the image is 640 x 480
  EXPECT_NE(camera_error(camera).find("for 800x600 images but the image is 640x480"),
            std::string::npos);
  camera.width = camera.height = 0;
  camera.fx = 0.0;
  EXPECT_NE(camera_error(camera).find("fx, fy must be positive"), std::string::npos);
  camera.fx = 700.0;
  camera.distortion[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(camera_error(camera).find("every value finite"), std::string::npos);
  options = {};
  options.apriltag_max_hamming = 3;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("apriltag_max_hamming"), std::string::npos);
}

TEST(DetectTarget, NamesOfStatusesAndOrders) {
  EXPECT_EQ(DetectionStatusName(DetectionStatus::kFound), "found");
  EXPECT_EQ(DetectionStatusName(DetectionStatus::kPartial), "partial");
  EXPECT_EQ(DetectionStatusName(DetectionStatus::kNotFound), "not_found");
  EXPECT_EQ(DetectionStatusName(DetectionStatus::kAmbiguous), "ambiguous");
  EXPECT_EQ(PointOrderName(PointOrder::kMarkers), "markers");
  EXPECT_EQ(PointOrderName(PointOrder::kConsistency), "consistency");
}

TEST(DetectOptions, IsValidNamesTheField) {
  using hecal::testing::RefusesNaming;
  const DetectOptions defaults;
  EXPECT_TRUE(hecal::testing::IsValidOptions(defaults));
  EXPECT_TRUE(
      RefusesNaming(defaults, "DetectOptions.min_points", [](auto& o) { o.min_points = 3; }));
  EXPECT_TRUE(RefusesNaming(defaults, "DetectOptions.apriltag_max_hamming",
                            [](auto& o) { o.apriltag_max_hamming = 3; }));
  EXPECT_TRUE(RefusesNaming(defaults, "DetectOptions.apriltag_decimate",
                            [](auto& o) { o.apriltag_decimate = 0.5; }));
}

}  // namespace
}  // namespace hecal::vision
