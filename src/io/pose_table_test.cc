#include "hecal/io/pose_table.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <ctime>
#include <filesystem>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/delimited_text.h"
#include "hecal/io/import_tabb.h"
#include "testing/elementary_rotations.h"
#include "testing/nearly_orthonormal.h"
#include "testing/options_validity.h"
#include "testing/random_poses.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// Independent definitions (not the library's Euler code): elementary rotations composed by hand.
using testing::Rx;
using testing::Ry;
using testing::Rz;

PoseTable ParsePoses(std::string_view text, const PoseReadOptions& options = {}) {
  return ParsePoseTable(text, "poses.csv", options);
}

// The InputError that parsing `text` raises; checks the one-line "file:line: what (fix: how)"
// shape every reader error must have.
InputError ParseError(std::string_view text, const PoseReadOptions& options = {}) {
  try {
    ParsePoses(text, options);
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_THAT(message, HasSubstr("(fix: ")) << message;
    EXPECT_TRUE(message.starts_with("poses.csv")) << message;
    EXPECT_FALSE(error.fix().empty()) << message;
    return error;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("", 0, "", "");
}

void ExpectRotationNear(const Pose& pose, const Eigen::Matrix3d& expected, double tolerance) {
  EXPECT_LE((pose.linear() - expected).cwiseAbs().maxCoeff(), tolerance)
      << "got\n"
      << pose.linear() << "\nexpected\n"
      << expected;
}

void ExpectTranslationNear(const Pose& pose, const Eigen::Vector3d& expected, double tolerance) {
  EXPECT_LE((pose.translation() - expected).cwiseAbs().maxCoeff(), tolerance)
      << "got " << pose.translation().transpose() << " expected " << expected.transpose();
}

// ---- reading each rotation group
// -----------------------------------------------------------------

TEST(ReadPoseTableTest, Quaternion) {
  const double h = std::sqrt(0.5);
  const PoseTable table = ParsePoses("x,y,z,qw,qx,qy,qz\n1,2,3,1,0,0,0\n0.5,0,-1," +
                                     std::to_string(h) + ",0,0," + std::to_string(h) + "\n");
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.unit, LengthUnit::kMetre);
  ASSERT_TRUE(table.rotation);
  EXPECT_EQ(table.rotation->ToString(), "quaternion");
  ExpectTranslationNear(table.rows[0].pose, Eigen::Vector3d(1, 2, 3), 0);
  ExpectRotationNear(table.rows[0].pose, Eigen::Matrix3d::Identity(), 0);
  ExpectTranslationNear(table.rows[1].pose, Eigen::Vector3d(0.5, 0, -1), 0);
  ExpectRotationNear(table.rows[1].pose, Rz(std::numbers::pi / 2), 1e-6);
  EXPECT_EQ(table.rows[0].line, 2);
  EXPECT_EQ(table.rows[1].line, 3);
  EXPECT_FALSE(table.rows[0].id);
  EXPECT_FALSE(table.rows[0].stamp);
  EXPECT_TRUE(table.warnings.empty());
}

TEST(ReadPoseTableTest, AbbQuaternionColumnsAreWxyz) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
  std::ostringstream text;
  text.precision(17);
  text << "q1,q2,q3,q4,x_mm,y_mm,z_mm\n"
       << q.w() << "," << q.x() << "," << q.y() << "," << q.z() << ",100,200,300\n";
  const PoseTable table = ParsePoses(text.str());
  EXPECT_EQ(table.rotation->ToString(), "abb");
  EXPECT_EQ(table.unit, LengthUnit::kMillimetre);
  ExpectRotationNear(table.rows[0].pose, q.toRotationMatrix(), 1e-15);
  ExpectTranslationNear(table.rows[0].pose, Eigen::Vector3d(0.1, 0.2, 0.3), 1e-15);
}

TEST(ReadPoseTableTest, RotationVectorInRadiansDegreesAndUrSpelling) {
  const Eigen::Matrix3d expected =
      Eigen::AngleAxisd(std::numbers::pi / 3, Eigen::Vector3d(0, 0.6, 0.8)).toRotationMatrix();
  const std::string row = "0,0,0," + std::to_string(0.0) + "," +
                          "0.6283185307179586,"
                          "0.8377580409572781\n";  // (0, 0.6, 0.8) · π/3
  ExpectRotationNear(ParsePoses("x,y,z,rx,ry,rz\n" + row).rows[0].pose, expected, 1e-15);
  ExpectRotationNear(ParsePoses("x,y,z,rx_deg,ry_deg,rz_deg\n0,0,0,0,36,48\n").rows[0].pose,
                     expected, 1e-15);
  PoseReadOptions degrees;
  degrees.degrees = true;
  const PoseTable flagged = ParsePoses("x,y,z,rx,ry,rz\n0,0,0,0,36,48\n", degrees);
  ExpectRotationNear(flagged.rows[0].pose, expected, 1e-15);
  EXPECT_TRUE(flagged.degrees);
  EXPECT_EQ(flagged.rotation->ToString(), "rotvec");
}

TEST(ReadPoseTableTest, RotationVectorLongerThanTwoPi) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 2).normalized();
  for (double angle : {7.0, 100.0, 1e6}) {
    std::ostringstream text;
    text.precision(17);
    text << "x,y,z,rx,ry,rz\n0,0,0," << angle * axis.x() << "," << angle * axis.y() << ","
         << angle * axis.z() << "\n";
    ExpectRotationNear(ParsePoses(text.str()).rows[0].pose,
                       Eigen::AngleAxisd(angle, axis).toRotationMatrix(), 1e-9 * angle);
  }
  // Huge angles in degrees must not overflow into NaN.
  const PoseTable huge = ParsePoses("x,y,z,rx_deg,ry_deg,rz_deg\n0,0,0,1e308,1e308,-1e308\n");
  EXPECT_TRUE(huge.rows[0].pose.matrix().allFinite());
  EXPECT_LT((huge.rows[0].pose.linear().transpose() * huge.rows[0].pose.linear() -
             Eigen::Matrix3d::Identity())
                .norm(),
            1e-12);
}

TEST(ReadPoseTableTest, Matrix) {
  const Eigen::Matrix3d R = Rz(0.3) * Ry(-1.2) * Rx(2.5);
  std::ostringstream text;
  text.precision(17);
  text << "id,r11,r12,r13,r21,r22,r23,r31,r32,r33,x,y,z\nA";
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) text << "," << R(i, j);
  }
  text << ",1,2,3\n";
  const PoseTable table = ParsePoses(text.str());
  EXPECT_EQ(table.rotation->ToString(), "matrix");
  ExpectRotationNear(table.rows[0].pose, R, 1e-15);
  EXPECT_EQ(table.rows[0].id, "A");
}

TEST(ReadPoseTableTest, MatrixWithinToleranceIsOrthonormalised) {
  Eigen::Matrix3d R = Rz(0.3) * Ry(-1.2) * Rx(2.5);
  Eigen::Matrix3d noisy = R;
  noisy(0, 1) += 3e-7;
  noisy(2, 2) -= 2e-7;
  std::ostringstream text;
  text.precision(17);
  text << "x,y,z,r11,r12,r13,r21,r22,r23,r31,r32,r33\n0,0,0";
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) text << "," << noisy(i, j);
  }
  const Pose pose = ParsePoses(text.str()).rows[0].pose;
  EXPECT_LT((pose.linear().transpose() * pose.linear() - Eigen::Matrix3d::Identity())
                .cwiseAbs()
                .maxCoeff(),
            1e-14);
  EXPECT_NEAR(pose.linear().determinant(), 1.0, 1e-14);
  ExpectRotationNear(pose, R, 1e-6);
}

