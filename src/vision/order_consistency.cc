// Canonical point order of grid targets, per image and across images (order_consistency.h).
#include "hecal/vision/order_consistency.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "detection_internal.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/so3.h"
#include "hecal/vision/opencv_pnp.h"

namespace hecal::vision {
namespace {
// Chessboard colours: fraction of interior squares that must agree with one of the two orders.
constexpr double kColourAgreement = 0.8;

// Twice the signed area of a quadrilateral in pixel coordinates (u right, v down).
double SignedArea(const cv::Point2f& a, const cv::Point2f& b, const cv::Point2f& c,
                  const cv::Point2f& d) {
  const cv::Point2f corners[4] = {a, b, c, d};
  double area = 0.0;
  for (int k = 0; k < 4; ++k) {
    const cv::Point2f& p = corners[k];
    const cv::Point2f& q = corners[(k + 1) % 4];
    area += static_cast<double>(p.x) * q.y - static_cast<double>(q.x) * p.y;
  }
  return area;
}

// Bilinear grey level at a sub-pixel position (clamped to the image).
double Sample(const cv::Mat& gray, const cv::Point2f& p) {
  const double x = std::clamp(static_cast<double>(p.x), 0.0, gray.cols - 1.0);
  const double y = std::clamp(static_cast<double>(p.y), 0.0, gray.rows - 1.0);
  const int x0 = std::min(static_cast<int>(x), std::max(0, gray.cols - 2));
  const int y0 = std::min(static_cast<int>(y), std::max(0, gray.rows - 2));
  const int x1 = std::min(x0 + 1, gray.cols - 1);
  const int y1 = std::min(y0 + 1, gray.rows - 1);
  const double fx = x - x0, fy = y - y0;
  return (1 - fy) * ((1 - fx) * gray.at<uchar>(y0, x0) + fx * gray.at<uchar>(y0, x1)) +
         fy * ((1 - fx) * gray.at<uchar>(y1, x0) + fx * gray.at<uchar>(y1, x1));
}

// Fraction of the interior squares of a chessboard grid whose colour agrees with the canonical
// colouring for this order (order_consistency.h, step 2).
double CanonicalColourAgreement(const cv::Mat& gray, int cols, int rows,
                                const std::vector<cv::Point2f>& grid) {
  std::vector<double> samples;
  std::vector<bool> canonical_black;
  for (int r = 0; r + 1 < rows; ++r) {
    for (int c = 0; c + 1 < cols; ++c) {
      const cv::Point2f quad[4] = {grid[r * cols + c], grid[r * cols + c + 1],
                                   grid[(r + 1) * cols + c + 1], grid[(r + 1) * cols + c]};
      const cv::Point2f centre = (quad[0] + quad[1] + quad[2] + quad[3]) * 0.25f;
      double value = Sample(gray, centre);
      for (const cv::Point2f& corner : quad)
        value += Sample(gray, centre + 0.25f * (corner - centre));
      samples.push_back(value / 5.0);
      canonical_black.push_back((c + r) % 2 == 0);  // square (c + 1, r + 1)
    }
  }
  std::vector<double> sorted = samples;
  const auto middle = sorted.begin() + static_cast<long>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  double median = *middle;
  if (sorted.size() % 2 == 0) {
    median = 0.5 * (median + *std::max_element(sorted.begin(), middle));
  }
  int agree = 0;
  for (size_t k = 0; k < samples.size(); ++k) {
    if ((samples[k] < median) == canonical_black[k]) ++agree;
  }
  return static_cast<double>(agree) / static_cast<double>(samples.size());
}

template <typename Point>
void ReverseRows(int cols, int rows, std::vector<Point>* grid) {
  for (int r = 0; r < rows / 2; ++r) {
    std::swap_ranges(grid->begin() + r * cols, grid->begin() + (r + 1) * cols,
                     grid->begin() + (rows - 1 - r) * cols);
  }
}

// The x-axis direction of a grid in the image: Σ_r p(cols−1, r) − p(0, r).
template <typename Point, typename Get>
Eigen::Vector2d XAxis(int cols, int rows, const std::vector<Point>& grid, Get pixel) {
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();
  for (int r = 0; r < rows; ++r) {
    direction += pixel(grid[static_cast<size_t>(r * cols + cols - 1)]) -
                 pixel(grid[static_cast<size_t>(r * cols)]);
  }
  return direction;
}

// The image rule's choice: x pointing right, or down on a tie.
bool PointsRightOrDown(const Eigen::Vector2d& x_axis) {
  return x_axis.x() > 0.0 || (x_axis.x() == 0.0 && x_axis.y() > 0.0);
}

enum class Decision { kKeep, kTurn, kUndecided };

double Angle(const Eigen::Matrix3d& R) {
  return so3::Log(R).norm();
}

struct View {
  Detection* detection = nullptr;
  Eigen::Vector2d x_axis = Eigen::Vector2d::Zero();
  Eigen::Matrix3d R_camera_target = Eigen::Matrix3d::Identity();
  bool has_pose = false;
  Eigen::Matrix3d R_base_gripper = Eigen::Matrix3d::Identity();
};

Decision RobotDecision(const View& ordered, const View& candidate, double tolerance) {
  if (!ordered.has_pose || !candidate.has_pose) return Decision::kUndecided;
  const double robot = Angle(ordered.R_base_gripper.transpose() * candidate.R_base_gripper);
  const Eigen::Matrix3d half_turn = Eigen::Vector3d(-1.0, -1.0, 1.0).asDiagonal();
  const double keep =
      Angle(candidate.R_camera_target * ordered.R_camera_target.transpose()) - robot;
  const double turn =
      Angle(candidate.R_camera_target * half_turn * ordered.R_camera_target.transpose()) - robot;
  const bool keep_agrees = std::abs(keep) < tolerance;
  const bool turn_agrees = std::abs(turn) < tolerance;
  if (keep_agrees == turn_agrees) return Decision::kUndecided;
  return keep_agrees ? Decision::kKeep : Decision::kTurn;
}

Decision ImageDecision(const View& ordered, const View& candidate, double margin) {
  const double norms = ordered.x_axis.norm() * candidate.x_axis.norm();
  if (!(norms > 0.0)) return Decision::kUndecided;
  const double angle =
      std::acos(std::clamp(ordered.x_axis.dot(candidate.x_axis) / norms, -1.0, 1.0));
  if (angle < std::numbers::pi / 2 - margin) return Decision::kKeep;
  if (angle > std::numbers::pi / 2 + margin) return Decision::kTurn;
  return Decision::kUndecided;
}

}  // namespace

GridOrder CanonicalGridOrder(const cv::Mat& gray, const pose::TargetSpec& target,
                             std::vector<cv::Point2f>* grid) {
  const int cols = target.cols, rows = target.rows;
  if (static_cast<int>(grid->size()) != cols * rows) return GridOrder::kInvalid;
  const auto at = [&](int c, int r) { return (*grid)[static_cast<size_t>(r * cols + c)]; };
  const double area =
      SignedArea(at(0, 0), at(cols - 1, 0), at(cols - 1, rows - 1), at(0, rows - 1));
  if (!(std::abs(area) >= 1.0)) return GridOrder::kInvalid;  // under a pixel²: no grid
  if (area < 0.0) ReverseRows(cols, rows, grid);
  if (target.type == pose::TargetType::kAsymmetricCircles) return GridOrder::kUnique;
  if (target.type == pose::TargetType::kChessboard && (cols + rows) % 2 == 1) {
    const double agreement = CanonicalColourAgreement(gray, cols, rows, *grid);
    if (agreement >= kColourAgreement) return GridOrder::kUnique;
    if (agreement <= 1.0 - kColourAgreement) {
      std::reverse(grid->begin(), grid->end());
      return GridOrder::kUnique;
    }
  }
  const auto pixel = [](const cv::Point2f& p) { return Eigen::Vector2d(p.x, p.y); };
  if (!PointsRightOrDown(XAxis(cols, rows, *grid, pixel))) std::reverse(grid->begin(), grid->end());
  return GridOrder::kSymmetric;
}

bool OrderOptions::IsValid(std::string* why) const {
  if (!(angle_tolerance_deg > 0.0 && angle_tolerance_deg < 90.0)) {
    return Invalid(why, "OrderOptions.angle_tolerance_deg", "must be between 0 and 90 degrees",
                   "give the robot rule's tolerance (default 3)");
  }
  if (!(direction_margin_deg > 0.0 && direction_margin_deg < 90.0)) {
    return Invalid(why, "OrderOptions.direction_margin_deg", "must be between 0 and 90 degrees",
                   "give the image rule's margin (default 20)");
  }
  if (!R_base_gripper.empty() && !camera) {
    return Invalid(why, "OrderOptions.camera",
                   "the robot rule (R_base_gripper given) needs the camera intrinsics",
                   "give the camera as well, or leave R_base_gripper empty for the image rule");
  }
  return true;
}

OrderReport ResolveOrder(const pose::TargetSpec& target, const OrderOptions& options,
                         std::vector<Detection>* detections) {
  RequireValid(options);
  const bool robot_rule = !options.R_base_gripper.empty();
  if (robot_rule && options.R_base_gripper.size() != detections->size()) {
    throw InputError("options", 0,
                     std::to_string(options.R_base_gripper.size()) + " robot rotations for " +
                         std::to_string(detections->size()) + " detections",
                     "give one R_base_gripper per detection, in the same order");
  }
  internal::RequireUsableTarget(target);
  const std::vector<pose::ObjectPoint> object = pose::ObjectPoints(target);

  std::vector<View> views;
  std::vector<int> indices;
  for (size_t k = 0; k < detections->size(); ++k) {
    Detection& detection = (*detections)[k];
    if (detection.status != DetectionStatus::kAmbiguous || detection.order != PointOrder::kImage ||
        detection.num_points() != static_cast<int>(object.size())) {
      continue;
    }
    View view;
    view.detection = &detection;
    view.x_axis = XAxis(target.cols, target.rows, detection.points,
                        [](const ImagePoint& p) { return p.pixel; });
    if (robot_rule) {
      view.R_base_gripper = options.R_base_gripper[k];
      std::vector<Eigen::Vector3d> positions;
      std::vector<Eigen::Vector2d> pixels;
      for (const ImagePoint& p : detection.points) {
        positions.push_back(object[static_cast<size_t>(p.id)].position);
        pixels.push_back(p.pixel);
      }
      try {
        view.R_camera_target =
            SolvePnPOpenCv(PnpMethod::kIppe, positions, pixels, *options.camera).linear();
        view.has_pose = true;
      } catch (const DegenerateError&) {
        view.has_pose = false;  // stays undecided, hence ambiguous
      }
    }
    views.push_back(view);
    indices.push_back(static_cast<int>(k));
  }
  OrderReport report;
  if (views.empty()) return report;

  enum class State { kOpen, kOrdered, kConflict };
  std::vector<State> state = {State::kOrdered};  // the reference
  state.resize(views.size(), State::kOpen);
  report.reference = indices[0];
  const auto turn = [&](size_t j) {
    std::vector<ImagePoint>& points = views[j].detection->points;
    for (size_t a = 0, b = points.size() - 1; a < b; ++a, --b)
      std::swap(points[a].pixel, points[b].pixel);
    views[j].x_axis = -views[j].x_axis;
    views[j].R_camera_target =
        views[j].R_camera_target * Eigen::Vector3d(-1.0, -1.0, 1.0).asDiagonal();
    report.turned.push_back(indices[j]);
  };
  const auto apply = [&](size_t j, bool keep, bool half_turn) {
    if (keep && half_turn) {
      state[j] = State::kConflict;
    } else if (keep || half_turn) {
      if (half_turn) turn(j);
      state[j] = State::kOrdered;
    }
  };
  if (robot_rule) {
    // Every ordered view is a witness; repeat until no view changes.
    for (bool changed = true; changed;) {
      changed = false;
      for (size_t j = 0; j < views.size(); ++j) {
        if (state[j] != State::kOpen) continue;
        bool keep = false, half_turn = false;
        for (size_t i = 0; i < views.size(); ++i) {
          if (state[i] != State::kOrdered) continue;
          const Decision decision =
              RobotDecision(views[i], views[j], options.angle_tolerance_deg * kRadiansPerDegree);
          keep = keep || decision == Decision::kKeep;
          half_turn = half_turn || decision == Decision::kTurn;
        }
        apply(j, keep, half_turn);
        changed = changed || state[j] == State::kOrdered;
      }
    }
  } else {
    // A chain: each view against the one before it.
    for (size_t j = 1; j < views.size(); ++j) {
      if (state[j - 1] != State::kOrdered) break;
      const Decision decision =
          ImageDecision(views[j - 1], views[j], options.direction_margin_deg * kRadiansPerDegree);
      apply(j, decision == Decision::kKeep, decision == Decision::kTurn);
    }
  }
  std::sort(report.turned.begin(), report.turned.end());
  const std::string rule = robot_rule ? "robot rotation angles" : "image directions";
  for (size_t j = 0; j < views.size(); ++j) {
    Detection& detection = *views[j].detection;
    if (state[j] == State::kOrdered) {
      detection.status = DetectionStatus::kFound;
      detection.order = j == 0 ? PointOrder::kReference : PointOrder::kConsistency;
      detection.message += j == 0 ? "; order reference of the set"
                                  : "; order made consistent with image " +
                                        std::to_string(report.reference) + " (" + rule + ")";
    } else {
      report.ambiguous.push_back(indices[j]);
      detection.message += state[j] == State::kConflict
                               ? "; order undecided: the " + rule + " disagree between images"
                           : robot_rule ? "; order undecided: no image decides it by the " + rule
                                        : "; order undecided: the image directions of this "
                                          "view and the one before it (or an earlier view) "
                                          "differ by about a quarter turn";
    }
  }
  return report;
}

}  // namespace hecal::vision
