#include "hecal/io/import_opencv_yaml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/import_moveit.h"
#include "hecal/io/import_tabb.h"
#include "io_test_util.h"
#include "testing/elementary_rotations.h"
#include "testing/nearly_orthonormal.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;

// Hand-made fixtures in hecal's opencv-yaml layout (src/io/testdata/README.md).
const std::string kTabbMm = test_util::kSource + "/src/io/testdata/opencv_handeye_tabb_mm.yml";
const std::string kMoveit = test_util::kSource + "/src/io/testdata/opencv_handeye_moveit.yml";

ImportedPoses Tabb() {
  const std::string dir = test_util::kSource + "/data/tabb-rwhe-dataset1/";
  return ParseTabb(ReadFile(dir + "robot_cali.txt"), "robot_cali.txt", ReadFile(dir + "cali.txt"),
                   "cali.txt");
}

TEST(ImportOpenCvYaml, RotationMatricesAndVectorsInMillimetres) {
  const ImportedPoses poses =
      ParseOpenCvHandEyeYaml(ReadFile(kTabbMm), kTabbMm, LengthUnit::kMillimetre);
  const ImportedPoses tabb = Tabb();
  ASSERT_EQ(poses.robot.rows.size(), 12u);
  ASSERT_EQ(poses.camera->rows.size(), 12u);
  EXPECT_EQ(poses.robot.unit, LengthUnit::kMillimetre);
  for (size_t i = 0; i < 12; ++i) {
    EXPECT_TRUE(poses.robot.rows[i].pose.isApprox(tabb.robot.rows[i].pose, 1e-9)) << i;
    EXPECT_TRUE(poses.camera->rows[i].pose.isApprox(tabb.camera->rows[i].pose, 1e-9)) << i;
    EXPECT_EQ(*poses.robot.rows[i].id, *tabb.robot.rows[i].id);  // ids: [image0, ...]
  }
  EXPECT_THAT(poses.robot_notes[3], HasSubstr("gripper2base = T_base_gripper, used as is"));
  // Without --units mm the same numbers are read as metres: 1000 times too far.
  const ImportedPoses metres =
      ParseOpenCvHandEyeYaml(ReadFile(kTabbMm), kTabbMm, LengthUnit::kMetre);
  EXPECT_NEAR(metres.camera->rows[0].pose.translation().norm() /
                  tabb.camera->rows[0].pose.translation().norm(),
              1000.0, 1e-6);
}

TEST(ImportOpenCvYaml, InverseKeysAreInverted) {
  const ImportedPoses poses =
      ParseOpenCvHandEyeYaml(ReadFile(kMoveit), kMoveit, LengthUnit::kMetre);
  const std::string path = test_util::kSource + "/data/moveit-calibration/pose_samples.json";
  const ImportedPoses moveit = ParseMoveitSamples(ReadFile(path), path);
  ASSERT_EQ(poses.robot.rows.size(), 10u);
  for (size_t i = 0; i < 10; ++i) {
    // T_base2gripper (the base in the gripper frame) becomes T_base_gripper = M_eef.
    EXPECT_TRUE(poses.robot.rows[i].pose.isApprox(moveit.robot.rows[i].pose, 1e-12)) << i;
    EXPECT_TRUE(poses.camera->rows[i].pose.isApprox(moveit.camera->rows[i].pose, 1e-12)) << i;
  }
  EXPECT_EQ(*poses.robot.rows[9].id, "9");
  EXPECT_THAT(poses.robot_notes[3], HasSubstr("INVERTED"));
}

std::string List(const std::string& key, const std::string& entry, int count) {
  std::string text = key + ":\n";
  for (int i = 0; i < count; ++i) text += "   - " + entry + "\n";
  return text;
}

const std::string kRotationYaml = "[1, 0, 0, 0, 1, 0, 0, 0, 1]";
const std::string kTranslationYaml = "[0.1, 0.2, 0.3]";

std::string Arrays(int robot, int camera) {
  return List("R_gripper2base", kRotationYaml, robot) +
         List("t_gripper2base", kTranslationYaml, robot) +
         List("R_target2cam", kRotationYaml, camera) +
         List("t_target2cam", kTranslationYaml, camera);
}