// A robot controller's own matrices, 2e-5 from orthonormal, written with 17 digits.
std::vector<testing::NearlyOrthonormal> ControllerMatrices() {
  return {testing::ControllerMatrix(Rz(0.3) * Ry(-1.2) * Rx(2.5), 0.4e-5),
          testing::ControllerMatrix(Rx(1.9) * Rz(-0.6), 1e-5),
          testing::ControllerMatrix(Ry(3.1), 0.7e-5)};
}

void ExpectProjectedWithANote(const PoseTable& table,
                              const std::vector<testing::NearlyOrthonormal>& written) {
  ASSERT_EQ(table.rows.size(), written.size());
  for (size_t i = 0; i < written.size(); ++i) {
    ExpectRotationNear(table.rows[i].pose, written[i].rotation, 1e-15);
  }
  ASSERT_EQ(table.warnings.size(), 1u);
  EXPECT_THAT(table.warnings[0],
              HasSubstr("poses.csv: 3 of 3 rotation matrices were not orthonormal within 1e-6 "
                        "(largest error 2.0e-05 at line 3); projected onto the nearest rotation"));
}

TEST(ReadPoseTableTest, ControllerMatricesAreProjectedWithANote) {
  const std::vector<testing::NearlyOrthonormal> written = ControllerMatrices();
  std::string columns = "x_mm,y_mm,z_mm,r11,r12,r13,r21,r22,r23,r31,r32,r33\n";
  std::string lines;
  for (const testing::NearlyOrthonormal& m : written) {
    columns += "512.3,-87,630.2," + testing::Digits17(m.matrix, ",") + "\n";
    lines +=
        testing::Digits17(testing::Homogeneous(m.matrix, Eigen::Vector3d(0.5, 0.1, 0.6)), " ") +
        "\n";
  }
  ExpectProjectedWithANote(ParsePoses(columns), written);
  ExpectProjectedWithANote(ParsePoses("# 16 numbers per line\n" + lines), written);
}

// Tabb & Ahmad Yousef's robot_cali.txt (6 decimals, RᵀR off by up to 1.3e-6) as r11..r33 columns
// with the file's own digits: projected with a note, to the same rotations as the tabb importer.
TEST(ReadPoseTableTest, SixDecimalTabbMatricesAreProjectedWithANote) {
  const std::string dir = std::string(HECAL_SOURCE_DIR) + "/data/tabb-rwhe-dataset1/";
  const std::string robot_cali = ReadFile(dir + "robot_cali.txt");
  std::istringstream in(robot_cali);
  int count = 0;
  in >> count;
  std::string text = "x_mm,y_mm,z_mm,r11,r12,r13,r21,r22,r23,r31,r32,r33\n";
  std::vector<Eigen::Matrix3d> printed;
  for (int i = 0; i < count; ++i) {
    std::string token[16];
    for (std::string& entry : token) in >> entry;
    text += token[3] + "," + token[7] + "," + token[11];
    Eigen::Matrix3d M;
    for (int k = 0; k < 9; ++k) {
      const std::string& entry = token[4 * (k / 3) + k % 3];
      text += "," + entry;
      M(k / 3, k % 3) = std::stod(entry);
    }
    text += "\n";
    printed.push_back(M);
  }
  ASSERT_EQ(printed.size(), 88u);
  const PoseTable table = ParsePoses(text);
  ASSERT_EQ(table.rows.size(), 88u);
  const ImportedPoses imported =
      ParseTabb(robot_cali, "robot_cali.txt", ReadFile(dir + "cali.txt"), "cali.txt");
  for (size_t i = 0; i < 88; ++i) {
    const Eigen::Matrix3d R = table.rows[i].pose.linear();
    EXPECT_TRUE(testing::IsNearestRotation(R, printed[i], 1e-12)) << i;
    ExpectRotationNear(imported.robot.rows[i].pose.inverse(), R, 0.0);
  }
  ASSERT_EQ(table.warnings.size(), 1u);
  ASSERT_EQ(imported.robot.warnings.size(), 1u);
  // The same count as the importer's note, and the error within what 6 decimals explain.
  const std::string of_88 = imported.robot.warnings[0].substr(
      std::string("robot_cali.txt: ").size(),
      imported.robot.warnings[0].find(" rotation") - std::string("robot_cali.txt: ").size());
  EXPECT_THAT(of_88, ::testing::EndsWith("of 88"));
  EXPECT_THAT(table.warnings[0], HasSubstr("poses.csv: " + of_88 + " rotation matrices"));
  EXPECT_THAT(table.warnings[0], HasSubstr("within what entries printed to +-5.0e-07 allow"));
}

TEST(ReadPoseTableTest, UnitNamedSaysWhetherTheFileFixedTheUnit) {
  PoseReadOptions millimetres;
  millimetres.units = LengthUnit::kMillimetre;
  const PoseTable suffix_mm = ParsePoses("x_mm,y_mm,z_mm,qw,qx,qy,qz\n1,2,3,1,0,0,0\n");
  EXPECT_TRUE(suffix_mm.unit_named);
  EXPECT_EQ(suffix_mm.unit, LengthUnit::kMillimetre);
  const PoseTable suffix_m = ParsePoses("X_M,Y_M,Z_M,qw,qx,qy,qz\n1,2,3,1,0,0,0\n", millimetres);
  EXPECT_TRUE(suffix_m.unit_named);
  EXPECT_EQ(suffix_m.unit, LengthUnit::kMetre);  // the suffix wins over --units
  const PoseTable flag = ParsePoses("x,y,z,qw,qx,qy,qz\n1,2,3,1,0,0,0\n", millimetres);
  EXPECT_FALSE(flag.unit_named);
  EXPECT_EQ(flag.unit, LengthUnit::kMillimetre);
  EXPECT_FALSE(ParsePoses("x,y,z,qw,qx,qy,qz\n1,2,3,1,0,0,0\n").unit_named);  // the default, m
  const PoseTable lines = ParsePoses("1 0 0 1 0 1 0 2 0 0 1 3\n", millimetres);
  EXPECT_FALSE(lines.unit_named);
  EXPECT_EQ(lines.unit, LengthUnit::kMillimetre);
}

