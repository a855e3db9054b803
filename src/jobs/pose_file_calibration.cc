// Calibration from two pose tables: see pose_file_calibration.h.
#include "hecal/jobs/pose_file_calibration.h"

#include <filesystem>
#include <system_error>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/plausibility.h"
#include "hecal/io/quaternion_columns.h"
#include "hecal/jobs/pose_calibration.h"

namespace hecal::jobs {
namespace {

// Step 3: one file given twice (or a copy of it); the same poses in two files are refused by
// CalibratePairedPoses.
void RefuseSameFile(const PoseFileCalibrationOptions& options) {
  std::error_code error;
  if (!std::filesystem::equivalent(options.robot, options.camera, error) || error) return;
  const PoseFileWords& words = options.file_words;
  throw InputError(
      options.camera, 0, "is the same file as " + words.robot + " " + options.robot,
      "give the robot poses (T_base_gripper, from the controller) with " + words.robot +
          " and the camera poses (T_camera_target, from PnP or hecal detect) with " + words.camera);
}

}  // namespace

bool PoseFileCalibrationOptions::IsValid(std::string* why) const {
  if (!calibrate.IsValid(why)) return false;
  if (robot.empty()) {
    return Invalid(why, "PoseFileCalibrationOptions.robot", "is empty",
                   "give the robot pose table, one T_base_gripper per station");
  }
  if (camera.empty()) {
    return Invalid(why, "PoseFileCalibrationOptions.camera", "is empty",
                   "give the camera pose table, one T_camera_target per station");
  }
  return robot_read.IsValid(why) && camera_read.IsValid(why);
}

PairedPoses PairedTablePoses(const PoseFileCalibrationOptions& options, const io::PoseTable& robot,
                             const io::PoseTable& camera, const io::Stations& stations) {
  PairedPoses poses;
  poses.data.T_base_gripper = stations.robot;
  poses.data.T_camera_target = stations.camera;
  poses.data.robot_unit_named = robot.unit_named;
  poses.data.camera_unit_named = camera.unit_named;
  poses.data.robot_quaternions = io::HasQuaternionColumns(robot);
  poses.data.camera_quaternions = io::HasQuaternionColumns(camera);
  poses.check = {.setup = options.setup,
                 .consensus = options.calibrate.consensus,
                 .robot_source = options.robot,
                 .camera_source = options.camera,
                 .robot_inverted = options.robot_read.invert,
                 .camera_inverted = options.camera_read.invert,
                 .robot_matrix_lines = !robot.rotation,
                 .camera_matrix_lines = !camera.rotation,
                 .words = options.words};
  poses.unit = robot.unit;
  poses.station_ids = stations.ids;
  poses.robot_words = options.file_words.robot;
  poses.camera_words = options.file_words.camera;
  poses.notes = robot.warnings;
  poses.notes.insert(poses.notes.end(), camera.warnings.begin(), camera.warnings.end());
  return poses;
}

PoseFileCalibration CalibrateFromPoseFiles(const PoseFileCalibrationOptions& options) {
  RequireValid(options);
  const io::PoseTable robot = io::ReadPoseTable(options.robot, options.robot_read);
  const io::PoseTable camera = io::ReadPoseTable(options.camera, options.camera_read);
  const io::Stations stations = io::PairStations(robot, camera);
  RefuseSameFile(options);
  const PairedPoses poses = PairedTablePoses(options, robot, camera, stations);
  return {CalibratePairedPoses(poses, options.calibrate, options.all_methods).document};
}

}  // namespace hecal::jobs
