// The options of the calibrate jobs (jobs::PoseFileCalibrationOptions, jobs/pose_file_
// calibration.h; jobs::GlobalImageMatchOptions, jobs/global_matches.h) through `hecal
// calibrate`: a field their IsValid refuses exits 2 with exactly one line `hecal: --flag:
// problem (fix: ...)` naming the flag that sets it (field_flags.h), prints nothing on stdout and
// writes no result file. Fields that flags cannot make invalid by themselves (an empty --camera
// selects the image form; an empty --images the correspondence file; --intrinsics, --target and
// the ranges of --threads, --matches-per-motion and --pixel-sigma are refused earlier, by the
// flag checks and report::GlobalCalibrationOptions) are checked for their table row instead:
// every field IsValid can name maps to the flag that sets it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "field_flags.h"
#include "hecal/jobs/pose_file_calibration.h"
#if defined(HECAL_HAVE_OPENCV_PEERS)
#include "hecal/jobs/global_matches.h"
#endif

namespace hecal::cli {
namespace {

using cli_test::Hecal;
using cli_test::Outcome;

class CalibrateJobOptions : public cli_test::CliTest {
 protected:
  // Exit 2, exactly `line` on stderr, no stdout, no result file.
  void ExpectRefused(std::vector<std::string> args, const std::string& line) const {
    args.insert(args.end(), {"--output", Path("result.json")});
    const Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 2) << run.err;
    EXPECT_EQ(run.err, line + "\n");
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_FALSE(std::filesystem::exists(Path("result.json")));
  }
};

// The field IsValid names for `options` (nothing when valid) and its flag.
template <typename Options>
std::string FlagOfRefusedField(const Options& options) {
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  const std::string field = why.substr(0, why.find(": "));
  const auto flag = FlagForField(field);
  EXPECT_TRUE(flag.has_value()) << field << " has no flag";
  return flag ? std::string(*flag) : field;
}

TEST_F(CalibrateJobOptions, PoseFileCalibrationOptionsNameTheFlag) {
  const std::string camera = Write("camera.csv", "x,y,z,qw,qx,qy,qz\n");
  ExpectRefused({"calibrate", "--robot", "", "--camera", camera, "--setup", "eye-in-hand"},
                "hecal: --robot: is empty (fix: give the robot pose table, one T_base_gripper "
                "per station)");

  jobs::PoseFileCalibrationOptions options;
  options.robot = "robot.csv";
  options.camera = "camera.csv";
  ASSERT_TRUE(options.IsValid(nullptr));
  const std::vector<std::pair<std::function<void(jobs::PoseFileCalibrationOptions&)>, std::string>>
      cases = {{[](auto& o) { o.robot.clear(); }, "--robot"},
               {[](auto& o) { o.camera.clear(); }, "--camera"},
               {[](auto& o) { o.calibrate.covariance.samples = 1; }, "--covariance-samples"},
               {[](auto& o) {
                  o.calibrate.robot_sigma = estimation::PoseSigma{-1.0, 0.0};
                },
                "--robot-sigma"}};
  for (const auto& [spoil, flag] : cases) {
    jobs::PoseFileCalibrationOptions bad = options;
    spoil(bad);
    EXPECT_EQ(FlagOfRefusedField(bad), flag);
  }
}

#if defined(HECAL_HAVE_OPENCV_PEERS)
TEST_F(CalibrateJobOptions, GlobalImageMatchOptionsNameTheFlag) {
  std::filesystem::create_directories(Path("images"));
  const std::string camera = Write("camera.yaml", "");
  for (const char* target : {"target.yaml", "none"}) {
    ExpectRefused({"calibrate", "--method", "global", "--robot", "", "--images", Path("images"),
                   "--target", target, "--intrinsics", camera, "--setup", "eye-in-hand"},
                  "hecal: --robot: is empty (fix: give the robot pose table, one T_base_gripper "
                  "per image)");
  }

  jobs::GlobalImageMatchOptions options;
  options.robot = "robot.csv";
  options.images = "images";
  options.target = "target.yaml";
  options.intrinsics = "camera.yaml";
  ASSERT_TRUE(options.IsValid(nullptr));
  const std::vector<std::pair<std::function<void(jobs::GlobalImageMatchOptions&)>, std::string>>
      cases = {{[](auto& o) { o.robot.clear(); }, "--robot"},
               {[](auto& o) { o.images.clear(); }, "--images"},
               {[](auto& o) { o.intrinsics.clear(); }, "--intrinsics"},
               {[](auto& o) { o.target.clear(); }, "--target"},
               {[](auto& o) { o.threads = -1; }, "--threads"},
               {[](auto& o) { o.matches_per_motion = 0; }, "--matches-per-motion"},
               {[](auto& o) { o.pixel_sigma = std::nan(""); }, "--pixel-sigma"}};
  for (const auto& [spoil, flag] : cases) {
    jobs::GlobalImageMatchOptions bad = options;
    spoil(bad);
    EXPECT_EQ(FlagOfRefusedField(bad), flag);
  }
}
#endif

}  // namespace
}  // namespace hecal::cli
