// `hecal calibrate` on the mistakes real users make (handeye/convention_check.h,
// estimation/plausibility.h, estimation/station_selection.h): each ends in a refusal (exit 2, one
// line naming the fix, no result file) or a result with a warning that names it — never a silent
// wrong answer. Simulated data with known truth, and the bundled real sets (camodocal-artag,
// eye-to-hand with one gross outlier; moveit-calibration, eye-to-hand; tabb-rwhe-dataset1,
// 6-decimal rotation matrices).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/so3.h"
#include "hecal/sim/gross_outliers.h"
#include "hecal/sim/thesis_protocol.h"

namespace hecal::cli {
namespace {

using cli_test::Hecal;
using cli_test::kData;
using cli_test::PoseOf;
using nlohmann::json;

// How a pose file is written.
struct Layout {
  double scale = 1.0;   // lengths multiplied by this
  std::string suffix;   // "" (unit not named), "_m" or "_mm"
  bool invert = false;  // write T⁻¹
  bool xyzw = false;    // quaternion values in x,y,z,w order under qw,qx,qy,qz names
};
Layout Plain() {
  return {};
}
Layout Scaled(double scale, const std::string& suffix = "") {
  return {scale, suffix, false, false};
}
Layout Inverted() {
  return {1.0, "", true, false};
}
Layout Xyzw() {
  return {1.0, "", false, true};
}

std::string PoseCsv(const std::vector<Pose>& poses, const Layout& layout) {
  std::ostringstream csv;
  csv.precision(17);
  const std::string& u = layout.suffix;
  csv << "id,x" << u << ",y" << u << ",z" << u << ",qw,qx,qy,qz\n";
  for (size_t i = 0; i < poses.size(); ++i) {
    const Pose T = layout.invert ? Pose(poses[i].inverse()) : poses[i];
    const Eigen::Quaterniond q(T.linear());
    const Eigen::Vector3d t = T.translation() * layout.scale;
    csv << "s" << i << "," << t.x() << "," << t.y() << "," << t.z() << ",";
    if (layout.xyzw) {
      csv << q.x() << "," << q.y() << "," << q.z() << "," << q.w() << "\n";
    } else {
      csv << q.w() << "," << q.x() << "," << q.y() << "," << q.z() << "\n";
    }
  }
  return csv.str();
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

bool AnyWarningContains(const json& result, const std::string& part) {
  for (const json& warning : result["warnings"])
    if (Contains(warning.get<std::string>(), part)) return true;
  return false;
}

class CalibrateConventions : public cli_test::CliTest {
 protected:
  // Thesis-protocol data, 20 stations, 1 mm / 1°.
  static sim::SimulatedData Simulate(handeye::Setup setup, uint64_t seed) {
    std::mt19937_64 rng(seed);
    sim::ProtocolOptions options;
    options.setup = setup;
    options.stations = 20;
    const sim::NoiseModel noise{sim::NoiseModel::Kind::kGaussian, kRadiansPerDegree, 1e-3};
    return sim::SimulateThesisProtocol(options, noise, noise, rng);
  }

  void WriteData(const sim::SimulatedData& data, const Layout& robot, const Layout& camera) {
    Write("robot.csv", PoseCsv(data.T_base_gripper, robot));
    Write("camera.csv", PoseCsv(data.T_camera_target, camera));
  }

  std::vector<std::string> Args(const std::string& setup) const {
    return {"calibrate", "--robot", Path("robot.csv"), "--camera",         Path("camera.csv"),
            "--setup",   setup,     "--output",        Path("result.json")};
  }

  // Exit 2, one line on stderr holding every part, no result file.
  cli_test::Outcome ExpectRefused(const std::vector<std::string>& args,
                                  const std::vector<std::string>& parts) {
    std::filesystem::remove(Path("result.json"));
    const cli_test::Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 2) << run.out << run.err;
    for (const std::string& part : parts) EXPECT_TRUE(Contains(run.err, part)) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(std::filesystem::exists(Path("result.json")));
    return run;
  }

  json ExpectSolved(const std::vector<std::string>& args) {
    const cli_test::Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 0) << run.err;
    if (run.code != 0) return json::object({{"warnings", json::array()}, {"X", json::object()}});
    last_out_ = run.out;
    return json::parse(Read("result.json"));
  }

