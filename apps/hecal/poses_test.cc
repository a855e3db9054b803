// `hecal poses convert` through RunHecal: exit codes, the one-line error on stderr, no output file
// on error, and the content of the output (checked against rotations composed by hand).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "cli.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/io/atomic_file.h"
#include "testing/csv_reader.h"
#include "testing/elementary_rotations.h"
#include "testing/nearly_orthonormal.h"

namespace hecal::cli {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// Independent definitions (not the library's Euler code): elementary rotations composed by hand.
using testing::Rx;
using testing::Ry;
using testing::Rz;

using csv_test::Csv;

Csv ReadCsv(const fs::path& path) {
  EXPECT_TRUE(fs::exists(path)) << path;
  return csv_test::ReadCsv(path.string());
}

class PosesConvertTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("hecal_poses_test_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& contents) {
    const std::string path = (dir_ / name).string();
    io::WriteFileAtomically(path, contents);
    return path;
  }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  int Run(std::vector<std::string> args) {
    args.insert(args.begin(), {"hecal", "poses", "convert"});
    out_.str("");
    err_.str("");
    return RunHecal(args, out_, err_);
  }

  // Runs a conversion that must fail with exit 2, one line on stderr naming `where`, and no
  // output file.
  void ExpectBadInput(std::vector<std::string> args, const std::string& where,
                      const std::string& what) {
    const std::string output = Path("never.csv");
    args.insert(args.end(), {"--output", output});
    EXPECT_EQ(Run(args), 2) << err_.str();
    const std::string err = err_.str();
    EXPECT_THAT(err, StartsWith("hecal: ")) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_THAT(err, HasSubstr(where)) << err;
    EXPECT_THAT(err, HasSubstr(what)) << err;
    EXPECT_THAT(err, HasSubstr("fix")) << err;
    EXPECT_FALSE(fs::exists(output));
    for (const auto& entry : fs::directory_iterator(dir_)) {
      EXPECT_THAT(entry.path().filename().string(), Not(HasSubstr("never")));
    }
  }

  fs::path dir_;
  std::ostringstream out_;
  std::ostringstream err_;
};

constexpr const char* kKukaMillimetres =
    "# KUKA robot poses\n"
    "id,stamp,x_mm,y_mm,z_mm,a,b,c\n"
    "p1,0.5,100,200,300,10,20,30\n"
    "p2,1.5,-100.25,0,1000,170,-89.9,-179\n";

TEST_F(PosesConvertTest, KukaToQuaternionKeepsIdStampAndUnit) {
  const std::string input = Write("robot.csv", kKukaMillimetres);
  const std::string output = Path("out.csv");
  ASSERT_EQ(Run({"--input", input, "--output", output, "--to", "quaternion"}), 0) << err_.str();
  EXPECT_EQ(err_.str(), "");
  EXPECT_THAT(out_.str(), HasSubstr("wrote 2 poses"));
  const Csv csv = ReadCsv(output);
  EXPECT_TRUE(csv.comments.empty());
  EXPECT_EQ(csv.header, (std::vector<std::string>{"id", "stamp", "x_mm", "y_mm", "z_mm", "qw", "qx",
                                                  "qy", "qz"}));
  ASSERT_EQ(csv.rows.size(), 2u);
  EXPECT_EQ(csv.rows[0][0], "p1");
  EXPECT_EQ(csv.rows[1][0], "p2");
  EXPECT_EQ(csv.Number(0, "stamp"), 0.5);
  EXPECT_EQ(csv.Number(1, "stamp"), 1.5);
  EXPECT_EQ(csv.Number(1, "x_mm"), -100.25);
  EXPECT_EQ(csv.Number(1, "z_mm"), 1000);
  const double abc[2][3] = {{10, 20, 30}, {170, -89.9, -179}};
  for (size_t i = 0; i < 2; ++i) {
    const Eigen::Quaterniond expected(Rz(abc[i][0] * kRadiansPerDegree) *
                                      Ry(abc[i][1] * kRadiansPerDegree) *
                                      Rx(abc[i][2] * kRadiansPerDegree));
    const double sign = expected.w() < 0 ? -1.0 : 1.0;  // output has qw ≥ 0
    EXPECT_NEAR(csv.Number(i, "qw"), sign * expected.w(), 1e-15);
    EXPECT_NEAR(csv.Number(i, "qx"), sign * expected.x(), 1e-15);
    EXPECT_NEAR(csv.Number(i, "qy"), sign * expected.y(), 1e-15);
    EXPECT_NEAR(csv.Number(i, "qz"), sign * expected.z(), 1e-15);
    EXPECT_GE(csv.Number(i, "qw"), 0.0);
  }
}