TEST(ImportOpenCvYaml, ControllerMatricesAreProjectedWithANote) {
  // R_gripper2base as 3x3 data and T_target2cam as a 4x4, both 2e-5 from orthonormal, 17 digits.
  const testing::NearlyOrthonormal robot =
      testing::ControllerMatrix(testing::Rz(-0.8) * testing::Ry(1.3), 1e-5);
  const testing::NearlyOrthonormal camera =
      testing::ControllerMatrix(testing::Rx(3.0) * testing::Rz(0.2), 1e-5);
  // (Appended piece by piece: GCC 12's -Wrestrict false positive, bug 105329, trips on "[" + s.)
  std::string R = "[";
  R += testing::Digits17(robot.matrix, ", ");
  R += "]";
  std::string T = "[";
  T += testing::Digits17(testing::Homogeneous(camera.matrix, Eigen::Vector3d(0, 0, 1)), ", ");
  T += "]";
  const std::string text = List("R_gripper2base", R, 1) +
                           List("t_gripper2base", kTranslationYaml, 1) + List("T_target2cam", T, 1);
  const ImportedPoses poses = ParseOpenCvHandEyeYaml(text, "h.yml", LengthUnit::kMetre);
  EXPECT_LT((poses.robot.rows[0].pose.linear() - robot.rotation).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((poses.camera->rows[0].pose.linear() - camera.rotation).cwiseAbs().maxCoeff(), 1e-15);
  ASSERT_EQ(poses.robot.warnings.size(), 1u);
  EXPECT_THAT(poses.robot.warnings[0],
              HasSubstr("h.yml: 1 of 1 robot rotation matrices were not orthonormal within 1e-6 "
                        "(largest error 2.0e-05 at line 2 (robot pose 0 (R_gripper2base[0])))"));
  ASSERT_EQ(poses.camera->warnings.size(), 1u);
  EXPECT_THAT(poses.camera->warnings[0], HasSubstr("h.yml: 1 of 1 camera rotation matrices"));
}

TEST(ImportOpenCvYaml, PlainListsAndCameraInverse) {
  const std::string text = List("R_gripper2base", kRotationYaml, 1) +
                           List("t_gripper2base", kTranslationYaml, 1) +
                           List("T_cam2target", "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 5]]", 1);
  const ImportedPoses poses = ParseOpenCvHandEyeYaml(text, "h.yml", LengthUnit::kMetre);
  EXPECT_TRUE(poses.robot.rows[0].pose.translation().isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
  EXPECT_TRUE(poses.camera->rows[0].pose.translation().isApprox(Eigen::Vector3d(0, 0, -5)));
}

void ExpectOpenCvYamlError(const std::string& text, const std::string& part) {
  try {
    ParseOpenCvHandEyeYaml(text, "h.yml", LengthUnit::kMetre);
    ADD_FAILURE() << "no error; expected " << part;
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr(part)) << text;
  }
}

TEST(ImportOpenCvYaml, RejectsBadInput) {
  ExpectOpenCvYamlError("", "not a YAML map");
  ExpectOpenCvYamlError("%YAML:1.0\nR_gripper2base: [\n", "not valid YAML");
  ExpectOpenCvYamlError("foo: 1\n", "no robot poses");
  ExpectOpenCvYamlError(
      List("R_gripper2base", kRotationYaml, 1) + List("t_gripper2base", kTranslationYaml, 1),
      "no camera poses");
  ExpectOpenCvYamlError(Arrays(2, 1), "there are 2 robot poses");
  ExpectOpenCvYamlError(
      List("R_gripper2base", kRotationYaml, 2) + List("t_gripper2base", kTranslationYaml, 1) +
          List("R_target2cam", kRotationYaml, 2) + List("t_target2cam", kTranslationYaml, 2),
      "R_gripper2base has 2 entries but t_gripper2base has 1");
  ExpectOpenCvYamlError(List("R_gripper2base", kRotationYaml, 1) +
                            List("R_target2cam", kRotationYaml, 1) +
                            List("t_target2cam", kTranslationYaml, 1),
                        "R_gripper2base has no matching t_gripper2base");
  ExpectOpenCvYamlError(Arrays(1, 1) + List("T_base2gripper", "[1]", 1),
                        "robot poses are given twice");
  ExpectOpenCvYamlError("R_gripper2base: []\nt_gripper2base: []\nT_target2cam: []\n", "empty");
  ExpectOpenCvYamlError("R_gripper2base:\nt_gripper2base:\n",
                        "R_gripper2base is not a list of matrices");
  ExpectOpenCvYamlError("R_gripper2base: 5\nt_gripper2base: []\n", "not a list of matrices");
  ExpectOpenCvYamlError(
      List("R_gripper2base", "[1, 0, 0, 0]", 1) + List("t_gripper2base", kTranslationYaml, 1) +
          List("R_target2cam", kRotationYaml, 1) + List("t_target2cam", kTranslationYaml, 1),
      "neither a 3x3 rotation matrix nor a 3x1 rotation vector");
  ExpectOpenCvYamlError(List("R_gripper2base", "[1, 0, 0, 0, 1, 0, 0, 0, 1.1]", 1) +
                            List("t_gripper2base", kTranslationYaml, 1) +
                            List("R_target2cam", kRotationYaml, 1) +
                            List("t_target2cam", kTranslationYaml, 1),
                        "not orthonormal");
  ExpectOpenCvYamlError(
      List("R_gripper2base", kRotationYaml, 1) + List("t_gripper2base", "[1, 2]", 1) +
          List("R_target2cam", kRotationYaml, 1) + List("t_target2cam", kTranslationYaml, 1),
      "not a 3-vector");
  ExpectOpenCvYamlError(
      List("R_gripper2base", kRotationYaml, 1) + List("t_gripper2base", "[.inf, 2, 3]", 1) +
          List("R_target2cam", kRotationYaml, 1) + List("t_target2cam", kTranslationYaml, 1),
      "non-finite");
  ExpectOpenCvYamlError(Arrays(1, 1) + "ids: [a, b]\n", "ids has 2 entries for 1 poses");
  ExpectOpenCvYamlError(Arrays(2, 2) + "ids: [a, a]\n", "repeats");
  ExpectOpenCvYamlError(List("T_gripper2base", "[[1, 0], [0, 1]]", 1) +
                            List("R_target2cam", kRotationYaml, 1) +
                            List("t_target2cam", kTranslationYaml, 1),
                        "not a 4x4 or 3x4 transform");
  ExpectOpenCvYamlError(List("T_gripper2base", "[[1, 0, 0, 0], [0, 1]]", 1), "row 1 has 2 values");
  ExpectOpenCvYamlError(List("T_gripper2base", "{rows: 4, cols: 4, dt: u, data: []}", 1), "dt");
}

}  // namespace
}  // namespace hecal::io
