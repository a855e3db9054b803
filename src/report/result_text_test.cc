// The result text against lines written by hand for a result whose numbers are known: X a
// quarter turn about z at (100, 200, 300) mm, two stations used, one rejected, in millimetres;
// and the side-by-side comparison of two methods 1 mm apart; from images, a refinement that moved
// X by 2° and 5 mm from the pose level and refined the intrinsics.
#include "hecal/report/result_text.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <sstream>
#include <string>

#include "hecal/geometry/angle_units.h"

namespace hecal::report {
namespace {

estimation::CalibrationResult QuarterTurn(estimation::Method method, double tz_m) {
  estimation::CalibrationResult result;
  result.method = method;
  Eigen::Matrix3d R;
  R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  result.X.linear() = R;
  result.X.translation() = Eigen::Vector3d(0.1, 0.2, tz_m);
  result.residuals = {{0.5 * kRadiansPerDegree, 1.25e-3, 0.8, false},
                      {2.0 * kRadiansPerDegree, 4e-3, 3.5, true}};
  result.rotation_rms = 1.5 * kRadiansPerDegree;
  result.translation_rms = 3e-3;
  result.rejected = {1};
  result.rejected_residuals = {{10.0 * kRadiansPerDegree, 0.05, 20.0, true}};
  result.rejected_ids = {"s2"};
  result.warnings = {"a warning"};
  return result;
}

ResultDocument Document() {
  ResultDocument document;
  document.setup = handeye::Setup::kEyeInHand;
  document.unit = io::LengthUnit::kMillimetre;
  document.station_ids = {"s1", "s2", "s3"};
  document.rejected = {1};
  document.results = {QuarterTurn(estimation::Method::kMl, 0.3)};
  return document;
}

TEST(ResultText, SummaryLines) {
  const ResultDocument document = Document();
  std::ostringstream out;
  PrintResultSummary(out, document, document.results[0]);
  const std::string text = out.str();
  const auto has = [&](const std::string& line) {
    EXPECT_NE(text.find(line + "\n"), std::string::npos) << "missing: " << line << "\n" << text;
  };
  EXPECT_EQ(text.rfind("method ml (eye-in-hand, 2 stations)\nX = T_gripper_camera\n", 0), 0u);
  has("  [   0.000000  -1.000000   0.000000 | 100.000000 ]");
  has("  [   1.000000   0.000000   0.000000 | 200.000000 ]");
  has("  [   0.000000   0.000000   1.000000 | 300.000000 ]");
  has("  rotation 90.000000 deg about (0.000000 0.000000 1.000000), translation 100.000000 "
      "200.000000 300.000000 mm");
  has("Z = T_base_target");
  has("residual RMS: 1.5000 deg, 3.0000 mm");
  has("  station        rotation_deg   translation_mm   whitened");
  has("  s1                  0.5000           1.2500     0.8000");
  has("  s3                  2.0000           4.0000     3.5000   > 3σ, check this station");
  has("  s2                 10.0000          50.0000    20.0000   rejected: outlier, not used");
  has("warning: a warning");
  EXPECT_EQ(text.find("covariance"), std::string::npos);  // none computed
}

// X turns the camera's x into the gripper's y: σ (1, 2, 3) mm along the camera's axes is
// (2, 1, 3) mm along the gripper's. Z is the identity rotation: its two lines agree.
TEST(ResultText, SigmaAlongBothFrames) {
  ResultDocument document = Document();
  estimation::CalibrationCovariance covariance;
  covariance.covariance.setZero();
  covariance.covariance.diagonal() << 1e-6, 1e-6, 1e-6, 1e-6, 4e-6, 9e-6, 1e-6, 1e-6, 1e-6, 16e-6,
      25e-6, 36e-6;
  covariance.covariance(0, 4) = covariance.covariance(4, 0) = 1e-6;  // must not enter
  document.results[0].covariance = covariance;
  std::ostringstream out;
  PrintResultSummary(out, document, document.results[0]);
  const std::string text = out.str();
  const auto has = [&](const std::string& line) {
    EXPECT_NE(text.find(line + "\n"), std::string::npos) << "missing: " << line << "\n" << text;
  };
  has("  1σ X: rotation (0.057296 0.057296 0.057296) deg, translation (1.000000 2.000000 "
      "3.000000) mm");
  has("  1σ of X's translation along the gripper's axes: (2.000000 1.000000 3.000000) mm");
  has("  1σ of Z's translation along the base's axes: (4.000000 5.000000 6.000000) mm");
}

TEST(ResultText, ComparisonAgainstMl) {
  ResultDocument document = Document();
  document.all_methods = true;
  document.results.push_back(QuarterTurn(estimation::Method::kTsaiLenz, 0.301));
  document.failures = {{estimation::Method::kShah, "too few stations"}};
  std::ostringstream out;
  PrintMethodComparison(out, document);
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("\nside by side (X T_gripper_camera)\n", 0), 0u) << text;
  // tsai-lenz: the same rotation, 1 mm further along z than ml.
  EXPECT_NE(text.find("  tsai-lenz        100.000000  200.000000  301.000000      1.5000   3.0000"
                      "      0.0000    1.0000\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("  shah            refused: too few stations\n"), std::string::npos) << text;
}

// The pose level is X turned back by 2° about x and shifted by (3, 4, 0) mm: the refinement moved
// X by 2 deg and 5 mm. s3's image is flagged; the intrinsics before → after ± 1σ round to 7 and 5
// significant digits, the 1σ to 2.
TEST(ResultText, ImageSummaryLines) {
  ResultDocument document = Document();
  ImageReport images;
  images.pose_level.method = estimation::Method::kTsaiLenz;
  images.pose_level.X = document.results[0].X;
  images.pose_level.X.linear() *=
      Eigen::AngleAxisd(-2.0 * kRadiansPerDegree, Eigen::Vector3d::UnitX()).matrix();
  images.pose_level.X.translation() += Eigen::Vector3d(3e-3, 4e-3, 0.0);
  images.rms_px = 0.25;
  images.pixel_sigma = 0.1876;
  images.pixel_sigma_estimated = true;
  images.image_rms_px = {0.2, 1.5};
  images.image_outlier = {false, true};
  pose::CameraModel before;
  before.fx = 800.0;
  before.fy = 810.0;
  before.cx = 320.0;
  before.cy = 240.0;
  images.camera = before;
  images.camera.fx = 801.2345678;
  images.camera.distortion[0] = -0.123456;
  images.intrinsics_sigma =
      std::array<double, pose::kNumIntrinsics>{0.1234, 0.5, 0.25, 0.25, 0.00123, 0, 0, 0, 0};
  document.images = images;
  std::ostringstream out;
  PrintImageResultSummary(out, document, before);
  const std::string text = out.str();
  const auto has = [&](const std::string& line) {
    EXPECT_NE(text.find(line + "\n"), std::string::npos) << "missing: " << line << "\n" << text;
  };
  EXPECT_EQ(text.rfind("\npose level (tsai-lenz on the PnP poses), then the joint reprojection "
                       "refinement moved X by 2 deg, 5 mm\nmethod ml (eye-in-hand, 2 stations)\n",
                       0),
            0u)
      << text;
  has("intrinsics refined with X and Z (before → after ± 1σ):");
  has("  fx 800 → 801.2346 ± 0.12");
  has("  fy 810 → 810 ± 0.5");
  has("  k1 0 → -0.12346 ± 0.0012");
  has("reprojection: RMS 0.250 px over every point; pixel sigma 0.188 px (estimated)");
  has("  image          rms_px");
  has("  s1              0.200");
  has("  s3              1.500   > 3σ, check this image");
  EXPECT_LT(text.find("warning: a warning"), text.find("intrinsics refined"));
}

}  // namespace
}  // namespace hecal::report