TEST(ReadPoseTableTest, EulerPresetsAgainstElementaryRotations) {
  const double a = 10, b = -35, c = 120;  // degrees
  // kuka: A, B, C = intrinsic ZYX → Rz(A) Ry(B) Rx(C); degrees by default.
  const PoseTable kuka = ParsePoses("x,y,z,a,b,c\n0,0,0,10,-35,120\n");
  EXPECT_EQ(kuka.rotation->ToString(), "kuka");
  EXPECT_TRUE(kuka.degrees);
  ExpectRotationNear(
      kuka.rows[0].pose,
      Rz(a * kRadiansPerDegree) * Ry(b * kRadiansPerDegree) * Rx(c * kRadiansPerDegree), 1e-15);
  // fanuc: W, P, R = extrinsic xyz → Rz(R) Ry(P) Rx(W); degrees by default.
  const PoseTable fanuc = ParsePoses("x,y,z,w,p,r\n0,0,0,10,-35,120\n");
  EXPECT_EQ(fanuc.rotation->ToString(), "fanuc");
  ExpectRotationNear(
      fanuc.rows[0].pose,
      Rz(c * kRadiansPerDegree) * Ry(b * kRadiansPerDegree) * Rx(a * kRadiansPerDegree), 1e-15);
  // rpy: extrinsic xyz in radians.
  const PoseTable rpy = ParsePoses("x,y,z,roll,pitch,yaw\n0,0,0,0.1,-0.2,0.3\n");
  EXPECT_EQ(rpy.rotation->ToString(), "rpy");
  EXPECT_FALSE(rpy.degrees);
  ExpectRotationNear(rpy.rows[0].pose, Rz(0.3) * Ry(-0.2) * Rx(0.1), 1e-15);
  // Suffixes override the preset's unit.
  const PoseTable kuka_rad = ParsePoses("x,y,z,a_rad,b_rad,c_rad\n0,0,0,0.1,-0.2,0.3\n");
  EXPECT_FALSE(kuka_rad.degrees);
  ExpectRotationNear(kuka_rad.rows[0].pose, Rz(0.1) * Ry(-0.2) * Rx(0.3), 1e-15);
  const PoseTable rpy_deg = ParsePoses("x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0,10,-35,120\n");
  ExpectRotationNear(
      rpy_deg.rows[0].pose,
      Rz(c * kRadiansPerDegree) * Ry(b * kRadiansPerDegree) * Rx(a * kRadiansPerDegree), 1e-15);
}

TEST(ReadPoseTableTest, GenericEulerNeedsASequence) {
  const std::string text = "x,y,z,a1,a2,a3\n0,0,0,0.1,0.2,0.3\n";
  const InputError error = ParseError(text);
  EXPECT_EQ(error.line(), 1);
  EXPECT_THAT(error.what(), HasSubstr("--euler"));

  PoseReadOptions options;
  options.euler = EulerSequence::Parse("ZXZ");
  const PoseTable table = ParsePoses(text, options);
  EXPECT_EQ(table.rotation->ToString(), "euler:ZXZ");
  ExpectRotationNear(table.rows[0].pose, Rz(0.1) * Rx(0.2) * Rz(0.3), 1e-15);

  options.euler = EulerSequence::Parse("zxz");  // extrinsic: applied about fixed axes
  ExpectRotationNear(ParsePoses(text, options).rows[0].pose, Rz(0.3) * Rx(0.2) * Rz(0.1), 1e-15);
}

TEST(ReadPoseTableTest, EulerDirectiveDeclaresTheSequenceAndWinsOverTheFlag) {
  const std::string text = "# euler: ZYX\nx,y,z,a1,a2,a3\n0,0,0,0.1,0.2,0.3\n";
  ExpectRotationNear(ParsePoses(text).rows[0].pose, Rz(0.1) * Ry(0.2) * Rx(0.3), 1e-15);
  PoseReadOptions options;
  options.euler = EulerSequence::Parse("xyz");
  ExpectRotationNear(ParsePoses(text, options).rows[0].pose, Rz(0.1) * Ry(0.2) * Rx(0.3), 1e-15);
  // An ordinary comment that merely mentions Euler angles is not a directive.
  EXPECT_EQ(ParseError("# euler angles below\nx,y,z,a1,a2,a3\n0,0,0,0,0,0\n").line(), 2);
  // Two different directives.
  EXPECT_EQ(ParseError("# euler: ZYX\n# euler: xyz\nx,y,z,a1,a2,a3\n0,0,0,0,0,0\n").line(), 2);
}

TEST(ReadPoseTableTest, PresetColumnsRejectAConflictingSequence) {
  PoseReadOptions options;
  options.euler = EulerSequence::Parse("xyz");
  const InputError error = ParseError("x,y,z,a,b,c\n0,0,0,1,2,3\n", options);
  EXPECT_THAT(error.what(), HasSubstr("ZYX"));
  options.euler = EulerSequence::Parse("ZYX");  // the same sequence is fine
  EXPECT_EQ(ParsePoses("x,y,z,a,b,c\n0,0,0,1,2,3\n", options).rows.size(), 1u);
}

TEST(ReadPoseTableTest, GimbalLockRowsReadExactly) {
  const PoseTable table = ParsePoses("x,y,z,a,b,c\n0,0,0,30,90,40\n0,0,0,-30,-90,20\n");
  ExpectRotationNear(
      table.rows[0].pose,
      Rz(30 * kRadiansPerDegree) * Ry(std::numbers::pi / 2) * Rx(40 * kRadiansPerDegree), 1e-15);
  ExpectRotationNear(
      table.rows[1].pose,
      Rz(-30 * kRadiansPerDegree) * Ry(-std::numbers::pi / 2) * Rx(20 * kRadiansPerDegree), 1e-15);
}

// ---- layout, units, ids, stamps
// ------------------------------------------------------------------

TEST(ReadPoseTableTest, ColumnsInAnyOrderAnyCaseWithIdAndStamp) {
  const PoseTable table = ParsePoses(
      "QZ, Stamp ,X,qw,ID,Y,qx,Z,qy\n"
      "0,12.5,1,1,first,2,0,3,0\n"
      "1,13.25,4,0,\"second, quoted\",5,0,6,0\n");
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].id, "first");
  EXPECT_EQ(table.rows[0].stamp, 12.5);
  ExpectTranslationNear(table.rows[0].pose, Eigen::Vector3d(1, 2, 3), 0);
  EXPECT_EQ(table.rows[1].id, "second, quoted");
  EXPECT_EQ(table.rows[1].stamp, 13.25);
  ExpectRotationNear(table.rows[1].pose, Rz(std::numbers::pi), 1e-15);
}

TEST(ReadPoseTableTest, CommentsBlankLinesCrLfAndByteOrderMark) {
  const PoseTable table = ParsePoses(
      "\xEF\xBB\xBF# exported by a robot\r\n\r\n  # another comment\r\nx,y,z,qw,qx,qy,qz\r\n"
      "# between rows\r\n1,2,3,1,0,0,0\r\n\r\n4,5,6,1,0,0,0\r\n");
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].line, 6);
  EXPECT_EQ(table.rows[1].line, 8);
  ExpectTranslationNear(table.rows[1].pose, Eigen::Vector3d(4, 5, 6), 0);
}

TEST(ReadPoseTableTest, WhitespaceSeparatedHeaderedFile) {
  const PoseTable table = ParsePoses("x y z\tqw qx qy qz\n1 2\t3 1 0 0 0\n");
  ASSERT_EQ(table.rows.size(), 1u);
  ExpectTranslationNear(table.rows[0].pose, Eigen::Vector3d(1, 2, 3), 0);
}

TEST(ReadPoseTableTest, LengthUnits) {
  const std::string plain = "x,y,z,qw,qx,qy,qz\n100,-200,300.5,1,0,0,0\n";
  EXPECT_EQ(ParsePoses(plain).unit, LengthUnit::kMetre);
  ExpectTranslationNear(ParsePoses(plain).rows[0].pose, Eigen::Vector3d(100, -200, 300.5), 0);
  PoseReadOptions mm;
  mm.units = LengthUnit::kMillimetre;
  const PoseTable flagged = ParsePoses(plain, mm);
  EXPECT_EQ(flagged.unit, LengthUnit::kMillimetre);
  ExpectTranslationNear(flagged.rows[0].pose, Eigen::Vector3d(0.1, -0.2, 0.3005), 1e-16);
  const std::string suffixed = "x_mm,y_mm,z_mm,qw,qx,qy,qz\n100,-200,300.5,1,0,0,0\n";
  EXPECT_EQ(ParsePoses(suffixed).unit, LengthUnit::kMillimetre);
  ExpectTranslationNear(ParsePoses(suffixed).rows[0].pose, Eigen::Vector3d(0.1, -0.2, 0.3005),
                        1e-16);
  // Suffixes win over the flag.
  const std::string metres = "x_m,y_m,z_m,qw,qx,qy,qz\n1,2,3,1,0,0,0\n";
  const PoseTable won = ParsePoses(metres, mm);
  EXPECT_EQ(won.unit, LengthUnit::kMetre);
  ExpectTranslationNear(won.rows[0].pose, Eigen::Vector3d(1, 2, 3), 0);
}

