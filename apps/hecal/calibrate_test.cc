// `hecal calibrate` through RunHecal: the result file contract (docs/result-file.md) on real data
// (moveit-calibration, upstream answer in its SOURCE.md) and on synthetic data with known truth,
// `--method all`, units, and bad or degenerate input (exit 2, one line, no output file).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_test_util.h"
#include "hecal/estimation/methods.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/so3.h"
#include "hecal/sim/thesis_protocol.h"
#include "testing/pose_csv.h"

namespace hecal::cli {
namespace {

using cli_test::Hecal;
using cli_test::PoseOf;
using nlohmann::json;
using testing::PoseCsv;

const std::string kMoveIt = std::string(HECAL_SOURCE_DIR) + "/data/moveit-calibration/";

double AngleBetween(const Pose& a, const Pose& b) {
  return so3::Log(a.linear().transpose() * b.linear()).norm();
}

// covariance.method is the method asked for, with "+model_check" appended exactly when the model
// check inflated the covariance (covariance.model_check.used; docs/uncertainty.md).
void ExpectCovarianceMethod(const json& result, const std::string& method) {
  const json& covariance = result["covariance"];
  const bool used =
      covariance.contains("model_check") && covariance["model_check"].value("used", false);
  EXPECT_EQ(covariance["method"], used ? method + "+model_check" : method) << result["method"];
}

class CalibrateCommand : public cli_test::CliTest {
 protected:
  // Imports the bundled moveit samples into robot.csv / camera.csv.
  void ImportMoveIt() {
    const cli_test::Outcome run =
        Hecal({"import", "--format", "moveit", kMoveIt + "pose_samples.json", "--robot",
               Path("robot.csv"), "--camera", Path("camera.csv")});
    ASSERT_EQ(run.code, 0) << run.err;
  }

  // Thesis-protocol data (seeded) written to robot.csv / camera.csv in millimetres.
  sim::SimulatedData WriteSyntheticMm(handeye::Setup setup, int stations, uint64_t seed,
                                      double rotation_sigma, double translation_sigma) {
    std::mt19937_64 rng(seed);
    sim::ProtocolOptions options;
    options.setup = setup;
    options.stations = stations;
    const sim::NoiseModel noise{sim::NoiseModel::Kind::kGaussian, rotation_sigma,
                                translation_sigma};
    sim::SimulatedData data = sim::SimulateThesisProtocol(options, noise, noise, rng);
    Write("robot.csv", PoseCsv(data.T_base_gripper, 1e3, "_mm"));
    Write("camera.csv", PoseCsv(data.T_camera_target, 1e3, "_mm"));
    return data;
  }

