// Feature matching (vision/feature_matches.h) on a synthetic textured pair: a plane covered with
// blurred noise, seen by a camera and by a second camera moved by a known (R, t); the second image
// is the first warped by the plane's homography H = K (R + t nᵀ/d) K⁻¹. Every returned pair must
// satisfy the true epipolar constraint, and unrelated images must be refused. SIFT keypoints are
// checked against mirror symmetry.
#include "hecal/vision/feature_matches.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgproc.hpp>

#include "hecal/core/error.h"
#include "testing/options_validity.h"

namespace hecal::vision {
namespace {

constexpr int kWidth = 640, kHeight = 480;
constexpr double kFocal = 500.0;

pose::CameraModel Camera() {
  pose::CameraModel camera;
  camera.fx = camera.fy = kFocal;
  camera.cx = (kWidth - 1) / 2.0;
  camera.cy = (kHeight - 1) / 2.0;
  camera.width = kWidth;
  camera.height = kHeight;
  return camera;
}

cv::Mat Texture(int seed) {
  cv::Mat noise(kHeight, kWidth, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::Mat texture;
  cv::GaussianBlur(noise, texture, cv::Size(0, 0), 2.0);
  cv::normalize(texture, texture, 0, 255, cv::NORM_MINMAX);
  return texture;
}

struct Pair {
  cv::Mat first, second;
  Eigen::Matrix3d R;  // x_second = R x_first + t
  Eigen::Vector3d t;
};

// The plane z = 2 (first camera frame) seen from a camera turned by 8° and moved by 0.3 m.
Pair PlanePair() {
  Pair pair;
  pair.R = Eigen::AngleAxisd(8.0 * M_PI / 180.0, Eigen::Vector3d(0.2, 1.0, 0.1).normalized())
               .toRotationMatrix();
  pair.t = Eigen::Vector3d(-0.3, 0.05, 0.1);
  const Eigen::Vector3d n(0.0, 0.0, 1.0);
  const double d = 2.0;
  Eigen::Matrix3d K;
  K << kFocal, 0, Camera().cx, 0, kFocal, Camera().cy, 0, 0, 1;
  const Eigen::Matrix3d H = K * (pair.R + pair.t * n.transpose() / d) * K.inverse();
  cv::Mat H_cv;
  cv::eigen2cv(H, H_cv);
  pair.first = Texture(7);
  cv::warpPerspective(pair.first, pair.second, H_cv, pair.first.size(), cv::INTER_LINEAR);
  return pair;
}

TEST(FeatureMatches, PairsSatisfyTheTrueEpipolarConstraint) {
  const Pair pair = PlanePair();
  FeatureMatchOptions options;
  options.max_matches = 60;
  const ImageFeatures first = DetectFeatures(pair.first), second = DetectFeatures(pair.second);
  const std::vector<FeatureMatch> matches =
      MatchFeatures(first, second, Camera(), options, "first.png", "second.png");
  // Without the cap: the RANSAC inliers of a well-textured pair number in the hundreds.
  FeatureMatchOptions all = options;
  all.max_matches = 100000;
  const int inliers =
      int(MatchFeatures(first, second, Camera(), all, "first.png", "second.png").size());
  EXPECT_GE(inliers, 300);
  ASSERT_EQ(int(matches.size()), options.max_matches);
  int cells_hit[8][8] = {};
  for (const FeatureMatch& m : matches) {
    EXPECT_NEAR(m.first_ray.norm(), 1.0, 1e-12);
    EXPECT_NEAR(m.second_ray.norm(), 1.0, 1e-12);
    // The angle of the second ray to the epipolar plane span(t, R v): within the threshold
    // 4√2 · 0.5 px / f (keypoints are located to a fraction of a pixel).
    const Eigen::Vector3d normal = pair.t.cross(pair.R * m.first_ray).normalized();
    EXPECT_LT(std::abs(std::asin(normal.dot(m.second_ray))), 4.0 * std::sqrt(2.0) * 0.5 / kFocal);
    // The pixels agree with the homography to 2 px (no wrong match on the plane).
    const Eigen::Vector3d x(m.first_ray / m.first_ray.z());
    const Eigen::Vector3d y = pair.R * x * 2.0 + pair.t;
    EXPECT_NEAR(kFocal * y.x() / y.z() + Camera().cx, m.second_pixel.x(), 2.0);
    EXPECT_NEAR(kFocal * y.y() / y.z() + Camera().cy, m.second_pixel.y(), 2.0);
    ++cells_hit[int(m.first_pixel.y() / kHeight * 8)][int(m.first_pixel.x() / kWidth * 8)];
  }
  // Spread: the matches fall in at least half of an 8 × 8 grid's cells.
  int occupied = 0;
  for (const auto& row : cells_hit) {
    for (int c : row) occupied += c > 0;
  }
  EXPECT_GE(occupied, 32);
}

TEST(FeatureMatches, OrbPairsSatisfyTheTrueEpipolarConstraint) {
  const Pair pair = PlanePair();
  FeatureMatchOptions options;
  options.kind = FeatureKind::kOrb;
  options.max_matches = 100000;
  const ImageFeatures first = DetectFeatures(pair.first, 8000, FeatureKind::kOrb);
  const ImageFeatures second = DetectFeatures(pair.second, 8000, FeatureKind::kOrb);
  ASSERT_EQ(first.descriptors.depth(), CV_8U);  // binary: matched by Hamming distance
  const std::vector<FeatureMatch> matches =
      MatchFeatures(first, second, Camera(), options, "first.png", "second.png");
  EXPECT_GE(int(matches.size()), 100);
  for (const FeatureMatch& m : matches) {
    const Eigen::Vector3d normal = pair.t.cross(pair.R * m.first_ray).normalized();
    // Within the threshold of the RANSAC essential matrix, which ORB's coarse keypoints (below)
    // put off the true one: twice the threshold of the true epipolar plane.
    EXPECT_LT(std::abs(std::asin(normal.dot(m.second_ray))), 8.0 * std::sqrt(2.0) * 0.5 / kFocal);
    // ORB keypoints lie on the pixel grid of their pyramid level (no sub-pixel refinement;
    // 1.2⁷ ≈ 3.6 px at the coarsest of its 8 levels), and both of a pair are off: the
    // homography to 5 px, which still tells a wrong match (another point of the texture) from
    // a right one.
    const Eigen::Vector3d x(m.first_ray / m.first_ray.z());
    const Eigen::Vector3d y = pair.R * x * 2.0 + pair.t;
    EXPECT_NEAR(kFocal * y.x() / y.z() + Camera().cx, m.second_pixel.x(), 5.0);
    EXPECT_NEAR(kFocal * y.y() / y.z() + Camera().cy, m.second_pixel.y(), 5.0);
  }
}

// A detector that finds the point at (x, y) in an image must find it at (W − 1 − x, H − 1 − y)
// in the image turned by 180° (OpenCV's pixel-centre coordinates). Mapped back, the keypoints
// of the two detections agree on average within 0.02 px per axis (OpenCV's own SIFT keypoints,
// 0.25 px off, are 0.5 px apart this way).
TEST(DetectFeatures, SiftKeypointsAreWhereTheImageTurnedBy180DegreesPutsThem) {
  const cv::Mat image = Texture(11);
  cv::Mat turned;
  cv::flip(image, turned, -1);
  const ImageFeatures a = DetectFeatures(image);
  const ImageFeatures b = DetectFeatures(turned);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int n = 0;
  for (const cv::KeyPoint& kb : b.keypoints) {
    const Eigen::Vector2d back(kWidth - 1 - kb.pt.x, kHeight - 1 - kb.pt.y);
    for (const cv::KeyPoint& ka : a.keypoints) {
      const Eigen::Vector2d d = back - Eigen::Vector2d(ka.pt.x, ka.pt.y);
      if (d.norm() < 0.75 && std::abs(ka.size - kb.size) < 0.05 * ka.size) {
        sum += d;
        ++n;
        break;
      }
    }
  }
  ASSERT_GT(n, 100);
  EXPECT_LT(std::abs(sum.x() / n), 0.02) << n << " keypoints";
  EXPECT_LT(std::abs(sum.y() / n), 0.02) << n << " keypoints";
}

TEST(FeatureMatches, UnrelatedImagesAreRefusedNamingBoth) {
  try {
    MatchFeatures(DetectFeatures(Texture(1)), DetectFeatures(Texture(2)), Camera(), {}, "a.png",
                  "b.png");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("b.png"), std::string::npos) << e.what();
  }
}

TEST(FeatureMatchOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const FeatureMatchOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "FeatureMatchOptions.ratio", [](auto& o) { o.ratio = 1.5; }));
  EXPECT_TRUE(RefusesNaming(defaults, "FeatureMatchOptions.pixel_sigma",
                            [](auto& o) { o.pixel_sigma = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "FeatureMatchOptions.min_matches",
                            [](auto& o) { o.min_matches = 4; }));
  EXPECT_TRUE(RefusesNaming(defaults, "FeatureMatchOptions.max_matches",
                            [](auto& o) { o.max_matches = 7; }));
}

}  // namespace
}  // namespace hecal::vision
