// `hecal calibrate --target-scale` (docs/target-scale.md) on simulated stations seen through a
// board printed at 96 % of its description, both setups: by default the scale is measured,
// named in a warning and applied (X and Z within 3 mm of the truth); `stated` keeps the described
// size (Z 20 mm off) and still says it; a given 0.96 recovers X with nothing estimated; a correct
// board is not flagged; every result carries the certificate; the flag's mistakes are refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "cli_test_util.h"
#include "testing/scene.h"

namespace hecal::cli {
namespace {

using cli_test::CliTest;
using cli_test::Hecal;
using ::testing::HasSubstr;

class CalibrateTargetScaleTest : public CliTest {
 protected:
  // 15 stations, the camera 0.5 m from the board, 0.1° / 0.5 mm per component; the camera
  // poses as a PnP with the described size gives them for a board printed at `printed`.
  testing::Scene WriteScene(handeye::Setup setup, double printed) {
    std::mt19937_64 rng(7);
    testing::SceneOptions options;
    options.setup = setup;
    options.start_distance = 0.5;
    options.cube_side = 0.3;
    options.hand_eye_offset = 0.1;
    options.robot_noise = options.camera_noise = {0.1 * M_PI / 180.0, 0.5e-3};
    const testing::Scene scene = testing::MakeScene(options, rng);
    io::PoseTable robot, camera;
    for (size_t i = 0; i < scene.T_base_gripper.size(); ++i) {
      Pose seen = scene.T_camera_target[i];
      seen.translation() /= printed;
      robot.rows.push_back({scene.T_base_gripper[i], std::nullopt, std::nullopt, 0});
      camera.rows.push_back({seen, std::nullopt, std::nullopt, 0});
    }
    Write("robot.csv", io::FormatPoseTable(robot, {}));
    Write("camera.csv", io::FormatPoseTable(camera, {}));
    return scene;
  }
  cli_test::Outcome Calibrate(handeye::Setup setup, const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"calibrate",
                                     "--robot",
                                     Path("robot.csv"),
                                     "--camera",
                                     Path("camera.csv"),
                                     "--setup",
                                     std::string(handeye::SetupName(setup)),
                                     "--output",
                                     Path("result.json")};
    args.insert(args.end(), extra.begin(), extra.end());
    return Hecal(args);
  }
  nlohmann::json Result() { return nlohmann::json::parse(Read("result.json")); }
};

// X's translation error in units of its σ along the parent frame's axes (the largest).
double WorstSigmas(const nlohmann::json& result, const Pose& truth) {
  const Pose X = cli_test::PoseOf(result["X"]);
  const auto& sigma = result["covariance"]["sigma"]["X"]["translation_in_parent"]["translation"];
  double worst = 0.0;
  for (int k = 0; k < 3; ++k) {
    worst = std::max(worst, std::abs(X.translation()(k) - truth.translation()(k)) /
                                sigma[static_cast<size_t>(k)].get<double>());
  }
  return worst;
}

// The larger translation error of X and Z (a board's scale moves one or both: here mostly Z,
// the target's position, by (1 − scale) × the camera–target distance).
double TranslationError(const nlohmann::json& result, const testing::Scene& scene) {
  return std::max((cli_test::PoseOf(result["X"]).translation() - scene.X.translation()).norm(),
                  (cli_test::PoseOf(result["Z"]).translation() - scene.Z.translation()).norm());
}

TEST_F(CalibrateTargetScaleTest, AMisprintedBoardIsMeasuredNamedAndApplied) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::Scene scene = WriteScene(setup, 0.96);
    const cli_test::Outcome run = Calibrate(setup, {});
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_THAT(run.out + run.err, HasSubstr("not the size its description states"));
    EXPECT_THAT(run.out, HasSubstr("X and Z at the measured size"));
    const nlohmann::json result = Result();
    const nlohmann::json& target = result["target"];
    EXPECT_TRUE(target["mismatch"].get<bool>());
    EXPECT_NEAR(target["scale"].get<double>(), 0.96, 3 * target["scale_sigma"].get<double>());
    EXPECT_EQ(target["applied_scale"], target["scale"]);
    EXPECT_LT(WorstSigmas(result, scene.X), 3.0);
    EXPECT_TRUE(result["certificate"]["certified"].get<bool>());

    const double error = TranslationError(result, scene);
    EXPECT_LT(error, 3e-3);

    // stated: the described size, Z ~20 mm off, the mismatch still said.
    const cli_test::Outcome stated = Calibrate(setup, {"--target-scale", "stated"});
    ASSERT_EQ(stated.code, 0) << stated.err;
    EXPECT_THAT(stated.out + stated.err, HasSubstr("--target-scale stated asks"));
    EXPECT_EQ(Result()["target"]["applied_scale"].get<double>(), 1.0);
    EXPECT_GT(TranslationError(Result(), scene), 10e-3);

    // A given scale: applied, nothing estimated.
    const cli_test::Outcome given = Calibrate(setup, {"--target-scale", "0.96"});
    ASSERT_EQ(given.code, 0) << given.err;
    EXPECT_TRUE(Result()["target"]["given"].get<bool>());
    EXPECT_LT(WorstSigmas(Result(), scene.X), 3.0);
  }
}

TEST_F(CalibrateTargetScaleTest, ACorrectBoardIsNotFlagged) {
  const testing::Scene scene = WriteScene(handeye::Setup::kEyeInHand, 1.0);
  const cli_test::Outcome run = Calibrate(handeye::Setup::kEyeInHand, {});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_THAT(run.out + run.err, ::testing::Not(HasSubstr("description states")));
  const nlohmann::json result = Result();
  EXPECT_FALSE(result["target"]["mismatch"].get<bool>());
  // Answered at the measured size all the same (within its σ of 1).
  EXPECT_EQ(result["target"]["applied_scale"], result["target"]["scale"]);
  EXPECT_LT(WorstSigmas(result, scene.X), 3.0);
}

TEST_F(CalibrateTargetScaleTest, TheFlagsMistakesAreRefused) {
  WriteScene(handeye::Setup::kEyeInHand, 1.0);
  for (const char* bad : {"96%", "0", "3", "auto", ""}) {
    const cli_test::Outcome run = Calibrate(handeye::Setup::kEyeInHand, {"--target-scale", bad});
    EXPECT_EQ(run.code, 2) << bad;
    EXPECT_THAT(run.err, HasSubstr("--target-scale")) << bad;
    EXPECT_FALSE(std::filesystem::exists(Path("result.json")));
  }
}

}  // namespace
}  // namespace hecal::cli
