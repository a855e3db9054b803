// Test helpers for the render → detect chain: a camera with lens distortion, view poses, the
// projected ground truth of a target's points, the detection's errors against it (size and
// outward offset) and OpenCV's solvePnP on a detection.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <vector>

#include "hecal/geometry/so3.h"
#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"
#include "hecal/vision/detection.h"

namespace hecal::vision::test_views {

inline constexpr double kDeg = std::numbers::pi / 180.0;

// 800 × 600 px, f = 700 px, principal point off-centre, radial and tangential distortion of a
// typical machine-vision lens.
inline pose::CameraModel TestCamera() {
  return {.fx = 700.0,
          .fy = 702.0,
          .cx = 401.3,
          .cy = 297.8,
          .width = 800,
          .height = 600,
          .distortion = {-0.12, 0.05, 0.0008, -0.0005, 0.0}};
}

// The centre of the target's points (target frame).
inline Eigen::Vector3d TargetCentre(const pose::TargetSpec& target) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const std::vector<pose::ObjectPoint> points = pose::ObjectPoints(target);
  for (const pose::ObjectPoint& point : points) sum += point.position;
  return sum / static_cast<double>(points.size());
}

// T_camera_target with the target's centre on the optical axis at `distance` metres, the board
// turned by `roll_deg` about its normal and tilted by tilt_x_deg, tilt_y_deg about the camera's
// x and y axes (frontal at zero).
inline Pose ViewPose(const pose::TargetSpec& target, double distance, double tilt_x_deg,
                     double tilt_y_deg, double roll_deg) {
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(tilt_x_deg * kDeg, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(tilt_y_deg * kDeg, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(roll_deg * kDeg, Eigen::Vector3d::UnitZ()))
                                .toRotationMatrix();
  return MakePose(R, Eigen::Vector3d(0.0, 0.0, distance) - R * TargetCentre(target));
}

// Pixel of every object point (index = id).
inline std::vector<Eigen::Vector2d> ProjectedTruth(const pose::TargetSpec& target,
                                                   const pose::CameraModel& camera,
                                                   const Pose& T_camera_target) {
  std::vector<Eigen::Vector2d> pixels;
  for (const pose::ObjectPoint& point : pose::ObjectPoints(target)) {
    pixels.push_back(pose::Project(camera, T_camera_target * point.position));
  }
  return pixels;
}

// The centroid of the image of a disc (target frame centre, radius in metres): the area centroid
// of its projected outline (4096 points through pose::Project, lens distortion included). A
// centroid detector measures this point; under perspective it differs from the projected centre.
inline Eigen::Vector2d ImagedDiscCentroid(const pose::CameraModel& camera,
                                          const Pose& T_camera_target,
                                          const Eigen::Vector3d& centre, double radius) {
  constexpr int kOutline = 4096;
  std::vector<Eigen::Vector2d> outline;
  for (int k = 0; k < kOutline; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kOutline;
    outline.push_back(pose::Project(
        camera,
        T_camera_target * (centre + radius * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0))));
  }
  double area = 0.0;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  for (int k = 0; k < kOutline; ++k) {
    const Eigen::Vector2d& p = outline[static_cast<size_t>(k)];
    const Eigen::Vector2d& q = outline[static_cast<size_t>((k + 1) % kOutline)];
    const double cross = p.x() * q.y() - q.x() * p.y();
    area += cross;
    moment += cross * (p + q);
  }
  return moment / (3.0 * area);
}

struct PixelErrors {
  double max = 0.0;
  double rms = 0.0;
};

inline PixelErrors CompareWithTruth(const Detection& detection,
                                    const std::vector<Eigen::Vector2d>& truth) {
  PixelErrors errors;
  double sum = 0.0;
  for (const ImagePoint& p : detection.points) {
    const double e = (p.pixel - truth.at(static_cast<size_t>(p.id))).norm();
    errors.max = std::max(errors.max, e);
    sum += e * e;
  }
  if (!detection.points.empty()) errors.rms = std::sqrt(sum / detection.num_points());
  return errors;
}

// The mean offset of the detected points along the direction from the centre of their truth to
// each true point, px: positive when the points sit outward (the pattern imaged too large, which
// PnP turns into a pose too close).
inline double MeanOutwardOffset(const Detection& detection,
                                const std::vector<Eigen::Vector2d>& truth) {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const ImagePoint& p : detection.points) centre += truth.at(static_cast<size_t>(p.id));
  centre /= static_cast<double>(detection.num_points());
  double sum = 0.0;
  for (const ImagePoint& p : detection.points) {
    const Eigen::Vector2d& t = truth.at(static_cast<size_t>(p.id));
    sum += (p.pixel - t).dot((t - centre).normalized());
  }
  return sum / detection.num_points();
}

// T_camera_target from cv::solvePnP (SOLVEPNP_ITERATIVE) on the detection's points.
inline Pose OpenCvPose(const Detection& detection, const pose::TargetSpec& target,
                       const pose::CameraModel& camera) {
  const std::vector<pose::ObjectPoint> object = pose::ObjectPoints(target);
  std::vector<cv::Point3d> positions;
  std::vector<cv::Point2d> pixels;
  for (const ImagePoint& p : detection.points) {
    const Eigen::Vector3d& P = object.at(static_cast<size_t>(p.id)).position;
    positions.emplace_back(P.x(), P.y(), P.z());
    pixels.emplace_back(p.pixel.x(), p.pixel.y());
  }
  const cv::Matx33d K(camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0);
  const cv::Mat distortion(camera.distortion, true);
  cv::Mat rvec, tvec;
  cv::solvePnP(positions, pixels, K, distortion, rvec, tvec, false, cv::SOLVEPNP_ITERATIVE);
  return MakePose(
      so3::Exp(Eigen::Vector3d(rvec.at<double>(0), rvec.at<double>(1), rvec.at<double>(2))),
      Eigen::Vector3d(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2)));
}

inline double RotationErrorDeg(const Pose& a, const Pose& b) {
  return so3::Log(a.linear().transpose() * b.linear()).norm() / kDeg;
}

}  // namespace hecal::vision::test_views
