// `hecal calibrate` from pose tables, and the flags and summary of every form: see calibrate.h.
#include "calibrate.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <numbers>
#include <numeric>
#include <sstream>
#include <utility>

#include "bounds.h"
#include "conventions.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/plausibility.h"
#include "hecal/geometry/rotation.h"
#include "hecal/io/atomic_file.h"
#include "hecal/report/pose_calibration.h"
#include "list_flags.h"

namespace hecal::cli {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;
// The printout lists every station up to this many, else the largest residuals only.
constexpr size_t kMaxPrintedStations = 200;
constexpr size_t kLargestPrintedStations = 20;

// "MM,DEG" (ParseNoiseLevel) → PoseSigma in metres and radians (its range is
// CalibrateOptions::IsValid's).
estimation::PoseSigma ParseSigma(const std::string& flag, const std::string& text) {
  const study::NoiseLevel level = ParseNoiseLevel(flag, text, ',', /*single=*/false);
  return {level.deg / kDegrees, level.mm * 1e-3};
}

void PrintPose(std::ostream& out, std::string_view name, std::string_view frame, const Pose& T,
               double scale, std::string_view unit) {
  const AxisAngle aa = AxisAngleFromMatrix(T.linear());
  out << name << " = " << frame << "\n";
  for (int r = 0; r < 3; ++r) {
    out << "  [";
    for (int c = 0; c < 3; ++c) out << std::setw(11) << T.linear()(r, c);
    out << " |" << std::setw(11) << T.translation()(r) * scale << " ]\n";
  }
  out << "  rotation " << aa.angle * kDegrees << " deg about (" << aa.axis.transpose()
      << "), translation " << (T.translation() * scale).transpose() << " " << unit << "\n";
}

// 1σ per axis in degrees and millimetres, whatever the file unit (the result file has both).
void PrintSigma(std::ostream& out, std::string_view name, const Matrix6d& covariance) {
  const Vector6d sd = covariance.diagonal().cwiseSqrt();
  out << "  1σ " << name << ": rotation (" << sd.head<3>().transpose() * kDegrees
      << ") deg, translation (" << sd.tail<3>().transpose() * 1000.0 << ") mm\n";
}

}  // namespace

void PrintSummary(std::ostream& out, const report::ResultDocument& document,
                  const estimation::CalibrationResult& result) {
  const double scale = 1.0 / io::MetresPer(document.unit);
  const std::string_view unit = io::UnitName(document.unit);
  out << std::fixed << std::setprecision(6);
  out << "method " << handeye::Info(result.method).name << " ("
      << handeye::SetupName(document.setup) << ", " << result.residuals.size() << " stations)\n";
  PrintPose(out, "X", handeye::XFrameName(document.setup), result.X, scale, unit);
  PrintPose(out, "Z", handeye::ZFrameName(document.setup), result.Z, scale, unit);
  if (result.covariance) {
    const estimation::CalibrationCovariance& c = *result.covariance;
    out << "covariance: " << estimation::CovarianceMethodName(c.method);
    if (c.method == estimation::CovarianceMethod::kMonteCarlo) {
      out << " (" << c.samples << " samples)";
    } else if (c.solves > 0) {
      out << " (" << c.solves << " solves)";
    }
    out << "\n";
    PrintSigma(out, "X", c.X());
    PrintSigma(out, "Z", c.Z());
  }
  out << std::setprecision(4) << "residual RMS: " << result.rotation_rms * kDegrees << " deg, "
      << result.translation_rms * scale << " " << unit << "\n";
  out << "  station        rotation_deg   translation_" << unit << "   whitened\n";
  const std::vector<std::string> used = report::UsedStationIds(document);
  const size_t shown = std::min(used.size(), result.residuals.size());
  // Every station up to kMaxPrintedStations; above, the largest whitened residuals (the file
  // has them all).
  std::vector<size_t> order(shown);
  std::iota(order.begin(), order.end(), size_t{0});
  if (shown > kMaxPrintedStations) {
    std::partial_sort(order.begin(), order.begin() + kLargestPrintedStations, order.end(),
                      [&](size_t a, size_t b) {
                        return result.residuals[a].whitened > result.residuals[b].whitened;
                      });
    order.resize(kLargestPrintedStations);
    out << "  (the " << kLargestPrintedStations << " largest of " << shown
        << " stations; every station is in the result file)\n";
  }
  for (const size_t k : order) {
    const estimation::StationResidual& r = result.residuals[k];
    out << "  " << std::left << std::setw(14) << used[k] << std::right << std::setw(12)
        << r.rotation * kDegrees << std::setw(17) << r.translation * scale << std::setw(11)
        << r.whitened << (r.outlier ? "   > 3σ, check this station" : "") << "\n";
  }
  for (size_t k = 0; k < result.rejected_residuals.size(); ++k) {
    const estimation::StationResidual& r = result.rejected_residuals[k];
    const std::string id = k < result.rejected_ids.size() ? result.rejected_ids[k]
                                                          : std::to_string(result.rejected[k] + 1);
    out << "  " << std::left << std::setw(14) << id << std::right << std::setw(12)
        << r.rotation * kDegrees << std::setw(17) << r.translation * scale << std::setw(11)
        << r.whitened << "   rejected: outlier, not used\n";
  }
  for (const std::string& warning : result.warnings) out << "warning: " << warning << "\n";
  out.unsetf(std::ios::floatfield);
}

