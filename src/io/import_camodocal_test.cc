#include "hecal/io/import_camodocal.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "testing/elementary_rotations.h"
#include "testing/nearly_orthonormal.h"
#include "testing/pose_spread.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;

const std::string kPairs =
    std::string(HECAL_SOURCE_DIR) + "/data/camodocal-artag/TransformPairsInput.yml";

// SOURCE.md: OpenCV PARK without sample 36, X = T_ee_marker.
Pose CamodocalParkX() {
  Eigen::Matrix3d R;
  R << -0.99685, 0.07272, 0.03158, 0.03145, -0.00292, 0.99950, 0.07277, 0.99735, 0.00062;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return testing::PoseOf(svd.matrixU() * svd.matrixV().transpose(),
                         Eigen::Vector3d(0.01191, 0.10286, -0.00236));
}

// Eye-to-hand with the marker on the end effector: T_base_camera_i = T_base_ee_i · X ·
// T_camera_marker_i⁻¹ must be the same for every sample.
std::vector<Pose> BaseCamera(const ImportedPoses& poses, bool invert_camera) {
  std::vector<Pose> cameras;
  const Pose X = CamodocalParkX();
  for (size_t i = 0; i < poses.robot.rows.size(); ++i) {
    const Pose& camera = poses.camera->rows[i].pose;
    cameras.push_back(poses.robot.rows[i].pose * X * (invert_camera ? camera.inverse() : camera));
  }
  return cameras;
}

TEST(ImportCamodocal, RealPairsAreConsistentExceptSample36) {
  const ImportedPoses poses = ParseCamodocalPairs(ReadFile(kPairs), kPairs);
  ASSERT_EQ(poses.robot.rows.size(), 42u);
  ASSERT_EQ(poses.camera->rows.size(), 42u);
  EXPECT_EQ(poses.robot.rows[36].id, "36");
  // T1_0 row-major: translation (0.612, -0.0399, 0.261) m.
  EXPECT_NEAR(poses.robot.rows[0].pose.translation().x(), 6.1211838349307879e-01, 1e-15);
  EXPECT_NEAR(poses.robot.rows[0].pose.translation().y(), -3.9910451893784837e-02, 1e-15);

  const std::vector<Pose> cameras = BaseCamera(poses, true);
  std::vector<Pose> without_36 = cameras;
  without_36.erase(without_36.begin() + 36);
  const Pose mean = testing::ChordalMean(without_36);
  const testing::Spread spread = testing::SpreadAround(cameras, mean);
  const testing::Deviation outlier = spread.deviations[36];
  double others_rotation = 0.0;
  double others_translation = 0.0;
  for (size_t i = 0; i < spread.deviations.size(); ++i) {
    if (i == 36) continue;
    others_rotation = std::max(others_rotation, spread.deviations[i].rotation_deg);
    others_translation = std::max(others_translation, spread.deviations[i].translation);
  }
  std::printf(
      "[camodocal] T_base_camera mean t = (%.3f, %.3f, %.3f) m; sample 36: %.1f deg / "
      "%.3f m; others max %.1f deg / %.3f m, mean %.1f deg\n",
      mean.translation().x(), mean.translation().y(), mean.translation().z(), outlier.rotation_deg,
      outlier.translation, others_rotation, others_translation, spread.mean_rotation_deg);
  // SOURCE.md: sample 36 is 24 deg and 0.34 m off the others; the others spread 2-4 deg;
  // eye-to-hand T_base_cam t = (1.355, -0.303, 0.703) m.
  EXPECT_EQ(spread.worst_rotation, 36u);
  EXPECT_EQ(spread.worst_translation, 36u);
  EXPECT_NEAR(outlier.rotation_deg, 24.0, 3.0);
  EXPECT_NEAR(outlier.translation, 0.34, 0.04);
  EXPECT_LT(others_rotation, 10.0);
  EXPECT_LT(others_translation, 0.1);
  EXPECT_NEAR(mean.translation().x(), 1.355, 0.03);
  EXPECT_NEAR(mean.translation().y(), -0.303, 0.03);
  EXPECT_NEAR(mean.translation().z(), 0.703, 0.03);

  // Reading T2_i the other way round (as T_marker_camera) scatters the camera by metres.
  std::vector<Pose> wrong = BaseCamera(poses, false);
  wrong.erase(wrong.begin() + 36);
  EXPECT_GT(testing::MaxAxisStd(wrong), 0.2);
}

const char* kMatrixI =
    " !!opencv-matrix\n   rows: 4\n   cols: 4\n   dt: d\n"
    "   data: [ 1., 0., 0., 0.5, 0., 1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1. ]\n";

std::string Pairs(int frame_count, int pairs) {
  std::string text = "%YAML:1.0\nframeCount: " + std::to_string(frame_count) + "\n";
  for (int i = 0; i < pairs; ++i) {
    text += "T1_" + std::to_string(i) + ":" + kMatrixI;
    text += "T2_" + std::to_string(i) + ":" + kMatrixI;
  }
  return text;
}

