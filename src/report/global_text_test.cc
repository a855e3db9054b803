// The target-free summary against lines written by hand for a result whose numbers are known: X a
// quarter turn about z at (100, 200, 300) mm with 1σ (1, 2, 3) mm along the camera's axes — (2, 1,
// 3) mm along the gripper's — and a certificate, noise levels and match counts chosen to show the
// rounding to 4 significant digits.
#include "hecal/report/global_text.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace hecal::report {
namespace {

GlobalCalibrationResult QuarterTurn() {
  GlobalCalibrationResult result;
  result.options.setup = handeye::Setup::kEyeInHand;
  estimation::EpipolarPolish& polish = result.robot_noise.polish;
  polish.X.linear() << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  polish.X.translation() << 0.1, 0.2, 0.3;
  polish.covariance.diagonal() << 1e-6, 4e-6, 9e-6, 1e-6, 4e-6, 9e-6;
  result.noise = {0.001, 0.0005, 0.0002};
  result.certificate = {0.00123456, 0.00234567, 1234, 5678, 1.23456, true};
  result.inliers = 100;
  result.removed.resize(2);
  result.threshold = 0.0123456;
  return result;
}

std::string Text(const GlobalCalibrationResult& result, io::LengthUnit unit) {
  std::ostringstream out;
  PrintGlobalSummary(out, result, unit);
  return out.str();
}

TEST(GlobalText, SummaryLines) {
  const std::string text = Text(QuarterTurn(), io::LengthUnit::kMillimetre);
  const auto has = [&](const std::string& line) {
    EXPECT_NE(text.find(line + "\n"), std::string::npos) << "missing: " << line << "\n" << text;
  };
  EXPECT_EQ(text.rfind("method global (eye-in-hand, target-free)\nT_gripper_camera: rotation "
                       "vector [rad] ",
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("1.5708, translation [mm] 100 200 300\n"), std::string::npos) << text;
  has("  1 sigma: rotation [rad] 0.001 0.002 0.003, translation [mm] 1 2 3");
  has("  1 sigma of the translation along the gripper's axes [mm] 2 1 3");
  has("  noise (estimated): ray [rad] 0.001, robot per pose: rotation [rad] 0.0005, translation "
      "[mm] 0.2");
  has("certificate: max ray error in [0.001235, 0.002346] rad (certified), 1234 cubes, 5678 LPs, "
      "1.235 s");
  has("matches: 100 inliers, 2 removed (L∞ threshold 0.01235 rad, then the re-check at the "
      "polished X)");
}

TEST(GlobalText, RobotGivenMetresAndAnOpenGap) {
  GlobalCalibrationResult result = QuarterTurn();
  result.robot_noise.robot_given = true;
  result.certificate.certified = false;
  result.options.setup = handeye::Setup::kEyeToHand;
  const std::string text = Text(result, io::LengthUnit::kMetre);
  EXPECT_EQ(text.rfind("method global (eye-to-hand, target-free)\nT_base_camera: ", 0), 0u) << text;
  EXPECT_NE(text.find(", translation [m] 0.1 0.2 0.3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("along the base's axes [m] 0.002 0.001 0.003\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  noise (robot given, ray estimated): ray [rad] 0.001, robot per pose: "
                      "rotation [rad] 0.0005, translation [m] 0.0002\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("rad (gap not closed), 1234 cubes"), std::string::npos) << text;
}

}  // namespace
}  // namespace hecal::report
