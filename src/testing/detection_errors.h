// Test support (not installed): the errors of a detection and of a pose against a rendered
// scene's truth (testing/rendered_scene.h): the imaged centroid of a disc (what a centroid
// detector measures), the detected points' size and outward offset against the projected truth,
// OpenCV's cv::solvePnP (SOLVEPNP_ITERATIVE) on a detection as an independent pose, and the
// rotation (degrees) and translation (millimetres) between two poses. Pixels, metres.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <vector>

#include "hecal/geometry/so3.h"
#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"
#include "hecal/vision/detection.h"

namespace hecal::testing {

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

inline PixelErrors CompareWithTruth(const vision::Detection& detection,
                                    const std::vector<Eigen::Vector2d>& truth) {
  PixelErrors errors;
  double sum = 0.0;
  for (const vision::ImagePoint& p : detection.points) {
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
inline double MeanOutwardOffset(const vision::Detection& detection,
                                const std::vector<Eigen::Vector2d>& truth) {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const vision::ImagePoint& p : detection.points)
    centre += truth.at(static_cast<size_t>(p.id));
  centre /= static_cast<double>(detection.num_points());
  double sum = 0.0;
  for (const vision::ImagePoint& p : detection.points) {
    const Eigen::Vector2d& t = truth.at(static_cast<size_t>(p.id));
    sum += (p.pixel - t).dot((t - centre).normalized());
  }
  return sum / detection.num_points();
}

// T_camera_target from cv::solvePnP (SOLVEPNP_ITERATIVE) on the detection's points.
inline Pose OpenCvPose(const vision::Detection& detection, const pose::TargetSpec& target,
                       const pose::CameraModel& camera) {
  const std::vector<pose::ObjectPoint> object = pose::ObjectPoints(target);
  std::vector<cv::Point3d> positions;
  std::vector<cv::Point2d> pixels;
  for (const vision::ImagePoint& p : detection.points) {
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

// Rotation angle between two poses (degrees) and translation distance (millimetres).
inline double RotationErrorDeg(const Pose& a, const Pose& b) {
  return so3::Log(a.linear().transpose() * b.linear()).norm() / (std::numbers::pi / 180.0);
}
inline double TranslationErrorMm(const Pose& a, const Pose& b) {
  return 1e3 * (a.translation() - b.translation()).norm();
}

}  // namespace hecal::testing