  // Expects exit 2, one line on stderr containing `part`, and no result file.
  void ExpectRefused(std::vector<std::string> args, const std::string& part) {
    args.insert(args.end(), {"--output", Path("result.json")});
    const cli_test::Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 2) << run.out << run.err;
    EXPECT_NE(run.err.find(part), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(std::filesystem::exists(Path("result.json")));
  }
};

// Real data, default method: the result file follows docs/result-file.md and X meets the upstream
// expectation (t ≈ (0.659, −0.249, 0.830) m to 0.01).
TEST_F(CalibrateCommand, MoveItResultFileFollowsTheContract) {
  ImportMoveIt();
  const cli_test::Outcome run =
      Hecal({"calibrate", "--robot", Path("robot.csv"), "--camera", Path("camera.csv"), "--setup",
             "eye-to-hand", "--output", Path("result.json")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("method ml (eye-to-hand, 50 stations)"), std::string::npos) << run.out;
  const json result = json::parse(Read("result.json"));
  EXPECT_FALSE(result["hecal_version"].get<std::string>().empty());
  EXPECT_EQ(result["setup"], "eye-to-hand");
  EXPECT_EQ(result["method"], "ml");
  EXPECT_EQ(result["units"]["length"], "m");
  EXPECT_EQ(result["units"]["angle"], "rad");
  EXPECT_EQ(result["X"]["frame"], "T_base_camera");
  EXPECT_EQ(result["Z"]["frame"], "T_gripper_target");

  const Pose X = PoseOf(result["X"]);
  EXPECT_TRUE(X.translation().isApprox(Eigen::Vector3d(0.659, -0.249, 0.830), 0.01));
  for (int k = 0; k < 3; ++k)
    EXPECT_DOUBLE_EQ(result["X"]["translation"][k].get<double>(), X.translation()(k));
  const json& q = result["X"]["quaternion_wxyz"];
  const Eigen::Quaterniond quaternion(q[0].get<double>(), q[1].get<double>(), q[2].get<double>(),
                                      q[3].get<double>());
  EXPECT_NEAR(quaternion.norm(), 1.0, 1e-12);
  EXPECT_LT(so3::Log(quaternion.toRotationMatrix().transpose() * X.linear()).norm(), 1e-12);
  EXPECT_EQ(result["X"]["matrix"][3], json({0.0, 0.0, 0.0, 1.0}));

  // Covariance: 6×6, symmetric, positive diagonal, right perturbation.
  EXPECT_EQ(result["covariance"]["parameterization"], "right, (rx,ry,rz,tx,ty,tz)");
  for (const char* block : {"X", "Z"}) {
    const json& C = result["covariance"][block];
    ASSERT_EQ(C.size(), 6u);
    for (int r = 0; r < 6; ++r) {
      ASSERT_EQ(C[r].size(), 6u);
      EXPECT_GT(C[r][r].get<double>(), 0.0);
      for (int c = 0; c < 6; ++c) EXPECT_DOUBLE_EQ(C[r][c].get<double>(), C[c][r].get<double>());
    }
  }
  // t's 1σ along the parent frame's axes (eye-to-hand: X = T_base_camera in the base's, Z =
  // T_gripper_target in the gripper's): sqrt of the diagonal of R̂ C_tt R̂ᵀ from the file's own
  // matrix and covariance, written in the file's unit and printed in millimetres.
  for (const auto& [block, parent] : {std::pair{"X", "base"}, std::pair{"Z", "gripper"}}) {
    const json& in_parent = result["covariance"]["sigma"][block]["translation_in_parent"];
    EXPECT_EQ(in_parent["frame"], parent);
    Eigen::Matrix3d C_tt;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) C_tt(r, c) = result["covariance"][block][3 + r][3 + c];
    }
    const Eigen::Matrix3d R = PoseOf(result[block]).linear();
    const Eigen::Vector3d expected = (R * C_tt * R.transpose()).diagonal().cwiseSqrt();
    std::ostringstream line;
    line << "  1σ of " << block << "'s translation along the " << parent << "'s axes: (";
    const size_t at = run.out.find(line.str());
    ASSERT_NE(at, std::string::npos) << run.out;
    std::istringstream printed(run.out.substr(at + line.str().size()));
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(in_parent["translation"][k].get<double>(), expected(k), 1e-12 * expected(k));
      double mm = 0.0;
      printed >> mm;
      EXPECT_NEAR(mm, 1e3 * expected(k), 1e-6) << block << " axis " << k;
    }
  }
  // Residuals and stations: one per station, ids from the import.
  EXPECT_EQ(result["residuals"]["per_station"].size(), 50u);
  EXPECT_EQ(result["residuals"]["per_station"][0]["id"], "0");
  EXPECT_GT(result["residuals"]["rotation_rms_deg"].get<double>(), 0.0);
  EXPECT_LT(result["residuals"]["translation_rms"].get<double>(), 0.01);
  EXPECT_EQ(result["stations"]["used"].size(), 50u);
  EXPECT_TRUE(result["stations"]["rejected"].empty());
  // No sigmas given: estimated, and a warning says so.
  EXPECT_TRUE(result["noise"]["estimated"].get<bool>());
  ASSERT_FALSE(result["warnings"].empty());
  EXPECT_NE(result["warnings"][0].get<std::string>().find("estimated"), std::string::npos);
}