  std::string last_out_;
};

// Robot poses given inverted (T_gripper_base), both setups: refused, naming --robot-inverse and
// both residuals; with the flag the result is right.
TEST_F(CalibrateConventions, InvertedRobotFileIsNamed) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const std::string name(handeye::SetupName(setup));
    const sim::SimulatedData data = Simulate(setup, 11);
    WriteData(data, Inverted(), Plain());
    ExpectRefused(Args(name), {"robot poses inverted", "--robot-inverse", "median station residual",
                               "against", "as given"});
    std::vector<std::string> fixed = Args(name);
    fixed.push_back("--robot-inverse");
    const json result = ExpectSolved(fixed);
    EXPECT_LT(so3::Distance(PoseOf(result["X"]).linear(), data.X.linear()), 2.0 * kRadiansPerDegree)
        << name;
  }
}

// Camera poses given inverted, and the wrong setup: refused with the setup that fits and the
// camera inversion as the other reading (poses alone cannot tell them apart).
TEST_F(CalibrateConventions, InvertedCameraFileAndWrongSetupAreNamed) {
  const sim::SimulatedData in_hand = Simulate(handeye::Setup::kEyeInHand, 12);
  WriteData(in_hand, Plain(), Inverted());
  ExpectRefused(Args("eye-in-hand"), {"--camera-inverse", "--setup eye-to-hand", "as given"});
  WriteData(in_hand, Plain(), Plain());
  ExpectRefused(Args("eye-to-hand"), {"these data fit the camera on the robot (eye-in-hand)",
                                      "run with --setup eye-in-hand", "as given (eye-to-hand)"});
  const sim::SimulatedData to_hand = Simulate(handeye::Setup::kEyeToHand, 13);
  WriteData(to_hand, Plain(), Plain());
  ExpectRefused(Args("eye-in-hand"),
                {"these data fit the camera fixed (eye-to-hand)", "run with --setup eye-to-hand"});
}

// --setup auto picks the setup the data fit, and says so with both residuals.
TEST_F(CalibrateConventions, SetupAutoPicksTheSetupThatFits) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const std::string name(handeye::SetupName(setup));
    const sim::SimulatedData data = Simulate(setup, 14);
    WriteData(data, Plain(), Plain());
    const json result = ExpectSolved(Args("auto"));
    EXPECT_EQ(result["setup"], name);
    EXPECT_TRUE(AnyWarningContains(result, "--setup auto chose " + name)) << result["warnings"];
    EXPECT_LT(so3::Distance(PoseOf(result["X"]).linear(), data.X.linear()),
              2.0 * kRadiansPerDegree);
  }
}

// A robot file in millimetres without a unit, the camera in metres: refused, naming the robot
// file and its unit; the reverse for the camera file; the fix (a unit in the header) works.
TEST_F(CalibrateConventions, MillimetresReadAsMetresAreNamed) {
  const sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 15);
  WriteData(data, Scaled(1e3), Plain());
  ExpectRefused(Args("eye-in-hand"), {Path("robot.csv"), "millimetres, not metres", "x_mm"});
  WriteData(data, Plain(), Scaled(1e3));
  ExpectRefused(Args("eye-in-hand"), {Path("camera.csv"), "millimetres, not metres"});
  WriteData(data, Scaled(1e3, "_mm"), Plain());
  const json result = ExpectSolved(Args("eye-in-hand"));
  EXPECT_EQ(result["units"]["length"], "mm");
  EXPECT_NEAR((PoseOf(result["X"]).translation() * 1e-3 - data.X.translation()).norm(), 0.0, 0.02);
}

// Both files in unnamed millimetres fit as well as in metres: the result is computed, and a
// warning names the lengths as millimetres read as metres.
TEST_F(CalibrateConventions, BothFilesInUnnamedMillimetresAreWarnedAbout) {
  const sim::SimulatedData data = Simulate(handeye::Setup::kEyeToHand, 16);
  WriteData(data, Scaled(1e3), Scaled(1e3));
  const json result = ExpectSolved(Args("eye-to-hand"));
  EXPECT_TRUE(AnyWarningContains(result, "millimetres read as metres")) << result["warnings"];
  EXPECT_TRUE(Contains(last_out_, "warning: the camera-to-target distance is"));
  // Named as millimetres: no warning.
  WriteData(data, Scaled(1e3, "_mm"), Scaled(1e3, "_mm"));
  EXPECT_FALSE(AnyWarningContains(ExpectSolved(Args("eye-to-hand")), "read as"));
}

// Quaternion values written x,y,z,w under qw,qx,qy,qz names: refused, naming the file.
TEST_F(CalibrateConventions, MislabelledQuaternionColumnsAreNamed) {
  const sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 17);
  WriteData(data, Xyzw(), Plain());
  ExpectRefused(Args("eye-in-hand"), {Path("robot.csv"), "quaternion columns"});
}

