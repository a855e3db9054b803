// RenderTarget: the printed pattern against OpenCV's own board drawings, the area-exactness that
// makes rendered corners unbiased, the noise model, and input checks.
#include "hecal/vision/render.h"

#include <gtest/gtest.h>

#include <limits>
#include <opencv2/aruco/charuco.hpp>
#include <opencv2/imgproc.hpp>

#include "hecal/core/error.h"
#include "testing/detection_errors.h"
#include "testing/options_validity.h"
#include "testing/rendered_scene.h"

namespace hecal::vision {
namespace {

// A camera looking straight at the board's plane so that board point (x, y) lands on pixel
// (x, y) / metres_per_pixel − ½: pixel (i, j) covers the board square
// [i, i + 1) × [j, j + 1) × metres_per_pixel, as cv::aruco's draw() maps pixels.
struct PixelAlignedView {
  pose::CameraModel camera;
  Pose T_camera_target;
};

PixelAlignedView Frontal(int width, int height, double metres_per_pixel) {
  PixelAlignedView view;
  constexpr double kDistance = 1.0;
  view.camera.fx = view.camera.fy = kDistance / metres_per_pixel;
  view.camera.cx = view.camera.cy = -0.5;
  view.camera.width = width;
  view.camera.height = height;
  view.T_camera_target =
      MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, kDistance));
  return view;
}

double FractionDiffering(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat difference;
  cv::absdiff(a, b, difference);
  return static_cast<double>(cv::countNonZero(difference > 64)) / static_cast<double>(a.total());
}

RenderOptions BlackAndWhite() {
  RenderOptions options;
  options.black = 0.0;
  options.white = 255.0;
  options.margin = 0.0;
  return options;
}

// OpenCV 4.6's CharucoBoard::draw: the same picture, pixel for pixel (up to boundary pixels of
// OpenCV's resampled markers). Lengths are binary fractions (pixel 2^-14 m, square 128 px,
// marker 98 px = 7 cells of 14 px) so that OpenCV's float arithmetic rounds no size.
TEST(RenderTarget, CharucoMatchesOpenCvDrawing) {
  constexpr double kPixel = 1.0 / 16384.0;
  pose::TargetSpec target{.type = pose::TargetType::kCharuco,
                          .cols = 5,
                          .rows = 4,
                          .square = 128 * kPixel,
                          .marker = 98 * kPixel,
                          .dictionary = "DICT_5X5_100"};
  const PixelAlignedView view = Frontal(640, 512, kPixel);
  const cv::Mat ours = RenderTarget(target, view.camera, view.T_camera_target, BlackAndWhite());
  const cv::Ptr<cv::aruco::CharucoBoard> board = cv::aruco::CharucoBoard::create(
      5, 4, static_cast<float>(target.square), static_cast<float>(target.marker),
      cv::aruco::getPredefinedDictionary(cv::aruco::DICT_5X5_100));
  cv::Mat theirs;
  board->draw(cv::Size(640, 512), theirs, 0, 1);
  EXPECT_LT(FractionDiffering(ours, theirs), 0.002);
}

TEST(RenderTarget, ArucoGridMatchesOpenCvDrawing) {
  pose::TargetSpec target;
  target.type = pose::TargetType::kArucoGrid;
  target.cols = 4;
  target.rows = 3;
  target.marker = 0.006;   // 60 px = 6 cells of 10 px
  target.spacing = 0.002;  // 20 px
  target.dictionary = "DICT_4X4_250";
  target.first_id = 30;
  const PixelAlignedView view = Frontal(300, 220, 1e-4);
  const cv::Mat ours = RenderTarget(target, view.camera, view.T_camera_target, BlackAndWhite());
  const cv::Ptr<cv::aruco::GridBoard> board = cv::aruco::GridBoard::create(
      4, 3, 0.006f, 0.002f, cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_250), 30);
  cv::Mat theirs;
  board->draw(cv::Size(300, 220), theirs, 0, 1);
  EXPECT_LT(FractionDiffering(ours, theirs), 0.002);
}

