// Test helpers for the data-set consistency checks of the importers: how much a set of poses that
// should all be the same (e.g. T_base_target_i = T_base_gripper_i · X · T_camera_target_i for a
// known X) actually varies.
#pragma once

#include <Eigen/SVD>
#include <cmath>
#include <vector>

#include "hecal/geometry/so3.h"
#include "hecal/geometry/types.h"

namespace hecal::testing {

struct Deviation {
  double rotation_deg = 0.0;  // angle of R_aᵀ R_b
  double translation = 0.0;   // |t_a − t_b|, metres
};

inline Deviation Between(const Pose& a, const Pose& b) {
  return {so3::Distance(a.linear(), b.linear()) * 180.0 / M_PI,
          (a.translation() - b.translation()).norm()};
}

// The chordal mean: the rotation nearest to the mean rotation matrix, and the mean translation.
inline Pose ChordalMean(const std::vector<Pose>& poses) {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  for (const Pose& pose : poses) {
    sum += pose.linear();
    t += pose.translation();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sum, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d R = svd.matrixU() * svd.matrixV().transpose();
  if (R.determinant() < 0) {
    Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();
    flip(2, 2) = -1.0;
    R = svd.matrixU() * flip * svd.matrixV().transpose();
  }
  Pose mean = Pose::Identity();
  mean.linear() = R;
  mean.translation() = t / static_cast<double>(poses.size());
  return mean;
}

struct Spread {
  std::vector<Deviation> deviations;  // of each pose from the reference
  double mean_rotation_deg = 0.0;
  double max_rotation_deg = 0.0;
  double mean_translation = 0.0;
  double max_translation = 0.0;
  size_t worst_rotation = 0;     // index of the largest rotation deviation
  size_t worst_translation = 0;  // index of the largest translation deviation
};

inline Spread SpreadAround(const std::vector<Pose>& poses, const Pose& reference) {
  Spread spread;
  for (size_t i = 0; i < poses.size(); ++i) {
    const Deviation d = Between(poses[i], reference);
    spread.deviations.push_back(d);
    spread.mean_rotation_deg += d.rotation_deg / static_cast<double>(poses.size());
    spread.mean_translation += d.translation / static_cast<double>(poses.size());
    if (d.rotation_deg > spread.max_rotation_deg) {
      spread.max_rotation_deg = d.rotation_deg;
      spread.worst_rotation = i;
    }
    if (d.translation > spread.max_translation) {
      spread.max_translation = d.translation;
      spread.worst_translation = i;
    }
  }
  return spread;
}

// Per-axis standard deviation of the positions, the largest of the three (metres).
inline double MaxAxisStd(const std::vector<Pose>& poses) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Pose& pose : poses) mean += pose.translation();
  mean /= static_cast<double>(poses.size());
  Eigen::Vector3d variance = Eigen::Vector3d::Zero();
  for (const Pose& pose : poses) {
    variance += (pose.translation() - mean).cwiseAbs2();
  }
  variance /= static_cast<double>(poses.size());
  return std::sqrt(variance.maxCoeff());
}

// Pose from a rotation matrix and a translation.
inline Pose PoseOf(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  Pose pose = Pose::Identity();
  pose.linear() = R;
  pose.translation() = t;
  return pose;
}

}  // namespace hecal::testing
