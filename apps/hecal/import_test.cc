// `hecal import` through RunHecal: every real data set imports to a CSV pair that hecal's own
// reader reads back (units from the header) and that passes the data set's consistency check;
// errors exit 2 with one line on stderr and leave the output paths untouched.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "cli.h"
#include "cli_test_util.h"
#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/pose_table.h"
#include "hecal/sim/thesis_protocol.h"
#include "testing/csv_reader.h"
#include "testing/pose_spread.h"

namespace hecal::cli {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

using cli_test::kData;
const std::string kFixtures = std::string(HECAL_SOURCE_DIR) + "/src/io/testdata/";

Pose RotationTranslation(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return testing::PoseOf(svd.matrixU() * svd.matrixV().transpose(), t);
}

class ImportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("hecal_import_test_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  std::string Write(const std::string& name, const std::string& contents) {
    io::WriteFileAtomically(Path(name), contents);
    return Path(name);
  }

  int Run(std::vector<std::string> args) {
    args.insert(args.begin(), {"hecal", "import"});
    std::ostringstream out;
    std::ostringstream err;
    const int code = RunHecal(args, out, err);
    out_ = out.str();
    err_ = err.str();
    return code;
  }

  // Runs an import expected to fail: exit 2, one line on stderr, and no file in the directory.
  void ExpectFailure(std::vector<std::string> args, const std::string& part) {
    EXPECT_EQ(Run(std::move(args)), 2) << out_ << err_;
    EXPECT_THAT(err_, StartsWith("hecal: "));
    EXPECT_THAT(err_, HasSubstr(part));
    EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
    EXPECT_TRUE(fs::is_empty(dir_)) << "a failed import wrote a file";
  }

  io::PoseTable Read(const std::string& name) const {
    return io::ReadPoseTable(Path(name), io::PoseReadOptions{});
  }

  fs::path dir_;
  std::string out_;
  std::string err_;
};

TEST_F(ImportTest, MoveitEyeToHand) {
  ASSERT_EQ(Run({"--format", "moveit", kData + "moveit-calibration/pose_samples.json", "--robot",
                 Path("robot.csv"), "--camera", Path("camera.csv")}),
            0)
      << err_;
  EXPECT_THAT(out_, HasSubstr("wrote 50 robot poses (T_base_gripper, m)"));
  const csv_test::Csv csv = csv_test::ReadCsv(Path("robot.csv"));
  EXPECT_EQ(csv.header, (std::vector<std::string>{"id", "x", "y", "z", "qw", "qx", "qy", "qz"}));
  EXPECT_THAT(csv.comments[0], HasSubstr("import --format moveit"));
  EXPECT_THAT(csv.comments[2], HasSubstr("pose_samples.json"));

  const io::Stations stations = io::PairStations(Read("robot.csv"), Read("camera.csv"));
  ASSERT_EQ(stations.robot.size(), 50u);
  // SOURCE.md: with the upstream X = T_base_camera the target is ~6 mm from the eef, std ~2.5 mm.
  const Pose X = testing::PoseOf((Eigen::AngleAxisd(0.230, Eigen::Vector3d::UnitX()) *
                                  Eigen::AngleAxisd(-2.540, Eigen::Vector3d::UnitY()) *
                                  Eigen::AngleAxisd(1.950, Eigen::Vector3d::UnitZ()))
                                     .toRotationMatrix(),
                                 Eigen::Vector3d(0.659, -0.249, 0.830));
  std::vector<Pose> targets;
  for (size_t i = 0; i < 50; ++i) {
    targets.push_back(stations.robot[i].inverse() * X * stations.camera[i]);
  }
  EXPECT_LT(testing::ChordalMean(targets).translation().norm(), 0.012);
  EXPECT_LT(testing::MaxAxisStd(targets), 0.005);
}