// The same file (or the same poses) as robot and camera: refused.
TEST_F(CalibrateConventions, TheSameFileTwiceIsRefused) {
  const sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 18);
  WriteData(data, Plain(), Plain());
  ExpectRefused({"calibrate", "--robot", Path("robot.csv"), "--camera", Path("robot.csv"),
                 "--setup", "eye-in-hand", "--output", Path("result.json")},
                {"is the same file as --robot"});
  Write("copy.csv", Read("robot.csv"));
  ExpectRefused({"calibrate", "--robot", Path("robot.csv"), "--camera", Path("copy.csv"), "--setup",
                 "eye-in-hand", "--output", Path("result.json")},
                {"holds the same poses as --robot"});
}

// One station with a random robot pose: rejected and listed with its residual; X equals the
// result without it; --keep-outliers uses it (and flags it).
TEST_F(CalibrateConventions, AGrossOutlierIsRejectedAndListed) {
  sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 19);
  const sim::SimulatedData clean = data;
  std::mt19937_64 rng(5);
  const std::vector<int> replaced = sim::InjectGrossOutliers(&data, 1, rng);
  std::string id = "s";  // appended: "s" + to_string trips GCC 12's -Wrestrict (bug 105329)
  id += std::to_string(replaced[0]);
  WriteData(data, Plain(), Plain());
  const json result = ExpectSolved(Args("eye-in-hand"));
  EXPECT_EQ(result["stations"]["rejected"], json::array({id}));
  EXPECT_EQ(result["stations"]["used"].size(), 19u);
  EXPECT_TRUE(result["stations"]["outlier_rejection"].get<bool>());
  EXPECT_EQ(result["seed"], 1);
  ASSERT_EQ(result["residuals"]["rejected"].size(), 1u);
  EXPECT_EQ(result["residuals"]["rejected"][0]["id"], id);
  EXPECT_GT(result["residuals"]["rejected"][0]["rotation_deg"].get<double>(), 5.0);
  EXPECT_TRUE(Contains(last_out_, "rejected: outlier, not used")) << last_out_;
  EXPECT_TRUE(AnyWarningContains(result, "station " + id + " rejected as an outlier"));
  const Pose X = PoseOf(result["X"]);

  std::vector<Pose> robot, camera;
  for (size_t i = 0; i < data.T_base_gripper.size(); ++i) {
    if (static_cast<int>(i) == replaced[0]) continue;
    robot.push_back(clean.T_base_gripper[i]);
    camera.push_back(clean.T_camera_target[i]);
  }
  Write("robot.csv", PoseCsv(robot, Plain()));
  Write("camera.csv", PoseCsv(camera, Plain()));
  const Pose without = PoseOf(ExpectSolved(Args("eye-in-hand"))["X"]);
  EXPECT_LT(so3::Distance(X.linear(), without.linear()), 1e-6);
  EXPECT_LT((X.translation() - without.translation()).norm(), 1e-6);

  WriteData(data, Plain(), Plain());
  std::vector<std::string> keep = Args("eye-in-hand");
  keep.push_back("--keep-outliers");
  const json kept = ExpectSolved(keep);
  EXPECT_TRUE(kept["stations"]["rejected"].empty());
  EXPECT_FALSE(kept["stations"]["outlier_rejection"].get<bool>());
}

// Implausible residuals (robot and camera rows not paired: the camera file shuffled) are never a
// silent exit 0: a warning says the poses do not describe one rigid setup.
TEST_F(CalibrateConventions, ShuffledPairsGiveALoudWarningOrARefusal) {
  sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 20);
  std::mt19937_64 rng(6);
  std::shuffle(data.T_camera_target.begin(), data.T_camera_target.end(), rng);
  WriteData(data, Plain(), Plain());
  const cli_test::Outcome run = Hecal(Args("eye-in-hand"));
  if (run.code == 0) {
    EXPECT_TRUE(
        AnyWarningContains(json::parse(Read("result.json")), "do not describe one rigid setup"));
  } else {
    EXPECT_EQ(run.code, 2) << run.err;
  }
}

