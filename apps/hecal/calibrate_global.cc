// `hecal calibrate --method global` (calibrate.h: RunCalibrateGlobal): binds the flags into
// report::GlobalCalibrationOptions, checks which source of matches the flags name, reads them
// (jobs::ReadGlobalMatches from a correspondence file, jobs::GlobalMatchesFromImages from
// images), runs jobs::CalibrateGlobal, prints, and writes the result file (--output) and its
// HTML page (--report, report/global_page.h), both or neither.
#include <chrono>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <sstream>
#include <string>

#include "bounds.h"
#include "calibrate.h"
#include "hecal/hecal.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include "job_output.h"
#endif

namespace hecal::cli {
namespace {

jobs::GlobalMatches ReadMatches(const CalibrateFlags& flags, const io::PoseReadOptions& read,
                                [[maybe_unused]] const report::GlobalCalibrationOptions& options,
                                [[maybe_unused]] const Io& io) {
  if (!flags.camera.empty()) {
    throw InputError("--camera", 0, "--method global reads point matches, not camera poses",
                     "give the matches with --correspondences FILE, or the images with --images "
                     "DIR --target target.yaml (docs/global.md)");
  }
  if (!flags.images.empty()) {
    if (!flags.correspondences.empty()) {
      throw InputError("--correspondences", 0, "--images and --correspondences were both given",
                       "give the matches from one source: the images' target corners or the file");
    }
    if (flags.target.empty()) {
      throw InputError("--target", 0, "--method global with --images needs --target",
                       "give --target target.yaml to match its corners, or --target none to "
                       "match generic image features (docs/global.md)");
    }
    if (flags.intrinsics.empty()) {
      throw InputError("--intrinsics", 0,
                       "--method global with --images needs the camera's intrinsics (estimating "
                       "them would need a target's geometry)",
                       "give --intrinsics camera.yaml (e.g. calibrated with hecal detect)");
    }
#if defined(HECAL_HAVE_OPENCV_PEERS)
    jobs::GlobalImageMatchOptions match;
    match.robot = flags.robot;
    match.robot_read = read;
    match.images = flags.images;
    match.intrinsics = flags.intrinsics;
    if (flags.target == "none") {
      match.source = flags.features == "orb" ? jobs::MatchSource::kOrb : jobs::MatchSource::kSift;
    } else {
      match.target = flags.target;
    }
    match.matches_per_motion = options.matches_per_motion;
    match.pixel_sigma = options.pixel_sigma;
    match.threads = options.threads;
    match.caller = "hecal calibrate --method global";
    return jobs::GlobalMatchesFromImages(match, PrintingCallbacks(io));
#else
    throw InputError("--images", 0, "this hecal was built without the vision layer (OpenCV)",
                     "rebuild with -DHECAL_BUILD_VISION=ON, or give --correspondences FILE");
#endif
  }
  if (flags.correspondences.empty()) {
    throw InputError("--correspondences", 0, "--method global needs point matches",
                     "give --correspondences FILE (CSV: first,second,u1,v1,u2,v2; "
                     "docs/global.md), or target images with --images DIR --target target.yaml");
  }
  return jobs::ReadGlobalMatches(flags.robot, read, flags.correspondences, flags.intrinsics);
}

// The search's bounds on standard error while it runs, one line each time the search hands
// them out (every 5 s): the time since the search began against its budget, so a long search
// shows how far the gap has closed and when it will end.
std::function<void(const global::SearchProgress&)> SearchProgressPrinter(const Io& io,
                                                                         double budget) {
  const auto begin = std::chrono::steady_clock::now();
  return [&io, begin, budget](const global::SearchProgress& p) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    std::ostringstream line;
    line << std::setprecision(3) << "hecal: global search: solve " << p.round
         << ", max ray error in [" << p.lower << ", " << p.upper << "] rad (gap "
         << p.upper - p.lower << "), " << p.cubes << " cubes, " << std::fixed
         << std::setprecision(0) << seconds << " s of " << budget << " s\n";
    io.err << line.str() << std::flush;
  };
}

}  // namespace

void RunCalibrateGlobal(const CalibrateFlags& flags, const Io& io) {
  if (!flags.setup) {
    throw InputError("--setup", 0, "--method global needs the setup, got 'auto'",
                     "give --setup eye-in-hand or --setup eye-to-hand");
  }
  report::GlobalCalibrationOptions options;
  options.setup = *flags.setup;
  options.epsilon = flags.epsilon;
  options.relative_gap = flags.relative_gap;
  options.reach = flags.reach;
  options.max_cubes = flags.max_cubes;
  options.time_budget = flags.time_budget;
  options.matches_per_motion = flags.matches_per_motion;
  options.threads = flags.threads;
  if (const std::optional<double> sigma = ParsePixelSigma(flags.pixel_sigma))
    options.pixel_sigma = *sigma;
  if (!flags.robot_sigma.empty())
    options.robot_sigma = ParseSigma("--robot-sigma", flags.robot_sigma);
  RequireValid(options);
  if (flags.features != "sift" && flags.features != "orb") {
    throw InputError("--features", 0, "unknown feature kind '" + flags.features + "'",
                     "give --features sift or --features orb");
  }
  options.seed = flags.seed;
  const io::LengthUnit units = flags.units;
  io::PoseReadOptions read;
  read.units = units;
  read.degrees = flags.degrees;
  read.invert = flags.robot_inverse;

  const jobs::GlobalMatches matches = ReadMatches(flags, read, options, io);
  const report::GlobalCalibrationResult result =
      jobs::CalibrateGlobal(matches, options, SearchProgressPrinter(io, options.time_budget));
  report::PrintGlobalSummary(io.out, result, units);
  for (const std::string& warning : result.warnings)
    io.err << "hecal: warning: " << warning << "\n";
  const std::string json = report::GlobalResultJson(result);
  std::vector<io::OutputFile> outputs;
  if (!flags.output.empty()) outputs.push_back({"--output", flags.output, json});
  if (!flags.report.empty()) {
    const std::string title = std::filesystem::path(flags.report).filename().string();
    outputs.push_back(
        {"--report", flags.report, report::FormatGlobalReport(json, "the global result", title)});
  }
  io::WriteFilesAtomically(outputs);
  for (const std::string& file : {flags.output, flags.report}) {
    if (!file.empty()) io.out << "wrote " << file << "\n";
  }
}

}  // namespace hecal::cli