TEST_F(PosesConvertTest, UnitsAndDegreesApplyToTheOutput) {
  const std::string input = Write("robot.csv", kKukaMillimetres);
  const std::string output = Path("out.csv");
  ASSERT_EQ(
      Run({"--input", input, "--output", output, "--to", "rotvec", "--units", "m", "--degrees"}), 0)
      << err_.str();
  const Csv csv = ReadCsv(output);
  EXPECT_EQ(csv.header,
            (std::vector<std::string>{"id", "stamp", "x", "y", "z", "rx_deg", "ry_deg", "rz_deg"}));
  EXPECT_NEAR(csv.Number(0, "x"), 0.1, 1e-16);
  EXPECT_NEAR(csv.Number(1, "x"), -0.10025, 1e-16);
  const Eigen::AngleAxisd expected(Rz(10 * kRadiansPerDegree) * Ry(20 * kRadiansPerDegree) *
                                   Rx(30 * kRadiansPerDegree));
  const Eigen::Vector3d omega = expected.angle() * expected.axis() / kRadiansPerDegree;
  EXPECT_NEAR(csv.Number(0, "rx_deg"), omega.x(), 1e-12);
  EXPECT_NEAR(csv.Number(0, "ry_deg"), omega.y(), 1e-12);
  EXPECT_NEAR(csv.Number(0, "rz_deg"), omega.z(), 1e-12);

  // Without --degrees, rotation vectors are radians; without --units, the input's mm.
  ASSERT_EQ(Run({"--input", input, "--output", output, "--to", "ur"}), 0) << err_.str();
  const Csv ur = ReadCsv(output);
  EXPECT_EQ(ur.header,
            (std::vector<std::string>{"id", "stamp", "x_mm", "y_mm", "z_mm", "rx", "ry", "rz"}));
  EXPECT_NEAR(ur.Number(0, "rx"), omega.x() * kRadiansPerDegree, 1e-14);
}

TEST_F(PosesConvertTest, EulerOutputDeclaresItsSequence) {
  const std::string input = Write("robot.csv", kKukaMillimetres);
  const std::string output = Path("out.csv");
  ASSERT_EQ(Run({"--input", input, "--output", output, "--to", "euler:xyz", "--degrees"}), 0)
      << err_.str();
  const Csv csv = ReadCsv(output);
  EXPECT_EQ(csv.comments, std::vector<std::string>{"# euler: xyz"});
  EXPECT_EQ(csv.header, (std::vector<std::string>{"id", "stamp", "x_mm", "y_mm", "z_mm", "a1_deg",
                                                  "a2_deg", "a3_deg"}));
  // Extrinsic xyz (c, b, a) is intrinsic ZYX (a, b, c).
  EXPECT_NEAR(csv.Number(0, "a1_deg"), 30, 1e-12);
  EXPECT_NEAR(csv.Number(0, "a2_deg"), 20, 1e-12);
  EXPECT_NEAR(csv.Number(0, "a3_deg"), 10, 1e-12);

  // The output reads back without --euler, and converts back to the same KUKA angles.
  const std::string back = Path("back.csv");
  ASSERT_EQ(Run({"--input", output, "--output", back, "--to", "kuka"}), 0) << err_.str();
  const Csv kuka = ReadCsv(back);
  EXPECT_EQ(kuka.header, (std::vector<std::string>{"id", "stamp", "x_mm", "y_mm", "z_mm", "a_deg",
                                                   "b_deg", "c_deg"}));
  EXPECT_NEAR(kuka.Number(1, "a_deg"), 170, 1e-9);
  EXPECT_NEAR(kuka.Number(1, "b_deg"), -89.9, 1e-9);
  EXPECT_NEAR(kuka.Number(1, "c_deg"), -179, 1e-9);
  EXPECT_EQ(kuka.rows[1][2], "-100.25");
}

