// Every checked field of the options the calibrate, detect, import and poses commands fill, driven
// through `hecal` with a bad value of its flag: the library's IsValid refuses it
// (core/options_check.h), and the user sees exit 2, one line naming the FLAG (field_flags.h maps
// the field), nothing on stdout and no output file. Fields no flag sets
// (CalibrateOptions.robust_scale, MlOptions, StroblOptions, ConsensusOptions and
// StationSelectionOptions counts, ReprojectionOptions) are tested beside their structs in src/.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "testing/scene.h"

namespace hecal::cli {
namespace {

using cli_test::Hecal;
using cli_test::Outcome;

const std::string kKuka2 = std::string(HECAL_SOURCE_DIR) + "/data/rwhe-kuka2/";

// One bad value: its flag, the field of the library that holds it, and a piece of the problem.
struct Case {
  std::vector<std::string> flags;
  std::string flag;
  std::string field;
  std::string problem;
};

class OptionsFlags : public cli_test::CliTest {
 protected:
  void WriteStations() {
    std::mt19937_64 rng(11);
    testing::SceneOptions options;
    options.stations = 8;
    const testing::Scene scene = testing::MakeScene(options, rng);
    Write("robot.csv", Csv(scene.T_base_gripper));
    Write("camera.csv", Csv(scene.T_camera_target));
  }

  static std::string Csv(const std::vector<Pose>& poses) {
    std::ostringstream csv;
    csv.precision(17);
    csv << "x,y,z,r11,r12,r13,r21,r22,r23,r31,r32,r33\n";
    for (const Pose& T : poses) {
      csv << T.translation().x() << "," << T.translation().y() << "," << T.translation().z();
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) csv << "," << T.linear()(r, c);
      csv << "\n";
    }
    return csv.str();
  }