TEST_F(ImportTest, TabbStaysInMillimetresAndWritesIntrinsics) {
  ASSERT_EQ(Run({"--format", "tabb", kData + "tabb-rwhe-dataset1/robot_cali.txt",
                 kData + "tabb-rwhe-dataset1/cali.txt", "--robot", Path("robot.csv"), "--camera",
                 Path("camera.csv"), "--intrinsics", Path("camera.yaml")}),
            0)
      << err_;
  const csv_test::Csv robot_csv = csv_test::ReadCsv(Path("robot.csv"));
  EXPECT_EQ(robot_csv.header,
            (std::vector<std::string>{"id", "x_mm", "y_mm", "z_mm", "qw", "qx", "qy", "qz"}));
  EXPECT_EQ(robot_csv.Text(76, "id"), "image76");
  bool inverted_note = false;
  for (const std::string& comment : robot_csv.comments) {
    inverted_note =
        inverted_note || comment.find("INVERTED to T_base_gripper") != std::string::npos;
  }
  EXPECT_TRUE(inverted_note);
  // robot_cali.txt prints 6 decimals, so some rotations are projected onto SO(3): one warning on
  // stderr and the same text as a '# note:' line in robot.csv.
  const std::string note = kData + "tabb-rwhe-dataset1/robot_cali.txt: ";
  EXPECT_THAT(err_, StartsWith("hecal: warning: " + note));
  EXPECT_THAT(err_, HasSubstr(" of 88 rotation matrices were not orthonormal within 1e-6"));
  const std::string warning = err_.substr(0, err_.find('\n'));
  EXPECT_NE(std::find(robot_csv.comments.begin(), robot_csv.comments.end(),
                      "# note: " + warning.substr(std::string("hecal: warning: ").size())),
            robot_csv.comments.end());
  // cali.txt line 1: t = (-267.636, 270.545, 2122.28) mm, written as is.
  EXPECT_NEAR(csv_test::ReadCsv(Path("camera.csv")).Number(0, "z_mm"), 2122.28, 1e-9);
  const std::string yaml = io::ReadFile(Path("camera.yaml"));
  EXPECT_THAT(yaml, HasSubstr("fx: 1081.59\nfy: 1083.49\ncx: 317.249\ncy: 245.791\n"));
  EXPECT_THAT(yaml, HasSubstr("model: plumb_bob"));

  // Read back with units from the header: Tabb's own X and Z still fit pose by pose.
  const io::PoseTable robot = Read("robot.csv");
  EXPECT_EQ(robot.unit, io::LengthUnit::kMillimetre);
  const io::Stations stations = io::PairStations(robot, Read("camera.csv"));
  Eigen::Matrix3d Rx;
  Rx << 0.00471733, 0.00619057, 0.99997, -0.038563, 0.999238, -0.00600412, -0.999245, -0.0385335,
      0.00495246;
  Eigen::Matrix3d Rz;
  Rz << 0.997365, -0.0725279, 0.00171889, 0.072544, 0.997283, -0.0128158, -0.000784715, 0.0129068,
      0.999916;
  const Pose T_target_base =
      RotationTranslation(Rx, Eigen::Vector3d(-382.141, 44.7342, -2201.57) * 1e-3);
  const Pose T_camera_gripper =
      RotationTranslation(Rz, Eigen::Vector3d(8.98549, 29.718, -2.96242) * 1e-3);
  std::vector<Pose> targets;
  for (size_t i = 0; i < stations.robot.size(); ++i) {
    targets.push_back(stations.robot[i] * T_camera_gripper.inverse() * stations.camera[i]);
  }
  const testing::Spread spread = testing::SpreadAround(targets, T_target_base.inverse());
  EXPECT_NEAR(spread.mean_rotation_deg, 0.39, 0.02);
  EXPECT_NEAR(spread.mean_translation, 0.0064, 0.0003);
  EXPECT_NEAR(spread.max_translation, 0.0157, 0.0005);
}

TEST_F(ImportTest, TabbFromADirectory) {
  ASSERT_EQ(Run({"--format", "tabb", kData + "tabb-rwhe-dataset1", "--robot", Path("r.csv"),
                 "--camera", Path("c.csv")}),
            0)
      << err_;
  EXPECT_EQ(Read("r.csv").rows.size(), 88u);
}