TEST_F(PosesConvertTest, Invert) {
  const std::string input =
      Write("in.csv", "x,y,z,qw,qx,qy,qz\n1,2,3," + std::to_string(std::cos(0.25)) + ",0,0," +
                          std::to_string(std::sin(0.25)) + "\n");
  const std::string output = Path("out.csv");
  ASSERT_EQ(Run({"--input", input, "--output", output, "--to", "matrix", "--invert"}), 0)
      << err_.str();
  const Csv csv = ReadCsv(output);
  const Eigen::Matrix3d R = Rz(0.5);
  const Eigen::Vector3d t = -R.transpose() * Eigen::Vector3d(1, 2, 3);
  EXPECT_NEAR(csv.Number(0, "x"), t.x(), 1e-6);
  EXPECT_NEAR(csv.Number(0, "y"), t.y(), 1e-6);
  EXPECT_NEAR(csv.Number(0, "z"), t.z(), 1e-6);
  EXPECT_NEAR(csv.Number(0, "r12"), R(1, 0), 1e-6);
  EXPECT_NEAR(csv.Number(0, "r21"), R(0, 1), 1e-6);
  EXPECT_THAT(out_.str(), HasSubstr("inverted"));
}

TEST_F(PosesConvertTest, InputFlagsForUnsuffixedFiles) {
  // a1,a2,a3 in degrees and millimetres, sequence by --euler.
  const std::string input = Write("in.csv", "x,y,z,a1,a2,a3\n1000,0,-500,90,0,0\n");
  const std::string output = Path("out.csv");
  ASSERT_EQ(Run({"--input", input, "--output", output, "--to", "rotvec", "--input-units", "mm",
                 "--input-degrees", "--euler", "ZYX"}),
            0)
      << err_.str();
  const Csv csv = ReadCsv(output);
  EXPECT_EQ(csv.header, (std::vector<std::string>{"x_mm", "y_mm", "z_mm", "rx", "ry", "rz"}));
  EXPECT_EQ(csv.Number(0, "x_mm"), 1000);
  EXPECT_EQ(csv.Number(0, "z_mm"), -500);
  EXPECT_NEAR(csv.Number(0, "rz"), std::numbers::pi / 2, 1e-15);
  // Header suffixes win over the input flags.
  const std::string suffixed =
      Write("suffixed.csv", "x_m,y_m,z_m,rx_rad,ry_rad,rz_rad\n1,2,3,0,0,1\n");
  ASSERT_EQ(Run({"--input", suffixed, "--output", output, "--to", "rotvec", "--input-units", "mm",
                 "--input-degrees"}),
            0)
      << err_.str();
  const Csv won = ReadCsv(output);
  EXPECT_EQ(won.header, (std::vector<std::string>{"x", "y", "z", "rx", "ry", "rz"}));
  EXPECT_EQ(won.Number(0, "x"), 1);
  EXPECT_NEAR(won.Number(0, "rz"), 1, 1e-15);
}

TEST_F(PosesConvertTest, HeaderlessMatrixInput) {
  const std::string input = Write("m16.txt",
                                  "0 -1 0 100\t1 0 0 200 0 0 1 300 0 0 0 1\n"
                                  "1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1\n");
  const std::string output = Path("out.csv");
  ASSERT_EQ(Run({"--input", input, "--output", output, "--to", "fanuc", "--input-units", "mm"}), 0)
      << err_.str();
  const Csv csv = ReadCsv(output);
  EXPECT_EQ(csv.header,
            (std::vector<std::string>{"x_mm", "y_mm", "z_mm", "w_deg", "p_deg", "r_deg"}));
  EXPECT_EQ(csv.Number(0, "y_mm"), 200);
  EXPECT_NEAR(csv.Number(0, "r_deg"), 90, 1e-12);
  EXPECT_NEAR(csv.Number(1, "w_deg"), 0, 1e-12);
}

