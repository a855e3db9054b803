// The options structs of the library jobs, driven through `hecal`: for every field an
// options struct's IsValid checks (jobs::SimulateOptions, ...), a bad value given on the command
// line exits 2 with exactly one line `hecal: --flag: problem (fix: ...)` naming the flag that set
// the field (field_flags.h), without the field's "Options." name, prints nothing on stdout and
// writes no output file. Options no flag can make invalid are tested beside their structs in src/:
// io::PoseReadOptions and PoseWriteOptions (--units, --euler, --to are parsed into valid enums),
// contour::ShapeTrackerOptions and RenderOptions beyond the fields SequenceTrackingOptions and
// SequenceRenderOptions bound more tightly, UnscentedPoseOptions.bias_threshold,
// uncertainty::MeanOptions, estimation::StationTestOptions, sim::TriangleThresholdOptions and
// ProtocolOptions, and the vision options (DetectOptions, IntrinsicsOptions,
// IntrinsicsFitOptions, OrderOptions, RenderOptions).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

using JobOptions = cli_test::CliTest;

// jobs::SimulateOptions::IsValid, field by field.
TEST_F(JobOptions, SimulateOptionsNameTheFlag) {
  const auto simulate = [&](std::vector<std::string> extra) {
    // Every case below is refused before the study runs.
    std::vector<std::string> args = {"simulate", "--method", "andreff", "--output",
                                     Path("trials.csv")};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const std::string out = "trials.csv";
  ExpectRefused(simulate({"--stations", "5,2"}), "--stations", "'2' is outside the range 3 to",
                out);
  ExpectRefused(simulate({"--outliers", "-1"}), "--outliers", "'-1' is outside the range 0 to",
                out);
  ExpectRefused(simulate({"--sigma", "0.1/200"}), "--sigma", "0 to 180 deg", out);
  ExpectRefused(simulate({"--robot-scale", "0"}), "--robot-scale", "above 0", out);
  ExpectRefused(simulate({"--sigma", "100/1", "--robot-scale", "20"}), "--robot-scale",
                "must stay within 1000 mm", out);
  ExpectRefused(simulate({"--trials", "0"}), "--trials", "from 1 to 100000, got 0", out);
  ExpectRefused(simulate({"--threads", "300"}), "--threads", "from 0 to 256, got 300", out);
  ExpectRefused(simulate({"--covariance-samples", "1"}), "--covariance-samples",
                "from 2 to 100000, got 1", out);
  std::string many = "3";
  for (int n = 4; n < 10010; ++n) {
    many += ',';
    many += std::to_string(n);
  }
  ExpectRefused(simulate({"--stations", many}), "--stations", "settings, more than 10000", out);
  ExpectRefused(simulate({"--trials", "100000", "--stations", "5,6,7,8,9,10,11,12,13,14,15"}),
                "--trials", "trial rows, more than 1000000", out);
}

// study::BenchOptions::IsValid, field by field (bench writes no file: stdout stays empty).
TEST_F(JobOptions, BenchOptionsNameTheFlag) {
  const std::string none = "no-such-output";
  ExpectRefused({"bench", "--stations", "10,2"}, "--stations", "'2' is outside the range 3 to",
                none);
  ExpectRefused({"bench", "--datasets", "0"}, "--datasets", "from 1 to 10000, got 0", none);
  ExpectRefused({"bench", "--stations", "100000", "--datasets", "100"}, "--datasets",
                "poses, the most hecal bench generates", none);
  ExpectRefused({"bench", "--min-time", "-1"}, "--min-time", "must be 0 to 3600 seconds", none);
  ExpectRefused({"bench", "--sigma", "2000"}, "--sigma", "0 to 1000 mm", none);
}

// report::GlobalCalibrationOptions::IsValid (calibrate --method global), field by field; checked
// before any file is read (the files named here do not exist).
TEST_F(JobOptions, GlobalCalibrationOptionsNameTheFlag) {
  const auto global = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"calibrate",       "--method",          "global",
                                     "--setup",         "eye-in-hand",       "--robot",
                                     Path("robot.csv"), "--correspondences", Path("matches.csv"),
                                     "--output",        Path("global.json")};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const std::string out = "global.json";
  ExpectRefused(global({"--epsilon", "0"}), "--epsilon", "above 0 and at most 1 rad", out);
  ExpectRefused(global({"--relative-gap", "1"}), "--relative-gap", "at least 0 and below 1", out);
  ExpectRefused(global({"--reach", "0"}), "--reach", "above 0 and at most 1000 m", out);
  ExpectRefused(global({"--max-cubes", "0"}), "--max-cubes", "at least 1", out);
  for (const char* budget : {"0", "-5", "nan", "inf", "1e8"}) {
    ExpectRefused(global({"--time-budget", budget}), "--time-budget", "above 0 and at most 1e7 s",
                  out);
  }
  ExpectRefused(global({"--matches-per-motion", "7"}), "--matches-per-motion",
                "at least 8 and at most 100000", out);
  ExpectRefused(global({"--threads", "300"}), "--threads", "from 0 to 256, got 300", out);
  ExpectRefused(global({"--pixel-sigma", "0"}), "--pixel-sigma", "above 0 to 100 px, got 0", out);
}