// Every method side by side; each meets the upstream expectation; YAML by extension.
TEST_F(CalibrateCommand, AllMethodsSideBySide) {
  ImportMoveIt();
  const cli_test::Outcome run =
      Hecal({"calibrate", "--robot", Path("robot.csv"), "--camera", Path("camera.csv"), "--setup",
             "eye-to-hand", "--method", "all", "--output", Path("all.json")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("side by side"), std::string::npos);
  const json all = json::parse(Read("all.json"));
  ASSERT_EQ(all["results"].size(), estimation::AllMethods().size());
  size_t k = 0;
  for (const estimation::MethodInfo& info : estimation::AllMethods()) {
    const json& result = all["results"][k++];
    EXPECT_EQ(result["method"], std::string(info.name));
    EXPECT_TRUE(
        PoseOf(result["X"]).translation().isApprox(Eigen::Vector3d(0.659, -0.249, 0.830), 0.01))
        << info.name;
    // Every method carries a covariance: ml's linear one, the UT through the others.
    ASSERT_TRUE(result.contains("covariance")) << info.name;
    ExpectCovarianceMethod(result, info.method == estimation::Method::kMl ? "linear" : "unscented");
  }
  const cli_test::Outcome yaml =
      Hecal({"calibrate", "--robot", Path("robot.csv"), "--camera", Path("camera.csv"), "--setup",
             "eye-to-hand", "--method", "shah", "--output", Path("shah.yaml")});
  ASSERT_EQ(yaml.code, 0) << yaml.err;
  EXPECT_NE(Read("shah.yaml").find("method: shah"), std::string::npos) << Read("shah.yaml");
}

// Synthetic thesis-protocol data in millimetres with known truth and given noise: the result is
// in mm (translations and the covariance's translation block) and X is within 4σ of the truth.
TEST_F(CalibrateCommand, SyntheticDataInMillimetresWithGivenNoise) {
  const sim::SimulatedData data =
      WriteSyntheticMm(handeye::Setup::kEyeInHand, 20, 5, 0.2 * kRadiansPerDegree, 0.5e-3);
  const cli_test::Outcome run =
      Hecal({"calibrate", "--robot", Path("robot.csv"), "--camera", Path("camera.csv"), "--setup",
             "eye-in-hand", "--robot-sigma", "0.5,0.2", "--camera-sigma", "0.5,0.2", "--output",
             Path("result.json")});
  ASSERT_EQ(run.code, 0) << run.err;
  const json result = json::parse(Read("result.json"));
  EXPECT_EQ(result["units"]["length"], "mm");
  EXPECT_FALSE(result["noise"]["estimated"].get<bool>());
  EXPECT_NEAR(result["noise"]["robot_sigma"]["translation"].get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(result["noise"]["robot_sigma"]["rotation_deg"].get<double>(), 0.2, 1e-12);
  EXPECT_EQ(result["residuals"]["per_station"][3]["id"], "s3");

  Pose X = PoseOf(result["X"]);
  X.translation() *= 1e-3;
  const json& C = result["covariance"]["X"];
  double rotation_sd = 0.0, translation_sd = 0.0;  // metres
  for (int k = 0; k < 3; ++k) {
    rotation_sd += C[k][k].get<double>();
    translation_sd += C[k + 3][k + 3].get<double>() * 1e-6;
  }
  rotation_sd = std::sqrt(rotation_sd);
  translation_sd = std::sqrt(translation_sd);
  EXPECT_GT(translation_sd, 1e-4);  // mm² scaled back: a millimetre-level 1σ, not m²
  EXPECT_LT(translation_sd, 1e-2);
  EXPECT_LT(AngleBetween(X, data.X), 4.0 * rotation_sd);
  EXPECT_LT((X.translation() - data.X.translation()).norm(), 4.0 * translation_sd);
}

// Many stations: the printout lists the 20 largest whitened residuals instead of every station
// (the result file keeps them all), and a covariance propagated through the solver, which needs
// a dense 12n x 12n input, is refused above 500 stations before anything is written.
TEST_F(CalibrateCommand, ManyStationsPrintTheLargestResidualsAndBoundTheCovariance) {
  WriteSyntheticMm(handeye::Setup::kEyeInHand, 501, 9, 0.2 * kRadiansPerDegree, 0.5e-3);
  const std::vector<std::string> args = {
      "calibrate", "--robot",     Path("robot.csv"), "--camera",  Path("camera.csv"),
      "--setup",   "eye-in-hand", "--method",        "tsai-lenz", "--keep-outliers"};
  std::vector<std::string> with_output = args;
  with_output.insert(with_output.end(), {"--output", Path("result.json")});
  const cli_test::Outcome run = Hecal(with_output);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("the 20 largest of 501 stations"), std::string::npos) << run.out;
  EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n') < 80, true) << run.out;
  const json result = json::parse(Read("result.json"));
  EXPECT_EQ(result["residuals"]["per_station"].size(), 501u);
  // The information covariance, inflated by the model check when it finds the model's σ too
  // small (a closed form's information is a lower bound: model_check.h).
  const std::string method = result["covariance"]["method"];
  EXPECT_EQ(method, result["covariance"]["model_check"]["used"].get<bool>()
                        ? "information+model_check"
                        : "information");
  std::filesystem::remove(Path("result.json"));
  std::vector<std::string> unscented = args;
  unscented.insert(unscented.end(), {"--covariance", "unscented"});
  ExpectRefused(unscented, "at most 500 stations, got 501");
}

// --covariance: the UT and a seeded Monte Carlo through park-martin on the same synthetic data;
// the UT's σ per axis is within 10% (+ 3 standard errors) of the Monte Carlo's, the file says
// how it was computed, and the same seed writes the same file.
TEST_F(CalibrateCommand, CovarianceMethodsAgreeAndMonteCarloIsSeeded) {
  WriteSyntheticMm(handeye::Setup::kEyeToHand, 12, 6, 0.5 * kRadiansPerDegree, 1e-3);
  const std::vector<std::string> base = {"calibrate",
                                         "--robot",
                                         Path("robot.csv"),
                                         "--camera",
                                         Path("camera.csv"),
                                         "--setup",
                                         "eye-to-hand",
                                         "--method",
                                         "park-martin",
                                         "--robot-sigma",
                                         "1,0.5",
                                         "--camera-sigma",
                                         "1,0.5"};
  auto run = [&](std::vector<std::string> extra, const std::string& file) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    args.insert(args.end(), {"--output", Path(file)});
    const cli_test::Outcome outcome = Hecal(args);
    EXPECT_EQ(outcome.code, 0) << outcome.err;
    return json::parse(Read(file));
  };
  const json ut = run({}, "ut.json");  // park-martin's default
  ExpectCovarianceMethod(ut, "unscented");
  EXPECT_EQ(ut["covariance"]["solves"], 1 + 24 * 12);
  const json mc =
      run({"--covariance", "montecarlo", "--covariance-samples", "1000", "--seed", "4"}, "mc.json");
  ExpectCovarianceMethod(mc, "montecarlo");
  EXPECT_EQ(mc["covariance"]["samples"], 1000);
  EXPECT_EQ(mc["covariance"]["failed_samples"], 0);
  for (const char* block : {"X", "Z"}) {
    for (const char* part : {"rotation_deg", "translation"}) {
      for (int k = 0; k < 3; ++k) {
        const double a = ut["covariance"]["sigma"][block][part][k].get<double>();
        const double b = mc["covariance"]["sigma"][block][part][k].get<double>();
        const double se = mc["covariance"]["sigma_std_error"][block][part][k].get<double>();
        EXPECT_NEAR(a, b, 0.1 * b + 3.0 * se) << block << " " << part << " " << k;
      }
    }
  }
  const json again = run({"--covariance", "montecarlo", "--covariance-samples", "1000", "--seed",
                          "4", "--threads", "1"},
                         "again.json");
  EXPECT_EQ(again["covariance"], mc["covariance"]);  // same seed, any thread count
  const json linear = run({"--covariance", "linear"}, "linear.json");
  ExpectCovarianceMethod(linear, "linear");
}

