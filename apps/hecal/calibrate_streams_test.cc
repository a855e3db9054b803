// `hecal calibrate --streams` on real data (data/ethz-robot-arm: ETH's robot arm with an SR300,
// a 50 Hz robot stream and a 30 Hz camera stream on unsynchronised clocks; its SOURCE.md's
// reference X from OpenCV PARK on 57 nearest-stamp pairs, tolerance 1° / 1 cm) and the refusals
// of bad streams.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

using cli_test::CliTest;
using cli_test::Hecal;
using ::testing::HasSubstr;

class CalibrateStreamsTest : public CliTest {
 protected:
  void Import() {
    const std::string dir = std::string(HECAL_SOURCE_DIR) + "/data/ethz-robot-arm/";
    const cli_test::Outcome run =
        Hecal({"import", "--format", "ethz",
               dir + "robot_arm_complete_bag_color_and_ir_base_link_sr300_hinge.csv",
               dir + "robot_arm_complete_bag_color_and_ir_target_ir.csv", "--robot",
               Path("robot.csv"), "--camera", Path("camera.csv")});
    ASSERT_EQ(run.code, 0) << run.err;
  }
  nlohmann::json Calibrate(const std::vector<std::string>& extra) {
    std::vector<std::string> args = {
        "calibrate", "--robot", Path("robot.csv"), "--camera", Path("camera.csv"),
        "--streams", "--setup", "eye-in-hand",     "--output", Path("result.json")};
    args.insert(args.end(), extra.begin(), extra.end());
    const cli_test::Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 0) << run.err;
    EXPECT_THAT(run.out, HasSubstr("time offset (camera stamp t = robot time t + offset)"));
    return nlohmann::json::parse(Read("result.json"));
  }
};

TEST_F(CalibrateStreamsTest, EthRobotArmInOneCommand) {
  Import();
  const nlohmann::json fitted = Calibrate({});
  // X = T_gripper_camera against SOURCE.md's reference (rotation matrix and translation in m).
  Eigen::Matrix3d R_reference;
  R_reference << 0.45313, -0.01182, 0.89136, -0.89144, -0.00894, 0.45305, 0.00261, -0.99989,
      -0.01459;
  const Eigen::Vector3d t_reference(0.00019, -0.01594, 0.00522);
  Eigen::Matrix3d R;
  Eigen::Vector3d t;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) R(r, c) = fitted["X"]["matrix"][r][c];
    t(r) = fitted["X"]["matrix"][r][3];
  }
  const double angle = Eigen::AngleAxisd(R_reference.transpose() * R).angle();
  EXPECT_LT(angle, 1.0 * M_PI / 180);         // measured 0.78°
  EXPECT_LT((t - t_reference).norm(), 0.01);  // measured 1.8 mm
  // The offset: about −15 ms (the camera's stamps lag), with a σ well under a millisecond.
  const nlohmann::json& offset = fitted["time_offset"];
  EXPECT_TRUE(offset["estimated"].get<bool>());
  EXPECT_NEAR(offset["seconds"].get<double>(), -0.0155, 0.005);
  EXPECT_GT(offset["sigma"].get<double>(), 0.0);
  EXPECT_LT(offset["sigma"].get<double>(), 0.002);
  EXPECT_EQ(fitted["streams"]["robot_samples"], 2817);
  EXPECT_EQ(fitted["streams"]["camera_samples"], 1703);
  EXPECT_EQ(fitted["streams"]["stations_from"], "camera");
  // Without the offset (paired as if the clocks agreed) the fit is measurably worse: measured
  // 4.27 against 3.76 mm of translation RMS, and the robot's rotation noise estimated at 0.047°
  // against 0.0039° (the 16 ms of motion are taken for robot noise).
  const nlohmann::json unsynchronised = Calibrate({"--time-offset", "0"});
  EXPECT_FALSE(unsynchronised["time_offset"]["estimated"].get<bool>());
  EXPECT_GT(unsynchronised["residuals"]["translation_rms"].get<double>(),
            1.08 * fitted["residuals"]["translation_rms"].get<double>());
  EXPECT_GT(unsynchronised["noise"]["robot_sigma"]["rotation_deg"].get<double>(),
            3.0 * fitted["noise"]["robot_sigma"]["rotation_deg"].get<double>());
}

TEST_F(CalibrateStreamsTest, BadStreamsAreRefusedNamingTheLine) {
  Write("robot.csv",
        "stamp,x,y,z,qw,qx,qy,qz\n0,0,0,0,1,0,0,0\n0.02,0,0,0,1,0,0,0\n0.01,0,0,0,1,0,0,0\n");
  Write("camera.csv", "stamp,x,y,z,qw,qx,qy,qz\n0,0,0,1,1,0,0,0\n0.1,0,0,1,1,0,0,0\n");
  const std::vector<std::string> args = {
      "calibrate", "--robot", Path("robot.csv"), "--camera", Path("camera.csv"),
      "--streams", "--setup", "eye-in-hand",     "--output", Path("out.json")};
  const cli_test::Outcome unsorted = Hecal(args);
  EXPECT_EQ(unsorted.code, 2);
  EXPECT_THAT(unsorted.err, HasSubstr(Path("robot.csv") + ":4:"));
  EXPECT_THAT(unsorted.err, HasSubstr("goes back in time"));
  EXPECT_FALSE(std::filesystem::exists(Path("out.json")));
  // Streams of different recordings.
  Write("robot.csv", "stamp,x,y,z,qw,qx,qy,qz\n0,0,0,0,1,0,0,0\n0.02,0,0,0,1,0,0,0\n");
  Write("camera.csv", "stamp,x,y,z,qw,qx,qy,qz\n100,0,0,1,1,0,0,0\n100.1,0,0,1,1,0,0,0\n");
  const cli_test::Outcome disjoint = Hecal(args);
  EXPECT_EQ(disjoint.code, 2);
  EXPECT_THAT(disjoint.err, HasSubstr("does not overlap the robot stream"));
  // A stream flag without --streams.
  const cli_test::Outcome flag =
      Hecal({"calibrate", "--robot", Path("robot.csv"), "--camera", Path("camera.csv"), "--setup",
             "eye-in-hand", "--time-offset", "0.1"});
  EXPECT_EQ(flag.code, 2);
  EXPECT_THAT(flag.err, HasSubstr("--time-offset applies to --streams only"));
}

}  // namespace
}  // namespace hecal::cli
