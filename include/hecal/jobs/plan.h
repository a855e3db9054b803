// `hecal plan` as one job (docs/plan.md): the robot poses to take before the robot moves, or the
// next ones to add to an existing calibration, chosen by the predicted covariance of X.
//
// Steps (PlanStations)
//   1. Options checked; the target (io/target_file.h), the intrinsics (io/camera_file.h) and the
//      workspace (io/workspace_file.h) read.
//   2. The nominal scene: X and Z from the workspace file, or with `existing` from the
//      calibration of the existing pose tables (jobs/pose_file_calibration.h, the noise then
//      estimated unless given), whose stations' information is the base of the design.
//   3. The perturbed nominals: 4 copies of the nominal with X and Z moved by the workspace's
//      nominal_error (rotation and translation, along ±(1, 1, 1)/√3 and ±(1, −1, 1)/√3).
//   4. Candidates that see the whole target at every nominal, inside the workspace
//      (plan/view_candidates.h; seeded, reproducible).
//   5. The stations: D-optimal for X, robust over the nominals (plan/station_design.h).
//   6. The prediction: X's first-order covariance at the nominal with the chosen stations (and
//      before them, with `existing`); with a goal, the number of stations that reaches it
//      (greedy additions up to kMaxGoalStations).
// Units: metres and radians; the robot poses in the base frame (T_base_gripper).
// Errors: hecal::InputError for bad options or files (naming the field, or the file and line),
// and when too few candidates see the target (naming what to change). Nothing is written.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/pose_sigma.h"
#include "hecal/handeye/problem.h"
#include "hecal/io/pose_table.h"

namespace hecal::jobs {

inline constexpr int kMaxGoalStations = 200;

struct PlanOptions {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  int stations = 10;        // how many to plan (with `existing`: how many to add)
  std::string target;       // target.yaml
  std::string intrinsics;   // camera.yaml
  std::string workspace;    // workspace.yaml
  double distance = 0.0;    // metres, camera to board; 0: the board fills half the image width
  double max_board_tilt = 0.7853981633974483;  // radians (45°) between the view and the board
  // Noise for the prediction; with `existing`, estimated from it when absent.
  std::optional<estimation::PoseSigma> robot_sigma;
  std::optional<estimation::PoseSigma> camera_sigma;
  // The existing calibration's tables (both or neither), read with `read`.
  std::string existing_robot;
  std::string existing_camera;
  io::PoseReadOptions read;
  std::optional<estimation::PoseSigma> goal;  // per-axis 1σ of X wanted: rotation, translation
  std::uint64_t seed = 1;

  // core/options_check.h: false naming PlanOptions.stations (below 1, or below 3 for a new plan),
  // .target / .intrinsics / .workspace (empty), .distance (negative or not finite),
  // .max_board_tilt (not in (0, 80°]), .robot_sigma / .camera_sigma (not positive and finite),
  // .existing_robot / .existing_camera (one without the other), .goal (not positive).
  bool IsValid(std::string* why) const;
};

struct PlanResult {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  Pose X = Pose::Identity();  // the nominal scene used
  Pose Z = Pose::Identity();
  bool nominal_from_existing = false;
  std::vector<Pose> T_base_gripper;   // the planned stations
  std::vector<Pose> T_camera_target;  // where the camera sees the target from, at the nominal
  estimation::PoseSigma robot_sigma;  // used for the prediction
  estimation::PoseSigma camera_sigma;
  Eigen::Matrix<double, 6, 6> predicted = Eigen::Matrix<double, 6, 6>::Zero();  // X, with them
  std::optional<Eigen::Matrix<double, 6, 6>> before;  // X, existing stations only
  int existing_stations = 0;
  int candidates = 0;  // candidates that saw the target
  int samples = 0;     // poses sampled to find them
  // With a goal: the stations in all (existing + planned) that reach it; nullopt when
  // kMaxGoalStations do not.
  std::optional<int> goal_stations;
};

PlanResult PlanStations(const PlanOptions& options);

}  // namespace hecal::jobs
