// Calibration from two pose tables: see pose_file_calibration.h.
#include "hecal/jobs/pose_file_calibration.h"

#include <filesystem>
#include <system_error>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/plausibility.h"
#include "hecal/io/quaternion_columns.h"
#include "hecal/report/pose_calibration.h"

namespace hecal::jobs {
namespace {

// Step 3: one file given twice (or a copy) holds the same poses as robot and camera.
void RefuseSamePoses(const PoseFileCalibrationOptions& options, const io::Stations& stations) {
  std::error_code error;
  const bool same_path =
      std::filesystem::equivalent(options.robot, options.camera, error) && !error;
  bool same_poses = !stations.robot.empty();
  for (size_t i = 0; same_poses && i < stations.robot.size(); ++i) {
    same_poses = stations.robot[i].isApprox(stations.camera[i], 1e-12) ||
                 stations.robot[i].isApprox(stations.camera[i].inverse(), 1e-12);
  }
  if (!same_path && !same_poses) return;
  const PoseFileWords& words = options.file_words;
  throw InputError(
      options.camera, 0,
      same_path
          ? "is the same file as " + words.robot + " " + options.robot
          : "holds the same poses as " + words.robot + " " + options.robot + " (or their inverses)",
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

PoseFileCalibration CalibrateFromPoseFiles(const PoseFileCalibrationOptions& options) {
  RequireValid(options);
  const io::PoseTable robot = io::ReadPoseTable(options.robot, options.robot_read);
  const io::PoseTable camera = io::ReadPoseTable(options.camera, options.camera_read);
  const io::Stations stations = io::PairStations(robot, camera);
  RefuseSamePoses(options, stations);

  handeye::PoseData data;
  data.T_base_gripper = stations.robot;
  data.T_camera_target = stations.camera;
  data.robot_unit_named = robot.unit_named;
  data.camera_unit_named = camera.unit_named;
  data.robot_quaternions = io::HasQuaternionColumns(robot);
  data.camera_quaternions = io::HasQuaternionColumns(camera);
  const handeye::ConventionCheck check =
      handeye::CheckConventions(data, {.setup = options.setup,
                                       .consensus = options.calibrate.consensus,
                                       .robot_source = options.robot,
                                       .camera_source = options.camera,
                                       .robot_inverted = options.robot_read.invert,
                                       .camera_inverted = options.camera_read.invert,
                                       .robot_matrix_lines = !robot.rotation,
                                       .camera_matrix_lines = !camera.rotation,
                                       .words = options.words});
  const handeye::Problem problem =
      handeye::MakeProblem(check.setup, stations.robot, stations.camera);

  report::PoseCalibrationInput input{
      problem, robot.unit, stations.ids,
      estimation::PlausibilityInput{check.setup, stations.robot, stations.camera, robot.unit_named,
                                    camera.unit_named},
      check.notes};
  input.notes.insert(input.notes.end(), robot.warnings.begin(), robot.warnings.end());
  input.notes.insert(input.notes.end(), camera.warnings.begin(), camera.warnings.end());
  return {report::CalibrateFromPoses(input, options.calibrate, options.all_methods)};
}

}  // namespace hecal::jobs