// A single ArUco marker is centred on the target origin (pose/target.h): seen frontally with the
// tag's top-left corner on pixel corner (0, 0), it is OpenCV's drawMarker, pixel for pixel.
TEST(RenderTarget, SingleArucoMarkerMatchesOpenCvDrawing) {
  pose::TargetSpec target{.type = pose::TargetType::kAruco, .dictionary = "DICT_4X4_250", .id = 17};
  constexpr double kPixel = 1e-4;
  target.size = 60 * kPixel;  // 6 cells of 10 px
  PixelAlignedView view = Frontal(60, 60, kPixel);
  view.T_camera_target.translation() += Eigen::Vector3d(target.size / 2, target.size / 2, 0.0);
  const cv::Mat ours = RenderTarget(target, view.camera, view.T_camera_target, BlackAndWhite());
  cv::Mat theirs;
  cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_250)->drawMarker(17, 60, theirs, 1);
  EXPECT_EQ(FractionDiffering(ours, theirs), 0.0);
}

// Area-exactness: the imaged amount of black (Σ (white − I) / (white − black) over the board)
// equals the area of the projected black squares, so edges sit where they should. A dilation of
// the black by δ px would add δ × the squares' perimeter (here ~2000 px): the tolerance, 1 px²,
// bounds δ at 0.0005 px.
TEST(RenderTarget, ImagedBlackAreaEqualsProjectedArea) {
  pose::TargetSpec target{
      .type = pose::TargetType::kChessboard, .cols = 3, .rows = 2, .square = 0.06};
  pose::CameraModel camera = hecal::testing::DetectionCamera();
  camera.distortion = {0.0, 0.0, 0.0, 0.0, 0.0};  // straight edges: the squares are quadrilaterals
  const double s = target.square;
  for (const Pose& T : {hecal::testing::FrontalView(target, 0.5, 0.0, 0.0, 0.0),
                        hecal::testing::FrontalView(target, 0.5, -15.0, 20.0, -25.0)}) {
    RenderOptions options;
    options.black = 0.0;
    options.white = 255.0;
    options.supersampling = 32;  // sampling noise of the edge pixels' areas: ~0.2 px² in all
    const cv::Mat image = RenderTarget(target, camera, T, options);
    const auto project = [&](double x, double y) {
      const Eigen::Vector2d p = pose::Project(camera, T * Eigen::Vector3d(x, y, 0.0));
      return cv::Point2f(static_cast<float>(p.x()), static_cast<float>(p.y()));
    };
    // Board and half of its white margin: every pixel there is pattern or paper.
    const std::vector<cv::Point2f> region = {project(-1.5 * s, -1.5 * s),
                                             project(3.5 * s, -1.5 * s), project(3.5 * s, 2.5 * s),
                                             project(-1.5 * s, 2.5 * s)};
    double black = 0.0;
    for (int v = 0; v < image.rows; ++v) {
      for (int u = 0; u < image.cols; ++u) {
        if (cv::pointPolygonTest(region, cv::Point2f(static_cast<float>(u), static_cast<float>(v)),
                                 false) > 0) {
          black += (255.0 - image.at<uchar>(v, u)) / 255.0;
        }
      }
    }
    double area = 0.0;
    for (int i = 0; i <= target.cols; ++i) {
      for (int j = 0; j <= target.rows; ++j) {
        if ((i + j) % 2 != 0) continue;  // square (i, j) is black iff i + j is even
        const double x0 = (i - 1) * s, y0 = (j - 1) * s;
        area += cv::contourArea(std::vector<cv::Point2f>{
            project(x0, y0), project(x0 + s, y0), project(x0 + s, y0 + s), project(x0, y0 + s)});
      }
    }
    EXPECT_NEAR(black, area, 1.0);
  }
}

// The same area test for a disc: its imaged dark area equals the area of the projected circle.
TEST(RenderTarget, CirclesHaveTheirProjectedArea) {
  pose::TargetSpec target{.type = pose::TargetType::kCircles, .cols = 3, .rows = 2, .square = 0.1};
  pose::CameraModel camera = hecal::testing::DetectionCamera();
  const Pose T = hecal::testing::FrontalView(target, 0.6, 20.0, 0.0, 0.0);
  RenderOptions options;
  options.black = 0.0;
  options.white = 255.0;
  const cv::Mat image = RenderTarget(target, camera, T, options);
  const double radius = options.circle_radius * target.square;
  std::vector<cv::Point2f> outline;
  for (int k = 0; k < 720; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 720.0;
    const Eigen::Vector2d p =
        pose::Project(camera, T * Eigen::Vector3d(radius * std::cos(a), radius * std::sin(a), 0.0));
    outline.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
  }
  const cv::Rect box = cv::boundingRect(outline) + cv::Size(8, 8) - cv::Point(4, 4);
  double dark = 0.0;
  for (int v = box.y; v < box.y + box.height; ++v) {
    for (int u = box.x; u < box.x + box.width; ++u) dark += (255.0 - image.at<uchar>(v, u)) / 255.0;
  }
  EXPECT_NEAR(dark, cv::contourArea(outline), 0.002 * cv::contourArea(outline));
}

