// `hecal pose`, `bench` and `simulate` refusing bad values through the command line: the pose
// job's options (jobs::PoseFromFilesOptions: --method read by jobs::ParsePoseMethod as the flag is
// read, before anything else; the point options by its IsValid before any file is read) and the
// shared readers of choices (list_flags.h: ParseChoice, ParseChoiceList) and number lists
// (bounds.h: ParseNumberList). Each refusal exits 2 with exactly one line
// `hecal: --flag: problem (fix: ...)` naming the flag (never the options field), prints nothing
// on stdout and writes no output file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

class PoseBenchOptions : public cli_test::CliTest {
 protected:
  std::vector<std::string> Pose(std::vector<std::string> extra) const {
    std::vector<std::string> args = {"pose",           "--points",        Path("object.csv"),
                                     "--image-points", Path("image.csv"), "--output",
                                     Path("pose.json")};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  }
};

constexpr const char* kPoseMethods = "linear, linear-raw, dlt, ippe, sqpnp, epnp, iterative";

// --method is read as the flag is read: first, whatever else is missing (here the camera, the
// files, even the required --points).
TEST_F(PoseBenchOptions, AnUnknownPoseMethodNamesTheFlagBeforeAnythingElse) {
  ExpectRefusedLine(
      {"pose", "--method", "p3p"},
      std::string("--method: unknown method 'p3p' (fix: use one of ") + kPoseMethods + ")",
      "pose.json");
  ExpectRefusedLine(
      Pose({"--method", "p3p"}),
      std::string("--method: unknown method 'p3p' (fix: use one of ") + kPoseMethods + ")",
      "pose.json");
  ExpectRefusedLine(
      Pose({"--method", "IPPE", "--focal", "800"}),
      std::string("--method: unknown method 'IPPE' (fix: use one of ") + kPoseMethods + ")",
      "pose.json");
  // A known method: PoseFromFilesOptions::IsValid (the point options) comes next.
  ExpectRefusedLine(
      Pose({"--method", "sqpnp", "--focal", "0"}),
      "--focal: expected a positive number, got '0' (fix: give the focal length in px)",
      "pose.json");
}

TEST_F(PoseBenchOptions, ChoicesNameTheFlagAndTheChoices) {
  ExpectRefusedLine(Pose({"--focal", "800", "--units", "ft"}),
                    "--units: unknown unit 'ft' (fix: use m or mm)", "pose.json");
  ExpectRefusedLine(
      {"bench", "--setup", "eye-on-hand"},
      "--setup: unknown setup 'eye-on-hand' (fix: use eye-in-hand (camera on the robot) "
      "or eye-to-hand (camera fixed))",
      "none");
  // A choice is taken as given; in a list, items are trimmed and each one is checked.
  ExpectRefusedLine(
      {"bench", "--setup", " eye-in-hand"},
      "--setup: unknown setup ' eye-in-hand' (fix: use eye-in-hand (camera on the robot) "
      "or eye-to-hand (camera fixed))",
      "none");
  ExpectRefusedLine(
      {"simulate", "--setup", "eye-in-hand, eye-to-hand,sideways", "--output", Path("trials.csv")},
      "--setup: unknown setup 'sideways' (fix: use eye-in-hand or eye-to-hand (or both, "
      "comma separated))",
      "trials.csv");
  ExpectRefusedLine(
      {"simulate", "--noise", "gaussian,laplace"},
      "--noise: unknown noise kind 'laplace' (fix: use gaussian, uniform, systematic, "
      "student-t3 or pnp)",
      "none");
  ExpectRefusedLine({"simulate", "--covariance", "sampled"},
                    "--covariance: unknown covariance method 'sampled' (fix: use none, default, "
                    "linear, unscented or montecarlo)",
                    "none");
}

TEST_F(PoseBenchOptions, NumberListsNameTheFlagAndTheItem) {
  ExpectRefusedLine(Pose({"--focal", "800", "--principal-point", "640"}),
                    "--principal-point: expected 2 numbers, got 1 ('640') (fix: give 2 "
                    "comma-separated numbers CX,CY (px))",
                    "pose.json");
  ExpectRefusedLine(Pose({"--focal", "800", "--principal-point", "640,nan"}),
                    "--principal-point: 'nan' is not a finite number (in '640,nan') (fix: give 2 "
                    "comma-separated numbers CX,CY (px))",
                    "pose.json");
  ExpectRefusedLine(
      {"simulate", "--robot-scale", "1,x"},
      "--robot-scale: 'x' is not a finite number (in '1,x') (fix: give comma-separated "
      "numbers (robot noise over the level, e.g. 1,5))",
      "none");
  ExpectRefusedLine({"simulate", "--robot-scale", "1,inf"},
                    "--robot-scale: 'inf' is not a finite number (in '1,inf') (fix: give "
                    "comma-separated numbers (robot noise over the level, e.g. 1,5))",
                    "none");
}

}  // namespace
}  // namespace hecal::cli