// The output may not be the input (docs/reliability.md): refused, the file untouched.
TEST_F(PosesConvertTest, TheInputIsNeverTheOutput) {
  const std::string path = Write("robot.csv", kKukaMillimetres);
  EXPECT_EQ(Run({"--input", path, "--output", path, "--to", "abb"}), 2);
  EXPECT_NE(err_.str().find("--output names the input --input"), std::string::npos) << err_.str();
  EXPECT_EQ(io::ReadFile(path), kKukaMillimetres);
}

TEST_F(PosesConvertTest, NearlyUnitQuaternionWarnsButSucceeds) {
  const std::string input = Write("in.csv", "x,y,z,qw,qx,qy,qz\n0,0,0,1.0004,0,0,0\n");
  ASSERT_EQ(Run({"--input", input, "--output", Path("out.csv"), "--to", "rotvec"}), 0);
  EXPECT_EQ(err_.str(), "hecal: warning: " + input +
                            ": 1 of 1 quaternions were not unit within 1e-6 (largest |norm - 1| "
                            "4.0e-04 at line 2); normalised\n");
  // A norm far from 1 is not a quaternion: refused, no output.
  ExpectBadInput(
      {"--input", Write("two.csv", "x,y,z,qw,qx,qy,qz\n0,0,0,2,0,0,0\n"), "--to", "rotvec"},
      "two.csv:2", "quaternion norm 2, not 1");
}

TEST_F(PosesConvertTest, BadFlags) {
  const std::string input = Write("robot.csv", kKukaMillimetres);
  ExpectBadInput({"--input", input, "--to", "quat"}, "--to", "unknown rotation format 'quat'");
  ExpectBadInput({"--input", input, "--to", "euler:XYZX"}, "--to", "unknown rotation format");
  ExpectBadInput({"--input", input, "--to", "rotvec", "--units", "cm"}, "--units",
                 "--units: unknown unit 'cm' (fix: use m or mm)");
  ExpectBadInput({"--input", input, "--to", "rotvec", "--input-units", "inch"}, "--input-units",
                 "--input-units: unknown unit 'inch'");
  ExpectBadInput({"--input", input, "--to", "rotvec", "--euler", "abc"}, "--euler",
                 "unknown Euler sequence 'abc'");
  ExpectBadInput({"--input", input}, "--to", "required");
  ExpectBadInput({"--to", "rotvec"}, "--input", "required");
}

TEST_F(PosesConvertTest, ProjectedControllerMatricesAreAWarning) {
  // A controller's own matrix, 2e-5 from orthonormal, written with 17 digits: converted to the
  // nearest rotation, with one warning line for the file.
  const testing::NearlyOrthonormal m = testing::ControllerMatrix(Rz(0.7) * Ry(0.2), 1e-5);
  const std::string input =
      Write("controller.txt",
            testing::Digits17(testing::Homogeneous(m.matrix, Eigen::Vector3d(0.1, 0.2, 0.3)), " ") +
                "\n");
  const std::string output = Path("out.csv");
  ASSERT_EQ(Run({"--input", input, "--output", output, "--to", "quaternion"}), 0) << err_.str();
  char change[16];  // the projection removes m.matrix - m.rotation
  std::snprintf(change, sizeof(change), "%.1e", (m.matrix - m.rotation).cwiseAbs().maxCoeff());
  EXPECT_EQ(err_.str(), "hecal: warning: " + input +
                            ": 1 of 1 rotation matrices were not orthonormal within 1e-6 (largest "
                            "error 2.0e-05 at line 1); projected onto the nearest rotation "
                            "(largest change of an entry " +
                            change + ")\n");
  const Csv csv = ReadCsv(output);
  const Eigen::Quaterniond expected(m.rotation);
  const double sign = expected.w() < 0 ? -1.0 : 1.0;
  EXPECT_NEAR(csv.Number(0, "qw"), sign * expected.w(), 1e-15);
  EXPECT_NEAR(csv.Number(0, "qz"), sign * expected.z(), 1e-15);
}

