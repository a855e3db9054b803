// Input errors end to end: bad values of options the library checks itself, bad files and data
// that cannot determine X, each driven through `hecal`. Every one exits 2 with exactly one line
// `hecal: SOURCE: problem (fix: ...)` whose SOURCE is the flag the user typed (the library names
// the options field, field_flags.h maps it) or the file, and writes no output file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "field_flags.h"
#include "testing/pose_csv.h"
#include "testing/scene.h"

namespace hecal::cli {
namespace {

using cli_test::Hecal;
using cli_test::kData;
using cli_test::Outcome;

class InputErrors : public cli_test::CliTest {
 protected:
  // Noise-free stations written as robot.csv / camera.csv.
  void WriteStations(int stations) {
    std::mt19937_64 rng(5);
    testing::SceneOptions options;
    options.stations = stations;
    const testing::Scene scene = testing::MakeScene(options, rng);
    Write("robot.csv", testing::PoseCsv(scene.T_base_gripper, 1e3, "_mm"));
    Write("camera.csv", testing::PoseCsv(scene.T_camera_target, 1e3, "_mm"));
  }

  std::vector<std::string> Calibrate(const std::vector<std::string>& extra) const {
    std::vector<std::string> args = {"calibrate",        "--setup",         "eye-in-hand",
                                     "--robot",          Path("robot.csv"), "--camera",
                                     Path("camera.csv"), "--output",        Path("result.yaml")};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  }

  // Exit 2, one line naming `source` first, nothing written.
  void ExpectRefused(const std::vector<std::string>& args, const std::string& source,
                     const std::string& problem) const {
    const Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 2) << run.err;
    EXPECT_EQ(run.err.rfind("hecal: " + source + ": ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find(problem), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_FALSE(std::filesystem::exists(Path("result.yaml")));
    EXPECT_FALSE(std::filesystem::exists(Path("robot_out.csv")));
  }
};

// Values the library rejects (CovarianceOptions.method, ImportOptions.units / .setup,
// PnpMethod): the message names the flag, never the field.
TEST_F(InputErrors, LibraryChecksNameTheFlag) {
  WriteStations(501);  // above kMaxPropagatedStations (500)
  ExpectRefused(Calibrate({"--covariance", "unscented"}), "--covariance",
                "needs a dense 12n x 12n input covariance");

  const std::string moveit = kData + "moveit-calibration/pose_samples.json";
  ExpectRefused({"import", "--format", "moveit", moveit, "--units", "mm", "--robot",
                 Path("robot_out.csv"), "--camera", Path("camera_out.csv")},
                "--units", "so a length unit does not apply");
  ExpectRefused({"import", "--format", "moveit", moveit, "--setup", "eye-in-hand", "--robot",
                 Path("robot_out.csv"), "--camera", Path("camera_out.csv")},
                "--setup", "only easy_handeye needs it");
}

#if defined(HECAL_HAVE_OPENCV_PEERS)
TEST_F(InputErrors, PnpMethodChecksNameTheMethodFlag) {
  // Eight points off any plane: ippe needs coplanar points.
  Write("object.csv",
        "id,x,y,z\na,0,0,0\nb,0.1,0,0\nc,0,0.1,0\nd,0,0,0.1\ne,0.1,0.1,0\n"
        "f,0.1,0,0.1\ng,0,0.1,0.1\nh,0.1,0.1,0.1\n");
  Write("image.csv",
        "id,u,v\na,320,240\nb,400,240\nc,320,320\nd,330,250\ne,400,320\n"
        "f,410,250\ng,330,330\nh,410,330\n");
  Write("camera.yaml",
        "fx: 800\nfy: 800\ncx: 320\ncy: 240\nwidth: 640\nheight: 480\ndistortion:\n  model: "
        "plumb_bob\n  coefficients: [0, 0, 0, 0, 0]\n");
  ExpectRefused(
      {"pose", "--points", Path("object.csv"), "--image-points", Path("image.csv"), "--intrinsics",
       Path("camera.yaml"), "--method", "ippe", "--output", Path("result.yaml")},
      "--method ippe", "needs coplanar object points");
}
#endif

// Flags the CLI checks itself name the flag the same way.
TEST_F(InputErrors, CommandLineChecksNameTheFlag) {
  WriteStations(6);
  ExpectRefused(Calibrate({"--robust", "tukey"}), "--robust", "unknown loss 'tukey'");
  ExpectRefused(Calibrate({"--robot-sigma", "x,0.1"}), "--robot-sigma", "");
}

// A file that is missing or malformed is named by its path (and line).
TEST_F(InputErrors, BadFilesNameTheFile) {
  WriteStations(6);
  std::vector<std::string> missing = Calibrate({});
  missing[4] = Path("missing.csv");  // --robot's value
  ExpectRefused(missing, Path("missing.csv"), "cannot read");
  Write("camera.csv", "id,x_mm,y_mm,z_mm,qw,qx,qy,qz\ns0,1,2,3,1,0,0,0\ns1,1,2,x,1,0,0,0\n");
  ExpectRefused(Calibrate({}), Path("camera.csv") + ":3", "is not a number");
}

// Data that cannot determine X: two stations are one motion.
TEST_F(InputErrors, TooFewStationsExitTwo) {
  WriteStations(2);
  for (const char* method : {"tsai-lenz", "ml"}) {
    const Outcome run = Hecal(Calibrate({"--method", method}));
    EXPECT_EQ(run.code, 2) << method << ": " << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(std::filesystem::exists(Path("result.yaml")));
  }
}

// The table itself: a listed field becomes its flag; a file, a line and unknown text stay.
TEST(FieldFlags, MapsFieldsAndLeavesOtherSources) {
  EXPECT_EQ(FlagForField("CalibrateOptions.robot_sigma"), "--robot-sigma");
  EXPECT_EQ(FlagForField("StudyOptions.trials"), "--trials");
  EXPECT_FALSE(FlagForField("robot.csv").has_value());
  EXPECT_FALSE(FlagForField("CalibrateOptions.robust_scale").has_value());  // no flag sets it

  EXPECT_EQ(WithFlag(InputError("Setting.gross_outliers", 0, "too many", "fewer")).source(),
            "--outliers");
  EXPECT_EQ(WithFlag(InputError("PnpMethod ippe", 0, "needs coplanar points", "")).source(),
            "--method ippe");
  const InputError file = WithFlag(InputError("robot.csv", 4, "bad row", "fix it"));
  EXPECT_EQ(file.source(), "robot.csv");
  EXPECT_EQ(std::string(file.what()), "robot.csv:4: bad row (fix: fix it)");
}

}  // namespace
}  // namespace hecal::cli