TEST_F(ImportTest, CamodocalOutlier) {
  ASSERT_EQ(Run({"--format", "camodocal", kData + "camodocal-artag/TransformPairsInput.yml",
                 "--robot", Path("robot.csv"), "--camera", Path("camera.csv")}),
            0)
      << err_;
  const io::Stations stations = io::PairStations(Read("robot.csv"), Read("camera.csv"));
  ASSERT_EQ(stations.ids.size(), 42u);
  Eigen::Matrix3d R;
  R << -0.99685, 0.07272, 0.03158, 0.03145, -0.00292, 0.99950, 0.07277, 0.99735, 0.00062;
  const Pose X = RotationTranslation(R, Eigen::Vector3d(0.01191, 0.10286, -0.00236));
  std::vector<Pose> cameras;
  for (size_t i = 0; i < 42; ++i) {
    cameras.push_back(stations.robot[i] * X * stations.camera[i].inverse());
  }
  std::vector<Pose> others = cameras;
  others.erase(others.begin() + 36);
  const testing::Spread spread = testing::SpreadAround(cameras, testing::ChordalMean(others));
  EXPECT_EQ(stations.ids[spread.worst_rotation], "36");
  EXPECT_NEAR(spread.deviations[36].rotation_deg, 24.0, 3.0);
  EXPECT_NEAR(spread.deviations[36].translation, 0.34, 0.04);
}

TEST_F(ImportTest, EthzKeepsStampsAndDoesNotPair) {
  const std::string prefix = kData + "ethz-robot-arm/robot_arm_complete_bag_color_and_ir_";
  ASSERT_EQ(Run({"--format", "ethz", prefix + "base_link_sr300_hinge.csv", prefix + "target_ir.csv",
                 "--robot", Path("robot.csv"), "--camera", Path("camera.csv")}),
            0)
      << err_;
  EXPECT_THAT(out_, HasSubstr("unsynchronised"));
  const io::PoseTable robot = Read("robot.csv");
  const io::PoseTable camera = Read("camera.csv");
  ASSERT_EQ(robot.rows.size(), 2817u);
  ASSERT_EQ(camera.rows.size(), 1703u);
  EXPECT_DOUBLE_EQ(*camera.rows[0].stamp, 1487321563.1803279);
  EXPECT_DOUBLE_EQ(*robot.rows[2816].stamp, 1487321620.00);
  const csv_test::Csv csv = csv_test::ReadCsv(Path("camera.csv"));
  EXPECT_EQ(csv.header[1], "stamp");
  // Rows are not stations: pairing them by id or order must fail, never silently succeed.
  EXPECT_THROW(io::PairStations(robot, camera), InputError);

  // Paired by nearest stamp (within 10 ms, one pair per second) with SOURCE.md's reference X,
  // the target sits at (0.6589, -0.2100, 0.0084) m in the base.
  Eigen::Matrix3d R;
  R << 0.45313, -0.01182, 0.89136, -0.89144, -0.00894, 0.45305, 0.00261, -0.99989, -0.01459;
  const Pose X = RotationTranslation(R, Eigen::Vector3d(0.00019, -0.01594, 0.00522));
  std::vector<Pose> targets;
  double last = -1e300;
  size_t r = 0;
  for (const io::PoseRow& row : camera.rows) {
    if (*row.stamp < last + 1.0) continue;
    while (r + 1 < robot.rows.size() && std::abs(*robot.rows[r + 1].stamp - *row.stamp) <=
                                            std::abs(*robot.rows[r].stamp - *row.stamp)) {
      ++r;
    }
    if (std::abs(*robot.rows[r].stamp - *row.stamp) > 0.010) continue;
    targets.push_back(robot.rows[r].pose * X * row.pose);
    last = *row.stamp;
  }
  EXPECT_NEAR(static_cast<double>(targets.size()), 57.0, 2.0);
  const Pose mean = testing::ChordalMean(targets);
  EXPECT_NEAR(mean.translation().x(), 0.6589, 0.005);
  EXPECT_NEAR(mean.translation().y(), -0.2100, 0.005);
  EXPECT_NEAR(mean.translation().z(), 0.0084, 0.005);
  EXPECT_LT(testing::MaxAxisStd(targets), 0.005);
}

TEST_F(ImportTest, Matrix16RobotOnly) {
  ASSERT_EQ(Run({"--format", "matrix16", kData + "rwhe-kuka2/RobotPosesVec.txt", "--robot",
                 Path("robot.csv")}),
            0)
      << err_;
  EXPECT_FALSE(fs::exists(Path("camera.csv")));
  const io::PoseTable robot = Read("robot.csv");
  ASSERT_EQ(robot.rows.size(), 28u);
  // RobotPosesVec.txt line 1: R11 R12 R13 tx ... with tx = -0.567412354, tz = 0.606329834.
  EXPECT_NEAR(robot.rows[0].pose.translation().x(), -0.567412354, 1e-12);
  EXPECT_NEAR(robot.rows[0].pose.translation().z(), 0.606329834, 1e-12);
  EXPECT_NEAR(robot.rows[0].pose.linear()(0, 0), -0.839981243, 1e-8);
  fs::remove(Path("robot.csv"));
  ExpectFailure({"--format", "matrix16", kData + "rwhe-kuka2/RobotPosesVec.txt", "--robot",
                 Path("r.csv"), "--camera", Path("c.csv")},
                "--camera: given, but matrix16 got only a robot file");
}

