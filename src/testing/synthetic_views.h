// Test support for the vision tests: camera poses that look at a planar board (its points:
// testing/image_scene.h, GridPoints) from chosen directions (testing/rendered_scene.h's LookAt),
// and pixels projected with OpenCV's own plumb_bob model (cv::projectPoints, the reference for
// pose/camera_model.h), optionally with Gaussian pixel noise.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/calib3d.hpp>
#include <random>
#include <vector>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"
#include "testing/rendered_scene.h"

namespace hecal::vision::testing {

using hecal::testing::LookAt;  // testing/rendered_scene.h

inline std::vector<Eigen::Vector2d> Project(const std::vector<Eigen::Vector3d>& points,
                                            const Pose& T_camera_target,
                                            const pose::CameraModel& camera) {
  std::vector<cv::Point3d> object;
  for (const Eigen::Vector3d& p : points) object.emplace_back(p.x(), p.y(), p.z());
  const Eigen::AngleAxisd angle_axis(T_camera_target.linear());
  const Eigen::Vector3d w = angle_axis.angle() * angle_axis.axis();
  const Eigen::Vector3d t = T_camera_target.translation();
  const cv::Matx33d K(camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0);
  std::vector<cv::Point2d> image;
  cv::projectPoints(object, cv::Vec3d(w.x(), w.y(), w.z()), cv::Vec3d(t.x(), t.y(), t.z()), K,
                    cv::Vec<double, 5>(camera.distortion.data()), image);
  std::vector<Eigen::Vector2d> pixels;
  for (const cv::Point2d& q : image) pixels.emplace_back(q.x, q.y);
  return pixels;
}

inline void AddNoise(double sigma_px, std::mt19937_64& rng, std::vector<Eigen::Vector2d>* pixels) {
  hecal::NormalDistribution noise(0.0, sigma_px);
  for (Eigen::Vector2d& p : *pixels) {
    const double dy = noise(rng);  // y first: the order the tests' data were generated in
    const double dx = noise(rng);
    p += Eigen::Vector2d(dx, dy);
  }
}

// Rotation angle between two poses (radians) and translation distance (metres).
inline double RotationError(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}
inline double TranslationError(const Pose& a, const Pose& b) {
  return (a.translation() - b.translation()).norm();
}

}  // namespace hecal::vision::testing