TEST(ReadPoseTableTest, AngleSuffixWinsOverDegreesFlag) {
  PoseReadOptions degrees;
  degrees.degrees = true;
  const PoseTable table = ParsePoses("x,y,z,rx_rad,ry_rad,rz_rad\n0,0,0,0,0,1\n", degrees);
  EXPECT_FALSE(table.degrees);
  ExpectRotationNear(table.rows[0].pose, Rz(1.0), 1e-15);
}

TEST(ReadPoseTableTest, HeaderlessMatrixLines) {
  const Eigen::Matrix3d R = Rz(0.3) * Ry(-1.2) * Rx(2.5);
  std::ostringstream m16, m12;
  m16.precision(17);
  m12.precision(17);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      m16 << R(i, j) << (j == 2 && i == 0 ? "\t" : " ");
      m12 << R(i, j) << ", ";
    }
    m16 << (i + 1) * 100 << " ";
    m12 << (i + 1) * 100 << (i < 2 ? ", " : "");
  }
  m16 << "0 0 0 1";
  PoseReadOptions mm;
  mm.units = LengthUnit::kMillimetre;
  for (const std::string& line : {m16.str(), m12.str()}) {
    const PoseTable table = ParsePoses("# matrix lines\n" + line + "\n" + line + "\n", mm);
    ASSERT_EQ(table.rows.size(), 2u) << line;
    EXPECT_FALSE(table.rotation);
    EXPECT_EQ(table.unit, LengthUnit::kMillimetre);
    EXPECT_EQ(table.rows[1].line, 3);
    ExpectRotationNear(table.rows[0].pose, R, 1e-15);
    ExpectTranslationNear(table.rows[0].pose, Eigen::Vector3d(0.1, 0.2, 0.3), 1e-16);
  }
}

TEST(ReadPoseTableTest, InvertOption) {
  PoseReadOptions invert;
  invert.invert = true;
  const std::string text = "x,y,z,a,b,c\n0.1,0.2,0.3,10,20,30\n";
  const Pose direct = ParsePoses(text).rows[0].pose;
  const Pose inverted = ParsePoses(text, invert).rows[0].pose;
  EXPECT_LT(((direct * inverted).matrix() - Eigen::Matrix4d::Identity()).norm(), 1e-15);
}

TEST(ReadPoseTableTest, NearlyUnitQuaternionsAreNormalisedWithANote) {
  // Norms 1.0002 and 1.0004 (within 1e-3): normalised, one note for the file; 1.0000001 is
  // rounding noise.
  const PoseTable table = ParsePoses(
      "x,y,z,qw,qx,qy,qz\n0,0,0,0.70725,0,0,0.70725\n0,0,0,1.0000001,0,0,0\n"
      "0,0,0,1.0004,0,0,0\n");
  ExpectRotationNear(table.rows[0].pose, Rz(std::numbers::pi / 2), 1e-15);
  ExpectRotationNear(table.rows[1].pose, Eigen::Matrix3d::Identity(), 1e-15);
  ExpectRotationNear(table.rows[2].pose, Eigen::Matrix3d::Identity(), 1e-15);
  ASSERT_EQ(table.warnings.size(), 1u);
  EXPECT_THAT(table.warnings[0],
              HasSubstr("poses.csv: 2 of 3 quaternions were not unit within 1e-6 (largest |norm "
                        "- 1| 4.0e-04 at line 4"));
  EXPECT_THAT(table.warnings[0], HasSubstr("normalised"));
  // 6-digit quaternions are normalised silently.
  EXPECT_TRUE(ParsePoses("x,y,z,qw,qx,qy,qz\n0,0,0,0.707107,0,0,0.707107\n").warnings.empty());
}

TEST(PoseTableErrorsTest, QuaternionsFarFromUnitAreRefused) {
  const InputError far = ParseError("x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n0,0,0,1.5,0,0,0\n");
  EXPECT_EQ(far.line(), 3);
  EXPECT_THAT(far.what(), HasSubstr("quaternion norm 1.5, not 1"));
  EXPECT_THAT(far.fix(), HasSubstr("are qw,qx,qy,qz a quaternion"));
  // The columns as the header names them (abb's q1..q4); huge values do not overflow the norm.
  EXPECT_THAT(ParseError("x,y,z,Q1,Q2,Q3,Q4\n0,0,0,2,0,0,2\n").fix(), HasSubstr("are Q1,Q2,Q3,Q4"));
  EXPECT_THAT(ParseError("x,y,z,qw,qx,qy,qz\n0,0,0,1e300,0,0,1e300\n").what(),
              HasSubstr("norm 1.41421e+300"));
}

TEST(ReadPoseTableTest, ReadsFromDisk) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "hecal_pose_table_read.csv").string();
  WriteFileAtomically(path, "x,y,z,qw,qx,qy,qz\n1,2,3,1,0,0,0\n");
  const PoseTable table = ReadPoseTable(path, {});
  EXPECT_EQ(table.source, path);
  ASSERT_EQ(table.rows.size(), 1u);
  std::filesystem::remove(path);
}

// ---- errors: one line each, with file:line and a fix
// ---------------------------------------------

TEST(PoseTableErrorsTest, UnreadableFile) {
  EXPECT_THROW(ReadPoseTable("/nonexistent/dir/poses.csv", {}), InputError);
}

TEST(PoseTableErrorsTest, NonFiniteValues) {
  for (const char* value : {"nan", "NaN", "inf", "-inf", "Infinity"}) {
    const InputError error =
        ParseError(std::string("x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n0,") + value + ",0,1,0,0,0\n");
    EXPECT_EQ(error.line(), 3) << value;
    EXPECT_THAT(error.what(), HasSubstr("non-finite")) << value;
    EXPECT_THAT(error.what(), HasSubstr("column y")) << value;
  }
  EXPECT_EQ(ParseError("x,y,z,qw,qx,qy,qz,stamp\n0,0,0,1,0,0,0,nan\n").line(), 2);
  EXPECT_EQ(ParseError("1 0 0 nan 0 1 0 0 0 0 1 0\n").line(), 1);
}

TEST(PoseTableErrorsTest, NotANumber) {
  const InputError error = ParseError("x,y,z,qw,qx,qy,qz\n0,0,zero,1,0,0,0\n");
  EXPECT_EQ(error.line(), 2);
  EXPECT_THAT(error.what(), HasSubstr("'zero' in column z is not a number"));
  EXPECT_EQ(ParseError("x,y,z,qw,qx,qy,qz\n0,0,,1,0,0,0\n").line(), 2);
}

