// ViSP pose files: the published layout (vpArray2D::saveYAML of a vpPoseVector) against rotation
// matrices built independently (Eigen::AngleAxis, hand-written elementary rotations), pairing by
// index, and every error the reader names.
#include "hecal/io/import_visp.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/import.h"
#include "hecal/io/import_moveit.h"
#include "testing/thrown.h"

namespace hecal::io {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// What vpArray2D::saveYAML writes for a vpPoseVector: default stream precision (6 digits),
// "data: " with a trailing space, two-space indent.
std::string SaveYaml(const std::array<double, 6>& v, const std::string& header = "") {
  std::ostringstream text;
  if (!header.empty()) text << header << "\n";
  text << "rows: 6\ncols: 1\ndata: \n";
  for (double x : v) text << "  - [" << x << "]\n";
  return text.str();
}

// ViSP's apps/calibration/hand-eye/data-eye-in-hand/franka_pose_rPe_1.yaml, byte for byte.
const std::string kFrankaRobot1 =
    "rows: 6\ncols: 1\ndata: \n  - [0.335091]\n  - [-0.0321497]\n  - [0.30857]\n  - [-3.01226]\n"
    "  - [0.0236777]\n  - [-0.451343]\n";

Eigen::Matrix3d FromThetaU(const Eigen::Vector3d& theta_u) {
  return Eigen::AngleAxisd(theta_u.norm(), theta_u.normalized()).toRotationMatrix();
}

InputError VispErrorOf(const std::vector<VispPoseFile>& files) {
  return testing::Thrown<InputError>([&] { ParseVispPoseFiles(files); });
}

TEST(ImportVisp, RealFileIsRobotPoseWithRotationVector) {
  const ImportedPoses poses =
      ParseVispPoseFiles({{"data/franka_pose_rPe_1.yaml", kFrankaRobot1},
                          {"data/franka_pose_cPo_1.yaml",
                           SaveYaml({0.01, -0.02, 0.5, 0.0, 0.0, std::numbers::pi / 2})}});
  ASSERT_EQ(poses.robot.rows.size(), 1u);
  const Pose& robot = poses.robot.rows[0].pose;
  EXPECT_TRUE(robot.translation().isApprox(Eigen::Vector3d(0.335091, -0.0321497, 0.30857), 1e-15));
  EXPECT_TRUE(robot.linear().isApprox(FromThetaU({-3.01226, 0.0236777, -0.451343}), 1e-14));
  EXPECT_EQ(poses.robot.unit, LengthUnit::kMetre);
  EXPECT_EQ(*poses.robot.rows[0].id, "1");
  // θu = (0, 0, π/2): a quarter turn about z, x → y (written out by hand).
  Eigen::Matrix3d quarter;
  quarter << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const Pose& camera = poses.camera->rows[0].pose;
  EXPECT_TRUE(camera.linear().isApprox(quarter, 1e-5));  // π/2 printed to 6 digits: 1.5708
  EXPECT_TRUE(camera.translation().isApprox(Eigen::Vector3d(0.01, -0.02, 0.5), 1e-15));
  EXPECT_THAT(poses.robot_notes[3], HasSubstr("pose_rPe_<i> = rMe = T_base_gripper"));
  EXPECT_THAT(poses.camera_notes[3], HasSubstr("pose_cPo_<i> = cMo = T_camera_target"));
  EXPECT_THAT(poses.robot_notes[1], HasSubstr("data/franka_pose_rPe_1.yaml"));
}

// src/io/testdata/visp: MoveIt samples 0-4 written as ViSP writes them (6 significant digits);
// they import to MoveIt's T_base_eef and T_camera_target within that rounding.
TEST(ImportVisp, FixtureMatchesTheMoveItSamples) {
  const std::string json =
      std::string(HECAL_SOURCE_DIR) + "/data/moveit-calibration/pose_samples.json";
  const ImportedPoses moveit = ParseMoveitSamples(ReadFile(json), json);
  const ImportedPoses visp = ImportFiles(
      ImportFormat::kVisp, {std::string(HECAL_SOURCE_DIR) + "/src/io/testdata/visp"}, {});
  ASSERT_EQ(visp.robot.rows.size(), 5u);
  for (size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(*visp.robot.rows[i].id, std::to_string(i + 1));
    const Pose* pairs[2][2] = {{&visp.robot.rows[i].pose, &moveit.robot.rows[i].pose},
                               {&visp.camera->rows[i].pose, &moveit.camera->rows[i].pose}};
    for (const auto& pair : pairs) {
      EXPECT_LT(so3::Distance(pair[0]->linear(), pair[1]->linear()), 1e-5);
      EXPECT_LT((pair[0]->translation() - pair[1]->translation()).norm(), 1e-6);
    }
  }
}

TEST(ImportVisp, RotationVectorsOfAnyMagnitude) {
  // 3π/2 about z is a quarter turn the other way; 2π + 0.3 about x is 0.3 about x.
  Eigen::Matrix3d minus_quarter;
  minus_quarter << 0, 1, 0, -1, 0, 0, 0, 0, 1;
  const Eigen::Matrix3d x_03 = (Eigen::Matrix3d() << 1, 0, 0, 0, std::cos(0.3), -std::sin(0.3), 0,
                                std::sin(0.3), std::cos(0.3))
                                   .finished();
  const std::string exact_minus_quarter =
      "rows: 6\ncols: 1\ndata:\n  - [0]\n  - [0]\n  - [0]\n  - [0]\n  - [0]\n"
      "  - [4.71238898038468985769]\n";
  const std::string exact_x =
      "rows: 6\ncols: 1\ndata:\n  - [0]\n  - [0]\n  - [0]\n  - [6.58318530717958623200]\n"
      "  - [0]\n  - [0]\n";
  const ImportedPoses poses =
      ParseVispPoseFiles({{"pose_fPe_0.yaml", exact_minus_quarter}, {"pose_cPo_0.yaml", exact_x}});
  EXPECT_TRUE(poses.robot.rows[0].pose.linear().isApprox(minus_quarter, 1e-14));
  EXPECT_TRUE(poses.camera->rows[0].pose.linear().isApprox(x_03, 1e-14));
  EXPECT_THAT(poses.robot_notes[3], HasSubstr("pose_fPe_<i>"));
}

TEST(ImportVisp, PairsByIndexInNumericOrder) {
  std::vector<VispPoseFile> files;
  for (int i : {10, 2, 1}) {
    const double x = i;
    files.push_back({"d/pose_cPo_" + std::to_string(i) + ".yml", SaveYaml({x, 0, 0, 0, 0, 0})});
    files.push_back({"d/ur_pose_rPe_" + std::to_string(i) + ".yaml",
                     SaveYaml({0, x, 0, 0, 0, 0}, "example: a YAML-formatted header")});
  }
  const ImportedPoses poses = ParseVispPoseFiles(files);
  ASSERT_EQ(poses.robot.rows.size(), 3u);
  const int expected[] = {1, 2, 10};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(*poses.robot.rows[k].id, std::to_string(expected[k]));
    EXPECT_EQ(*poses.camera->rows[k].id, std::to_string(expected[k]));
    EXPECT_EQ(poses.robot.rows[k].pose.translation().y(), expected[k]);
    EXPECT_EQ(poses.camera->rows[k].pose.translation().x(), expected[k]);
  }
  EXPECT_EQ(poses.robot.rows[0].line, 5);  // the data list, after saveYAML's header line
  EXPECT_THAT(poses.robot_notes[1], HasSubstr("3 files in d: ur_pose_rPe_1.yaml ... "));
}

