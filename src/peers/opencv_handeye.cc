#include "hecal/peers/opencv_handeye.h"

#include <opencv2/calib3d.hpp>
#include <stdexcept>
#include <string>

namespace hecal::peers {
namespace {

cv::Mat RotationMat(const Eigen::Matrix3d& R) {
  cv::Mat m(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m.at<double>(r, c) = R(r, c);
  }
  return m;
}

cv::Mat TranslationMat(const Eigen::Vector3d& t) {
  cv::Mat m(3, 1, CV_64F);
  for (int r = 0; r < 3; ++r) m.at<double>(r, 0) = t(r);
  return m;
}

// OpenCV returns CV_64F 3×3 and 3×1 matrices; NaN entries pass through unchanged.
Pose PoseFromMats(const cv::Mat& R, const cv::Mat& t) {
  Eigen::Matrix3d rotation;
  Eigen::Vector3d translation;
  cv::Mat R64, t64;
  R.convertTo(R64, CV_64F);
  t.convertTo(t64, CV_64F);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rotation(r, c) = R64.at<double>(r, c);
    translation(r) = t64.at<double>(r, 0);
  }
  return MakePose(rotation, translation);
}

// Inverse of a rigid transform without assuming the rotation is orthonormal-exact (OpenCV's
// results are), via Rᵀ — the same as Isometry3d::inverse().
Pose Inverse(const Pose& T) {
  return MakePose(T.linear().transpose(), -T.linear().transpose() * T.translation());
}

}  // namespace

bool HasOpenCvPeer(handeye::ClosedForm method) {
  switch (method) {
    case handeye::ClosedForm::kTsaiLenz:
    case handeye::ClosedForm::kParkMartin:
    case handeye::ClosedForm::kHoraud:
    case handeye::ClosedForm::kAndreff:
    case handeye::ClosedForm::kDaniilidis:
    case handeye::ClosedForm::kShah:
    case handeye::ClosedForm::kLi:
      return true;
    default:
      return false;
  }
}

std::vector<handeye::ClosedForm> OpenCvPeerMethods() {
  std::vector<handeye::ClosedForm> methods;
  for (const handeye::ClosedFormInfo& info : handeye::ClosedForms()) {
    if (HasOpenCvPeer(info.form)) methods.push_back(info.form);
  }
  return methods;
}

OpenCvInput PrepareOpenCvInput(const handeye::Problem& problem) {
  OpenCvInput input;
  input.problem = problem;
  for (size_t i = 0; i < problem.A.size(); ++i) {
    const Pose& A = problem.A[i];
    const Pose& B = problem.B[i];
    const Pose A_inv = Inverse(A);
    input.R_A.push_back(RotationMat(A.linear()));
    input.t_A.push_back(TranslationMat(A.translation()));
    input.R_B.push_back(RotationMat(B.linear()));
    input.t_B.push_back(TranslationMat(B.translation()));
    input.R_A_inv.push_back(RotationMat(A_inv.linear()));
    input.t_A_inv.push_back(TranslationMat(A_inv.translation()));
  }
  return input;
}

handeye::Solution SolveWithOpenCv(handeye::ClosedForm method, const OpenCvInput& input,
                                  bool estimate_z) {
  handeye::Solution solution;
  if (method == handeye::ClosedForm::kShah || method == handeye::ClosedForm::kLi) {
    const cv::RobotWorldHandEyeCalibrationMethod flag = method == handeye::ClosedForm::kShah
                                                            ? cv::CALIB_ROBOT_WORLD_HAND_EYE_SHAH
                                                            : cv::CALIB_ROBOT_WORLD_HAND_EYE_LI;
    cv::Mat R_base2world, t_base2world, R_gripper2cam, t_gripper2cam;
    cv::calibrateRobotWorldHandEye(input.R_B, input.t_B, input.R_A_inv, input.t_A_inv, R_base2world,
                                   t_base2world, R_gripper2cam, t_gripper2cam, flag);
    solution.X = Inverse(PoseFromMats(R_gripper2cam, t_gripper2cam));
    solution.Z = Inverse(PoseFromMats(R_base2world, t_base2world));
    return solution;
  }
  cv::HandEyeCalibrationMethod flag = cv::CALIB_HAND_EYE_TSAI;
  switch (method) {
    case handeye::ClosedForm::kTsaiLenz:
      flag = cv::CALIB_HAND_EYE_TSAI;
      break;
    case handeye::ClosedForm::kParkMartin:
      flag = cv::CALIB_HAND_EYE_PARK;
      break;
    case handeye::ClosedForm::kHoraud:
      flag = cv::CALIB_HAND_EYE_HORAUD;
      break;
    case handeye::ClosedForm::kAndreff:
      flag = cv::CALIB_HAND_EYE_ANDREFF;
      break;
    case handeye::ClosedForm::kDaniilidis:
      flag = cv::CALIB_HAND_EYE_DANIILIDIS;
      break;
    default:
      throw std::invalid_argument("SolveWithOpenCv: OpenCV has no peer for method " +
                                  std::string(handeye::Info(method).name));
  }
  cv::Mat R_cam2gripper, t_cam2gripper;
  cv::calibrateHandEye(input.R_A, input.t_A, input.R_B, input.t_B, R_cam2gripper, t_cam2gripper,
                       flag);
  solution.X = PoseFromMats(R_cam2gripper, t_cam2gripper);
  if (estimate_z) solution.Z = handeye::EstimateZ(input.problem, solution.X);
  return solution;
}

handeye::Solution SolveWithOpenCv(handeye::ClosedForm method, const handeye::Problem& problem) {
  return SolveWithOpenCv(method, PrepareOpenCvInput(problem));
}

}  // namespace hecal::peers