TEST_F(ImportTest, Matrix16WithUnitsAndInverse) {
  const std::string robot = Write("robot.txt", "1 0 0 100 0 1 0 0 0 0 1 0 0 0 0 1\n");
  const std::string camera = Write("camera.txt", "1 0 0 0 0 1 0 0 0 0 1 300 0 0 0 1\n");
  ASSERT_EQ(Run({"--format", "matrix16", robot, camera, "--units", "mm", "--robot-inverse",
                 "--robot", Path("robot.csv"), "--camera", Path("camera.csv")}),
            0)
      << err_;
  const csv_test::Csv csv = csv_test::ReadCsv(Path("robot.csv"));
  EXPECT_DOUBLE_EQ(csv.Number(0, "x_mm"), -100.0);
  EXPECT_DOUBLE_EQ(csv_test::ReadCsv(Path("camera.csv")).Number(0, "z_mm"), 300.0);
}

TEST_F(ImportTest, EasyHandeyeAndOpenCvYamlFixtures) {
  ASSERT_EQ(Run({"--format", "easy_handeye", kFixtures + "easy_handeye_eye_on_base.samples",
                 "--robot", Path("robot.csv"), "--camera", Path("camera.csv")}),
            0)
      << err_;
  ASSERT_EQ(Run({"--format", "opencv-yaml", kFixtures + "opencv_handeye_moveit.yml", "--robot",
                 Path("robot2.csv"), "--camera", Path("camera2.csv")}),
            0)
      << err_;
  // Both hold MoveIt samples 0-9, one with the robot transform inverted on the way in.
  const io::PoseTable a = Read("robot.csv");
  const io::PoseTable b = Read("robot2.csv");
  ASSERT_EQ(a.rows.size(), 10u);
  for (size_t i = 0; i < 10; ++i) EXPECT_TRUE(a.rows[i].pose.isApprox(b.rows[i].pose, 1e-12));
  // --setup that contradicts the file is an error; opencv-yaml in millimetres needs --units mm.
  fs::remove_all(dir_);
  fs::create_directories(dir_);
  ExpectFailure({"--format", "easy_handeye", kFixtures + "easy_handeye_eye_on_base.samples",
                 "--setup", "eye-in-hand", "--robot", Path("r.csv"), "--camera", Path("c.csv")},
                "--setup: contradicts");
  ASSERT_EQ(Run({"--format", "opencv-yaml", kFixtures + "opencv_handeye_tabb_mm.yml", "--units",
                 "mm", "--robot", Path("r.csv"), "--camera", Path("c.csv")}),
            0)
      << err_;
  EXPECT_EQ(csv_test::ReadCsv(Path("c.csv")).header[1], "x_mm");
}

TEST_F(ImportTest, BadFlagsAndInputsWriteNothing) {
  const std::string json = kData + "moveit-calibration/pose_samples.json";
  const std::string robot = Path("robot.csv");
  const std::string camera = Path("camera.csv");
  ExpectFailure({"--format", "moveitt", json, "--robot", robot, "--camera", camera},
                "--format: unknown import format 'moveitt'");
  ExpectFailure({"--format", "moveit", json, "--robot", robot}, "--camera: is required");
  ExpectFailure({"--format", "moveit", json, "--robot", robot, "--camera", camera, "--units", "mm"},
                "--units");
  ExpectFailure({"--format", "matrix16", json, "--robot", robot, "--units", "cm"},
                "--units: unknown unit 'cm' (fix: use m or mm)");
  ExpectFailure({"--format", "easy_handeye", json, "--robot", robot, "--camera", camera, "--setup",
                 "sideways"},
                "--setup: unknown setup 'sideways' (fix: use eye-in-hand (camera on the robot) or "
                "eye-to-hand (camera fixed))");
  ExpectFailure({"--format", "moveit", json, "--robot", robot, "--camera", camera, "--intrinsics",
                 Path("k.yaml")},
                "--intrinsics");
  ExpectFailure({"--format", "moveit", Path("missing.json"), "--robot", robot, "--camera", camera},
                "missing.json");
  ExpectFailure({"--format", "moveit", json, "--robot", robot, "--camera", robot},
                "--camera names the same file as --robot");
  ExpectFailure(
      {"--format", "moveit", json, "--robot", robot, "--camera", Path("no/such/dir/camera.csv")},
      "does not exist");
  // Bad content: the camera side fails after the robot side parsed; still nothing is written.
  const std::string bad = Path("bad.json");
  io::WriteFileAtomically(bad,
                          "[[[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]],"
                          "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,2]]]]");
  EXPECT_EQ(Run({"--format", "moveit", bad, "--robot", robot, "--camera", camera}), 2);
  EXPECT_THAT(err_, HasSubstr("sample 0 M_obj: the last row"));
  EXPECT_FALSE(fs::exists(robot));
  EXPECT_FALSE(fs::exists(camera));
}

