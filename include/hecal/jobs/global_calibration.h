// Target-free, globally optimal calibration as one job (`hecal calibrate --method global`,
// docs/global.md): from the robot poses of the stations and point matches between the images of
// two stations (unit rays), global::SolveGlobalRobust removes wrong matches and certifies the
// L∞ optimum (global/outlier_removal.h, global/branch_and_bound.h); estimation::PolishAndRecheck
// polishes it in L2 and re-checks the removed pairs at the polished X; the final X and its
// covariance come from the polish with the robot's report::pose error marginalised, the covariance
// checked against the data's own spread (global_calibration_check.h)
// (estimation/epipolar_robot_noise.h: the three noise levels estimated, or the robot's held at
// `robot_sigma` when given — eye-to-hand widened by the lever arm of the gripper positions,
// estimation::HandPoseSigma — and only the ray noise estimated).
//
// Inputs (GlobalMatches): the hand report::pose of every station (T_base_gripper, metres), the
// motions as pairs of station indices with their names and the matched rays; `focal` (pixels) turns
// the pixel σ into radians of ray (1 for matches given as bearings). ReadGlobalMatches builds them
// from a robot file and a correspondence file (io/correspondence_file.h; stations by the robot
// file's ids when every row has one, else by 1-based row number; pixels are undistorted through
// the intrinsics file, bearings are taken as they are); the vision layer builds them from images
// (vision/corner_matches.h, vision/feature_matches.h).
// Thresholds: the outlier threshold is 4√2 · pixel_sigma / focal radians of ray.
// Frames and units: X = T_gripper_camera eye-in-hand, T_base_camera eye-to-hand (HandPose,
// global/epipolar_problem.h); metres and radians; covariance in the right perturbation
// (ω, v) of X.
// The result and its file: report/global_result.h.
//
// Errors: InputError naming the options field (report::GlobalCalibrationOptions::IsValid), the
// files with line (ReadGlobalMatches: a station the robot file does not have, pixels without
// intrinsics, a pixel that cannot be undistorted), a motion naming a station that is not
// there; DegenerateError when the matches do not determine X (too few pairs, motions that do
// not observe the length of X's translation).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "hecal/global/epipolar_problem.h"
#include "hecal/io/pose_table.h"
#include "hecal/report/global_result.h"

namespace hecal::jobs {

struct GlobalMotion {
  int first = 0;  // station indices into GlobalMatches::T_base_gripper
  int second = 0;
  std::string first_name;  // for the result's removed pairs
  std::string second_name;
  std::vector<global::BearingPair> pairs;  // v in the first camera, u in the second
};

struct GlobalMatches {
  std::vector<Pose> T_base_gripper;  // one per station, metres
  std::vector<GlobalMotion> motions;
  double focal = 1.0;  // pixels of the camera the rays come from; 1 for bearings
};

// Reads the robot poses (`read`: units, angles, inversion) and the correspondence file; the
// intrinsics file is needed when the matches are pixels ("" otherwise).
GlobalMatches ReadGlobalMatches(const std::string& robot_file, const io::PoseReadOptions& read,
                                const std::string& correspondence_file,
                                const std::string& intrinsics_file);

// Runs the job; RequireValid(options) first. `progress` (may be empty) receives the search's
// bounds while it runs, at most every 5 s (global::SearchOptions::progress).
report::GlobalCalibrationResult CalibrateGlobal(
    const GlobalMatches& matches, const report::GlobalCalibrationOptions& options,
    const std::function<void(const global::SearchProgress&)>& progress = {});

}  // namespace hecal::jobs
