// `hecal calibrate` from pose tables, and the flags of every form: see calibrate.h.
#include "calibrate.h"

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <memory>
#include <string_view>
#include <utility>

#include "bounds.h"
#include "choice_flags.h"
#include "conventions.h"
#include "hecal/hecal.h"
#include "list_flags.h"

namespace hecal::cli {

// "MM,DEG" (ParseNoiseLevel) → PoseSigma in metres and radians (its range is
// CalibrateOptions::IsValid's).
estimation::PoseSigma ParseSigma(const std::string& flag, const std::string& text) {
  const study::NoiseLevel level = ParseNoiseLevel(flag, text, ',', /*single=*/false);
  return {level.deg / kDegreesPerRadian, level.mm * 1e-3};
}

handeye::TranslationFix ParseFix(const std::string& text, io::LengthUnit units) {
  return handeye::ParseTranslationFix(text, io::MetresPer(units), io::UnitName(units), "--fix");
}

std::optional<double> ParsePixelSigma(const std::string& text) {
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    throw InputError("--pixel-sigma", 0, "expected a number of pixels, got '" + text + "'",
                     "write e.g. --pixel-sigma 0.5, or leave the flag out");
  }
  return value;
}

// --target-scale: fit | stated | a number (measured ÷ described size).
void ParseTargetScale(const std::string& text, estimation::CalibrateOptions* options) {
  using estimation::TargetScaleMode;
  if (text == "fit" || text == "stated") {
    options->target_scale = text == "fit" ? TargetScaleMode::kFit : TargetScaleMode::kStated;
    return;
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !(value > 0.5 && value < 2.0)) {
    throw InputError("--target-scale", 0,
                     "expected fit, stated or the measured ÷ described size between 0.5 and 2, "
                     "got '" +
                         text + "'",
                     "write e.g. --target-scale stated (the print was measured), or "
                     "--target-scale 0.96 (a board printed at 96 %)");
  }
  options->target_scale = TargetScaleMode::kGiven;
  options->given_target_scale = value;
}

CalibrateSettings ParseCalibrateFlags(const CalibrateFlags& flags) {
  CalibrateSettings settings;
  settings.setup = flags.setup;
  settings.all = flags.method == "all";
  const auto method = estimation::ParseMethod(flags.method);
  if (!settings.all && !method) {
    std::string names;
    for (const auto& info : estimation::AllMethods()) names += std::string(info.name) + " ";
    throw InputError("--method", 0, "unknown method '" + flags.method + "'",
                     "use one of: " + names + "all");
  }
  if (method) settings.options.method = *method;
  io::PoseReadOptions& read = settings.read;
  read.units = flags.units;
  read.degrees = flags.degrees;
  read.euler = flags.euler;
  estimation::CalibrateOptions& options = settings.options;
  if (!flags.robot_sigma.empty())
    options.robot_sigma = ParseSigma("--robot-sigma", flags.robot_sigma);
  if (!flags.camera_sigma.empty()) {
    options.camera_sigma = ParseSigma("--camera-sigma", flags.camera_sigma);
  }
  if (flags.covariance) options.covariance.method = *flags.covariance;
  options.covariance.samples = flags.covariance_samples;
  options.covariance.seed = flags.seed;
  options.consensus.seed = options.covariance.seed;
  options.reject_outliers = !flags.keep_outliers;
  options.covariance.threads = flags.threads;
  options.robust_loss = flags.robust;
  ParseTargetScale(flags.target_scale, &options);
  if (!flags.fix.empty()) {
    options.fix = ParseFix(flags.fix, flags.units);
    if (settings.all) {
      throw InputError("--fix", 0, "--method all runs every method, and only ml takes --fix",
                       "use --method ml (the default) with --fix");
    }
    if (!flags.images.empty()) {
      // The joint reprojection refinement of the image form has no constraint (planar.h).
      throw InputError("--fix", 0, "--fix works on camera poses, not yet with --images",
                       "detect the camera poses first (hecal detect --images DIR --target "
                       "target.yaml --output camera.csv), then calibrate --camera camera.csv "
                       "--fix ...");
    }
  }
  // Once, before any file is read: the job checks the same again (core/options_check.h).
  RequireValid(options);
  if (flags.images.empty() == flags.camera.empty()) {
    throw InputError(flags.images.empty() ? "--camera" : "--images", 0,
                     flags.images.empty() ? "neither --camera nor --images was given"
                                          : "--camera and --images were both given",
                     "give the camera poses (--camera camera.csv) or the images they come from "
                     "(--images DIR --target target.yaml), not both");
  }
  if (flags.images.empty()) {
    const std::pair<const char*, bool> image_flags[] = {
        {"--target", !flags.target.empty()},
        {"--intrinsics", !flags.intrinsics.empty()},
        {"--pixel-sigma", !flags.pixel_sigma.empty()},
        {"--refine-intrinsics", flags.refine_intrinsics}};
    for (const auto& [name, given] : image_flags) {
      if (given) {
        throw InputError(name, 0, std::string(name) + " applies to --images only",
                         "leave it out when calibrating from --camera poses, or give --images DIR");
      }
    }
  }
  return settings;
}