TEST_F(ImportTest, FailedSecondWriteRestoresTheFirstOutput) {
  const std::string json = kData + "moveit-calibration/pose_samples.json";
  const std::string robot = Write("robot.csv", "old robot contents\n");
  // A file name longer than any file system allows: the directory exists, the write fails.
  const std::string camera = Path(std::string(300, 'c') + ".csv");
  EXPECT_EQ(Run({"--format", "moveit", json, "--robot", robot, "--camera", camera}), 2);
  EXPECT_EQ(io::ReadFile(robot), "old robot contents\n");
  fs::remove(robot);
  EXPECT_EQ(Run({"--format", "moveit", json, "--robot", robot, "--camera", camera}), 2);
  EXPECT_FALSE(fs::exists(robot));
  EXPECT_TRUE(fs::is_empty(dir_));
}

// A pose as ViSP's vpPoseVector::saveYAML writes it: t, then θu from Eigen's angle-axis, with
// the stream's default 6 significant digits.
std::string VispPoseYaml(const Pose& pose) {
  const Eigen::AngleAxisd angle_axis(pose.linear());
  const Eigen::Vector3d theta_u = angle_axis.angle() * angle_axis.axis();
  std::ostringstream text;
  text << "rows: 6\ncols: 1\ndata: \n";
  for (int k = 0; k < 3; ++k) text << "  - [" << pose.translation()(k) << "]\n";
  for (int k = 0; k < 3; ++k) text << "  - [" << theta_u(k) << "]\n";
  return text.str();
}

