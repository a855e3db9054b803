// Target-free, globally optimal calibration as one job (`hecal calibrate --method global`,
// docs/global.md): from the robot poses of the stations and point matches between the images of
// two stations (unit rays), global::SolveGlobalRobust removes wrong matches and certifies the
// L∞ optimum (global/outlier_removal.h, global/branch_and_bound.h); estimation::PolishAndRecheck
// polishes it in L2 and re-checks the removed pairs at the polished X; the final X and its
// covariance come from the polish with the robot's pose error marginalised, the covariance
// checked against the data's own spread (global_calibration_check.h)
// (estimation/epipolar_robot_noise.h: the three noise levels estimated, or the robot's held at
// `robot_sigma` when given — eye-to-hand widened by the lever arm of the gripper positions,
// estimation::HandPoseSigma — and only the ray noise estimated).
//
// Inputs (GlobalMatches): the hand pose of every station (T_base_gripper, metres), the motions
// as pairs of station indices with their names and the matched rays; `focal` (pixels) turns the
// pixel σ into radians of ray (1 for matches given as bearings). ReadGlobalMatches builds them
// from a robot file and a correspondence file (io/correspondence_file.h; stations by the robot
// file's ids when every row has one, else by 1-based row number; pixels are undistorted through
// the intrinsics file, bearings are taken as they are); the vision layer builds them from images
// (vision/corner_matches.h, vision/feature_matches.h).
// Thresholds: the outlier threshold is 4√2 · pixel_sigma / focal radians of ray.
// Frames and units: X = T_gripper_camera eye-in-hand, T_base_camera eye-to-hand (HandPose,
// global/epipolar_problem.h); metres and radians; covariance in the right perturbation
// (ω, v) of X.
// Result file (WriteGlobalResult, JSON, docs/global.md "Command"): method, setup, X,
// certificate (with `stopped_by`: "gap reached", "below threshold", "max cubes" or
// "time budget", and the budgets), l_infinity_X, covariance (with the model check, the noise
// levels, `robot_sigma`: "given" or "estimated", and the independent-pairs covariance), polish,
// matches (inliers,
// thresholds, removed pairs with the stage that removed them), warnings.
//
// Errors: InputError naming the options field (GlobalCalibrationOptions::IsValid), the files
// with line (ReadGlobalMatches: a station the robot file does not have, pixels without
// intrinsics, a pixel that cannot be undistorted), a motion naming a station that is not
// there; DegenerateError when the matches do not determine X (too few pairs, motions that do
// not observe the length of X's translation).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/epipolar_robot_noise.h"
#include "hecal/global/branch_and_bound.h"
#include "hecal/global/epipolar_problem.h"
#include "hecal/io/pose_table.h"
#include "hecal/report/global_calibration_check.h"

namespace hecal::report {

struct GlobalCalibrationOptions {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  double epsilon = 2e-4;        // radians: the certificate's requested gap, in (0, 1]
  double relative_gap = 0.1;    // or this fraction of the optimum, in [0, 1)
  double reach = 2.0;           // metres: |t| of X is searched up to this, in (0, 1000]
  long max_cubes = 20'000'000;  // the search's budget of cube tests, ≥ 1
  // Seconds (wall clock) for the whole search — the L∞ rounds and the last solve together
  // (global/outlier_removal.h splits it) — in (0, 1e7]: past it the result is the best X found,
  // with the bounds proved, not certified. Matching and polish come on top (docs/global.md).
  double time_budget = 120.0;
  int matches_per_motion = 40;  // the most matches per motion taken from images, 8 … 100000
  int threads = 0;              // 0: every core (core/limits.h)
  std::uint64_t seed = 1;       // of the outlier consensus
  double pixel_sigma = 0.5;     // pixels per axis (radians for bearings), above 0 to 100
  // The robot's pose noise per axis when known (estimation/pose_sigma.h); nullopt: estimated.
  std::optional<estimation::PoseSigma> robot_sigma;

  // core/options_check.h: false naming GlobalCalibrationOptions.<field> outside the ranges above
  // (robot_sigma: estimation::SigmaIsValid).
  bool IsValid(std::string* why) const;
};

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

struct RemovedMatch {
  std::string first;  // station names of the motion
  std::string second;
  int id = 0;
  std::string by;  // "epipolar ransac", "l-infinity support set", "re-check at the polished X"
};

struct GlobalCalibrationResult {
  GlobalCalibrationOptions options;
  // The final X, covariance (the model check's: inflated where the data spread more than the
  // noise model says) and the model's noise.
  estimation::RobotNoisePolish robot_noise;
  GlobalCovarianceCheck covariance_check;  // with the model's own covariance in check
  // As reported: the ray σ estimated; the robot's σ_r, σ_t as given (robot_sigma), else as
  // estimated (those of the hand pose H, estimation/epipolar_robot_noise.h).
  estimation::EpipolarNoise noise;
  Matrix6d independent_covariance =
      Matrix6d::Zero();                  // of the re-check's polish (pairs independent)
  global::Certificate certificate;       // of the last global solve
  Pose l_infinity_X = Pose::Identity();  // the certified L∞ optimum
  int inliers = 0;                       // pairs kept
  double threshold = 0.0;                // radians: the L∞ rounds' threshold
  double pixel_threshold = 0.0;          // radians: 4√2 · pixel_sigma / focal
  double error_scale = 0.0;              // radians: the data's error scale
  std::vector<RemovedMatch> removed;     // in motion order, then pair order
  double search_seconds = 0.0;           // every global solve together
  // What the reader should know: a search stopped by a budget, weak evidence for the
  // covariance (in the result file's `warnings`; the CLI prints them as `hecal: warning:`).
  std::vector<std::string> warnings;
};

// Runs the job; RequireValid(options) first. `progress` (may be empty) receives the search's
// bounds while it runs, at most every 5 s (global::SearchOptions::progress).
GlobalCalibrationResult CalibrateGlobal(
    const GlobalMatches& matches, const GlobalCalibrationOptions& options,
    const std::function<void(const global::SearchProgress&)>& progress = {});

// The result file (above), as text, and written atomically.
std::string GlobalResultJson(const GlobalCalibrationResult& result);
void WriteGlobalResult(const std::string& path, const GlobalCalibrationResult& result);

}  // namespace hecal::report