void WriteCalibrateOutputs(const CalibrateFlags& flags, const io::PoseReadOptions& robot_read,
                           const report::ResultDocument& document, const Io& io) {
  if (!flags.output.empty()) {
    report::WriteResult(flags.output, document);
    io.out << "wrote " << flags.output << "\n";
  }
  if (!flags.report.empty()) {
    jobs::CalibrationReportOptions options;
    options.output = flags.report;
    options.robot = flags.robot;
    options.robot_read = robot_read;
    options.images = flags.images;  // --images: the thumbnails
    jobs::WriteCalibrationReport(document, "hecal calibrate --robot " + flags.robot, options);
    io.out << "wrote " << flags.report << "\n";
  }
}

jobs::PoseFileCalibrationOptions PoseFileOptions(const CalibrateFlags& flags,
                                                 const CalibrateSettings& settings) {
  jobs::PoseFileCalibrationOptions options;
  options.robot = flags.robot;
  options.camera = flags.camera;
  options.robot_read = settings.read;
  options.robot_read.invert = flags.robot_inverse;
  options.camera_read = settings.read;
  options.camera_read.invert = flags.camera_inverse;
  options.setup = settings.setup;
  options.calibrate = settings.options;
  options.all_methods = settings.all;
  options.words = ConventionFlagWords();
  options.file_words = {"--robot", "--camera"};
  return options;
}

void PrintCalibrateSummaries(const report::ResultDocument& document, const Io& io) {
  for (size_t k = 0; k < document.results.size(); ++k) {
    if (k > 0) io.out << "\n";
    report::PrintResultSummary(io.out, document, document.results[k]);
  }
  if (document.all_methods) report::PrintMethodComparison(io.out, document);
}

namespace {

// The flags bound into jobs::PoseFileCalibrationOptions; the job runs, then the summaries print.
void RunCalibratePoses(const CalibrateFlags& flags, const CalibrateSettings& settings,
                       const Io& io) {
  const jobs::PoseFileCalibrationOptions options = PoseFileOptions(flags, settings);
  const report::ResultDocument document = jobs::CalibrateFromPoseFiles(options).document;
  PrintCalibrateSummaries(document, io);
  WriteCalibrateOutputs(flags, options.robot_read, document, io);
}

void RunCalibrate(const CalibrateFlags& flags, const Io& io) {
  const auto check_outputs = [&] {
    io::CheckOutputs({{"--output", flags.output}, {"--report", flags.report}},
                     {{"--robot", flags.robot},
                      {"--camera", flags.camera},
                      {"--target", flags.target},
                      {"--intrinsics", flags.intrinsics},
                      {"--correspondences", flags.correspondences}});
  };
  if (flags.method == "global" || !flags.correspondences.empty()) {
    check_outputs();
    return RunCalibrateGlobal(flags, io);
  }
  const CalibrateSettings settings = ParseCalibrateFlags(flags);
  const CalibrateFlags defaults;
  const std::pair<const char*, bool> stream_flags[] = {
      {"--time-offset", flags.time_offset.has_value()},
      {"--time-offset-window", flags.time_offset_window != defaults.time_offset_window},
      {"--max-gap", flags.max_gap != defaults.max_gap},
      {"--max-speed", flags.max_speed != defaults.max_speed},
      {"--stations", flags.stations != defaults.stations}};
  for (const auto& [name, given] : stream_flags) {
    if (given && !flags.streams) {
      throw InputError(name, 0, std::string(name) + " applies to --streams only",
                       "add --streams when --robot and --camera are time-stamped streams, or "
                       "leave it out");
    }
  }
  check_outputs();
  if (!flags.stamps.empty() && !flags.streams) {
    throw InputError("--stamps", 0, "--stamps applies to --streams --images only",
                     "add --streams, or leave it out");
  }
  if (flags.streams) {
    RunCalibrateStreams(flags, settings, io);
  } else if (flags.images.empty()) {
    RunCalibratePoses(flags, settings, io);
  } else {
    RunCalibrateImages(flags, settings, io);
  }
}

}  // namespace