// A simulated eye-in-hand set written as ViSP's files (franka_pose_rPe_<i>.yaml,
// franka_pose_cPo_<i>.yaml, i = 1..15) in a folder with other files: `hecal import --format visp
// DIR`, then `hecal calibrate`, recovers the known X = T_gripper_camera and Z = T_base_target.
TEST_F(ImportTest, VispFolderImportsAndCalibratesToTheKnownX) {
  std::mt19937_64 rng(17);
  sim::ProtocolOptions options;
  options.setup = handeye::Setup::kEyeInHand;
  options.stations = 15;
  const sim::NoiseModel noise{sim::NoiseModel::Kind::kGaussian, 0.01 * M_PI / 180.0, 0.05e-3};
  const sim::SimulatedData data = sim::SimulateThesisProtocol(options, noise, noise, rng);
  fs::create_directories(dir_ / "visp");
  for (int i = 0; i < options.stations; ++i) {
    const std::string index = std::to_string(i + 1);
    Write("visp/franka_pose_rPe_" + index + ".yaml", VispPoseYaml(data.T_base_gripper[i]));
    Write("visp/franka_pose_cPo_" + index + ".yaml", VispPoseYaml(data.T_camera_target[i]));
    Write("visp/franka_image-" + index + ".png", "not read");
  }
  Write("visp/franka_camera.xml", "<root/>");
  ASSERT_EQ(
      Run({"--format", "visp", Path("visp"), "--robot", Path("r.csv"), "--camera", Path("c.csv")}),
      0)
      << err_;
  EXPECT_THAT(out_, HasSubstr("wrote 15 robot poses (T_base_gripper, m)"));
  const csv_test::Csv csv = csv_test::ReadCsv(Path("r.csv"));
  EXPECT_THAT(csv.comments[0], HasSubstr("import --format visp"));
  EXPECT_EQ(csv.Text(9, "id"), "10");  // numeric order: 1, 2, ..., 10, not 1, 10, 11, ...

  std::ostringstream out, err;
  ASSERT_EQ(RunHecal({"hecal", "calibrate", "--robot", Path("r.csv"), "--camera", Path("c.csv"),
                      "--setup", "eye-in-hand", "--output", Path("result.json")},
                     out, err),
            0)
      << err.str();
  const nlohmann::json result = nlohmann::json::parse(io::ReadFile(Path("result.json")));
  const auto pose_of = [&result](const char* name) {
    Eigen::Matrix4d M;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) M(r, c) = result[name]["matrix"][r][c].get<double>();
    }
    return Pose(M);
  };
  EXPECT_EQ(result["X"]["frame"], "T_gripper_camera");
  for (const auto& [name, truth] : {std::pair{"X", data.X}, std::pair{"Z", data.Z}}) {
    SCOPED_TRACE(name);
    const Pose estimate = pose_of(name);
    EXPECT_LT(Eigen::AngleAxisd(estimate.linear().transpose() * truth.linear()).angle(),
              0.02 * M_PI / 180.0);
    EXPECT_LT((estimate.translation() - truth.translation()).norm(), 0.2e-3);
  }

  // Robot files that hold T_gripper_base, imported with --robot-inverse: the same robot.csv.
  fs::create_directories(dir_ / "inverse");
  for (int i = 0; i < options.stations; ++i) {
    const std::string index = std::to_string(i);
    Write("inverse/pose_fPe_" + index + ".yaml", VispPoseYaml(data.T_base_gripper[i].inverse()));
    Write("inverse/pose_cPo_" + index + ".yaml", VispPoseYaml(data.T_camera_target[i]));
  }
  ASSERT_EQ(Run({"--format", "visp", Path("inverse/pose_*.yaml"), "--robot-inverse", "--robot",
                 Path("r2.csv"), "--camera", Path("c2.csv")}),
            0)
      << err_;
  const io::PoseTable direct = Read("r.csv");
  const io::PoseTable inverted = Read("r2.csv");
  ASSERT_EQ(inverted.rows.size(), direct.rows.size());
  for (size_t i = 0; i < direct.rows.size(); ++i) {
    EXPECT_LT((inverted.rows[i].pose.translation() - direct.rows[i].pose.translation()).norm(),
              1e-5);
  }
  bool noted = false;
  for (const std::string& comment : csv_test::ReadCsv(Path("r2.csv")).comments) {
    noted = noted || comment.find("--robot-inverse") != std::string::npos;
  }
  EXPECT_TRUE(noted);
}

TEST_F(ImportTest, VispErrorsWriteNothing) {
  fs::create_directories(dir_ / "visp");
  Write("visp/pose_rPe_1.yaml", VispPoseYaml(Pose::Identity()));
  Write("visp/pose_cPo_1.yaml", VispPoseYaml(Pose::Identity()));
  Write("visp/pose_rPe_2.yaml", VispPoseYaml(Pose::Identity()));
  const std::string robot = Path("robot.csv");
  const std::string camera = Path("camera.csv");
  const auto expect_failure = [&](std::vector<std::string> args, const std::string& part) {
    EXPECT_EQ(Run(std::move(args)), 2) << out_;
    EXPECT_THAT(err_, StartsWith("hecal: "));
    EXPECT_THAT(err_, HasSubstr(part));
    EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
    EXPECT_FALSE(fs::exists(robot));
    EXPECT_FALSE(fs::exists(camera));
  };
  expect_failure({"--format", "visp", Path("visp"), "--robot", robot, "--camera", camera},
                 "pose_rPe_2.yaml: station 2 has no camera pose file (pose_cPo_2.yaml) (fix: add "
                 "pose_cPo_2.yaml beside it, or remove pose_rPe_2.yaml)");
  Write("visp/pose_cPo_2.yaml", "rows: 6\ncols: 1\ndata: \n  - [1]\n  - [2]\n");
  expect_failure({"--format", "visp", Path("visp"), "--robot", robot, "--camera", camera},
                 "pose_cPo_2.yaml:4: data has 2 rows of 1 value");
  expect_failure(
      {"--format", "visp", Path("visp"), "--robot", robot, "--camera", camera, "--units", "mm"},
      "--units: visp files fix their own length unit (m)");
  expect_failure({"--format", "visp", Path("visp/*.csv"), "--robot", robot, "--camera", camera},
                 "matches no file");
}

}  // namespace
}  // namespace hecal::cli
