// Calibration from paired poses as one job: see pose_calibration.h.
#include "hecal/jobs/pose_calibration.h"

#include <cmath>
#include <exception>
#include <string>
#include <utility>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/methods.h"
#include "hecal/estimation/station_selection.h"

namespace hecal::jobs {
namespace {

// CalibratePairedPoses step 1: the same poses as robot and camera fit every X.
void RefuseSamePoses(const PairedPoses& poses) {
  const std::vector<Pose>& robot = poses.data.T_base_gripper;
  const std::vector<Pose>& camera = poses.data.T_camera_target;
  bool same = !robot.empty() && robot.size() == camera.size();
  for (size_t i = 0; same && i < robot.size(); ++i) {
    same = robot[i].isApprox(camera[i], 1e-12) || robot[i].isApprox(camera[i].inverse(), 1e-12);
  }
  if (!same) return;
  throw InputError(poses.check.camera_source, 0,
                   "holds the same poses as " + poses.robot_words + " " + poses.check.robot_source +
                       " (or their inverses)",
                   "give the robot poses (T_base_gripper, from the controller) with " +
                       poses.robot_words +
                       " and the camera poses (T_camera_target, from PnP or "
                       "hecal detect) with " +
                       poses.camera_words);
}

}  // namespace

void CheckPoseList(const std::vector<Pose>& poses, const std::string& source) {
  for (size_t i = 0; i < poses.size(); ++i) {
    const Eigen::Matrix3d R = poses[i].linear();
    const std::string pose = "pose at index " + std::to_string(i);
    if (!poses[i].matrix().allFinite()) {
      throw InputError(source, 0, pose + " is not finite (NaN or infinity)",
                       "remove the station or give its measured pose");
    }
    const double orthogonality =
        (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (orthogonality > 1e-6 || R.determinant() <= 0.0) {
      throw InputError(
          source, 0,
          pose + " has no proper rotation (|R^T R - I| = " + std::to_string(orthogonality) +
              ", det R = " + std::to_string(R.determinant()) + ")",
          "give 4x4 homogeneous transforms whose upper-left 3x3 is a rotation");
    }
  }
}

bool PoseCalibrationOptions::IsValid(std::string* why) const {
  if (!calibrate.IsValid(why)) return false;
  if (robot_source.empty()) {
    return Invalid(why, "PoseCalibrationOptions.robot_source", "is empty",
                   "name the robot poses (e.g. T_base_gripper)");
  }
  if (camera_source.empty()) {
    return Invalid(why, "PoseCalibrationOptions.camera_source", "is empty",
                   "name the camera poses (e.g. T_camera_target)");
  }
  return true;
}

PoseCalibration CalibratePoses(const std::vector<Pose>& T_base_gripper,
                               const std::vector<Pose>& T_camera_target,
                               const PoseCalibrationOptions& options) {
  RequireValid(options);
  if (T_base_gripper.size() != T_camera_target.size()) {
    throw InputError(options.camera_source, 0,
                     "has " + std::to_string(T_camera_target.size()) + " poses where " +
                         options.robot_source + " has " + std::to_string(T_base_gripper.size()),
                     "give one robot pose and one camera pose per station, in the same order");
  }
  const size_t n = T_base_gripper.size();
  if (!options.station_ids.empty() && options.station_ids.size() != n) {
    throw InputError("PoseCalibrationOptions.station_ids", 0,
                     "has " + std::to_string(options.station_ids.size()) + " ids for " +
                         std::to_string(n) + " stations",
                     "give one id per station, or none");
  }
  CheckPoseList(T_base_gripper, options.robot_source);
  CheckPoseList(T_camera_target, options.camera_source);

  PairedPoses poses;
  const io::LengthUnit robot_unit = options.robot_unit.value_or(io::LengthUnit::kMetre);
  const io::LengthUnit camera_unit = options.camera_unit.value_or(io::LengthUnit::kMetre);
  poses.data.T_base_gripper = T_base_gripper;
  poses.data.T_camera_target = T_camera_target;
  for (Pose& pose : poses.data.T_base_gripper) pose.translation() *= io::MetresPer(robot_unit);
  for (Pose& pose : poses.data.T_camera_target) pose.translation() *= io::MetresPer(camera_unit);
  poses.data.robot_unit_named = options.robot_unit.has_value();
  poses.data.camera_unit_named = options.camera_unit.has_value();
  poses.check = {.setup = options.setup,
                 .consensus = options.calibrate.consensus,
                 .robot_source = options.robot_source,
                 .camera_source = options.camera_source,
                 .words = options.words};
  poses.unit = robot_unit;
  poses.robot_words = "the robot list";
  poses.camera_words = "the camera list";
  poses.station_ids = options.station_ids;
  for (size_t i = 0; poses.station_ids.size() < n; ++i) {
    poses.station_ids.push_back(std::to_string(i + 1));
  }
  return CalibratePairedPoses(poses, options.calibrate, options.all_methods);
}

PoseCalibration CalibratePairedPoses(const PairedPoses& poses,
                                     const estimation::CalibrateOptions& options,
                                     bool all_methods) {
  RefuseSamePoses(poses);
  const handeye::ConventionCheck check = handeye::CheckConventions(poses.data, poses.check);
  const std::vector<Pose>& robot = poses.data.T_base_gripper;
  const std::vector<Pose>& camera = poses.data.T_camera_target;
  PoseCalibrationInput input{
      handeye::MakeProblem(check.setup, robot, camera), poses.unit, poses.station_ids,
      estimation::PlausibilityInput{check.setup, robot, camera, poses.data.robot_unit_named,
                                    poses.data.camera_unit_named},
      check.notes};
  input.notes.insert(input.notes.end(), poses.notes.begin(), poses.notes.end());
  return {CalibrateFromPoses(input, options, all_methods)};
}

void CheckFiniteResult(const estimation::CalibrationResult& result) {
  const bool finite = result.X.matrix().allFinite() && result.Z.matrix().allFinite() &&
                      std::isfinite(result.rotation_rms) && std::isfinite(result.translation_rms) &&
                      (!result.covariance || result.covariance->covariance.allFinite());
  if (!finite) {
    throw DegenerateError("X and Z: the solution is not finite",
                          "check the poses' values and units (lengths far beyond a robot's "
                          "reach overflow the solver)");
  }
}

report::ResultDocument CalibrateFromPoses(const PoseCalibrationInput& input,
                                          estimation::CalibrateOptions options, bool all_methods) {
  report::ResultDocument document;
  document.setup = input.problem.setup;
  document.unit = input.unit;
  document.station_ids = input.station_ids;
  document.all_methods = all_methods;
  options.station_ids = input.station_ids;
  // One selection of stations for every method.
  const estimation::StationSelection selection =
      estimation::SelectStationsFor(input.problem, options);
  document.rejected = selection.Rejected();
  if (all_methods) {
    // Degenerate data stop every method: then the first error is the answer. A method that
    // refuses data the others accept is reported and skipped.
    std::exception_ptr first_error;
    for (const estimation::MethodInfo& info : estimation::AllMethods()) {
      options.method = info.method;
      try {
        document.results.push_back(estimation::Calibrate(input.problem, options, selection));
      } catch (const DegenerateError& error) {
        if (!first_error) first_error = std::current_exception();
        document.failures.push_back({info.method, error.what()});
      }
    }
    if (document.results.empty()) std::rethrow_exception(first_error);
  } else {
    document.results.push_back(estimation::Calibrate(input.problem, options, selection));
  }
  for (estimation::CalibrationResult& result : document.results) {
    std::vector<std::string> notes = input.notes;
    for (std::string& warning : estimation::PlausibilityWarnings(input.plausibility, result)) {
      notes.push_back(std::move(warning));
    }
    result.warnings.insert(result.warnings.begin(), notes.begin(), notes.end());
  }
  for (const estimation::CalibrationResult& result : document.results) CheckFiniteResult(result);
  return document;
}

}  // namespace hecal::jobs