void RegisterCalibrateCommand(CLI::App& app, const Io& io) {
  auto flags = std::make_shared<CalibrateFlags>();
  CLI::App* command = app.add_subcommand(
      "calibrate",
      "Solve the hand–eye calibration from robot poses and camera poses (or target images)");
  command->add_option("--robot", flags->robot, "Robot poses T_base_gripper (docs/pose-files.md)")
      ->required();
  command->add_option("--camera", flags->camera, "Camera poses T_camera_target (CSV)");
  command->add_option("--images", flags->images,
                      "Instead of --camera: folder of target images, one per robot pose");
  command->add_option("--target", flags->target, "With --images: target.yaml");
  command->add_option("--intrinsics", flags->intrinsics,
                      "With --images: camera.yaml or ViSP camera XML (estimated when absent)");
  command->add_option("--pixel-sigma", flags->pixel_sigma,
                      "With --images: pixel noise per axis, px (estimated when absent)");
  AddWholeNumber(*command, "--threads", flags->threads,
                 "Threads for detection and covariance solves, 0 to 256 (default 0 = every "
                 "core)");
  command->add_flag("--refine-intrinsics", flags->refine_intrinsics,
                    "With --images: refine the intrinsics with X and Z in the joint refinement");
  AddSetupOrAutoFlag(*command, flags->setup,
                     "eye-in-hand (camera on the robot) | eye-to-hand (camera fixed) | auto (the "
                     "setup the data fit, with the evidence)")
      ->required();
  command->add_option("--method", flags->method,
                      "Method name, or all (default ml), or global (target-free, certified)");
  command->add_option("--correspondences", flags->correspondences,
                      "With --method global: point matches between station images (CSV)");
  command
      ->add_option("--epsilon", flags->epsilon,
                   "With --method global: requested certificate gap, radians")
      ->capture_default_str();
  AddWholeNumber(*command, "--matches-per-motion", flags->matches_per_motion,
                 "With --method global and --images: target corners used per motion, spread "
                 "over the target")
      ->capture_default_str();
  command
      ->add_option("--relative-gap", flags->relative_gap,
                   "With --method global: or this fraction of the optimum, when larger")
      ->capture_default_str();
  AddWholeNumber(*command, "--max-cubes", flags->max_cubes,
                 "With --method global: stop after this many cube tests with the bounds "
                 "proved so far")
      ->capture_default_str();
  command
      ->add_option("--time-budget", flags->time_budget,
                   "With --method global: stop the search after this many seconds with the "
                   "bounds proved so far")
      ->capture_default_str();
  command
      ->add_option("--features", flags->features,
                   "With --method global --target none: sift or orb image features")
      ->capture_default_str();
  command
      ->add_option("--reach", flags->reach,
                   "With --method global: search X's translation up to this length, metres")
      ->capture_default_str();
  command->add_flag("--streams", flags->streams,
                    "--robot and --camera are time-stamped streams (a stamp column): pair them by "
                    "time and fit the clocks' offset (docs/streams.md)");
  command->add_option("--time-offset", flags->time_offset,
                      "With --streams: the offset in seconds (camera stamp t is robot time t + "
                      "offset); estimated when absent");
  command
      ->add_option("--time-offset-window", flags->time_offset_window,
                   "With --streams: search the offset within ± this many seconds")
      ->capture_default_str();
  command->add_option("--max-gap", flags->max_gap,
                      "With --streams: never interpolate across a longer gap, seconds (default: 3 "
                      "sample periods)");
  command
      ->add_option("--max-speed", flags->max_speed,
                   "With --streams: no stations where the robot moves faster, MM,DEG per second")
      ->capture_default_str();
  AddWholeNumber(*command, "--stations", flags->stations,
                 "With --streams: keep at most this many stations, spread in rotation")
      ->capture_default_str();
  command->add_option("--robot-sigma", flags->robot_sigma,
                      "Robot pose noise per axis, MM,DEG (estimated when absent)");
  command->add_option("--camera-sigma", flags->camera_sigma,
                      "Camera pose noise per axis, MM,DEG (estimated when absent)");
  command->add_option("--stamps", flags->stamps,
                      "With --streams --images: the images' time stamps, CSV image,stamp "
                      "(default: the file names are the stamps)");
  command->add_option("--fix", flags->fix,
                      "Planar robot (all rotations about one axis): X's translation component "
                      "along that axis, given, e.g. tz=120mm (docs/planar.md)");
  command
      ->add_option("--target-scale", flags->target_scale,
                   "The target's printed size: fit (measured from the robot's motion, the answer "
                   "at the measured size), stated (the print was measured: keep the described "
                   "size), or the measured ÷ described size, e.g. 0.96 (docs/target-scale.md)")
      ->capture_default_str();
  command->add_option("--output", flags->output, "Result file (.json, or .yaml/.yml)");
  command->add_option("--report", flags->report,
                      "Interactive HTML page of the result (docs/report.md), e.g. report.html");
  AddLengthUnitFlag(*command, "--units", flags->units,
                    "Length unit of input columns without a suffix: m (default) or mm; "
                    "results use the robot file's unit");
  command->add_flag("--degrees", flags->degrees, "Angles without a suffix are in degrees");
  AddEulerFlag(*command, "--euler", flags->euler, "Euler sequence of a1,a2,a3 columns (e.g. ZYX)");
  command->add_flag("--robot-inverse", flags->robot_inverse,
                    "The robot file holds T_gripper_base: invert every pose");
  command->add_flag("--camera-inverse", flags->camera_inverse,
                    "The camera file holds T_target_camera: invert every pose");
  command->add_flag("--keep-outliers", flags->keep_outliers,
                    "Use every station: no outlier rejection (by default gross outliers are "
                    "rejected by consensus and a 3-sigma test, and listed)");
  AddChoice<estimation::RobustLoss>(*command, "--robust", flags->robust,
                                    estimation::ParseRobustLoss, "loss", "none, huber or cauchy",
                                    "Robust loss for ml: none|huber|cauchy");
  AddChoice<estimation::CovarianceMethod>(
      *command, "--covariance", flags->covariance,
      [](std::string_view text) -> std::optional<estimation::CovarianceMethod> {
        const auto method = estimation::ParseCovarianceMethod(text);
        if (method == estimation::CovarianceMethod::kNone) return std::nullopt;
        return method;
      },
      "covariance method",
      "linear, unscented, montecarlo or information (or leave it out for the method's default: "
      "linear for ml, unscented for the others up to 100 stations, information above)",
      "Covariance of X and Z: linear | unscented | montecarlo | information (default: linear "
      "for ml; unscented for the other methods up to 100 stations, information above)");
  AddWholeNumber(*command, "--covariance-samples", flags->covariance_samples,
                 "Monte Carlo samples for --covariance montecarlo (2 to 100000)")
      ->capture_default_str();
  AddWholeNumber(*command, "--seed", flags->seed,
                 "Random seed for --covariance montecarlo and the outlier consensus (0 to "
                 "2^64-1)")
      ->capture_default_str();
  command->callback([flags, &io] { RunCalibrate(*flags, io); });
}

}  // namespace hecal::cli
