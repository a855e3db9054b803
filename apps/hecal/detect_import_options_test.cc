// The options of `hecal import` (jobs::ImportJobOptions, io::ImportOptions) and `hecal detect`
// (jobs::PoseDetectionOptions with vision::ImageSetOptions), and the choices of choice_flags.h,
// driven through `hecal`: a bad value exits 2 with exactly the one line
// `hecal: --flag: problem (fix: ...)` naming the flag that set the field (field_flags.h), prints
// nothing on stdout and writes no file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

using cli_test::Hecal;
using cli_test::kData;
using cli_test::Outcome;

const std::string kMoveit = kData + "moveit-calibration/pose_samples.json";

class DetectImportOptions : public cli_test::CliTest {
 protected:
  // Exit 2, stderr exactly `line` and a line break; no stdout, nothing written in the folder.
  void ExpectRefused(const std::vector<std::string>& args, const std::string& line) const {
    const Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 2) << run.err;
    EXPECT_EQ(run.err, "hecal: " + line + "\n");
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_TRUE(std::filesystem::is_empty(dir_));
  }

  std::vector<std::string> Import(const std::string& format, const std::string& input,
                                  std::vector<std::string> extra) const {
    std::vector<std::string> args = {"import", "--format", format,
                                     input,    "--robot",  Path("robot.csv")};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  }
};

// jobs::ImportJobOptions::IsValid and io::ImportOptions::IsValid, field by field.
TEST_F(DetectImportOptions, ImportOptionsNameTheFlag) {
  ExpectRefused(
      {"import", "--format", "moveit", kMoveit, "--robot", "", "--camera", Path("camera.csv")},
      "--robot: is empty (fix: give the path of the robot table (T_base_gripper))");
  ExpectRefused(Import("moveit", kMoveit, {}),
                "--camera: is required for format moveit (fix: give the path of the camera "
                "table (only a robot-only matrix16 import may omit it))");
  ExpectRefused(Import("matrix16", kMoveit, {"--camera", Path("camera.csv")}),
                "--camera: given, but matrix16 got only a robot file (fix: pass the camera "
                "matrix file after the robot file, or leave the camera table out)");
  ExpectRefused(
      Import("moveit", kMoveit, {"--camera", Path("camera.csv"), "--intrinsics", Path("k.yaml")}),
      "--intrinsics: only tabb sources hold intrinsics (cali.txt), not moveit (fix: leave the "
      "intrinsics file out)");
  ExpectRefused(Import("moveit", kMoveit, {"--camera", Path("camera.csv"), "--units", "mm"}),
                "--units: moveit files fix their own length unit (m), so a length unit does not "
                "apply (fix: leave the unit unset (it is for matrix16 and opencv-yaml, whose "
                "files do not say))");
  ExpectRefused(
      Import("moveit", kMoveit, {"--camera", Path("camera.csv"), "--setup", "eye-in-hand"}),
      "--setup: does not apply to moveit (only easy_handeye needs it) (fix: leave the setup "
      "unset)");
}

// The choices, each parsed in one place (choice_flags.h), one wording each.
TEST_F(DetectImportOptions, ChoicesSayTheSameEverywhere) {
  const std::string camera = Path("camera.csv");
  ExpectRefused(Import("moveitt", kMoveit, {"--camera", camera}),
                "--format: unknown import format 'moveitt' (fix: use one of "
                "moveit|easy_handeye|camodocal|ethz|tabb|opencv-yaml|matrix16|visp)");
  ExpectRefused(Import("matrix16", kMoveit, {"--units", "cm"}),
                "--units: unknown unit 'cm' (fix: use m or mm)");
  ExpectRefused(Import("easy_handeye", kMoveit, {"--camera", camera, "--setup", "auto"}),
                "--setup: unknown setup 'auto' (fix: use eye-in-hand (camera on the robot) or "
                "eye-to-hand (camera fixed))");
  const std::vector<std::string> convert = {"poses", "convert",  "--input",
                                            kMoveit, "--output", Path("out.csv")};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = convert;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  ExpectRefused(with({"--to", "rotvec", "--input-units", "inch"}),
                "--input-units: unknown unit 'inch' (fix: use m or mm)");
  ExpectRefused(with({"--to", "rotvec", "--euler", "XYZX"}),
                "--euler: unknown Euler sequence 'XYZX' (fix: use three axis letters, lowercase "
                "= extrinsic, uppercase = intrinsic (e.g. xyz, ZYX, ZXZ))");
  ExpectRefused(with({"--to", "quat"}),
                "--to: unknown rotation format 'quat' (fix: use one of quaternion, rotvec, "
                "matrix, euler:SEQ (e.g. euler:ZYX, euler:xyz), rpy, kuka, fanuc, abb, ur)");
}

#if defined(HECAL_HAVE_OPENCV_PEERS)
// jobs::PoseDetectionOptions::IsValid with vision::ImageSetOptions::IsValid, field by field:
// refused before the folder is read (it does not exist).
TEST_F(DetectImportOptions, DetectOptionsNameTheFlag) {
  auto detect = [&](const std::string& images, const std::string& output,
                    const std::string& threads) {
    return std::vector<std::string>{"detect",   "--images", images,      "--target", Path("t.yaml"),
                                    "--output", output,     "--threads", threads};
  };
  ExpectRefused(detect(Path("images"), "", "0"),
                "--output: is empty (fix: give the path of the pose table to write)");
  const Outcome threads = Hecal(detect(Path("images"), Path("det.csv"), "257"));
  EXPECT_EQ(threads.code, 2);
  EXPECT_EQ(threads.err.rfind("hecal: --threads: must be a whole number from 0 to 256, got 257", 0),
            0u)
      << threads.err;
  const Outcome images = Hecal(detect("", Path("det.csv"), "0"));
  EXPECT_EQ(images.code, 2);
  EXPECT_EQ(images.err.rfind("hecal: --images: ", 0), 0u) << images.err;
  EXPECT_EQ(std::count(images.err.begin(), images.err.end(), '\n'), 1) << images.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}
#endif

}  // namespace
}  // namespace hecal::cli
