// The canonical point order of grid targets (order_consistency.h): per image from the pattern's
// own asymmetry, and across images for 180°-symmetric patterns. Truth: rendered views at known
// poses (render.h), where the true id of every pixel is known. Real images:
// order_consistency_kuka2_test (2 views) and order_consistency_kuka2_slow_test (all 28).
#include "hecal/vision/order_consistency.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "hecal/core/error.h"
#include "hecal/vision/render.h"
#include "testing/detection_errors.h"
#include "testing/options_validity.h"
#include "testing/rendered_scene.h"

namespace hecal::vision {
namespace {

using hecal::testing::CompareWithTruth;
using hecal::testing::DetectionCamera;
using hecal::testing::FrontalView;
using hecal::testing::ProjectedTruth;

pose::TargetSpec SymmetricCircles() {
  return {.type = pose::TargetType::kCircles, .cols = 7, .rows = 5, .square = 0.035};
}

cv::Mat Render(const pose::TargetSpec& target, const Pose& T) {
  RenderOptions render;
  render.blur_sigma = 0.7;
  return RenderTarget(target, DetectionCamera(), T, render);
}

std::vector<cv::Point2f> ToGrid(const std::vector<Eigen::Vector2d>& pixels) {
  std::vector<cv::Point2f> grid;
  for (const Eigen::Vector2d& p : pixels)
    grid.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
  return grid;
}

double GridError(const std::vector<cv::Point2f>& grid, const std::vector<Eigen::Vector2d>& truth) {
  double worst = 0.0;
  for (size_t k = 0; k < grid.size(); ++k) {
    worst = std::max(worst, std::hypot(grid[k].x - truth[k].x(), grid[k].y - truth[k].y()));
  }
  return worst;
}

// A detector may start from any corner. For a 9 × 6 chessboard (cols + rows odd) every one of the
// four labellings of the grid — as given, turned by a half turn, mirrored along x or along y — is
// brought back to the true order by handedness and square colours.
TEST(CanonicalGridOrder, ChessboardWithOddSumIsUniqueFromAnyStartingCorner) {
  const pose::TargetSpec target = hecal::testing::Chessboard(9, 6, 0.03);
  for (const double roll : {0.0, 75.0, 160.0, 250.0}) {
    const Pose T = FrontalView(target, 0.45, 15.0, -10.0, roll);
    const cv::Mat image = Render(target, T);
    const std::vector<Eigen::Vector2d> truth = ProjectedTruth(target, DetectionCamera(), T).pixels;
    const std::vector<cv::Point2f> canonical = ToGrid(truth);
    std::vector<std::vector<cv::Point2f>> labellings(4, canonical);
    std::reverse(labellings[1].begin(), labellings[1].end());
    for (int r = 0; r < target.rows; ++r) {
      std::reverse(labellings[2].begin() + r * target.cols,
                   labellings[2].begin() + (r + 1) * target.cols);
    }
    for (int r = 0; r < target.rows; ++r) {
      std::copy(canonical.begin() + r * target.cols, canonical.begin() + (r + 1) * target.cols,
                labellings[3].begin() + (target.rows - 1 - r) * target.cols);
    }
    for (size_t k = 0; k < labellings.size(); ++k) {
      std::vector<cv::Point2f> grid = labellings[k];
      EXPECT_EQ(CanonicalGridOrder(image, target, &grid), GridOrder::kUnique)
          << "roll " << roll << ", labelling " << k;
      EXPECT_LT(GridError(grid, truth), 1e-3) << "roll " << roll << ", labelling " << k;
    }
  }
}

// Without readable square colours (a flat image) the rule does not guess: symmetric.
TEST(CanonicalGridOrder, UnreadableColoursAreNotGuessed) {
  const pose::TargetSpec target = hecal::testing::Chessboard(9, 6, 0.03);
  const Pose T = FrontalView(target, 0.45, 0.0, 0.0, 0.0);
  std::vector<cv::Point2f> grid = ToGrid(ProjectedTruth(target, DetectionCamera(), T).pixels);
  const cv::Mat flat(600, 800, CV_8U, cv::Scalar(128));
  EXPECT_EQ(CanonicalGridOrder(flat, target, &grid), GridOrder::kSymmetric);
}

TEST(CanonicalGridOrder, DegenerateGridsAreInvalid) {
  const pose::TargetSpec target = hecal::testing::Chessboard(9, 6, 0.03);
  const cv::Mat flat(600, 800, CV_8U, cv::Scalar(128));
  std::vector<cv::Point2f> line;
  for (int k = 0; k < 54; ++k) line.emplace_back(10.0f + k, 20.0f + 2.0f * k);
  EXPECT_EQ(CanonicalGridOrder(flat, target, &line), GridOrder::kInvalid);
  std::vector<cv::Point2f> short_grid(10, cv::Point2f(1.0f, 1.0f));
  EXPECT_EQ(CanonicalGridOrder(flat, target, &short_grid), GridOrder::kInvalid);
}

// The synthetic image turned by 180° in-plane: the same physical corners get the same ids (each
// moves to (W − 1 − u, H − 1 − v)), whichever corner the detector starts from.
TEST(DetectTargetOrder, ChessboardTurnedInThePlaneKeepsItsIds) {
  const pose::TargetSpec target = hecal::testing::Chessboard(9, 6, 0.03);
  const Pose T = FrontalView(target, 0.45, 15.0, -10.0, 8.0);
  const cv::Mat image = Render(target, T);
  cv::Mat turned;
  cv::rotate(image, turned, cv::ROTATE_180);
  const Detection upright = DetectTarget(image, target);
  const Detection half_turn = DetectTarget(turned, target);
  ASSERT_EQ(upright.status, DetectionStatus::kFound) << upright.message;
  ASSERT_EQ(half_turn.status, DetectionStatus::kFound) << half_turn.message;
  EXPECT_EQ(half_turn.order, PointOrder::kPattern);
  const std::vector<Eigen::Vector2d> truth = ProjectedTruth(target, DetectionCamera(), T).pixels;
  std::vector<Eigen::Vector2d> turned_truth;
  for (const Eigen::Vector2d& p : truth) {
    turned_truth.emplace_back(image.cols - 1 - p.x(), image.rows - 1 - p.y());
  }
  EXPECT_LT(CompareWithTruth(upright, truth).max, 0.1);
  EXPECT_LT(CompareWithTruth(half_turn, turned_truth).max, 0.1);
}

struct ViewSet {
  std::vector<Detection> detections;
  std::vector<std::vector<Eigen::Vector2d>> truth;
  std::vector<Eigen::Matrix3d> R_base_gripper;
};

// Views of a symmetric target with the camera rolled by `rolls` (degrees) about its axis, taken
// by an eye-in-hand robot (X = T_gripper_camera and Z = T_base_target fixed).
ViewSet SymmetricViews(const pose::TargetSpec& target, const std::vector<double>& rolls) {
  const Pose X =
      MakePose(so3::Exp(Eigen::Vector3d(0.3, -0.2, 1.1)), Eigen::Vector3d(0.05, -0.02, 0.1));
  const Pose Z =
      MakePose(so3::Exp(Eigen::Vector3d(3.0, 0.1, -0.2)), Eigen::Vector3d(0.8, 0.1, 0.2));
  ViewSet set;
  for (size_t k = 0; k < rolls.size(); ++k) {
    const Pose T =
        FrontalView(target, 0.5, k % 2 == 0 ? 12.0 : -8.0, k % 3 == 0 ? -10.0 : 6.0, rolls[k]);
    set.detections.push_back(DetectTarget(Render(target, T), target));
    set.truth.push_back(ProjectedTruth(target, DetectionCamera(), T).pixels);
    set.R_base_gripper.push_back((Z * T.inverse() * X.inverse()).linear());
  }
  return set;
}

void ExpectConsistentWithTruth(const ViewSet& set, const std::vector<int>& indices) {
  for (const int k : indices) {
    const Detection& detection = set.detections[static_cast<size_t>(k)];
    EXPECT_EQ(detection.status, DetectionStatus::kFound)
        << "view " << k << ": " << detection.message;
    EXPECT_LT(CompareWithTruth(detection, set.truth[static_cast<size_t>(k)]).max, 0.1)
        << "view " << k;
  }
}

// A symmetric chessboard (8 × 6) seen with the camera rolling 60° between consecutive views:
// every view alone is ambiguous; the image rule orders them all like the first (whose x axis
// points right, as the truth's), turning those the per-image rule had started from the far end.
TEST(ResolveOrder, ImageRuleOrdersViewsThatTurnGradually) {
  const pose::TargetSpec target = hecal::testing::Chessboard(8, 6, 0.03);
  ViewSet set = SymmetricViews(target, {0.0, 60.0, 120.0, 180.0, 240.0, 300.0});
  for (const Detection& detection : set.detections) {
    ASSERT_EQ(detection.status, DetectionStatus::kAmbiguous) << detection.message;
    ASSERT_EQ(detection.order, PointOrder::kImage);
  }
  const OrderReport report = ResolveOrder(target, {}, &set.detections);
  EXPECT_EQ(report.reference, 0);
  EXPECT_TRUE(report.ambiguous.empty());
  EXPECT_FALSE(report.turned.empty());  // views rolled beyond 90° start from the far end
  ExpectConsistentWithTruth(set, {0, 1, 2, 3, 4, 5});
  EXPECT_EQ(set.detections[0].order, PointOrder::kReference);
  EXPECT_EQ(set.detections[3].order, PointOrder::kConsistency);
}

// A view rolled by a quarter turn from the one before cannot be ordered from the images: it
// stays ambiguous and is listed, never guessed, and so does every later view (the chain breaks).
TEST(ResolveOrder, ImageRuleLeavesQuarterTurnsAmbiguous) {
  const pose::TargetSpec target = hecal::testing::Chessboard(8, 6, 0.03);
  ViewSet set = SymmetricViews(target, {0.0, 90.0, 110.0});
  const OrderReport report = ResolveOrder(target, {}, &set.detections);
  EXPECT_EQ(report.ambiguous, (std::vector<int>{1, 2}));
  for (const int k : {1, 2}) {
    EXPECT_EQ(set.detections[static_cast<size_t>(k)].status, DetectionStatus::kAmbiguous);
    EXPECT_NE(set.detections[static_cast<size_t>(k)].message.find("undecided"), std::string::npos);
  }
}

// With the robot's rotations the relative rotation angles decide, whatever the roll between
// views: quarter and three-quarter turns are ordered correctly.
TEST(ResolveOrder, RobotRuleOrdersAnyRoll) {
  const pose::TargetSpec target = hecal::testing::Chessboard(8, 6, 0.03);
  ViewSet set = SymmetricViews(target, {0.0, 90.0, 180.0, 270.0, 135.0});
  OrderOptions options;
  options.camera = DetectionCamera();
  options.R_base_gripper = set.R_base_gripper;
  const OrderReport report = ResolveOrder(target, options, &set.detections);
  EXPECT_TRUE(report.ambiguous.empty());
  ExpectConsistentWithTruth(set, {0, 1, 2, 3, 4});
}

// Robot rotations that do not belong to these views agree with neither order: the views stay
// ambiguous instead of being ordered by chance.
TEST(ResolveOrder, RobotRuleRefusesRotationsThatDoNotFit) {
  const pose::TargetSpec target = hecal::testing::Chessboard(8, 6, 0.03);
  ViewSet set = SymmetricViews(target, {0.0, 90.0, 180.0});
  OrderOptions options;
  options.camera = DetectionCamera();
  for (size_t k = 0; k < set.detections.size(); ++k) {
    options.R_base_gripper.push_back(
        so3::Exp(Eigen::Vector3d(0.0, 0.0, 0.7 * static_cast<double>(k))));
  }
  const OrderReport report = ResolveOrder(target, options, &set.detections);
  EXPECT_EQ(report.ambiguous, (std::vector<int>{1, 2}));
}

TEST(ResolveOrder, SymmetricCircleGridsToo) {
  const pose::TargetSpec target = SymmetricCircles();
  ViewSet set = SymmetricViews(target, {0.0, 60.0, 120.0, 180.0});
  for (const Detection& detection : set.detections) {
    ASSERT_EQ(detection.status, DetectionStatus::kAmbiguous) << detection.message;
  }
  const OrderReport report = ResolveOrder(target, {}, &set.detections);
  EXPECT_TRUE(report.ambiguous.empty());
  ExpectConsistentWithTruth(set, {0, 1, 2, 3});
}

TEST(ResolveOrder, LeavesUniquelyOrderedDetectionsAlone) {
  const pose::TargetSpec target = hecal::testing::Chessboard(9, 6, 0.03);
  std::vector<Detection> detections = {
      DetectTarget(Render(target, FrontalView(target, 0.45, 0.0, 0.0, 170.0)), target)};
  const std::vector<Detection> before = detections;
  const OrderReport report = ResolveOrder(target, {}, &detections);
  EXPECT_EQ(report.reference, -1);
  ASSERT_EQ(detections[0].points.size(), before[0].points.size());
  for (size_t k = 0; k < before[0].points.size(); ++k) {
    EXPECT_EQ(detections[0].points[k].pixel, before[0].points[k].pixel);
  }
}

TEST(ResolveOrder, RejectsInconsistentOptions) {
  const pose::TargetSpec target = hecal::testing::Chessboard(8, 6, 0.03);
  std::vector<Detection> detections(2);
  OrderOptions options;
  options.R_base_gripper.assign(2, Eigen::Matrix3d::Identity());
  EXPECT_THROW(ResolveOrder(target, options, &detections), InputError);  // no camera
  options.camera = DetectionCamera();
  options.R_base_gripper.assign(3, Eigen::Matrix3d::Identity());
  EXPECT_THROW(ResolveOrder(target, options, &detections), InputError);  // count
  options = {};
  options.direction_margin_deg = 95.0;
  EXPECT_THROW(ResolveOrder(target, options, &detections), InputError);
}

TEST(OrderOptions, IsValidNamesTheField) {
  using hecal::testing::RefusesNaming;
  const OrderOptions defaults;
  EXPECT_TRUE(hecal::testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "OrderOptions.angle_tolerance_deg",
                            [](auto& o) { o.angle_tolerance_deg = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "OrderOptions.direction_margin_deg",
                            [](auto& o) { o.direction_margin_deg = 95.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "OrderOptions.camera", [](auto& o) {
    o.R_base_gripper.assign(2, Eigen::Matrix3d::Identity());
  }));
}

}  // namespace
}  // namespace hecal::vision