// jobs::PointPoseOptions::IsValid (hecal pose), field by field; checked before any file is read.
TEST_F(JobOptions, PointPoseOptionsNameTheFlag) {
  const auto pose = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"pose",           "--points",        Path("object.csv"),
                                     "--image-points", Path("image.csv"), "--output",
                                     Path("pose.json")};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const std::string out = "pose.json";
  ExpectRefused(pose({}), "--focal", "give exactly one of focal and intrinsics", out);
  ExpectRefused(pose({"--focal", "800", "--intrinsics", Path("camera.yaml")}), "--focal",
                "give exactly one", out);
  ExpectRefused(pose({"--focal", "-3"}), "--focal", "expected a positive number, got '-3'", out);
  ExpectRefused(pose({"--intrinsics", Path("camera.yaml"), "--principal-point", "1,2"}),
                "--principal-point", "comes from the camera file", out);
  ExpectRefused(pose({"--focal", "800", "--pixel-sigma", "0"}), "--pixel-sigma",
                "must be above 0 to 100 px, got 0", out);
  ExpectRefused(pose({"--focal", "800", "--pixel-sigma", "1e9"}), "--pixel-sigma",
                "must be above 0 to 100 px", out);
}

// contour::ContourStudyOptions::IsValid (hecal contour study), field by field.
TEST_F(JobOptions, ContourStudyOptionsNameTheFlag) {
  const auto study = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"contour", "study", "--motion", "tx",
                                     "--from",  "0",     "--output", Path("study.csv")};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const std::vector<std::string> range = {"--to", "100", "--steps", "3"};
  const auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), range.begin(), range.end());
    return study(extra);
  };
  const std::string out = "study.csv";
  ExpectRefused(with({"--focal", "0"}), "--focal", "must be a positive number", out);
  ExpectRefused(with({"--z0", "-5"}), "--z0", "must be a positive number", out);
  ExpectRefused(with({"--pixel-size", "0"}), "--pixel-size", "must be a positive number", out);
  ExpectRefused(with({"--pixel-noise", "101"}), "--pixel-noise", "must be 0 to 100 px", out);
  ExpectRefused(study({"--to", "100", "--steps", "1"}), "--steps", "at least 2 steps", out);
  ExpectRefused(study({"--to", "100", "--steps", "20000"}), "--steps", "from 1 to 10000", out);
  ExpectRefused(with({"--samples", "1"}), "--samples", "from 2 to 1000000, got 1", out);
  ExpectRefused(study({"--to", "100", "--steps", "10000", "--samples", "20000"}), "--samples",
                "Monte Carlo solves", out);
  ExpectRefused(with({"--threads", "300"}), "--threads", "from 0 to 256, got 300", out);
  ExpectRefused({"contour", "study", "--motion", "tz", "--from", "0", "--to", "-6000", "--steps",
                 "3", "--output", Path("study.csv")},
                "--to", "Tz must stay above", out);
  ExpectRefused(with({"--ut-w0", "1.5"}), "--ut-w0", "", out);
}