TEST(ImportVisp, PairingErrorsNameTheFiles) {
  const std::string pose = SaveYaml({0, 0, 0, 0, 0, 0});
  testing::ExpectInputError(VispErrorOf({{"d/pose_rPe_1.yaml", pose},
                                         {"d/pose_cPo_1.yaml", pose},
                                         {"d/franka_pose_rPe_4.yaml", pose}}),
                            "d/franka_pose_rPe_4.yaml", 0,
                            "station 4 has no camera pose file (franka_pose_cPo_4.yaml)");
  testing::ExpectInputError(VispErrorOf({{"d/pose_cPo_7.yaml", pose}}), "d/pose_cPo_7.yaml", 0,
                            "station 7 has no robot pose file (pose_rPe_7.yaml)");
  const InputError both = VispErrorOf(
      {{"d/pose_fPe_3.yaml", pose}, {"d/pose_rPe_3.yaml", pose}, {"d/pose_cPo_3.yaml", pose}});
  testing::ExpectInputError(both, "d/pose_rPe_3.yaml", 0,
                            "station 3 already has a robot pose file, d/pose_fPe_3.yaml");
  EXPECT_THAT(both.fix(), HasSubstr("before ViSP 3.7"));
  testing::ExpectInputError(
      VispErrorOf({{"d/pose_cPo_03.yaml", pose}, {"d/pose_cPo_3.yaml", pose}}), "d/pose_cPo_3.yaml",
      0, "station 3 already has a camera pose file");
  testing::ExpectInputError(VispErrorOf({{"d/pose_xPe_3.yaml", pose}}), "d/pose_xPe_3.yaml", 0,
                            "is not a ViSP pose file name");
  testing::ExpectInputError(VispErrorOf({{"d/pose_cPo_3.txt", pose}}), "d/pose_cPo_3.txt", 0,
                            "is not a ViSP pose file name");
  testing::ExpectInputError(VispErrorOf({}), "INPUT", 0, "no ViSP pose files");
}

// A robot file with `text` and a good camera partner.
InputError RobotFileError(const std::string& text) {
  return VispErrorOf(
      {{"pose_rPe_1.yaml", text}, {"pose_cPo_1.yaml", SaveYaml({0, 0, 0, 0, 0, 0})}});
}

