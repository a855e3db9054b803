// `hecal calibrate --images`: see calibrate.h.
#include "calibrate.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <optional>
#include <vector>

#include "bounds.h"
#include "conventions.h"
#include "hecal/estimation/image_calibration.h"
#include "hecal/io/image_pairing.h"
#include "hecal/report/image_calibration.h"
#include "hecal/report/result_text.h"
#include "image_report.h"
#endif

namespace hecal::cli {

#if defined(HECAL_HAVE_OPENCV_PEERS)
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
  report::PrintImageResultSummary(io.out, document, set.camera);
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