TEST(PoseTableErrorsTest, WrongColumnCount) {
  const InputError fewer = ParseError("x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n0,0,0,1,0,0\n");
  EXPECT_EQ(fewer.line(), 3);
  EXPECT_THAT(fewer.what(), HasSubstr("6 values"));
  EXPECT_THAT(fewer.what(), HasSubstr("7 columns"));
  EXPECT_EQ(ParseError("x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0,5\n").line(), 2);
  EXPECT_EQ(ParseError("x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0,\n").line(), 2);
}

TEST(PoseTableErrorsTest, UnknownColumnSuggestsValidOnes) {
  const InputError typo = ParseError("x,y,z,qw,qx,qy,qzz\n0,0,0,1,0,0,0\n");
  EXPECT_EQ(typo.line(), 1);
  EXPECT_THAT(typo.what(), HasSubstr("unknown column 'qzz'"));
  EXPECT_THAT(typo.what(), HasSubstr("did you mean 'qz'"));
  EXPECT_THAT(typo.what(), HasSubstr("qw,qx,qy,qz"));
  const InputError alias = ParseError("tx,ty,tz,qw,qx,qy,qz\n0,0,0,1,0,0,0\n");
  EXPECT_THAT(alias.what(), HasSubstr("did you mean 'x'"));
  const InputError time = ParseError("timestamp,x,y,z,qw,qx,qy,qz\n0,0,0,0,1,0,0,0\n");
  EXPECT_THAT(time.what(), HasSubstr("did you mean 'stamp'"));
  const InputError semicolons = ParseError("x;y;z;qw;qx;qy;qz\n0;0;0;1;0;0;0\n");
  EXPECT_THAT(semicolons.what(), HasSubstr("commas"));
  EXPECT_THAT(ParseError("x,y,z,qw,qx,qy,qz,colour\n").what(), Not(HasSubstr("did you mean")));
}

TEST(PoseTableErrorsTest, EmptyAndDuplicateColumnNames) {
  EXPECT_THAT(ParseError("x,y,,z,qw,qx,qy,qz\n").what(), HasSubstr("column 3 has no name"));
  const InputError twice = ParseError("x,y,z,X,qw,qx,qy,qz\n");
  EXPECT_THAT(twice.what(), HasSubstr("twice"));
}

TEST(PoseTableErrorsTest, TwoRotationGroups) {
  const InputError error = ParseError("x,y,z,qw,qx,qy,qz,rx,ry,rz\n0,0,0,1,0,0,0,0,0,0\n");
  EXPECT_EQ(error.line(), 1);
  EXPECT_THAT(error.what(), HasSubstr("two rotation groups"));
  EXPECT_THAT(error.what(), HasSubstr("qw,qx,qy,qz"));
  EXPECT_THAT(error.what(), HasSubstr("rx,ry,rz"));
  EXPECT_THAT(ParseError("x,y,z,a,b,c,w,p,r\n").what(), HasSubstr("two rotation groups"));
  EXPECT_THAT(ParseError("x,y,z,roll,pitch,yaw,r\n").what(), HasSubstr("two rotation groups"));
}

TEST(PoseTableErrorsTest, MissingColumns) {
  EXPECT_THAT(ParseError("x,y,qw,qx,qy,qz\n0,0,1,0,0,0\n").what(),
              HasSubstr("missing position column(s) z"));
  EXPECT_THAT(ParseError("x,y,z,id\n0,0,0,a\n").what(), HasSubstr("no rotation columns"));
  const InputError partial = ParseError("x,y,z,qw,qx,qz\n");
  EXPECT_THAT(partial.what(), HasSubstr("lacks column(s) qy"));
  EXPECT_THAT(ParseError("x,y,z,r11,r12,r13,r21,r22,r23,r31,r32\n").what(),
              HasSubstr("lacks column(s) r33"));
}

TEST(PoseTableErrorsTest, MatrixNotARotationSaysWhy) {
  const InputError error = ParseError(
      "x,y,z,r11,r12,r13,r21,r22,r23,r31,r32,r33\n0,0,0,1,0,0,0,1,0,0,0,1\n"
      "0,0,0,1.01,0,0,0,1,0,0,0,1\n");
  EXPECT_EQ(error.line(), 3);
  EXPECT_THAT(error.what(), HasSubstr("not orthonormal"));
  EXPECT_THAT(error.what(), HasSubstr("2.0e-02"));  // |RᵀR − I| = 1.01² − 1
  // "1.01" is printed to +-5e-3, so the tolerance is 6 x 5e-3 capped at 1e-2.
  EXPECT_THAT(error.what(), HasSubstr("more than the 1.0e-02 allowed for entries printed to "
                                      "+-5.0e-03 (singular values 1.01, 1, 1)"));
  EXPECT_THAT(error.what(), Not(HasSubstr("digits")));
  // 5e-7 off is rounding (silent), 2e-6 gets a note, 1.2e-3 is refused.
  const std::string header = "x,y,z,r11,r12,r13,r21,r22,r23,r31,r32,r33\n";
  EXPECT_TRUE(ParsePoses(header + "0,0,0,1.00000025,0,0,0,1,0,0,0,1\n").warnings.empty());
  const PoseTable noted = ParsePoses(header + "0,0,0,1.000001,0,0,0,1,0,0,0,1\n");
  ExpectRotationNear(noted.rows[0].pose, Eigen::Matrix3d::Identity(), 1e-15);
  ASSERT_EQ(noted.warnings.size(), 1u);
  EXPECT_THAT(noted.warnings[0], HasSubstr("poses.csv: 1 of 1 rotation matrices"));
  EXPECT_THAT(ParseError(header + "0,0,0,1.0006,0,0,0,1,0,0,0,1\n").what(),
              HasSubstr("= 1.2e-03, more than the 1.0e-03 allowed"));
  // 3 decimals widen the tolerance to 6 x 5e-4 = 3e-3: 1.001 (2.0e-3 off) is within it.
  EXPECT_EQ(ParsePoses(header + "0,0,0,1.001,0,0,0,1,0,0,0,1\n").warnings.size(), 1u);
  // A reflection and a scaled rotation say so.
  EXPECT_THAT(ParseError(header + "0,0,0,-1,0,0,0,1,0,0,0,1\n").what(),
              HasSubstr("a reflection (det R = -1)"));
  EXPECT_THAT(ParseError(header + "0,0,0,0,-1.5,0,1.5,0,0,0,0,1.5\n").what(),
              HasSubstr("a rotation scaled by 1.5"));
  EXPECT_EQ(ParseError("1 0 0 0 0 1 0 0 0 0 2 0\n").line(), 1);
  EXPECT_EQ(ParseError("x,y,z,r11,r12,r13,r21,r22,r23,r31,r32,r33\n"
                       "0,0,0,1e200,1e200,1e200,-1e200,1e200,1e200,1,1,1\n")
                .line(),
            2);
}

TEST(PoseTableErrorsTest, LastRowOf4x4MustBe0001) {
  const InputError error =
      ParseError("1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n1 0 0 0 0 1 0 0 0 0 1 0 0 0 0.5 1\n");
  EXPECT_EQ(error.line(), 2);
  EXPECT_THAT(error.what(), HasSubstr("0 0 0.5 1, not 0 0 0 1"));
  EXPECT_EQ(ParseError("1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 2\n").line(), 1);
}