void ExpectCamodocalError(const std::string& text, const std::string& part) {
  try {
    ParseCamodocalPairs(text, "pairs.yml");
    ADD_FAILURE() << "no error; expected " << part;
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr(part)) << text;
  }
}

TEST(ImportCamodocal, ControllerMatricesAreProjectedWithANote) {
  // T1_0 as a controller writes its own pose: 2e-5 from orthonormal, 17 digits.
  const testing::NearlyOrthonormal m =
      testing::ControllerMatrix(testing::Rz(0.4) * testing::Rx(-1.1), 1e-5);
  const std::string text =
      "%YAML:1.0\nframeCount: 1\nT1_0: !!opencv-matrix\n   rows: 4\n   cols: 4\n   dt: d\n"
      "   data: [ " +
      testing::Digits17(testing::Homogeneous(m.matrix, Eigen::Vector3d(0.5, 0.25, 1.0)), ", ") +
      " ]\nT2_0:" + kMatrixI;
  const ImportedPoses poses = ParseCamodocalPairs(text, "pairs.yml");
  EXPECT_LT((poses.robot.rows[0].pose.linear() - m.rotation).cwiseAbs().maxCoeff(), 1e-15);
  ASSERT_EQ(poses.robot.warnings.size(), 1u);
  EXPECT_THAT(poses.robot.warnings[0],
              HasSubstr("pairs.yml: 1 of 1 robot rotation matrices were not orthonormal within "
                        "1e-6 (largest error 2.0e-05 at line 3 (T1_0)); projected"));
  EXPECT_TRUE(poses.camera->warnings.empty());
}

TEST(ImportCamodocal, ReadsOpenCvFileStorageYaml) {
  const ImportedPoses poses = ParseCamodocalPairs(Pairs(2, 2), "pairs.yml");
  ASSERT_EQ(poses.robot.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(poses.robot.rows[1].pose.translation().x(), 0.5);
  EXPECT_EQ(poses.robot.rows[1].line, 13);  // the T1_1 line
  // Also with "---" after the directive, as newer OpenCV writes it.
  std::string text = Pairs(1, 1);
  text.insert(text.find('\n') + 1, "---\n");
  EXPECT_EQ(ParseCamodocalPairs(text, "pairs.yml").camera->rows.size(), 1u);
}

TEST(ImportCamodocal, RejectsBadInput) {
  ExpectCamodocalError("", "not a YAML map");
  ExpectCamodocalError("%YAML:1.0\nT1_0: [", "not valid YAML");
  ExpectCamodocalError("%YAML:1.0\nfoo: 1\n", "no frameCount");
  ExpectCamodocalError(Pairs(3, 2), "pairs.yml:2: frameCount is 3 but the file has 2 T1_i entries");
  ExpectCamodocalError(Pairs(1, 2), "frameCount is 1 but the file has 2");
  ExpectCamodocalError(Pairs(0, 0), "frameCount is 0");
  ExpectCamodocalError("frameCount: -1\n", "not a whole number");
  ExpectCamodocalError("frameCount: 2.5\n", "not a whole number");
  std::string gap = Pairs(2, 2);
  gap.replace(gap.find("T1_1"), 4, "T1_7");
  ExpectCamodocalError(gap, "T1_1 is missing");
  std::string missing_t2 = Pairs(1, 1);
  missing_t2.replace(missing_t2.find("T2_0"), 4, "T3_0");
  ExpectCamodocalError(missing_t2, "the file has 0 T2_i entries");
  std::string wrong_count = Pairs(1, 1);
  wrong_count.replace(wrong_count.find("0., 0., 0., 1. ]"), 16, "0., 0., 1. ]");
  ExpectCamodocalError(wrong_count, "15 data values but rows x cols = 4 x 4");
  std::string nan = Pairs(1, 1);
  nan.replace(nan.find("0.5"), 3, ".nan");
  ExpectCamodocalError(nan, "non-finite");
  std::string word = Pairs(1, 1);
  word.replace(word.find("0.5"), 3, "abc");
  ExpectCamodocalError(word, "\"abc\", not a number");
  std::string skew = Pairs(1, 1);
  skew.replace(skew.find("1., 0., 0., 0.5"), 15, "1., 0.2, 0., 0.5");
  ExpectCamodocalError(skew, "T1_0: the rotation matrix is not orthonormal");
  std::string small = Pairs(1, 1);
  small.replace(small.find("rows: 4"), 7, "rows: 3");
  ExpectCamodocalError(small, "16 data values but rows x cols = 3 x 4");
  ExpectCamodocalError("frameCount: 1\nT1_0: 5\nT2_0: 5\n", "T1_0 is not a matrix");
  ExpectCamodocalError("frameCount: 1\nT1_0: {rows: 4}\nT2_0: 5\n", "not an !!opencv-matrix");
}

}  // namespace
}  // namespace hecal::io
