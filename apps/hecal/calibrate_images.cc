// `hecal calibrate --images`: see calibrate.h.
#include "calibrate.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <optional>
#include <vector>

#include "bounds.h"
#include "conventions.h"
#include "hecal/estimation/image_calibration.h"
#include "hecal/geometry/rotation.h"
#include "hecal/io/image_pairing.h"
#include "hecal/report/image_calibration.h"
#include "hecal/report/result_text.h"
#include "image_report.h"
#endif

namespace hecal::cli {

#if defined(HECAL_HAVE_OPENCV_PEERS)
namespace {

// Its range is ImageCalibrationOptions::IsValid's.
void PrintRefinedIntrinsics(std::ostream& out, const pose::CameraModel& before,
                            const report::ImageReport& report) {
  constexpr std::array<const char*, pose::kNumIntrinsics> kNames = {"fx", "fy", "cx", "cy", "k1",
                                                                    "k2", "p1", "p2", "k3"};
  const pose::IntrinsicParameters start = pose::IntrinsicsOf(before);
  const pose::IntrinsicParameters refined = pose::IntrinsicsOf(report.camera);
  out << "intrinsics refined with X and Z (before → after ± 1σ):\n";
  for (int k = 0; k < pose::kNumIntrinsics; ++k) {
    out << "  " << kNames[static_cast<size_t>(k)] << " " << std::setprecision(k < 4 ? 7 : 5)
        << start(k) << " → " << refined(k) << " ± " << std::setprecision(2)
        << (*report.intrinsics_sigma)[static_cast<size_t>(k)] << "\n";
  }
  out << std::setprecision(6);
}

void PrintImageTable(std::ostream& out, const report::ResultDocument& document,
                     const report::ImageReport& report) {
  out << std::fixed << std::setprecision(3) << "reprojection: RMS " << report.rms_px
      << " px over every point; pixel sigma " << report.pixel_sigma << " px ("
      << (report.pixel_sigma_estimated ? "estimated" : "given") << ")\n  image          rms_px\n";
  const std::vector<std::string> used = report::UsedStationIds(document);
  for (size_t k = 0; k < used.size(); ++k) {
    out << "  " << std::left << std::setw(14) << used[k] << std::right << std::setw(7)
        << report.image_rms_px[k] << (report.image_outlier[k] ? "   > 3σ, check this image" : "")
        << "\n";
  }
  out.unsetf(std::ios::floatfield);
}

}  // namespace

std::vector<Pose> RobotPosePerImage(const io::PoseTable& robot, const ImageSet& set,
                                    const std::string& images_dir, const Io& io) {
  std::vector<io::StationImage> stations;
  for (const ImageRecord& image : set.images) {
    stations.push_back({image.station, image.path, image.name});
  }
  return io::PairRobotWithStations(robot, stations, images_dir, [&io](const std::string& note) {
    io.err << "hecal: note: " << note << "\n";
  });
}

void RunCalibrateImages(const CalibrateFlags& flags, const CalibrateSettings& settings,
                        const Io& io) {
  if (settings.all) {
    throw InputError("--method", 0, "--method all is not available with --images",
                     "run hecal detect to write camera.csv, then hecal calibrate --camera "
                     "camera.csv --method all; or give one method");
  }
  if (settings.options.covariance.method == estimation::CovarianceMethod::kUnscented) {
    throw InputError("--covariance", 0,
                     "--covariance unscented is not available with --images (its input is the "
                     "noise of every detected pixel: thousands of sigma points)",
                     "use linear (the default) or montecarlo; or run hecal detect and "
                     "calibrate --camera camera.csv --covariance unscented on the poses");
  }
  if (flags.camera_inverse) {
    throw InputError("--camera-inverse", 0, "applies to --camera files only",
                     "leave it out: poses from --images are T_camera_target");
  }
  if (flags.target.empty()) {
    throw InputError("--target", 0, "--images needs --target",
                     "give the target description, e.g. --target target.yaml (docs/targets.md)");
  }
  if (flags.target == "none") {
    throw InputError("--target", 0,
                     "--target none (generic image features, no target) works with --method "
                     "global only: the other methods need the target's poses",
                     "add --method global, or give the target with --target target.yaml");
  }
  // Checked before the images are read; setup and camera follow from them.
  estimation::ImageCalibrationOptions options;
  options.calibrate = settings.options;
  options.pixel_sigma = ParsePixelSigma(flags.pixel_sigma);
  options.refine_intrinsics = flags.refine_intrinsics;
  RequireValid(options);
  io::PoseReadOptions robot_read = settings.read;
  robot_read.invert = flags.robot_inverse;
  const io::PoseTable robot = io::ReadPoseTable(flags.robot, robot_read);

  const ImageSet set = DetectImageSet(
      {flags.images, flags.target, flags.intrinsics, settings.options.covariance.threads},
      "hecal calibrate", io);
  const std::vector<Pose> robot_poses = RobotPosePerImage(robot, set, flags.images, io);

  report::ImageCalibrationInput input;
  input.unit = robot.unit;
  input.robot_unit_named = robot.unit_named;
  handeye::PoseData data;
  for (size_t i = 0; i < set.images.size(); ++i) {
    const ImageRecord& image = set.images[i];
    input.image_ids.push_back(image.id());
    input.skipped.push_back(image.skipped);
    if (!image.used()) continue;
    estimation::ImageStation station;
    station.T_base_gripper = robot_poses[i];
    station.T_camera_target = image.pose->T_camera_target;
    station.camera_covariance = image.pose->covariance;
    station.points = {ObjectPointsOf(image.detection, set.board), PixelsOf(image.detection)};
    data.T_base_gripper.push_back(station.T_base_gripper);
    data.T_camera_target.push_back(station.T_camera_target);
    input.stations.push_back(std::move(station));
  }
  data.robot_unit_named = robot.unit_named;
  data.robot_quaternions = HasQuaternionColumns(robot);
  data.camera_from_images = true;
  handeye::ConventionCheckOptions convention;
  convention.setup = settings.setup;
  convention.consensus = settings.options.consensus;
  convention.robot_source = flags.robot;
  convention.robot_inverted = flags.robot_inverse;
  convention.robot_matrix_lines = !robot.rotation;
  convention.words = ConventionFlagWords();
  const handeye::ConventionCheck check = handeye::CheckConventions(data, convention);
  input.notes = check.notes;
  input.notes.insert(input.notes.end(), robot.warnings.begin(), robot.warnings.end());
  input.intrinsics_source =
      set.estimated ? std::string("estimated from the images") : flags.intrinsics;
  if (set.estimated) input.intrinsics_rms_px = set.estimated->rms_px;

  options.setup = check.setup;
  options.camera = set.camera;
  const report::ResultDocument document = report::CalibrateFromImages(input, options);
  const estimation::CalibrationResult& result = document.results.front();
  const report::ImageReport& report = *document.images;

  const Pose step = report.pose_level.X.inverse() * result.X;
  const double scale = 1.0 / io::MetresPer(document.unit);
  io.out << "\npose level (" << estimation::Info(report.pose_level.method).name
         << " on the PnP poses), then the joint reprojection refinement moved X by "
         << std::setprecision(4)
         << AxisAngleFromMatrix(step.linear()).angle * 180.0 / std::numbers::pi << " deg, "
         << (result.X.translation() - report.pose_level.X.translation()).norm() * scale << " "
         << io::UnitName(document.unit) << "\n";
  io.out.unsetf(std::ios::floatfield);
  report::PrintResultSummary(io.out, document, result);
  if (report.intrinsics_sigma) PrintRefinedIntrinsics(io.out, set.camera, report);
  PrintImageTable(io.out, document, report);
  if (!flags.output.empty()) {
    report::WriteResult(flags.output, document);
    io.out << "wrote " << flags.output << "\n";
  }
}

#else

void RunCalibrateImages(const CalibrateFlags&, const CalibrateSettings&, const Io&) {
  throw InputError("hecal calibrate --images", 0,
                   "this hecal was built without the vision layer (OpenCV)",
                   "rebuild with -DHECAL_BUILD_VISION=ON, or give --camera camera.csv");
}

#endif

}  // namespace hecal::cli