// Real data, camodocal-artag (eye-to-hand, 42 AR-tag samples, sample 36 a gross outlier).
class CamodocalConventions : public CalibrateConventions {
 protected:
  void Import(const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args = {"import",    "--format",
                                     "camodocal", kData + "camodocal-artag/TransformPairsInput.yml",
                                     "--robot",   Path("robot.csv"),
                                     "--camera",  Path("camera.csv")};
    args.insert(args.end(), extra.begin(), extra.end());
    const cli_test::Outcome run = Hecal(args);
    ASSERT_EQ(run.code, 0) << run.err;
  }
};

// Run as eye-in-hand it names eye-to-hand, with both residuals; --setup auto picks eye-to-hand.
TEST_F(CamodocalConventions, WrongSetupIsNamedAndAutoGetsIt) {
  Import();
  ExpectRefused(Args("eye-in-hand"),
                {"these data fit the camera fixed (eye-to-hand)", "--setup eye-to-hand",
                 "median station residual", "as given (eye-in-hand)"});
  const json result = ExpectSolved(Args("auto"));
  EXPECT_EQ(result["setup"], "eye-to-hand");
  EXPECT_TRUE(AnyWarningContains(result, "--setup auto chose eye-to-hand"));
}

// The camera file inverted (a common fork writes T_marker_camera): run as eye-to-hand, the
// inversion is named; --setup auto then reads the data as a camera on the robot (the physically
// equivalent reading) and says that the inverted-camera reading fits as well.
TEST_F(CamodocalConventions, InvertedCameraFileIsNamed) {
  Import({"--camera-inverse"});
  ExpectRefused(Args("eye-to-hand"), {"--camera-inverse", "the camera poses inverted"});
  const json result = ExpectSolved(Args("auto"));
  EXPECT_EQ(result["setup"], "eye-in-hand");
  EXPECT_TRUE(AnyWarningContains(result, "with the camera poses inverted"));
}

// Sample 36 is rejected, and X is the same as without it (the same stations used).
TEST_F(CamodocalConventions, SampleThirtySixIsRejectedAndChangesNothing) {
  Import();
  const json with = ExpectSolved(Args("eye-to-hand"));
  const json& rejected = with["stations"]["rejected"];
  EXPECT_NE(std::find(rejected.begin(), rejected.end(), "36"), rejected.end()) << rejected;
  // The same files without sample 36.
  for (const char* name : {"robot.csv", "camera.csv"}) {
    std::istringstream in(Read(name));
    std::string text, line;
    while (std::getline(in, line))
      if (line.rfind("36,", 0) != 0) text += line + "\n";
    Write(name, text);
  }
  const json without = ExpectSolved(Args("eye-to-hand"));
  const Pose a = PoseOf(with["X"]), b = PoseOf(without["X"]);
  // Within 0.1σ of X on every axis (measured: identical).
  const Eigen::Vector3d rotation = so3::Log(a.linear().transpose() * b.linear());
  for (int k = 0; k < 3; ++k) {
    const double sigma_r = with["covariance"]["sigma"]["X"]["rotation_deg"][k].get<double>();
    const double sigma_t = with["covariance"]["sigma"]["X"]["translation"][k].get<double>();
    EXPECT_LT(std::abs(rotation(k)) / kRadiansPerDegree, 0.1 * sigma_r);
    EXPECT_LT(std::abs(a.translation()(k) - b.translation()(k)), 0.1 * sigma_t);
  }
  // --keep-outliers keeps it, flagged.
  Import();
  std::vector<std::string> keep = Args("eye-to-hand");
  keep.push_back("--keep-outliers");
  const json kept = ExpectSolved(keep);
  EXPECT_TRUE(kept["stations"]["rejected"].empty());
  EXPECT_TRUE(kept["residuals"]["per_station"][36]["outlier"].get<bool>());
}

// moveit-calibration (eye-to-hand, clean): --setup auto picks eye-to-hand, nothing is rejected.
TEST_F(CalibrateConventions, MoveItAutoSetupRejectsNothing) {
  const cli_test::Outcome import =
      Hecal({"import", "--format", "moveit", kData + "moveit-calibration/pose_samples.json",
             "--robot", Path("robot.csv"), "--camera", Path("camera.csv")});
  ASSERT_EQ(import.code, 0) << import.err;
  const json result = ExpectSolved(Args("auto"));
  EXPECT_EQ(result["setup"], "eye-to-hand");
  EXPECT_TRUE(result["stations"]["rejected"].empty());
  EXPECT_TRUE(
      PoseOf(result["X"]).translation().isApprox(Eigen::Vector3d(0.659, -0.249, 0.830), 0.01));
}

