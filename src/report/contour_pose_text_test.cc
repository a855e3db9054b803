// The contour pose text against lines written by hand for a pose whose numbers are known: a
// translation of mixed widths (Eigen pads every entry to the widest), Euler angles of 0.5, 0.25
// and −0.125 rad (28.6478898°, 14.3239449°, −7.16197244° to 9 digits), and a UT covariance with
// 1σ 0.1, 0.2, 0.3 and 0.01 rad (0.572957795°) and one parameter flagged as biased.
#include "hecal/report/contour_pose_text.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace hecal::report {
namespace {

contour::ShapePose KnownShapePose(contour::RotationForm form) {
  contour::ShapePose result;
  result.pose.translation << 10, -20, 30;
  result.pose.euler << 0.5, 0.25, -0.125;
  result.pose.form = form;
  return result;
}

std::string Text(const contour::ShapePose& result) {
  std::ostringstream out;
  PrintContourPose(out, result);
  return out.str();
}

TEST(ContourPoseText, PoseLines) {
  EXPECT_EQ(Text(KnownShapePose(contour::RotationForm::kZyx)),
            "translation (Tx, Ty, Tz) = ( 10 -20  30)  [unit of --z0]\n"
            "rotation matrix\n"
            "  1 0 0\n"
            "  0 1 0\n"
            "  0 0 1\n"
            "euler ZYX = (   0.5   0.25 -0.125) rad = ( 28.6478898  14.3239449 -7.16197244) deg\n");
}

TEST(ContourPoseText, UncertaintyAndBias) {
  contour::ShapePose result = KnownShapePose(contour::RotationForm::kZxz);
  contour::ContourPoseUncertainty ut;
  ut.parameters.setZero();
  ut.mean.setZero();
  ut.covariance = Matrix6d::Zero();
  ut.covariance.diagonal() << 0.01, 0.04, 0.09, 1e-4, 1e-4, 1e-4;
  ut.biased = {false, false, false, false, true, false};
  ut.any_biased = true;
  result.uncertainty = ut;
  const std::string text = Text(result);
  EXPECT_NE(text.find("euler ZXZ = ("), std::string::npos) << text;
  EXPECT_NE(text.find("\nUT (13 sigma points), 1σ: Tx 0.1 Ty 0.2 Tz 0.3 phi 0.572957795° theta "
                      "0.572957795° (biased) psi 0.572957795°\nbias: the UT mean departs"),
            std::string::npos)
      << text;
  ut.any_biased = false;
  ut.biased = {};
  result.uncertainty = ut;
  EXPECT_EQ(Text(result).find("bias"), std::string::npos);
}

}  // namespace
}  // namespace hecal::report
