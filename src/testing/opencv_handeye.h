// Test support (not installed): OpenCV 4.6's hand–eye functions as PEERS on hecal's Problem
// (problem.h: Z = A_i X B_i, B_i = T_camera_target_i). Only *_opencv_test.cc files include this.
//  - cv::calibrateHandEye(R_gripper2base, …, R_target2cam, …) solves A X = X B with
//    gripper2base = A_i and target2cam = B_i and returns cam2gripper = X (for eye-to-hand,
//    A_i = T_base_gripper⁻¹ is exactly the "inverse robot poses" OpenCV's docs prescribe).
//  - cv::calibrateRobotWorldHandEye(R_world2cam, …, R_base2gripper, …) solves
//    world2cam_i · base2world = gripper2cam · base2gripper_i with world2cam = B_i and
//    base2gripper = A_i⁻¹, so base2world = Z⁻¹ and gripper2cam = X⁻¹.
#pragma once

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"
#include "testing/handeye_solver_suite.h"

namespace hecal::testing {

inline cv::Mat ToCvRotation(const Pose& T) {
  cv::Mat R(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) R.at<double>(r, c) = T.linear()(r, c);
  }
  return R;
}

inline cv::Mat ToCvTranslation(const Pose& T) {
  cv::Mat t(3, 1, CV_64F);
  for (int r = 0; r < 3; ++r) t.at<double>(r) = T.translation()(r);
  return t;
}

inline Pose FromCv(const cv::Mat& R, const cv::Mat& t) {
  Eigen::Matrix3d rotation;
  Eigen::Vector3d translation;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rotation(r, c) = R.at<double>(r, c);
    translation(r) = t.at<double>(r);
  }
  return MakePose(rotation, translation);
}

struct CvPoseLists {
  std::vector<cv::Mat> R, t;
};

inline CvPoseLists ToCv(const std::vector<Pose>& poses, bool invert) {
  CvPoseLists lists;
  for (const Pose& T : poses) {
    const Pose P = invert ? T.inverse() : T;
    lists.R.push_back(ToCvRotation(P));
    lists.t.push_back(ToCvTranslation(P));
  }
  return lists;
}

// X from cv::calibrateHandEye.
inline Pose OpenCvHandEye(const handeye::Problem& problem, cv::HandEyeCalibrationMethod method) {
  const CvPoseLists robot = ToCv(problem.A, false);
  const CvPoseLists camera = ToCv(problem.B, false);
  cv::Mat R, t;
  cv::calibrateHandEye(robot.R, robot.t, camera.R, camera.t, R, t, method);
  return FromCv(R, t);
}

// X and Z from cv::calibrateRobotWorldHandEye.
inline handeye::Solution OpenCvRobotWorldHandEye(const handeye::Problem& problem,
                                                 cv::RobotWorldHandEyeCalibrationMethod method) {
  const CvPoseLists camera = ToCv(problem.B, false);
  const CvPoseLists robot = ToCv(problem.A, true);
  cv::Mat R_base2world, t_base2world, R_gripper2cam, t_gripper2cam;
  cv::calibrateRobotWorldHandEye(camera.R, camera.t, robot.R, robot.t, R_base2world, t_base2world,
                                 R_gripper2cam, t_gripper2cam, method);
  return handeye::Solution{FromCv(R_gripper2cam, t_gripper2cam).inverse(),
                           FromCv(R_base2world, t_base2world).inverse()};
}

// RMS errors against the truth of hecal and of the OpenCV peer on the same noisy data sets.
struct PeerAccuracy {
  double hecal_rotation_deg = 0.0, hecal_translation = 0.0;    // RMS over X (and Z)
  double opencv_rotation_deg = 0.0, opencv_translation = 0.0;  // RMS over X (and Z)
};

// `trials` BenignCase data sets per setup, n = 10, σ = 0.3 mm / 0.3° on robot and camera.
// solve(problem, use_opencv) returns the solution of either implementation; Z is compared too
// when check_z.
inline PeerAccuracy ComparePeerAccuracy(
    const std::function<handeye::Solution(const handeye::Problem&, bool)>& solve, int trials,
    bool check_z, const char* name) {
  double sums[4] = {0.0, 0.0, 0.0, 0.0};
  int count = 0;
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    for (int trial = 0; trial < trials; ++trial) {
      const Scene data =
          BenignCase(setup, 10, 1000 + trial, 0.3 * std::numbers::pi / 180.0, 0.3e-3);
      const handeye::Problem problem = data.MeasuredProblem();
      for (int impl = 0; impl < 2; ++impl) {
        const handeye::Solution solution = solve(problem, impl == 1);
        std::vector<PoseError> errors = {Error(solution.X, data.X)};
        if (check_z) errors.push_back(Error(solution.Z, data.Z));
        for (const PoseError& e : errors) {
          sums[2 * impl] += Degrees(e.rotation) * Degrees(e.rotation);
          sums[2 * impl + 1] += e.translation * e.translation;
        }
      }
      count += check_z ? 2 : 1;
    }
  }
  PeerAccuracy accuracy{std::sqrt(sums[0] / count), std::sqrt(sums[1] / count),
                        std::sqrt(sums[2] / count), std::sqrt(sums[3] / count)};
  std::printf(
      "%s RMS error vs truth (benign, 0.3 mm / 0.3 deg): hecal %.3f deg / %.2f mm, "
      "OpenCV %.3f deg / %.2f mm\n",
      name, accuracy.hecal_rotation_deg, 1e3 * accuracy.hecal_translation,
      accuracy.opencv_rotation_deg, 1e3 * accuracy.opencv_translation);
  return accuracy;
}

}  // namespace hecal::testing