  void ExpectRefused(std::vector<std::string> args, const Case& c) const {
    args.insert(args.end(), c.flags.begin(), c.flags.end());
    const Outcome run = Hecal(args);
    SCOPED_TRACE(c.field);
    EXPECT_EQ(run.code, 2) << run.err;
    EXPECT_EQ(run.err.rfind("hecal: " + c.flag + ": ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find(c.problem), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("Options."), std::string::npos) << run.err;  // a flag, not a field
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_TRUE(std::filesystem::is_empty(dir_ / "out")) << "an output was written";
  }

  void SetUp() override {
    cli_test::CliTest::SetUp();
    std::filesystem::create_directories(dir_ / "out");
  }
};

const char kRange[] = "must be a whole number from";
const char kNoise[] = "noise levels must be 0 to 1000 mm and 0 to 180 deg";

// CalibrateOptions and its CovarianceOptions, from pose tables.
TEST_F(OptionsFlags, CalibrateOptions) {
  WriteStations();
  const std::vector<std::string> calibrate = {
      "calibrate",        "--setup",         "eye-in-hand",
      "--robot",          Path("robot.csv"), "--camera",
      Path("camera.csv"), "--output",        Path("out/result.json")};
  const Case cases[] = {
      {{"--robot-sigma", "-0.5,0.1"}, "--robot-sigma", "CalibrateOptions.robot_sigma", kNoise},
      {{"--robot-sigma", "0.5,181"}, "--robot-sigma", "CalibrateOptions.robot_sigma", kNoise},
      {{"--camera-sigma", "1001,0.1"}, "--camera-sigma", "CalibrateOptions.camera_sigma", kNoise},
      {{"--robot-sigma", "0.5,0", "--camera-sigma", "0.5,0"},
       "--robot-sigma",
       "CalibrateOptions.robot_sigma (both zero)",
       "the noise model is singular"},
      {{"--covariance", "montecarlo", "--covariance-samples", "1"},
       "--covariance-samples",
       "CovarianceOptions.samples",
       "from 2 to 100000, got 1"},
      {{"--covariance-samples", "100001"},
       "--covariance-samples",
       "CovarianceOptions.samples",
       "from 2 to 100000, got 100001"},
      {{"--threads", "-1"}, "--threads", "CovarianceOptions.threads", kRange},
      {{"--threads", "257"}, "--threads", "CovarianceOptions.threads", "from 0 to 256, got 257"},
  };
  for (const Case& c : cases) ExpectRefused(calibrate, c);
}

// jobs::PoseConversionOptions, through `hecal poses convert`.
TEST_F(OptionsFlags, PoseConversionOptions) {
  ExpectRefused({"poses", "convert", "--to", "quaternion", "--output", Path("out/poses.csv")},
                {{"--input", ""}, "--input", "PoseConversionOptions.input", "no input pose table"});
}

// io::ImportOptions, through `hecal import` (the options that apply depend on the format).
TEST_F(OptionsFlags, ImportOptions) {
  const std::vector<std::string> import = {
      "import",   "--format",
      "moveit",   std::string(HECAL_SOURCE_DIR) + "/data/moveit-calibration/pose_samples.json",
      "--robot",  Path("out/robot.csv"),
      "--camera", Path("out/camera.csv")};
  const Case cases[] = {
      {{"--units", "mm"}, "--units", "ImportOptions.units", "so a length unit does not apply"},
      {{"--setup", "eye-to-hand"}, "--setup", "ImportOptions.setup", "only easy_handeye needs it"},
  };
  for (const Case& c : cases) ExpectRefused(import, c);
}

#if defined(HECAL_HAVE_OPENCV_PEERS)
// ImageCalibrationOptions (and the CalibrateOptions inside it), refused before any image is read.
TEST_F(OptionsFlags, ImageCalibrationOptions) {
  const std::vector<std::string> calibrate = {"calibrate",
                                              "--setup",
                                              "eye-in-hand",
                                              "--images",
                                              kKuka2 + "images",
                                              "--target",
                                              kKuka2 + "target.yaml",
                                              "--robot",
                                              kKuka2 + "RobotPosesVec.txt",
                                              "--output",
                                              Path("out/result.json")};
  const Case cases[] = {
      {{"--pixel-sigma", "0"},
       "--pixel-sigma",
       "ImageCalibrationOptions.pixel_sigma",
       "must be above 0 to 100 px, got 0"},
      {{"--pixel-sigma", "100.5"},
       "--pixel-sigma",
       "ImageCalibrationOptions.pixel_sigma",
       "got 100.5"},
      {{"--robot-sigma", "0.5,-1"}, "--robot-sigma", "CalibrateOptions.robot_sigma", kNoise},
      {{"--threads", "300"}, "--threads", "CovarianceOptions.threads", "from 0 to 256, got 300"},
  };
  for (const Case& c : cases) ExpectRefused(calibrate, c);
}

// vision::ImageSetOptions, through `hecal detect`.
TEST_F(OptionsFlags, ImageSetOptions) {
  const std::vector<std::string> detect = {"detect", "--output", Path("out/camera.csv")};
  const std::vector<std::string> images = {"--images", kKuka2 + "images"};
  const std::vector<std::string> target = {"--target", kKuka2 + "target.yaml"};
  const auto with = [&](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const Case cases[] = {
      {with(with(images, target), {"--threads", "-1"}), "--threads", "ImageSetOptions.threads",
       "from 0 to 256, got -1"},
      {with(with(images, target), {"--threads", "1000"}), "--threads", "ImageSetOptions.threads",
       "from 0 to 256, got 1000"},
      {with(with({"--images", ""}, target), {}), "--images", "ImageSetOptions.images",
       "no image folder given"},
      {with(images, {"--target", ""}), "--target", "ImageSetOptions.target",
       "no target file given"},
  };
  for (const Case& c : cases) ExpectRefused(detect, c);
}
#endif

}  // namespace
}  // namespace hecal::cli