TEST_F(CalibrateCommand, BadFlagsAreRefused) {
  ImportMoveIt();
  const std::vector<std::string> base = {"calibrate",  "--robot",          Path("robot.csv"),
                                         "--camera",   Path("camera.csv"), "--setup",
                                         "eye-to-hand"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  ExpectRefused(with({"--method", "magic"}), "unknown method 'magic'");
  ExpectRefused(with({"--robot-sigma", "1"}), "--robot-sigma");
  ExpectRefused(with({"--camera-sigma", "1,-2"}), "--camera-sigma");
  ExpectRefused(with({"--units", "inch"}), "unknown unit");
  ExpectRefused(with({"--robust", "tukey"}), "unknown loss");
  ExpectRefused(with({"--covariance", "bootstrap"}), "unknown covariance method 'bootstrap'");
  ExpectRefused(with({"--covariance", "none"}), "unknown covariance method 'none'");
  ExpectRefused(with({"--covariance", "montecarlo", "--covariance-samples", "1"}),
                "--covariance-samples");
  // Flags of the --images form are not silently ignored with --camera.
  ExpectRefused(with({"--target", "target.yaml"}), "--target applies to --images only");
  ExpectRefused(with({"--refine-intrinsics"}), "--refine-intrinsics applies to --images only");
  ExpectRefused({"calibrate", "--robot", Path("robot.csv"), "--camera", Path("camera.csv"),
                 "--setup", "on-the-desk"},
                "unknown setup");
}

TEST_F(CalibrateCommand, MismatchedTablesNameTheFile) {
  ImportMoveIt();
  std::string robot = Read("robot.csv");
  robot.erase(robot.rfind('\n', robot.size() - 2) + 1);  // drop the last station
  Write("short.csv", robot);
  ExpectRefused({"calibrate", "--robot", Path("short.csv"), "--camera", Path("camera.csv"),
                 "--setup", "eye-to-hand"},
                "49");
}

// Degenerate data (noise-free, all rotations about one axis): exit 2 naming the unobservable
// part — for one method and for all.
TEST_F(CalibrateCommand, DegenerateDataNameTheUnobservablePart) {
  std::vector<Pose> robot, camera;
  const Pose X = MakePose(so3::Exp(Eigen::Vector3d(0.1, 0.2, 0.3)), Eigen::Vector3d(0.05, 0, 0.1));
  const Pose Z = MakePose(so3::Exp(Eigen::Vector3d(0.3, -0.2, 1.0)), Eigen::Vector3d(0.8, 0.1, 0));
  for (int i = 0; i < 8; ++i) {
    const Pose A = MakePose(so3::Exp(Eigen::Vector3d(0, 0, 0.3 * i)),
                            Eigen::Vector3d(0.1 * i, 0.02 * i * i, 0.3));
    robot.push_back(A);
    camera.push_back(X.inverse() * A.inverse() * Z);
  }
  Write("robot.csv", PoseCsv(robot, 1.0, ""));
  Write("camera.csv", PoseCsv(camera, 1.0, ""));
  for (const char* method : {"ml", "all", "tsai-lenz"}) {
    ExpectRefused({"calibrate", "--robot", Path("robot.csv"), "--camera", Path("camera.csv"),
                   "--setup", "eye-in-hand", "--method", method},
                  "cannot observe the translation of X (T_gripper_camera) along");
  }
}

}  // namespace
}  // namespace hecal::cli
