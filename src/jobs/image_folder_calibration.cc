// Calibration from a folder of target images: see image_folder_calibration.h.
#include "hecal/jobs/image_folder_calibration.h"

#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "hecal/core/options_check.h"
#include "hecal/io/quaternion_columns.h"
#include "hecal/jobs/image_calibration.h"
#include "hecal/jobs/image_front_end.h"

namespace hecal::jobs {

bool ImageFolderCalibrationOptions::IsValid(std::string* why) const {
  if (!calibration.IsValid(why)) return false;
  if (robot.empty()) {
    return Invalid(why, "ImageFolderCalibrationOptions.robot", "is empty",
                   "give the robot pose table, one T_base_gripper per image");
  }
  return robot_read.IsValid(why) && images.IsValid(why);
}

namespace {

// The size a target's description states, by its key in target.yaml (io/target_file.h): the
// square (chessboard, ChArUco, circle pitch), the marker (marker grids) or the tag (one tag).
std::pair<std::string, double> DescribedSize(const pose::TargetSpec& target) {
  if (target.size > 0.0) return {"size", target.size};
  if (target.square > 0.0) return {"square", target.square};
  return {"marker", target.marker};
}

}  // namespace

ImageFolderCalibration CalibrateFromImageFolder(const ImageFolderCalibrationOptions& options,
                                                const JobCallbacks& callbacks) {
  RequireValid(options);
  const io::PoseTable robot = io::ReadPoseTable(options.robot, options.robot_read);
  vision::ImageSetOptions image_options = options.images;
  image_options.use = vision::ImageUse::kHandEye;
  const vision::ImageSet set = DetectImages(image_options, options.caller, callbacks);
  const std::vector<Pose> robot_poses =
      RobotPosePerImage(robot, set, options.images.images, callbacks);

  ImageCalibrationInput input;
  input.unit = robot.unit;
  std::tie(input.target_size_key, input.target_size) = DescribedSize(set.target);
  input.robot_unit_named = robot.unit_named;
  handeye::PoseData data;
  for (size_t i = 0; i < set.images.size(); ++i) {
    const vision::ImageRecord& image = set.images[i];
    input.image_ids.push_back(image.id());
    input.image_files.push_back(image.name);
    input.skipped.push_back(image.skipped);
    if (!image.used()) continue;
    estimation::ImageStation station;
    station.T_base_gripper = robot_poses[i];
    station.T_camera_target = image.pose->T_camera_target;
    station.camera_covariance = image.pose->covariance;
    station.points = {vision::ObjectPointsOf(image.detection, set.board),
                      vision::PixelsOf(image.detection)};
    data.T_base_gripper.push_back(station.T_base_gripper);
    data.T_camera_target.push_back(station.T_camera_target);
    input.stations.push_back(std::move(station));
  }
  data.robot_unit_named = robot.unit_named;
  data.robot_quaternions = io::HasQuaternionColumns(robot);
  data.camera_from_images = true;
  handeye::ConventionCheckOptions convention;
  convention.setup = options.setup;
  convention.consensus = options.calibration.calibrate.consensus;
  convention.robot_source = options.robot;
  convention.robot_inverted = options.robot_read.invert;
  convention.robot_matrix_lines = !robot.rotation;
  convention.words = options.words;
  const handeye::ConventionCheck check = handeye::CheckConventions(data, convention);
  input.notes = check.notes;
  input.notes.insert(input.notes.end(), robot.warnings.begin(), robot.warnings.end());
  input.intrinsics_source =
      set.estimated ? std::string("estimated from the images") : options.images.intrinsics;
  if (set.estimated) input.intrinsics_rms_px = set.estimated->rms_px;

  estimation::ImageCalibrationOptions calibration = options.calibration;
  calibration.setup = check.setup;
  calibration.camera = set.camera;
  return {CalibrateFromImages(input, calibration), set.camera};
}

}  // namespace hecal::jobs