// Tabb's published 6-decimal matrices (RᵀR off by up to 1.3e-6) as r11..r33 columns calibrate,
// with a note of the correction.
TEST_F(CalibrateConventions, SixDecimalMatricesCalibrateWithANote) {
  // robot_cali.txt: a count, then per pose a 4×4 of T_gripper_base (mm) printed with 6 decimals.
  // Rewritten as a matrix CSV (r11..r33 with x_mm) keeping the printed text; the camera poses
  // through `hecal import --format tabb` (ids image0, image1, …).
  std::ifstream in(kData + "tabb-rwhe-dataset1/robot_cali.txt");
  std::string count, token;
  in >> count;
  std::string text = "id,x_mm,y_mm,z_mm,r11,r12,r13,r21,r22,r23,r31,r32,r33\n";
  std::vector<std::string> m;
  int poses = 0;
  while (in >> token) {
    m.push_back(token);
    if (m.size() < 16) continue;
    text += "image" + std::to_string(poses++) + "," + m[3] + "," + m[7] + "," + m[11];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) text += "," + m[static_cast<size_t>(4 * r + c)];
    text += "\n";
    m.clear();
  }
  ASSERT_EQ(poses, 88);
  const cli_test::Outcome import =
      Hecal({"import", "--format", "tabb", kData + "tabb-rwhe-dataset1", "--robot",
             Path("imported.csv"), "--camera", Path("camera.csv")});
  ASSERT_EQ(import.code, 0) << import.err;
  Write("robot.csv", text);
  std::vector<std::string> args = Args("eye-in-hand");
  args.push_back("--robot-inverse");  // Tabb's robot file holds T_gripper_base
  const json tabb = ExpectSolved(args);
  EXPECT_TRUE(AnyWarningContains(tabb, "projected onto the nearest rotation")) << tabb["warnings"];
}

// A controller's 4×4 (16-number lines, 17 digits) 2e-5 off SO(3) calibrates with a note; a
// reflection and a matrix 0.1 off are refused with their true reason.
TEST_F(CalibrateConventions, ControllerMatricesCalibrateAndNonRotationsAreRefused) {
  // A controller's 4×4 (row-major, 17 digits) whose rotation is 2e-5 off SO(3).
  const sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 21);
  std::ostringstream lines;
  lines.precision(17);
  for (const Pose& T : data.T_base_gripper) {
    Eigen::Matrix4d M = T.matrix();
    M.topLeftCorner<3, 3>() *= Eigen::Matrix3d::Identity() + 1e-5 * Eigen::Matrix3d::Ones();
    for (int k = 0; k < 16; ++k) lines << M(k / 4, k % 4) << (k < 15 ? " " : "\n");
  }
  Write("robot.txt", lines.str());
  Write("camera.csv", PoseCsv(data.T_camera_target, Plain()));
  const json controller =
      ExpectSolved({"calibrate", "--robot", Path("robot.txt"), "--camera", Path("camera.csv"),
                    "--setup", "eye-in-hand", "--output", Path("result.json")});
  EXPECT_TRUE(AnyWarningContains(controller, "projected onto the nearest rotation"));
  EXPECT_LT(so3::Distance(PoseOf(controller["X"]).linear(), data.X.linear()),
            2.0 * kRadiansPerDegree);

  // A reflection, and a matrix 0.1 off: refused with the reason.
  std::istringstream in(lines.str());
  std::string first;
  std::getline(in, first);
  std::istringstream values(first);
  std::vector<double> m(16);
  for (double& v : m) values >> v;
  std::ostringstream reflected, sheared;
  reflected.precision(17);
  sheared.precision(17);
  for (int k = 0; k < 16; ++k) {
    reflected << (k % 4 == 2 && k < 12 ? -m[k] : m[k]) << (k < 15 ? " " : "\n");
    sheared << (k == 1 ? m[k] + 0.1 : m[k]) << (k < 15 ? " " : "\n");
  }
  Write("robot.txt", reflected.str() + lines.str().substr(first.size() + 1));
  const std::vector<std::string> bad = {"calibrate",   "--robot",          Path("robot.txt"),
                                        "--camera",    Path("camera.csv"), "--setup",
                                        "eye-in-hand", "--output",         Path("result.json")};
  ExpectRefused(bad, {"reflection"});
  Write("robot.txt", sheared.str() + lines.str().substr(first.size() + 1));
  const cli_test::Outcome run = ExpectRefused(bad, {"not orthonormal"});
  EXPECT_FALSE(Contains(run.err, "digits")) << run.err;
}

}  // namespace
}  // namespace hecal::cli
