// The pose text against lines written by hand: a quarter turn about z at (100, 0, 2000) mm,
// with and without a covariance.
#include "hecal/report/pose_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace hecal::report {
namespace {

pose::PoseEstimate QuarterTurnEstimate() {
  pose::PoseEstimate estimate;
  estimate.method = "dlt";
  Eigen::Matrix3d R;
  R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  estimate.T_camera_target.linear() = R;
  estimate.T_camera_target.translation() = Eigen::Vector3d(0.1, 0.0, 2.0);
  estimate.rms_px = 0.25;
  return estimate;
}

TEST(PoseText, UnrefinedInMillimetres) {
  std::ostringstream out;
  PrintPoseEstimate(out, QuarterTurnEstimate(), 12, io::LengthUnit::kMillimetre);
  EXPECT_EQ(out.str(),
            "method dlt (12 points)\n"
            "T_camera_target (x_camera = R x_target + t)\n"
            "  [   0.000000  -1.000000   0.000000 |  100.000000 ]\n"
            "  [   1.000000   0.000000   0.000000 |    0.000000 ]\n"
            "  [   0.000000   0.000000   1.000000 | 2000.000000 ]\n"
            "  t = ( 100.000000    0.000000 2000.000000) mm\n"
            "  rvec = (0.000000 0.000000 1.570796) rad, 90.000000 deg\n"
            "reprojection RMS 0.2500 px per point (no covariance: dlt is not refined)\n");
}

TEST(PoseText, RefinedWithItsSigma) {
  pose::PoseEstimate estimate = QuarterTurnEstimate();
  Vector6d variance;
  variance << std::pow(std::numbers::pi / 180.0, 2), 0, 0, 1e-6, 0, 0;  // 1°, 1 mm
  estimate.covariance = Matrix6d(variance.asDiagonal());
  estimate.sigma_px = 0.5;
  estimate.sigma_source = pose::SigmaSource::kGiven;
  std::ostringstream out;
  PrintPoseEstimate(out, estimate, 12, io::LengthUnit::kMetre);
  const std::string text = out.str();
  EXPECT_NE(text.find("  1σ rotation (rx, ry, rz) = (1.000000 0.000000 0.000000) deg\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("  1σ translation (tx, ty, tz) = (0.001000 0.000000 0.000000) m\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("reprojection RMS 0.2500 px per point, pixel σ 0.5000 px per axis (given)\n"),
            std::string::npos)
      << text;
}

}  // namespace
}  // namespace hecal::report