void ExpectFileError(const std::string& text, int line, const std::string& problem) {
  SCOPED_TRACE(text);
  testing::ExpectInputError(RobotFileError(text), "pose_rPe_1.yaml", line, problem);
}

TEST(ImportVisp, FileContentErrors) {
  const std::string head = "rows: 6\ncols: 1\ndata:\n";
  ExpectFileError(head + "  - [1]\n  - [2]\n  - [3]\n  - [4]\n  - [5]\n", 4,
                  "data has 5 rows of 1 value, but rows: 6, cols: 1 needs 6 rows of 1");
  ExpectFileError(head + "  - [1, 2, 3, 4, 5, 6]\n", 4, "data has 1 row of 6 values");
  ExpectFileError(head + "  [1, 2, 3, 4, 5, 6]\n", 4, "data has 1 row of 6 values");
  ExpectFileError("rows: 4\ncols: 4\ndata:\n  - [1, 0, 0, 0]\n", 1,
                  "rows: 4, cols: 4, but a vpPoseVector is 6x1");
  ExpectFileError(head + "  - [1]\n  - [abc]\n  - [3]\n  - [4]\n  - [5]\n  - [6]\n", 5,
                  "data[1][0] is \"abc\", not a number");
  ExpectFileError(head + "  - [1]\n  - [2]\n  - [3]\n  - [.nan]\n  - [5]\n  - [6]\n", 4,
                  "the pose vector contains a non-finite number");
  ExpectFileError(head + "  - [1]\n  - [1,5]\n  - [3]\n  - [4]\n  - [5]\n  - [6]\n", 5,
                  "row 1 has 2 values, row 0 has 1");
  ExpectFileError("cols: 1\ndata:\n  - [1]\n", 0, "has no 'rows'");
  ExpectFileError("rows: 6\ncols: 1\n", 0, "has no 'data'");
  ExpectFileError("rows: six\ncols: 1\n", 1, "rows is \"six\", not a number");
  ExpectFileError("- 1\n- 2\n", 1, "is not a vpPoseVector YAML file");
  ExpectFileError("rows: [6\n", 2, "not valid YAML");
}

class ImportVispFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("hecal_import_visp_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text = "x") {
    WriteFileAtomically((dir_ / name).string(), text);
    return (dir_ / name).string();
  }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> Names(const std::vector<std::string>& paths) const {
    std::vector<std::string> names;
    for (const std::string& path : paths) names.push_back(fs::path(path).filename().string());
    return names;
  }

  fs::path dir_;
};

TEST_F(ImportVispFiles, DirectoriesGlobsAndFiles) {
  for (const char* name :
       {"franka_pose_rPe_1.yaml", "franka_pose_cPo_1.yaml", "franka_pose_rPe_2.yaml",
        "franka_pose_cPo_2.yaml", "franka_image-1.png", "franka_camera.xml", "franka_ePc.yaml"}) {
    Write(name);
  }
  EXPECT_EQ(Names(ListVispPoseFiles({dir_.string()})),
            (std::vector<std::string>{"franka_pose_cPo_1.yaml", "franka_pose_cPo_2.yaml",
                                      "franka_pose_rPe_1.yaml", "franka_pose_rPe_2.yaml"}));
  // A glob, a file and the directory again: each file once.
  EXPECT_EQ(Names(ListVispPoseFiles(
                {Path("*_rPe_*.yaml"), Path("franka_pose_cPo_2.yaml"), dir_.string()})),
            (std::vector<std::string>{"franka_pose_cPo_1.yaml", "franka_pose_cPo_2.yaml",
                                      "franka_pose_rPe_1.yaml", "franka_pose_rPe_2.yaml"}));
  EXPECT_EQ(Names(ListVispPoseFiles({Path("franka_pose_?Po_[12].yaml")})),
            (std::vector<std::string>{"franka_pose_cPo_1.yaml", "franka_pose_cPo_2.yaml"}));

  const auto error = [](const std::vector<std::string>& inputs) {
    return testing::Thrown<InputError>([&] { ListVispPoseFiles(inputs); });
  };
  testing::ExpectInputError(error({Path("*.png")}), Path("franka_image-1.png"), 0,
                            "is not a ViSP pose file name");
  testing::ExpectInputError(error({Path("*.jpg")}), Path("*.jpg"), 0, "matches no file");
  testing::ExpectInputError(error({Path("franka_camera.xml")}), Path("franka_camera.xml"), 0,
                            "is not a ViSP pose file name");
  testing::ExpectInputError(error({Path("*/pose_cPo_1.yaml")}), Path("*/pose_cPo_1.yaml"), 0,
                            "wildcards in its directory part");
  testing::ExpectInputError(error({Path("none/pose_*.yaml")}), Path("none/pose_*.yaml"), 0,
                            "does not exist");
  fs::create_directories(dir_ / "empty");
  testing::ExpectInputError(error({Path("empty")}), Path("empty"), 0, "holds no ViSP pose files");
}

}  // namespace
}  // namespace hecal::io
