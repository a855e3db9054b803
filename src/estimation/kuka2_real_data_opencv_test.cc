// Real data: data/rwhe-kuka2 (Ali et al. 2019, 28 eye-in-hand chessboard views on a KUKA arm;
// see its SOURCE.md). Camera poses come from the images with OpenCV as a tool (the chessboard
// detector and PnP; hecal's own image pipeline is a later layer): findChessboardCornersSB on the
// 24×17 inner corners with 15 mm squares (default flags: CALIB_CB_EXHAUSTIVE | ACCURACY took
// about 3× the CPU for the same X to 0.01°), then solvePnP with the reference intrinsics of
// SOURCE.md. Robot poses: RobotPosesVec.txt, row-major 4×4 T_base_tcp in metres.
// Independent truth: SOURCE.md's reference X = T_gripper_camera (OpenCV PARK, confirmed by
// TSAI/HORAUD/DANIILIDIS/SHAH to 1 mm), rvec (−1.20742, 1.28362, −1.18276),
// t = (0.01439, −0.10790, −0.08187) m; suggested tolerance 0.1° / 2 mm.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/methods.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/rotation.h"
#include "hecal/geometry/so3.h"

namespace hecal::estimation {
namespace {

Pose PoseFromOpenCv(const cv::Mat& rvec, const cv::Mat& tvec) {
  const Eigen::Vector3d w(rvec.at<double>(0), rvec.at<double>(1), rvec.at<double>(2));
  const Eigen::Vector3d t(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
  return MakePose(so3::Exp(w), t);
}

struct Kuka2 {
  std::vector<Pose> T_base_gripper;
  std::vector<Pose> T_camera_target;
};

Kuka2 LoadKuka2() {
  const std::string dir = std::string(HECAL_SOURCE_DIR) + "/data/rwhe-kuka2/";
  Kuka2 data;
  std::ifstream robot(dir + "RobotPosesVec.txt");
  Eigen::Matrix4d M;
  while (true) {
    for (int k = 0; k < 16; ++k) robot >> M(k / 4, k % 4);
    if (!robot) break;
    data.T_base_gripper.emplace_back(M);
  }

  const cv::Matx33d K(1056.2855, 0, 958.7994, 0, 1056.4172, 586.9487, 0, 0, 1);
  const cv::Vec<double, 5> distortion(-0.131337, 0.099230, 0.000133, 0.000312, -0.049132);
  const cv::Size pattern(24, 17);
  constexpr double kSquare = 0.015;
  std::vector<cv::Point3d> board;
  for (int r = 0; r < pattern.height; ++r) {
    for (int c = 0; c < pattern.width; ++c) board.emplace_back(c * kSquare, r * kSquare, 0.0);
  }
  for (std::size_t i = 1; i <= data.T_base_gripper.size(); ++i) {
    const std::string name = dir + "images/im_" + (i < 10 ? "0" : "") + std::to_string(i) + ".png";
    const cv::Mat image = cv::imread(name, cv::IMREAD_GRAYSCALE);
    std::vector<cv::Point2f> corners;
    if (image.empty() || !cv::findChessboardCornersSB(image, pattern, corners)) {
      ADD_FAILURE() << "no chessboard in " << name;
      return {};
    }
    cv::Mat rvec, tvec;
    cv::solvePnP(board, corners, K, distortion, rvec, tvec);
    data.T_camera_target.push_back(PoseFromOpenCv(rvec, tvec));
  }
  return data;
}

TEST(Kuka2RealData, EveryMethodMatchesTheReferenceX) {
  const Kuka2 data = LoadKuka2();
  ASSERT_EQ(data.T_base_gripper.size(), 28u);
  ASSERT_EQ(data.T_camera_target.size(), 28u);
  const handeye::Problem problem =
      handeye::MakeProblem(handeye::Setup::kEyeInHand, data.T_base_gripper, data.T_camera_target);
  const Pose reference = MakePose(so3::Exp(Eigen::Vector3d(-1.20742, 1.28362, -1.18276)),
                                  Eigen::Vector3d(0.01439, -0.10790, -0.08187));

  for (const MethodInfo& info : AllMethods()) {
    CalibrateOptions options;
    options.method = info.method;
    // OpenCV's reference takes the described 15 mm squares on faith; compared at that size.
    options.target_scale = TargetScaleMode::kStated;
    const CalibrationResult result = Calibrate(problem, options);
    const Pose difference = reference.inverse() * result.X;
    const double rotation = so3::Log(difference.linear()).norm();
    const double translation = (result.X.translation() - reference.translation()).norm();
    // (SOURCE.md: OpenCV's ANDREFF is ~3 cm off here; hecal's re-solves the translation for
    // the orthogonalised rotation, andreff.h step 3.)
    // Daniilidis and Andreff weigh translation rows against rotation rows algebraically
    // (translations normalised by their RMS), so PnP depth noise tilts their rotation: measured
    // 0.157° / 1.2 mm and 0.100° / 0.28 mm. Every other method is within 0.05° / 1.1 mm of the
    // reference (ml 0.010° / 0.40 mm).
    const bool algebraic_joint =
        info.method == Method::kDaniilidis || info.method == Method::kAndreff;
    EXPECT_LT(rotation, (algebraic_joint ? 0.25 : 0.1) * kRadiansPerDegree) << info.name;
    EXPECT_LT(translation, 0.002) << info.name;
    if (info.method == Method::kMl) {
      // The target stays put in the base frame to sub-millimetre (SOURCE.md: < 0.5 mm std).
      EXPECT_LT(result.translation_rms, 1.5e-3);
      EXPECT_LT(result.rotation_rms, 0.2 * kRadiansPerDegree);
      ASSERT_TRUE(result.covariance.has_value());
      // The board is not printed at 15 mm (data/rwhe-kuka2/SOURCE.md, docs/target-scale.md):
      // measured at 94.7 % ± 1.0 % from these PnP poses, beyond 3σ of the description.
      ASSERT_TRUE(result.target_scale.has_value());
      EXPECT_NEAR(result.target_scale->scale, 0.947, 0.01);
      EXPECT_TRUE(result.target_scale->Mismatch());
      EXPECT_EQ(result.applied_target_scale, 1.0);
    }
  }
}

// By default the answer is at the measured size: X moves ~20 mm, to within 3σ of the board-free
// answer of docs/global.md (33.6, −102.7, −76.2) mm, and its σ includes the scale's.
TEST(Kuka2RealData, TheDefaultAnswersAtTheMeasuredBoardSize) {
  const Kuka2 data = LoadKuka2();
  const handeye::Problem problem =
      handeye::MakeProblem(handeye::Setup::kEyeInHand, data.T_base_gripper, data.T_camera_target);
  const CalibrationResult result = Calibrate(problem, CalibrateOptions{});
  ASSERT_TRUE(result.target_scale.has_value());
  EXPECT_EQ(result.applied_target_scale, result.target_scale->scale);
  const Eigen::Vector3d board_free(0.0336, -0.1027, -0.0762);
  const Eigen::Matrix3d R = result.X.linear();
  const Eigen::Matrix3d C = R * result.covariance->X().bottomRightCorner<3, 3>() * R.transpose();
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(std::abs(result.X.translation()(k) - board_free(k)), 3.0 * std::sqrt(C(k, k)))
        << "axis " << k;
  }
  ASSERT_TRUE(result.certificate.has_value());
  EXPECT_TRUE(result.certificate->certified);
  EXPECT_FALSE(result.warnings.empty());
}

}  // namespace
}  // namespace hecal::estimation