namespace {

// `--method all`: one line per method, side by side, with the difference from ml and the
// predicted RMS error of X (sqrt of the trace of its rotation and translation covariance).
void PrintComparison(std::ostream& out, const report::ResultDocument& document) {
  const double scale = 1.0 / io::MetresPer(document.unit);
  const std::string_view unit = io::UnitName(document.unit);
  const auto ml = std::find_if(document.results.begin(), document.results.end(),
                               [](const auto& r) { return r.method == handeye::Method::kMl; });
  const std::string length = "res_" + std::string(unit);
  out << "\nside by side (X " << handeye::XFrameName(document.setup) << ")\n  " << std::left
      << std::setw(16) << "method" << std::right << std::setw(11) << "tx" << std::setw(12) << "ty"
      << std::setw(12) << "tz" << std::setw(12) << "res_deg" << std::setw(9) << length;
  if (ml != document.results.end())
    out << std::setw(12) << "vs_ml_deg" << std::setw(10) << "vs_ml_" + std::string(unit);
  out << std::setw(11) << "1σ_deg" << std::setw(10) << "1σ_mm"
      << "  covariance\n";
  out << std::fixed;
  for (const estimation::CalibrationResult& r : document.results) {
    const Eigen::Vector3d t = r.X.translation() * scale;
    out << "  " << std::left << std::setw(16) << handeye::Info(r.method).name << std::right
        << std::setprecision(6) << std::setw(11) << t.x() << std::setw(12) << t.y() << std::setw(12)
        << t.z() << std::setprecision(4) << std::setw(12) << r.rotation_rms * kDegrees
        << std::setw(9) << r.translation_rms * scale;
    if (ml != document.results.end()) {
      const Pose d = ml->X.inverse() * r.X;
      out << std::setw(12) << AxisAngleFromMatrix(d.linear()).angle * kDegrees << std::setw(10)
          << (r.X.translation() - ml->X.translation()).norm() * scale;
    }
    if (r.covariance) {  // predicted RMS error of X: sqrt(trace) of each block
      const Matrix6d C = r.covariance->X();
      out << std::setw(10) << std::sqrt(C.topLeftCorner<3, 3>().trace()) * kDegrees << std::setw(9)
          << std::sqrt(C.bottomRightCorner<3, 3>().trace()) * 1000.0 << "  "
          << estimation::CovarianceMethodName(r.covariance->method);
    }
    out << "\n";
  }
  for (const report::MethodFailure& failure : document.failures)
    out << "  " << std::left << std::setw(16) << handeye::Info(failure.method).name << std::right
        << "refused: " << failure.message << "\n";
  out.unsetf(std::ios::floatfield);
}

}  // namespace