// contour::SequenceRenderOptions::IsValid (hecal contour render), field by field.
TEST_F(JobOptions, SequenceRenderOptionsNameTheFlag) {
  const auto render = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"contour", "render", "--output", Path("frames"),
                                     "--to=0,0,-100,3,2,4"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const std::vector<std::string> size = {"--size", "64,48"};
  // The camera and the size, unless `extra` gives them.
  const auto with = [&](std::vector<std::string> extra) {
    const auto gives = [&](const std::string& flag) {
      return std::find(extra.begin(), extra.end(), flag) != extra.end();
    };
    if (!gives("--focal")) extra.insert(extra.end(), {"--focal", "3000"});
    if (!gives("--z0")) extra.insert(extra.end(), {"--z0", "5000"});
    if (!gives("--size")) extra.insert(extra.end(), size.begin(), size.end());
    return render(extra);
  };
  const std::string out = "frames";
  ExpectRefused(with({"--focal", "0"}), "--focal", "must be a positive number", out);
  ExpectRefused(with({"--z0", "-5"}), "--z0", "must be a positive number", out);
  ExpectRefused(with({"--frames", "0"}), "--frames", "from 1 to 10000, got 0", out);
  ExpectRefused(with({"--frames", "10001"}), "--frames", "from 1 to 10000, got 10001", out);
  ExpectRefused(with({"--size", "7,48"}), "--size", "from 8 to 20000", out);
  ExpectRefused(with({"--size", "64,3000000000"}), "--size", "from 8 to 20000", out);
  ExpectRefused(with({"--size", "64.5,48"}), "--size", "whole numbers", out);
  ExpectRefused(with({"--size", "20000,5001", "--frames", "1"}), "--size", "pixels a frame", out);
  ExpectRefused(with({"--size", "500,500", "--frames", "10000"}), "--size", "in all", out);
  ExpectRefused(with({"--noise", "256"}), "--noise", "0 … 255 grey levels", out);
  ExpectRefused(with({"--blur", "-1"}), "--blur", "0 … 20 px", out);
}

// contour::SequenceTrackingOptions::IsValid (hecal contour track), field by field: refused
// before the images or the init contour are read (neither exists here).
TEST_F(JobOptions, SequenceTrackingOptionsNameTheFlag) {
  const auto track = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"contour", "track",          "--images", Path("none"),
                                     "--init",  Path("none.csv"), "--output", Path("track.csv")};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const std::vector<std::string> camera = {"--focal", "3000", "--z0", "5000"};
  const auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), camera.begin(), camera.end());
    return track(extra);
  };
  const std::string out = "track.csv";
  ExpectRefused(track({"--focal", "-1", "--z0", "5000"}), "--focal", "must be a positive number",
                out);
  ExpectRefused(track({"--focal", "3000", "--z0", "0"}), "--z0", "must be a positive number", out);
  ExpectRefused(with({"--search-range", "1"}), "--search-range", "must be 2 … 200 px", out);
  ExpectRefused(with({"--search-range", "201"}), "--search-range", "must be 2 … 200 px", out);
  ExpectRefused(with({"--measurement-sigma", "0"}), "--measurement-sigma", "above 0 to 100 px",
                out);
  ExpectRefused(with({"--measurement-sigma", "101"}), "--measurement-sigma", "above 0 to 100 px",
                out);
}

// contour::ShapePoseOptions::IsValid (hecal contour pose), field by field: the camera, Σ_S and the
// UT centre weight (contour pose writes no file: stdout stays empty).
TEST_F(JobOptions, ShapePoseOptionsNameTheFlag) {
  const auto pose = [](std::vector<std::string> extra) {
    std::vector<std::string> args = {"contour", "pose", "--shape=0,0,0,0,0,0", "--z0", "5000",
                                     "--focal", "50"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const std::string none = "no-such-output";
  ExpectRefused({"contour", "pose", "--shape=0,0,0,0,0,0", "--z0", "5000", "--focal", "0"},
                "--focal", "must be a positive number", none);
  ExpectRefused({"contour", "pose", "--shape=0,0,0,0,0,0", "--z0", "-1", "--focal", "50"}, "--z0",
                "must be a positive number", none);
  ExpectRefused(pose({"--covariance", "-1,1,1,1,1,1"}), "--covariance",
                "Σ_S has a negative eigenvalue", none);
  std::string asymmetric;
  for (int k = 0; k < 36; ++k) {
    if (k > 0) asymmetric += ',';
    asymmetric += k == 1 ? "0.5" : (k % 7 == 0 ? "1" : "0");
  }
  ExpectRefused(pose({"--covariance", asymmetric}), "--covariance", "Σ_S is not symmetric", none);
  ExpectRefused(pose({"--covariance", "1,1,1,1,1,1", "--ut-w0", "1.5"}), "--ut-w0",
                "w0 must be finite and below 1", none);
}

}  // namespace
}  // namespace hecal::cli