TEST_F(PosesConvertTest, BadInputFiles) {
  ExpectBadInput({"--input", Path("missing.csv"), "--to", "rotvec"}, "missing.csv", "cannot read");
  ExpectBadInput(
      {"--input", Write("nan.csv", "x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n0,nan,0,1,0,0,0\n"), "--to",
       "rotvec"},
      "nan.csv:3", "non-finite");
  ExpectBadInput({"--input", Write("col.csv", "x,y,z,qw,qx,qy,qzz\n"), "--to", "rotvec"},
                 "col.csv:1", "did you mean 'qz'");
  ExpectBadInput({"--input", Write("two.csv", "x,y,z,qw,qx,qy,qz,rx,ry,rz\n"), "--to", "rotvec"},
                 "two.csv:1", "two rotation groups");
  ExpectBadInput({"--input", Write("empty.csv", ""), "--to", "rotvec"}, "empty.csv", "empty");
  ExpectBadInput(
      {"--input", Write("count.csv", "x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0\n"), "--to", "rotvec"},
      "count.csv:2", "6 values");
  ExpectBadInput({"--input",
                  Write("ortho.csv",
                        "x,y,z,r11,r12,r13,r21,r22,r23,r31,r32,r33\n"
                        "0,0,0,1,0.25,0,0,1,0,0,0,1\n"),
                  "--to", "rotvec"},
                 "ortho.csv:2", "not orthonormal");
  ExpectBadInput(
      {"--input", Write("zero.csv", "x,y,z,qw,qx,qy,qz\n0,0,0,0,0,0,0\n"), "--to", "rotvec"},
      "zero.csv:2", "zero quaternion");
  ExpectBadInput({"--input",
                  Write("ids.csv",
                        "id,x,y,z,qw,qx,qy,qz\na,0,0,0,1,0,0,0\n"
                        "a,0,0,0,1,0,0,0\n"),
                  "--to", "rotvec"},
                 "ids.csv:3", "repeats");
  ExpectBadInput({"--input", Write("mixed.csv", "x_mm,y_m,z_mm,qw,qx,qy,qz\n"), "--to", "rotvec"},
                 "mixed.csv:1", "mixed length units");
  ExpectBadInput(
      {"--input", Write("m44.txt", "1 0 0 0 0 1 0 0 0 0 1 0 0 0 1 1\n"), "--to", "rotvec"},
      "m44.txt:1", "not 0 0 0 1");
  ExpectBadInput({"--input", Write("euler.csv", "x,y,z,a1,a2,a3\n0,0,0,0,0,0\n"), "--to", "rotvec"},
                 "euler.csv:1", "--euler");
}

TEST_F(PosesConvertTest, MissingOutputDirectory) {
  const std::string input = Write("robot.csv", kKukaMillimetres);
  const std::string output = Path("no/such/dir/out.csv");
  EXPECT_EQ(Run({"--input", input, "--output", output, "--to", "rotvec"}), 2);
  const std::string err = err_.str();
  EXPECT_THAT(err, HasSubstr("does not exist"));
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1);
  EXPECT_FALSE(fs::exists(Path("no")));
}

TEST_F(PosesConvertTest, FailedConversionLeavesAnExistingOutputUntouched) {
  const std::string output = Write("out.csv", "previous contents\n");
  const std::string input = Write("bad.csv", "x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n0,0,0,1,0,0,inf\n");
  EXPECT_EQ(Run({"--input", input, "--output", output, "--to", "rotvec"}), 2);
  EXPECT_EQ(io::ReadFile(output), "previous contents\n");
}

TEST_F(PosesConvertTest, HelpDocumentsTheUnitRules) {
  EXPECT_EQ(Run({"--help"}), 0);
  const std::string help = out_.str();
  for (const char* text :
       {"--input", "--output", "--to", "--units", "--degrees", "--invert", "--input-units",
        "--input-degrees", "--euler", "euler:SEQ", "header suffixes", "OUTPUT"}) {
    EXPECT_THAT(help, HasSubstr(text));
  }
}

}  // namespace
}  // namespace hecal::cli