CalibrateSettings ParseCalibrateFlags(const CalibrateFlags& flags) {
  CalibrateSettings settings;
  const auto setup = handeye::ParseSetup(flags.setup);
  if (!setup && flags.setup != "auto") {
    throw InputError("--setup", 0, "unknown setup '" + flags.setup + "'",
                     "use eye-in-hand (camera on the robot), eye-to-hand (camera fixed) or auto "
                     "(the one the data fit)");
  }
  settings.setup = setup;
  settings.all = flags.method == "all";
  const auto method = handeye::ParseMethod(flags.method);
  if (!settings.all && !method) {
    std::string names;
    for (const auto& info : handeye::AllMethods()) names += std::string(info.name) + " ";
    throw InputError("--method", 0, "unknown method '" + flags.method + "'",
                     "use one of: " + names + "all");
  }
  const auto units = io::ParseLengthUnit(flags.units);
  if (!units) throw InputError("--units", 0, "unknown unit '" + flags.units + "'", "use m or mm");
  if (method) settings.options.method = *method;
  io::PoseReadOptions& read = settings.read;
  read.units = *units;
  read.degrees = flags.degrees;
  if (!flags.euler.empty()) {
    read.euler = EulerSequence::Parse(flags.euler);
    if (!read.euler) {
      throw InputError("--euler", 0, "unknown Euler sequence '" + flags.euler + "'",
                       "use three axis letters, lowercase extrinsic (xyz) or uppercase intrinsic "
                       "(ZYX)");
    }
  }
  estimation::CalibrateOptions& options = settings.options;
  if (!flags.robot_sigma.empty())
    options.robot_sigma = ParseSigma("--robot-sigma", flags.robot_sigma);
  if (!flags.camera_sigma.empty()) {
    options.camera_sigma = ParseSigma("--camera-sigma", flags.camera_sigma);
  }
  if (!flags.covariance.empty()) {
    const auto covariance = estimation::ParseCovarianceMethod(flags.covariance);
    if (!covariance || *covariance == estimation::CovarianceMethod::kNone) {
      throw InputError("--covariance", 0, "unknown covariance method '" + flags.covariance + "'",
                       "use linear, unscented, montecarlo or information (or leave it out for "
                       "the method's default: linear for ml, unscented for the others up to "
                       "100 stations, information above)");
    }
    options.covariance.method = *covariance;
  }
  options.covariance.samples = flags.covariance_samples;
  options.covariance.seed = flags.seed;
  options.consensus.seed = options.covariance.seed;
  options.reject_outliers = !flags.keep_outliers;
  options.covariance.threads = flags.threads;
  const std::optional<estimation::RobustLoss> robust = estimation::ParseRobustLoss(flags.robust);
  if (!robust) {
    throw InputError("--robust", 0, "unknown loss '" + flags.robust + "'",
                     "use none, huber or cauchy");
  }
  options.robust_loss = *robust;
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

namespace {

// The same poses as robot and camera (one file given twice, or a copy) cannot calibrate anything.
void RefuseSameFile(const CalibrateFlags& flags, const io::Stations& stations) {
  std::error_code error;
  const bool same_path = std::filesystem::equivalent(flags.robot, flags.camera, error) && !error;
  bool same_poses = !stations.robot.empty();
  for (size_t i = 0; same_poses && i < stations.robot.size(); ++i) {
    same_poses = stations.robot[i].isApprox(stations.camera[i], 1e-12) ||
                 stations.robot[i].isApprox(stations.camera[i].inverse(), 1e-12);
  }
  if (same_path || same_poses) {
    throw InputError(
        flags.camera, 0,
        same_path ? "is the same file as --robot " + flags.robot
                  : "holds the same poses as --robot " + flags.robot + " (or their inverses)",
        "give the robot poses (T_base_gripper, from the controller) with --robot and "
        "the camera poses (T_camera_target, from PnP or hecal detect) with --camera");
  }
}

void RunCalibratePoses(const CalibrateFlags& flags, const CalibrateSettings& settings,
                       const Io& io) {
  const bool all = settings.all;
  const estimation::CalibrateOptions& options = settings.options;
  const io::PoseReadOptions& read = settings.read;
  io::PoseReadOptions robot_read = read;
  robot_read.invert = flags.robot_inverse;
  io::PoseReadOptions camera_read = read;
  camera_read.invert = flags.camera_inverse;
  const io::PoseTable robot = io::ReadPoseTable(flags.robot, robot_read);
  const io::PoseTable camera = io::ReadPoseTable(flags.camera, camera_read);
  const io::Stations stations = io::PairStations(robot, camera);
  RefuseSameFile(flags, stations);

  handeye::PoseData data;
  data.T_base_gripper = stations.robot;
  data.T_camera_target = stations.camera;
  data.robot_unit_named = robot.unit_named;
  data.camera_unit_named = camera.unit_named;
  data.robot_quaternions = HasQuaternionColumns(robot);
  data.camera_quaternions = HasQuaternionColumns(camera);
  const ConventionCheck check =
      CheckConventions(data, settings.setup,
                       {flags.robot, flags.camera, flags.robot_inverse, flags.camera_inverse,
                        !robot.rotation, !camera.rotation},
                       options.consensus);
  const handeye::Setup setup = check.setup;
  const handeye::Problem problem = handeye::MakeProblem(setup, stations.robot, stations.camera);

  report::PoseCalibrationInput input{
      problem, robot.unit, stations.ids,
      estimation::PlausibilityInput{setup, stations.robot, stations.camera, robot.unit_named,
                                    camera.unit_named},
      check.notes};
  input.notes.insert(input.notes.end(), robot.warnings.begin(), robot.warnings.end());
  input.notes.insert(input.notes.end(), camera.warnings.begin(), camera.warnings.end());
  const report::ResultDocument document = report::CalibrateFromPoses(input, options, all);
  for (size_t k = 0; k < document.results.size(); ++k) {
    if (k > 0) io.out << "\n";
    PrintSummary(io.out, document, document.results[k]);
  }
  if (all) PrintComparison(io.out, document);
  if (!flags.output.empty()) {
    report::WriteResult(flags.output, document);
    io.out << "wrote " << flags.output << "\n";
  }
}

void RunCalibrate(const CalibrateFlags& flags, const Io& io) {
  const auto check_outputs = [&] {
    io::CheckOutputs({{"--output", flags.output}}, {{"--robot", flags.robot},
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
  check_outputs();
  if (flags.images.empty()) {
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
  command
      ->add_option("--setup", flags->setup,
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
      ->add_option("--features", flags->features,
                   "With --method global --target none: sift or orb image features")
      ->capture_default_str();
  command
      ->add_option("--reach", flags->reach,
                   "With --method global: search X's translation up to this length, metres")
      ->capture_default_str();
  command->add_option("--robot-sigma", flags->robot_sigma,
                      "Robot pose noise per axis, MM,DEG (estimated when absent)");
  command->add_option("--camera-sigma", flags->camera_sigma,
                      "Camera pose noise per axis, MM,DEG (estimated when absent)");
  command->add_option("--output", flags->output, "Result file (.json, or .yaml/.yml)");
  command->add_option("--units", flags->units,
                      "Length unit of input columns without a suffix: m (default) or mm; "
                      "results use the robot file's unit");
  command->add_flag("--degrees", flags->degrees, "Angles without a suffix are in degrees");
  command->add_option("--euler", flags->euler, "Euler sequence of a1,a2,a3 columns (e.g. ZYX)");
  command->add_flag("--robot-inverse", flags->robot_inverse,
                    "The robot file holds T_gripper_base: invert every pose");
  command->add_flag("--camera-inverse", flags->camera_inverse,
                    "The camera file holds T_target_camera: invert every pose");
  command->add_flag("--keep-outliers", flags->keep_outliers,
                    "Use every station: no outlier rejection (by default gross outliers are "
                    "rejected by consensus and a 3-sigma test, and listed)");
  command->add_option("--robust", flags->robust, "Robust loss for ml: none|huber|cauchy");
  command->add_option("--covariance", flags->covariance,
                      "Covariance of X and Z: linear | unscented | montecarlo | information "
                      "(default: linear for ml; unscented for the other methods up to 100 "
                      "stations, information above)");
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
