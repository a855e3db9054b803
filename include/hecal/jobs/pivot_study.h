// The pivot study (`hecal simulate --pivot`; docs/pivot.md#the-study): synthetic pivots with
// ground truth (sim/pivot_simulation.h) calibrated by estimation::CalibratePivot, told the true
// noise and estimating it, per noise level and station count.
//
// Per trial k (seed SplitMix64(seed + k), the same scene for every fit of the trial): the scene
// drawn with the level's σ (mm and degrees per axis, Gaussian right perturbations), then two fits:
// "given" (PivotOptions::sigma the true σ) and "estimated" (no sigma). Per setting and fit:
//  - RMSE of the tip and of the pivot point: sqrt(mean |x̂ − x|²) over the trials (metres);
//  - NEES of the 6-vector (t_tip, p), ε = eᵀ Σ⁻¹ e with the fit's covariance, its mean with the
//    two-sided 95% band [χ²⁻¹(0.025; 6N), χ²⁻¹(0.975; 6N)] / N of a consistent covariance
//    (uncertainty/consistency.h), and the tip's 3-vector mean NEES (expected 3);
//  - coverage of the 1σ / 2σ ellipsoids (68.27% / 95.45% expected).
// With the noise estimated the NEES follows 6 F(6, 3m − 6), mean 6 (3m − 6)/(3m − 8) (6.23 at 20
// stations): above the χ² band by design when m is small (estimation/pivot.h step 4).
// A trial the estimator refuses (DegenerateError) is counted in `failures` and left out.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hecal/sim/pivot_simulation.h"
#include "hecal/study/study.h"

namespace hecal::jobs {

struct PivotStudyOptions {
  std::vector<study::NoiseLevel> sigmas = {{0.1, 0.1}};  // mm, deg per axis
  std::vector<int> stations = {20};
  int trials = 200;
  std::uint64_t seed = 1;
  double max_tilt_deg = 30.0;   // orientations within ± this about each flange axis
  bool reject_outliers = true;  // PivotOptions::reject_outliers of both fits

  // core/options_check.h: false naming PivotStudyOptions.<field>: sigmas (none, or a level with
  // 0 mm: the given fit needs translation noise), stations (3 … 100000 each), trials
  // (1 … 100000), max_tilt_deg (5 … 90).
  bool IsValid(std::string* why) const;
};

struct PivotStudyRow {
  study::NoiseLevel sigma;
  int stations = 0;
  bool estimated = false;  // the fit estimated the noise
  int trials = 0;          // fitted (failures left out)
  int failures = 0;
  double tip_rmse = 0.0;    // metres
  double pivot_rmse = 0.0;  // metres
  double mean_nees = 0.0;   // (t_tip, p), 6 dof
  double nees_low = 0.0;    // the 95% band of the mean for `trials`
  double nees_high = 0.0;
  double mean_tip_nees = 0.0;  // t_tip alone, 3 dof
  double coverage_1sigma = 0.0;
  double coverage_2sigma = 0.0;
};

struct PivotStudy {
  PivotStudyOptions options;
  std::vector<PivotStudyRow> rows;  // per level, per station count: given, then estimated
};

PivotStudy RunPivotStudy(const PivotStudyOptions& options);

// Trial `trial` of the setting (level, stations): the scene the study fits.
sim::PivotScene PivotStudyTrial(const PivotStudyOptions& options, const study::NoiseLevel& sigma,
                                int stations, int trial);

}  // namespace hecal::jobs