// A 4×4 written by columns (Eigen's and OpenGL's storage order): zeros where the translation
// belongs, the translation in the last row — the fix says so; other bad last rows do not.
TEST(PoseTableErrorsTest, AColumnMajor4x4GetsItsHint) {
  // R = Rz(90°), t = (0.1, 0.2, 0.3): row-major 0 -1 0 .1  1 0 0 .2  0 0 1 .3  0 0 0 1.
  const InputError transposed = ParseError("0 1 0 0 -1 0 0 0 0 0 1 0 0.1 0.2 0.3 1\n");
  EXPECT_THAT(transposed.what(), HasSubstr("looks column-major"));
  const InputError other = ParseError("0 -1 0 0.1 1 0 0 0.2 0 0 1 0.3 0 0 0.3 1\n");
  EXPECT_THAT(other.what(), Not(HasSubstr("column-major")));
  EXPECT_THAT(other.what(), HasSubstr("not 0 0 0 1"));
}

TEST(PoseTableErrorsTest, HeaderlessLinesNeed12Or16Numbers) {
  const InputError error = ParseError("1 0 0 0 0 1 0 0 0 0 1 0 5\n");
  EXPECT_EQ(error.line(), 1);
  EXPECT_THAT(error.what(), HasSubstr("12 (3×4) or 16 (4×4)"));
  EXPECT_THAT(error.what(), HasSubstr("has 13"));
  const InputError mixed = ParseError("1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n");
  EXPECT_EQ(mixed.line(), 2);
}

TEST(PoseTableErrorsTest, ZeroQuaternion) {
  const InputError error = ParseError("x,y,z,qw,qx,qy,qz\n0,0,0,0,0,0,0\n");
  EXPECT_EQ(error.line(), 2);
  EXPECT_THAT(error.what(), HasSubstr("zero quaternion"));
  EXPECT_EQ(ParseError("x,y,z,q1,q2,q3,q4\n0,0,0,1e-13,0,0,0\n").line(), 2);
  EXPECT_EQ(ParseError("x,y,z,q1,q2,q3,q4\n0,0,0,0,0,0,1e-300\n").line(), 2);
}

TEST(PoseTableErrorsTest, MixedUnits) {
  const InputError lengths = ParseError("x_mm,y_m,z_mm,qw,qx,qy,qz\n");
  EXPECT_THAT(lengths.what(), HasSubstr("mixed length units"));
  EXPECT_THAT(lengths.what(), HasSubstr("x_mm"));
  EXPECT_THAT(lengths.what(), HasSubstr("y_m"));
  EXPECT_THAT(ParseError("x_mm,y,z,qw,qx,qy,qz\n").what(), HasSubstr("mixed length units"));
  EXPECT_THAT(ParseError("x,y,z,a_deg,b_rad,c_deg\n").what(), HasSubstr("mixed angle units"));
  EXPECT_THAT(ParseError("x,y,z,roll_deg,pitch,yaw\n").what(), HasSubstr("mixed angle units"));
}

TEST(PoseTableErrorsTest, UnitsOnTheWrongColumns) {
  EXPECT_THAT(ParseError("x,y,z,qw_deg,qx_deg,qy_deg,qz_deg\n").what(),
              HasSubstr("cannot have an angle unit"));
  EXPECT_THAT(ParseError("x_deg,y_deg,z_deg,qw,qx,qy,qz\n").what(), HasSubstr("is a position"));
  EXPECT_THAT(ParseError("x,y,z,rx_mm,ry_mm,rz_mm\n").what(), HasSubstr("is a rotation"));
  EXPECT_THAT(ParseError("x,y,z,qw,qx,qy,qz,stamp_mm\n").what(), HasSubstr("cannot have a unit"));
}

TEST(PoseTableErrorsTest, EmptyFileAndHeaderOnly) {
  EXPECT_THAT(ParseError("").what(), HasSubstr("empty"));
  EXPECT_EQ(ParseError("").line(), 0);
  EXPECT_THAT(ParseError("# only a comment\n\n").what(), HasSubstr("no poses"));
  const InputError header_only = ParseError("# c\nx,y,z,qw,qx,qy,qz\n# nothing\n\n");
  EXPECT_EQ(header_only.line(), 2);
  EXPECT_THAT(header_only.what(), HasSubstr("header but no poses"));
}

TEST(PoseTableErrorsTest, DuplicateAndEmptyIds) {
  const InputError error =
      ParseError("id,x,y,z,qw,qx,qy,qz\na,0,0,0,1,0,0,0\nb,0,0,0,1,0,0,0\na,0,0,0,1,0,0,0\n");
  EXPECT_EQ(error.line(), 4);
  EXPECT_THAT(error.what(), HasSubstr("id 'a' repeats (first at line 2)"));
  EXPECT_EQ(ParseError("id,x,y,z,qw,qx,qy,qz\n,0,0,0,1,0,0,0\n").line(), 2);
}

TEST(PoseTableErrorsTest, BrokenQuotes) {
  EXPECT_EQ(ParseError("id,x,y,z,qw,qx,qy,qz\n\"a,0,0,0,1,0,0,0\n").line(), 2);
}

TEST(PoseTableErrorsTest, ControlCharactersAreEscapedInMessages) {
  const InputError error = ParseError(std::string("x,y,z,q\x01w,qx,qy,qz\n"));
  EXPECT_THAT(error.what(), HasSubstr("\\x01"));
}

// ---- writing
// -------------------------------------------------------------------------------------

PoseTable SmallTable() {
  PoseTable table;
  table.source = "memory";
  PoseRow row;
  row.pose = MakePose(Rz(std::numbers::pi / 2), Eigen::Vector3d(0.1, 0.25, -1));
  row.id = "a";
  row.stamp = 1.5;
  table.rows.push_back(row);
  return table;
}

PoseWriteOptions WriteAs(std::string_view format) {
  PoseWriteOptions options;
  options.rotation = *ParseRotationFormat(format);
  return options;
}

// The header line(s) of a written table, and the numbers of its last data row.
struct WrittenText {
  std::vector<std::string> lines;
  std::vector<double> numbers;  // the last row, id (if any) skipped
};
WrittenText Split(const std::string& text, bool has_id) {
  WrittenText written;
  LineCursor cursor(text);
  std::string_view line;
  while (cursor.Next(&line)) written.lines.emplace_back(line);
  std::vector<Field> fields;
  std::string error;
  EXPECT_TRUE(SplitFields(written.lines.back(), Separator::kComma, &fields, &error));
  for (size_t i = has_id ? 1 : 0; i < fields.size(); ++i) {
    double value = 0.0;
    EXPECT_TRUE(ParseDouble(fields[i].text, &value)) << fields[i].text;
    written.numbers.push_back(value);
  }
  return written;
}

void ExpectNumbersNear(const std::vector<double>& actual, const std::vector<double>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (size_t i = 0; i < actual.size(); ++i) {
    EXPECT_NEAR(actual[i], expected[i], 1e-13 * std::max(1.0, std::abs(expected[i]))) << i;
  }
}

