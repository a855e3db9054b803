// The result of the target-free, globally optimal calibration (jobs/global_calibration.h,
// `hecal calibrate --method global`, docs/global.md) and its file: the options it ran with, the
// final X with its covariance checked against the data's own spread (global_calibration_check.h),
// the noise levels, the L∞ certificate, the matches kept and removed, warnings.
// Result file (WriteGlobalResult, JSON, docs/global.md "Command"): method, setup, X,
// certificate (with `stopped_by`: "gap reached", "below threshold", "max cubes" or
// "time budget", and the budgets), l_infinity_X, covariance (with the model check, the noise
// levels, `robot_sigma`: "given" or "estimated", and the independent-pairs covariance), polish,
// matches (inliers, thresholds, removed pairs with the stage that removed them), motions (per
// motion, i.e. pair of stations: the pairs kept and removed, the RMS and largest residual of the
// kept pairs at the final X), warnings.
// Frames and units: X = T_gripper_camera eye-in-hand, T_base_camera eye-to-hand; metres and
// radians; covariance in the right perturbation (ω, v) of X.
//
// Errors: GlobalCalibrationOptions::IsValid names the field (core/options_check.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/epipolar_robot_noise.h"
#include "hecal/global/branch_and_bound.h"
#include "hecal/handeye/problem.h"
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

struct RemovedMatch {
  std::string first;  // station names of the motion
  std::string second;
  int id = 0;
  std::string by;  // "epipolar ransac", "l-infinity support set", "re-check at the polished X"
};

// One motion's residuals at the final X: the Sampson angle of each kept pair
// (estimation::SampsonAngle, radians of ray).
struct MotionResidual {
  std::string first;  // station names of the motion
  std::string second;
  int pairs = 0;     // kept
  int removed = 0;   // removed (RemovedMatch)
  double rms = 0.0;  // radians, over the kept pairs (0 when none)
  double max = 0.0;
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
  std::vector<MotionResidual> motions;   // in the order of the matches' motions
  double search_seconds = 0.0;           // every global solve together
  // What the reader should know: a search stopped by a budget, weak evidence for the
  // covariance (in the result file's `warnings`; the CLI prints them as `hecal: warning:`).
  std::vector<std::string> warnings;
};

// The result file (above), as text, and written atomically.
std::string GlobalResultJson(const GlobalCalibrationResult& result);
void WriteGlobalResult(const std::string& path, const GlobalCalibrationResult& result);

}  // namespace hecal::report
