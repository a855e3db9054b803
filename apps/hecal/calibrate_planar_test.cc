// `hecal calibrate --fix` on a simulated SCARA (sim/planar_robot.h; docs/planar.md): without the
// flag the run stops naming the free component and the flag; with it X and Z come back, the
// fixed component exactly; the flag's mistakes are refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "cli_test_util.h"
#include "hecal/sim/planar_robot.h"

namespace hecal::cli {
namespace {

using cli_test::CliTest;
using cli_test::Hecal;
using ::testing::HasSubstr;

class CalibratePlanarTest : public CliTest {
 protected:
  // 15 SCARA stations at 0.2 mm / 0.2° on every pose; the robot file in millimetres (x_mm …).
  sim::PlanarScene WriteScene(handeye::Setup setup) {
    std::mt19937_64 rng(5);
    sim::NoiseModel noise;
    noise.rotation_sigma = 0.2 * M_PI / 180.0;
    noise.translation_sigma = 0.2e-3;
    const sim::PlanarScene scene = sim::DrawPlanarScene(setup, 15, noise, noise, rng);
    const auto table = [](const std::vector<Pose>& poses) {
      io::PoseTable out;
      for (const Pose& pose : poses) out.rows.push_back({pose, std::nullopt, std::nullopt, 0});
      return out;
    };
    io::PoseWriteOptions millimetres;
    millimetres.units = io::LengthUnit::kMillimetre;
    Write("robot.csv", io::FormatPoseTable(table(scene.T_base_gripper), millimetres));
    Write("camera.csv", io::FormatPoseTable(table(scene.T_camera_target), {}));
    return scene;
  }
  cli_test::Outcome Calibrate(handeye::Setup setup, const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"calibrate",  "--robot",  Path("robot.csv"),
                                     "--camera",   Path("camera.csv"), "--setup",
                                     std::string(handeye::SetupName(setup)), "--output",
                                     Path("result.json")};
    args.insert(args.end(), extra.begin(), extra.end());
    return Hecal(args);
  }
};

TEST_F(CalibratePlanarTest, WithoutFixTheRunNamesTheFreeComponentAndTheFlag) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    WriteScene(setup);
    const cli_test::Outcome run = Calibrate(setup, {});
    EXPECT_EQ(run.code, 2) << run.out;
    EXPECT_THAT(run.err, HasSubstr("translation of X"));
    EXPECT_THAT(run.err, HasSubstr("--fix tz=VALUE"));
    EXPECT_FALSE(std::filesystem::exists(Path("result.json")));
  }
}

TEST_F(CalibratePlanarTest, WithFixXAndZComeBack) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const sim::PlanarScene scene = WriteScene(setup);
    const double tz_mm = scene.X.translation().z() * 1e3;
    const cli_test::Outcome run = Calibrate(setup, {"--fix", "tz=" + std::to_string(tz_mm) + "mm"});
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_THAT(run.out, HasSubstr("fixed: tz of X"));
    const nlohmann::json result = nlohmann::json::parse(Read("result.json"));
    ASSERT_TRUE(result.contains("fixed"));
    EXPECT_EQ(result["fixed"]["component"], "tz");
    EXPECT_EQ(result["units"]["length"], "mm");
    Eigen::Matrix4d X, Z;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        X(r, c) = result["X"]["matrix"][r][c];
        Z(r, c) = result["Z"]["matrix"][r][c];
      }
    }
    EXPECT_NEAR(X(2, 3), tz_mm, 1e-6);
    const double angle =
        Eigen::AngleAxisd(scene.X.linear().transpose() * X.topLeftCorner<3, 3>()).angle();
    EXPECT_LT(angle, 0.5 * M_PI / 180.0) << handeye::SetupName(setup);
    EXPECT_LT((X.topRightCorner<3, 1>() - 1e3 * scene.X.translation()).norm(), 3.0);
    EXPECT_LT((Z.topRightCorner<3, 1>() - 1e3 * scene.Z.translation()).norm(), 3.0);
  }
}

TEST_F(CalibratePlanarTest, TheFlagsMistakesAreRefused) {
  WriteScene(handeye::Setup::kEyeInHand);
  const auto refused = [&](const std::vector<std::string>& extra, const std::string& words) {
    const cli_test::Outcome run = Calibrate(handeye::Setup::kEyeInHand, extra);
    EXPECT_EQ(run.code, 2) << run.out;
    EXPECT_THAT(run.err, HasSubstr("--fix"));
    EXPECT_THAT(run.err, HasSubstr(words));
  };
  refused({"--fix", "tx=40mm"}, "fix tz instead");            // across the axis
  refused({"--fix", "tz=60"}, "give the unit");               // 60 m: millimetres meant
  refused({"--fix", "rz=0.1"}, "tx, ty or tz");               // not a translation
  refused({"--fix", "tz=6mm", "--method", "park-martin"}, "ml");
  refused({"--fix", "tz=6mm", "--method", "all"}, "ml");
  refused({"--fix", "tz=six"}, "a number");
  const cli_test::Outcome images =
      Hecal({"calibrate", "--robot", Path("robot.csv"), "--images", Path("."), "--target",
             Path("target.yaml"), "--setup", "eye-in-hand", "--fix", "tz=6mm"});
  EXPECT_EQ(images.code, 2);
  EXPECT_THAT(images.err, HasSubstr("hecal detect"));
}

}  // namespace
}  // namespace hecal::cli