// Background only (the board out of view): mean and spread are the background and noise_sigma;
// the same seed gives the same image, another seed another one.
TEST(RenderTarget, NoiseIsGaussianAndSeeded) {
  pose::TargetSpec target{
      .type = pose::TargetType::kChessboard, .cols = 5, .rows = 4, .square = 0.02};
  const Pose away = MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(5.0, 0.0, 1.0));
  RenderOptions options;
  options.noise_sigma = 4.0;
  options.background = 100.0;
  const cv::Mat a = RenderTarget(target, hecal::testing::DetectionCamera(), away, options);
  cv::Scalar mean, deviation;
  cv::meanStdDev(a, mean, deviation);
  EXPECT_NEAR(mean[0], 100.0, 0.1);
  EXPECT_NEAR(deviation[0], std::sqrt(16.0 + 1.0 / 12.0), 0.1);  // plus 8-bit rounding
  EXPECT_EQ(
      cv::countNonZero(a != RenderTarget(target, hecal::testing::DetectionCamera(), away, options)),
      0);
  options.seed = 2;
  EXPECT_GT(
      cv::countNonZero(a != RenderTarget(target, hecal::testing::DetectionCamera(), away, options)),
      0);
}

TEST(RenderTarget, RejectsImpossibleRequests) {
  pose::TargetSpec target{
      .type = pose::TargetType::kChessboard, .cols = 5, .rows = 4, .square = 0.02};
  const pose::CameraModel camera = hecal::testing::DetectionCamera();
  const Pose behind = MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, -0.5));
  EXPECT_THROW(RenderTarget(target, camera, behind), InputError);
  const Pose in_front = hecal::testing::FrontalView(target, 0.5, 0.0, 0.0, 0.0);
  RenderOptions options;
  options.circle_radius = 0.6;
  EXPECT_THROW(RenderTarget(target, camera, in_front, options), InputError);
  pose::CameraModel no_size = camera;
  no_size.width = no_size.height = 0;
  EXPECT_THROW(RenderTarget(target, no_size, in_front), InputError);
  // AprilTags whose data bits lie outside the border (tagStandard41h12) need room between them.
  pose::TargetSpec tags{.type = pose::TargetType::kAprilTagGrid,
                        .cols = 2,
                        .rows = 2,
                        .marker = 0.05,
                        .spacing = 0.001,
                        .family = "tagStandard41h12"};
  EXPECT_THROW(RenderTarget(tags, camera, hecal::testing::FrontalView(tags, 0.5, 0.0, 0.0, 0.0)),
               InputError);
  pose::TargetSpec bad = target;
  bad.square = -1.0;
  EXPECT_THROW(RenderTarget(bad, camera, in_front), InputError);
}

TEST(RenderOptions, IsValidNamesTheField) {
  using hecal::testing::RefusesNaming;
  const RenderOptions defaults;
  EXPECT_TRUE(hecal::testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "RenderOptions.size", [](auto& o) { o.height = -1; }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "RenderOptions.blur_sigma", [](auto& o) { o.blur_sigma = -1; }));
  EXPECT_TRUE(RefusesNaming(defaults, "RenderOptions.noise_sigma", [](auto& o) {
    o.noise_sigma = std::numeric_limits<double>::infinity();
  }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "RenderOptions.background", [](auto& o) { o.background = 256; }));
  EXPECT_TRUE(RefusesNaming(defaults, "RenderOptions.black", [](auto& o) { o.black = -1; }));
  EXPECT_TRUE(RefusesNaming(defaults, "RenderOptions.white", [](auto& o) { o.white = 300; }));
  EXPECT_TRUE(RefusesNaming(defaults, "RenderOptions.margin", [](auto& o) { o.margin = -0.5; }));
  EXPECT_TRUE(RefusesNaming(defaults, "RenderOptions.circle_radius",
                            [](auto& o) { o.circle_radius = 0.5; }));
  EXPECT_TRUE(RefusesNaming(defaults, "RenderOptions.supersampling",
                            [](auto& o) { o.supersampling = 65; }));
}

}  // namespace
}  // namespace hecal::vision