TEST(WritePoseTableTest, HeadersAndValues) {
  const double h = std::sqrt(0.5);
  WrittenText q = Split(FormatPoseTable(SmallTable(), WriteAs("quaternion")), true);
  EXPECT_EQ(q.lines[0], "id,stamp,x,y,z,qw,qx,qy,qz");
  EXPECT_TRUE(q.lines[1].starts_with("a,1.5,0.1,0.25,-1,"));
  ExpectNumbersNear(q.numbers, {1.5, 0.1, 0.25, -1, h, 0, 0, h});

  PoseWriteOptions mm = WriteAs("rotvec");
  mm.units = LengthUnit::kMillimetre;
  mm.degrees = true;
  mm.write_stamp = false;
  mm.comments = {"robot poses", "two\nlines"};
  WrittenText v = Split(FormatPoseTable(SmallTable(), mm), true);
  EXPECT_EQ(v.lines[0], "# robot poses");
  EXPECT_EQ(v.lines[1], "# two");
  EXPECT_EQ(v.lines[2], "# lines");
  EXPECT_EQ(v.lines[3], "id,x_mm,y_mm,z_mm,rx_deg,ry_deg,rz_deg");
  EXPECT_TRUE(v.lines[4].starts_with("a,100,250,-1000,")) << v.lines[4];
  ExpectNumbersNear(v.numbers, {100, 250, -1000, 0, 0, 90});

  WrittenText k = Split(FormatPoseTable(SmallTable(), WriteAs("kuka")), true);
  EXPECT_EQ(k.lines[0], "id,stamp,x,y,z,a_deg,b_deg,c_deg");
  ExpectNumbersNear(k.numbers, {1.5, 0.1, 0.25, -1, 90, 0, 0});

  WrittenText f = Split(FormatPoseTable(SmallTable(), WriteAs("fanuc")), true);
  EXPECT_EQ(f.lines[0], "id,stamp,x,y,z,w_deg,p_deg,r_deg");
  ExpectNumbersNear(f.numbers, {1.5, 0.1, 0.25, -1, 0, 0, 90});

  WrittenText r = Split(FormatPoseTable(SmallTable(), WriteAs("rpy")), true);
  EXPECT_EQ(r.lines[0], "id,stamp,x,y,z,roll,pitch,yaw");
  ExpectNumbersNear(r.numbers, {1.5, 0.1, 0.25, -1, 0, 0, std::numbers::pi / 2});

  WrittenText e = Split(FormatPoseTable(SmallTable(), WriteAs("euler:ZYX")), true);
  EXPECT_EQ(e.lines[0], "# euler: ZYX");
  EXPECT_EQ(e.lines[1], "id,stamp,x,y,z,a1,a2,a3");
  ExpectNumbersNear(e.numbers, {1.5, 0.1, 0.25, -1, std::numbers::pi / 2, 0, 0});

  EXPECT_EQ(Split(FormatPoseTable(SmallTable(), WriteAs("abb")), true).lines[0],
            "id,stamp,x,y,z,q1,q2,q3,q4");
  EXPECT_EQ(Split(FormatPoseTable(SmallTable(), WriteAs("ur")), true).lines[0],
            "id,stamp,x,y,z,rx,ry,rz");

  PoseWriteOptions no_id = WriteAs("matrix");
  no_id.write_id = false;
  WrittenText m = Split(FormatPoseTable(SmallTable(), no_id), false);
  EXPECT_EQ(m.lines[0], "stamp,x,y,z,r11,r12,r13,r21,r22,r23,r31,r32,r33");
  ExpectNumbersNear(m.numbers, {1.5, 0.1, 0.25, -1, 0, -1, 0, 1, 0, 0, 0, 0, 1});
}

TEST(WritePoseTableTest, ExactTextForExactValues) {
  PoseTable table = SmallTable();
  table.rows[0].pose.linear() = Eigen::Vector3d(-1, -1, 1).asDiagonal();  // π about z, exactly
  EXPECT_EQ(FormatPoseTable(table, WriteAs("quaternion")),
            "id,stamp,x,y,z,qw,qx,qy,qz\na,1.5,0.1,0.25,-1,0,0,0,1\n");
  PoseWriteOptions mm = WriteAs("matrix");
  mm.units = LengthUnit::kMillimetre;
  EXPECT_EQ(FormatPoseTable(table, mm),
            "id,stamp,x_mm,y_mm,z_mm,r11,r12,r13,r21,r22,r23,r31,r32,r33\n"
            "a,1.5,100,250,-1000,-1,0,0,0,-1,0,0,0,1\n");
}

TEST(WritePoseTableTest, QuaternionsAreCanonical) {
  // Rotations whose Eigen quaternion has w < 0 are written with qw ≥ 0.
  for (const Eigen::Matrix3d& R :
       {Eigen::Matrix3d(Rx(std::numbers::pi - 0.1) * Rz(3.0)), Eigen::Matrix3d(Rz(-3.1)),
        Eigen::Matrix3d(Ry(std::numbers::pi))}) {
    PoseTable table = SmallTable();
    table.rows[0].pose.linear() = R;
    PoseWriteOptions options = WriteAs("quaternion");
    options.write_id = options.write_stamp = false;
    const std::string text = FormatPoseTable(table, options);
    const std::string row = text.substr(text.find('\n') + 1, text.size() - text.find('\n') - 2);
    std::vector<Field> fields;
    std::string error;
    ASSERT_TRUE(SplitFields(row, Separator::kComma, &fields, &error));
    ASSERT_EQ(fields.size(), 7u);
    double qw = -1.0;
    ASSERT_TRUE(ParseDouble(fields[3].text, &qw));
    EXPECT_GE(qw, 0.0) << text;
  }
}

TEST(WritePoseTableTest, OutputThatOverflowsTheUnitIsAnInputError) {
  PoseTable table = SmallTable();
  table.rows[0].pose.translation().x() = 1e307;
  PoseWriteOptions mm = WriteAs("quaternion");
  mm.units = LengthUnit::kMillimetre;
  EXPECT_THROW(FormatPoseTable(table, mm), InputError);
}

TEST(WritePoseTableTest, IdsWithCarriageReturnsRoundTrip) {
  // Found by fuzz_pose_table: the reader keeps a '\r' inside an id; the writer must keep it too.
  const PoseTable table = ParsePoses("x,y,z,w,p,r,id\n1,2,3,0,9,0,t\r0\n2,2,3,0,9,0,\"end\r\"\n");
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].id, "t\r0");
  EXPECT_EQ(table.rows[1].id, "end\r");
  const PoseTable back = ParsePoses(FormatPoseTable(table, WriteAs("quaternion")));
  EXPECT_EQ(back.rows[0].id, "t\r0");
  EXPECT_EQ(back.rows[1].id, "end\r");
}

TEST(WritePoseTableTest, IdsMustBeAllOrNoneAndSingleLine) {
  PoseTable table = SmallTable();
  table.rows.push_back(table.rows[0]);
  table.rows[1].id.reset();
  EXPECT_THROW(FormatPoseTable(table, WriteAs("quaternion")), InputError);
  table.rows[1].id = "two\nlines";
  EXPECT_THROW(FormatPoseTable(table, WriteAs("quaternion")), InputError);
}

TEST(WritePoseTableTest, MissingDirectoryLeavesNoFile) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "hecal_pose_table_no_such_dir";
  std::filesystem::remove_all(dir);
  EXPECT_THROW(WritePoseTable((dir / "out.csv").string(), SmallTable(), WriteAs("quaternion")),
               InputError);
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(WritePoseTableTest, MillimetreDigitsSurviveReadAndWrite) {
  const std::string text = "x_mm,y_mm,z_mm,qw,qx,qy,qz\n123.456,-0.1,1000.25,1,0,0,0\n";
  PoseWriteOptions options = WriteAs("quaternion");
  options.units = LengthUnit::kMillimetre;
  EXPECT_EQ(FormatPoseTable(ParsePoses(text), options), text);
}

