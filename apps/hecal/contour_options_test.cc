// The options of the contour jobs driven through `hecal` (jobs::ContourTrackingOptions,
// jobs::ContourRenderingOptions, and the typed contour::ShapePoseOptions of `contour pose`): a bad
// value exits 2 with exactly one line `hecal: --flag: problem (fix: ...)` naming the flag that set
// the field (field_flags.h), prints nothing on stdout and writes nothing. The fields the jobs'
// options share with SequenceTrackingOptions, SequenceRenderOptions and ShapePoseOptions are
// driven field by field in job_options_test.cc.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

using ContourOptions = cli_test::CliTest;

#if defined(HECAL_HAVE_OPENCV_PEERS)

// jobs::ContourTrackingOptions::IsValid: the folder and the contour file, before anything is
// read or printed (the pose model line included).
TEST_F(ContourOptions, ContourTrackingOptionsNameTheFlag) {
  const auto track = [&](const std::string& images, const std::string& init) {
    return std::vector<std::string>{"contour", "track", "--images", images,
                                    "--init",  init,    "--focal",  "3000",
                                    "--z0",    "5000",  "--output", Path("t.csv")};
  };
  ExpectRefused(track("", Path("init.csv")), "--images", "is empty", "t.csv");
  ExpectRefused(track(Path("frames"), ""), "--init", "is empty", "t.csv");
}

// jobs::ContourRenderingOptions::IsValid: checked before the --contour file is read (it does not
// exist here) and before the output folder is created.
TEST_F(ContourOptions, ContourRenderingOptionsNameTheFlagBeforeTheContourIsRead) {
  const auto render = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"contour",
                                     "render",
                                     "--output",
                                     Path("frames"),
                                     "--contour",
                                     Path("missing.csv"),
                                     "--to=1,0,0,0,0,0",
                                     "--focal",
                                     "3000",
                                     "--z0",
                                     "5000",
                                     "--size",
                                     "64,48"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  ExpectRefused(render({"--frames", "0"}), "--frames", "from 1 to 10000", "frames");
  ExpectRefused(render({"--blur", "50"}), "--blur", "0 … 20 px", "frames");
  // Valid options: the missing contour file is the error, and no folder is left.
  ExpectRefused(render({}), Path("missing.csv"), "cannot read", "frames");
}

#endif  // HECAL_HAVE_OPENCV_PEERS

// contour::ShapePoseOptions bound as typed values: a number that is not one names its flag,
// --ut-w0 too when there is no --covariance to use it.
TEST_F(ContourOptions, ContourPoseBindsTypedNumbers) {
  const std::vector<std::string> pose = {"contour", "pose", "--shape=0,0,0,0,0,0", "--z0", "5000"};
  std::vector<std::string> args = pose;
  args.insert(args.end(), {"--focal", "fifty"});
  ExpectRefused(args, "--focal", "'fifty' is not a finite number", "none");
  args = pose;
  args.insert(args.end(), {"--focal", "50", "--ut-w0", "half"});
  ExpectRefused(args, "--ut-w0", "'half' is not a finite number", "none");
  args = pose;
  args.insert(args.end(), {"--focal", "50", "--covariance", "1,1,1,1,1,-1"});
  ExpectRefused(args, "--covariance", "negative eigenvalue", "none");
}

}  // namespace
}  // namespace hecal::cli