// Every format, preset, length unit and angle unit: write → read gives the same poses, ids and
// stamps, with no flags on the reading side.
TEST(WritePoseTableTest, RoundTripEveryFormatAndUnit) {
  std::mt19937_64 rng(42);
  PoseTable table;
  table.source = "memory";
  std::vector<Eigen::Matrix3d> rotations;
  for (const Eigen::Vector3d& omega : testing::EdgeCaseRotationVectors(rng)) {
    rotations.push_back(Eigen::AngleAxisd(omega.norm(), omega.norm() > 0 ? omega.normalized()
                                                                         : Eigen::Vector3d::UnitX())
                            .toRotationMatrix());
  }
  for (int i = 0; i < 200; ++i) rotations.push_back(testing::RandomRotation(rng));
  // Gimbal locks of the Tait–Bryan and proper sequences.
  for (double a : {-std::numbers::pi / 2, std::numbers::pi / 2}) {
    rotations.push_back(Rz(0.7) * Ry(a) * Rx(-0.4));
    rotations.push_back(Rx(0.7) * Ry(a) * Rz(-0.4));
    rotations.push_back(Rx(0.7) * Rz(a) * Ry(-0.4));
  }
  rotations.push_back(Rz(0.7) * Rx(std::numbers::pi) * Rz(0.2));
  rotations.push_back(Ry(0.7) * Rx(std::numbers::pi) * Ry(0.2));
  const std::string ids[] = {"plain", "with,comma", "with \"quote\"", "#hash", " spaced ", "ü"};
  hecal::UniformRealDistribution position(-2.0, 2.0);
  for (size_t i = 0; i < rotations.size(); ++i) {
    PoseRow row;
    const double z = position(rng);  // drawn last to first, as the test's data were generated
    const double y = position(rng);
    const double x = position(rng);
    row.pose = MakePose(rotations[i], Eigen::Vector3d(x, y, z));
    row.id = ids[i % std::size(ids)] + std::to_string(i);
    row.stamp = 1e9 + 0.001 * static_cast<double>(i);
    table.rows.push_back(row);
  }
  std::vector<std::string> formats = {"quaternion", "rotvec", "matrix", "rpy",
                                      "kuka",       "fanuc",  "abb",    "ur"};
  for (const char* sequence :
       {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz"}) {
    formats.push_back(std::string("euler:") + sequence);
    std::string upper = sequence;
    for (char& c : upper) c = static_cast<char>(std::toupper(c));
    formats.push_back("euler:" + upper);
  }
  for (const std::string& format : formats) {
    for (LengthUnit unit : {LengthUnit::kMetre, LengthUnit::kMillimetre}) {
      for (bool degrees : {false, true}) {
        PoseWriteOptions options = WriteAs(format);
        options.units = unit;
        options.degrees = degrees;
        const std::string text = FormatPoseTable(table, options);
        const PoseTable back = ParsePoses(text);
        SCOPED_TRACE(format + (unit == LengthUnit::kMillimetre ? " mm" : " m") +
                     (degrees ? " deg" : " rad"));
        ASSERT_EQ(back.rows.size(), table.rows.size());
        EXPECT_EQ(back.unit, unit);
        // ur and rotvec are the same columns; reading names them rotvec.
        EXPECT_EQ(back.rotation->ToString(), format == "ur" ? "rotvec" : format);
        for (size_t i = 0; i < table.rows.size(); ++i) {
          EXPECT_EQ(back.rows[i].id, table.rows[i].id);
          EXPECT_EQ(back.rows[i].stamp, table.rows[i].stamp);
          const double rotation_error =
              (back.rows[i].pose.linear() - table.rows[i].pose.linear()).cwiseAbs().maxCoeff();
          const double translation_error =
              (back.rows[i].pose.translation() - table.rows[i].pose.translation())
                  .cwiseAbs()
                  .maxCoeff();  // Within kGimbalLockTolerance of a lock, Euler angles set a3 = 0
                                // (euler.h) and
          // reproduce R only to O(distance · |a3|), documented as ≤ ~3e-7.
          double tolerance = 1e-13;
          if (options.rotation.sequence) {
            const EulerSequence& sequence = *options.rotation.sequence;
            const double a2 = EulerFromMatrix(table.rows[i].pose.linear(), sequence)[1];
            const double lock = sequence.proper()
                                    ? std::min(std::abs(a2), std::abs(std::numbers::pi - a2))
                                    : std::abs(std::abs(a2) - std::numbers::pi / 2);
            if (lock < 1e-6) tolerance = 1e-6;
          }
          EXPECT_LT(rotation_error, tolerance) << "row " << i << "\n"
                                               << table.rows[i].pose.linear();
          EXPECT_LT(translation_error, 1e-15) << "row " << i;
        }
      }
    }
  }
}

TEST(WritePoseTableTest, MetresInQuaternionFormatRoundTripBitExactTranslation) {
  std::mt19937_64 rng(3);
  PoseTable table;
  for (int i = 0; i < 100; ++i) {
    PoseRow row;
    row.pose = testing::RandomPose(rng, 10.0);
    table.rows.push_back(row);
  }
  const PoseTable back = ParsePoses(FormatPoseTable(table, WriteAs("matrix")));
  for (size_t i = 0; i < table.rows.size(); ++i) {
    EXPECT_EQ(back.rows[i].pose.translation(), table.rows[i].pose.translation());
  }
}

// ---- speed
// ---------------------------------------------------------------------------------------

TEST(PoseTableSpeedTest, HundredThousandRowsParseWellUnderASecond) {
  std::mt19937_64 rng(5);
  PoseTable table;
  for (int i = 0; i < 100000; ++i) {
    PoseRow row;
    row.pose = testing::RandomPose(rng);
    row.id = "station_" + std::to_string(i);
    row.stamp = i * 0.02;
    table.rows.push_back(row);
  }
  for (const char* format : {"quaternion", "matrix", "kuka"}) {
    PoseWriteOptions options = WriteAs(format);
    options.units = LengthUnit::kMillimetre;
    const std::string text = FormatPoseTable(
        table,
        options);  // Processor time, so that a loaded test machine does not make the test flaky.
    const std::clock_t start = std::clock();
    const PoseTable back = ParsePoses(text);
    const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    EXPECT_EQ(back.rows.size(), table.rows.size());
    EXPECT_LT(seconds, 1.0) << format;
    std::printf("%s: 100k rows (%zu bytes) parsed in %.3f s\n", format, text.size(), seconds);
  }
}

TEST(PoseReadOptions, IsValidNamesTheField) {
  const PoseReadOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(testing::RefusesNaming(defaults, "PoseReadOptions.units",
                                     [](auto& o) { o.units = static_cast<LengthUnit>(7); }));
  PoseReadOptions bad;
  bad.units = static_cast<LengthUnit>(7);
  EXPECT_THROW(ParsePoseTable("x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n", "t.csv", bad), InputError);
}

TEST(PoseWriteOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const PoseWriteOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "PoseWriteOptions.rotation", [](auto& o) {
    o.rotation.kind = static_cast<RotationFormat::Kind>(9);
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "PoseWriteOptions.rotation",
                            [](auto& o) { o.rotation.kind = RotationFormat::Kind::kEuler; }));
  EXPECT_TRUE(RefusesNaming(defaults, "PoseWriteOptions.rotation",
                            [](auto& o) { o.rotation.sequence = EulerSequence::Parse("xyz"); }));
  EXPECT_TRUE(RefusesNaming(defaults, "PoseWriteOptions.units",
                            [](auto& o) { o.units = static_cast<LengthUnit>(-1); }));
}

}  // namespace
}  // namespace hecal::io
